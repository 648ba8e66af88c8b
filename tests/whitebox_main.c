/* whitebox_main.c - the main of one white-box test of `make test`: the
 * test's code is in the shared implementation object (tests/whitebox.c);
 * the Makefile names the test (WHITEBOX_TEST, e.g. "test_kernel"). */
int plateau_test_whitebox(const char *name, int argc, char **argv);

int main(int argc, char **argv)
{
    return plateau_test_whitebox(WHITEBOX_TEST, argc, argv);
}
