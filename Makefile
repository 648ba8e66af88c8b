# plateau - build, test, demo and benchmarks.
#
#   make demo    the main job: reproduce the paper's examples (writes out/)
#   make test    every test file once: gcc -O2, the slow tests at smaller
#                sizes, the implementation compiled once for all the tests
#                of one configuration; a few minutes (the README's testing
#                section gives the figures); closes with "N passed,
#                N failed" and fails on any failure
#   make test-full  the whole matrix at full sizes (PLATEAU_TEST_FULL=1):
#                every test under gcc, clang and ASan+UBSan, the FMA build,
#                short fuzz passes, the header checks, the quick starts as C
#                and C++, make install, the browser check when it can run;
#                the same closing line.  CI runs make demo, make test, then
#                this
#   make check   the inner loop, under a minute: make test's binaries less
#                the tests that compile a configuration of their own and
#                the slowest to run
#   make bench   benchmarks (medians and ratios measured in one run)
#   make fuzz    each libFuzzer target for FUZZ_SECONDS (needs clang's libFuzzer)
#   make web     the library as a freestanding WebAssembly module and a page
#                using it, in out/web/ (needs clang's wasm32 target and wasm-ld;
#                skipped with a note otherwise); make web-check tests it in
#                headless Chromium against the command-line tool
#   make install PREFIX=... the headers, build/plateau and plateau.pc
#   make         the command-line tool build/plateau and the examples
#   make clean
#
# CC, CLANG, CXX, CLANGXX may be overridden; nothing needs installing.

CC      ?= cc
CLANG   ?= clang
CXX     ?= g++
CLANGXX ?= clang++
WARN    := -std=c99 -pedantic -Wall -Wextra -Werror
CXXWARN := -pedantic -Wall -Wextra -Werror
OPT     ?= -O2
SAN     := -O1 -g -fno-omit-frame-pointer -fsanitize=address,undefined -fno-sanitize-recover=all
LDLIBS  := -lm
HEADERS := plateau.h plateau_delaunay.h plateau_lm.h
# Every compile writes its header dependencies next to its output (foo.d);
# they are read back at the end of this file, so no list is kept by hand.
DEP     := -MMD -MP

TESTS    := $(patsubst tests/%.c,%,$(wildcard tests/test_*.c))
QUICKSTARTS := $(patsubst examples/%.c,%,$(wildcard examples/*_quickstart.c))
QS_TEST  := $(foreach q,$(QUICKSTARTS),$(foreach c,gcc gxx clang clangxx,build/quickstart/$(q).$(c)))
QS_CHECK := $(foreach q,$(QUICKSTARTS),$(foreach c,gcc-O0 gxx-O0,build/quickstart/$(q).$(c)))
EXAMPLES := $(filter-out $(QUICKSTARTS),$(patsubst examples/%.c,%,$(wildcard examples/*.c)))
BENCHES  := $(patsubst bench/%.c,%,$(wildcard bench/bench_*.c))
CLI_SRC  := $(wildcard cli/*.c)
CLI_HDR  := $(wildcard cli/*.h)

# The floating-point contraction check: test_fp_contract built the way gcc's
# default GNU mode builds it, a*b + c fused into one FMA (-ffp-contract=fast;
# -mfma where the CPU has FMA, so that the build really fuses), must still
# give valid meshes.  See DETERMINISM in plateau.h.
FMA_ARCH  := $(shell grep -qw fma /proc/cpuinfo 2>/dev/null && echo -mfma -DPLATEAU_TEST_EXPECT_FMA)
FMA_FLAGS := -std=gnu99 -ffp-contract=fast -O2 $(FMA_ARCH) -pedantic -Wall -Wextra -Werror
FMA_BINS  := build/fma/test_fp_contract

TEST_BINS := $(addprefix build/gcc/,$(TESTS)) $(addprefix build/clang/,$(TESTS)) \
             $(addprefix build/san/,$(TESTS)) $(FMA_BINS)

# libFuzzer targets (tests/fuzz/fuzz_*.c).  `make test` runs each for
# FUZZ_TEST_SECONDS when clang can link -fsanitize=fuzzer; `make fuzz` runs
# each for FUZZ_SECONDS.
FUZZ_SECONDS      ?= 60
FUZZ_TEST_SECONDS ?= 5
comma := ,
FUZZERS     := $(patsubst tests/fuzz/%.c,%,$(wildcard tests/fuzz/fuzz_*.c))
FUZZ_FLAGS  := -std=c99 -pedantic -Wall -Wextra -Werror -g -O1 -fno-omit-frame-pointer \
               -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=all
HAVE_FUZZER := $(shell printf 'int LLVMFuzzerTestOneInput(const unsigned char *d, unsigned long n) { (void)d; (void)n; return 0; }\n' \
                 | $(CLANG) -x c -fsanitize=fuzzer -o /dev/null - >/dev/null 2>&1 && echo yes)
FUZZ_CHECKS := $(if $(HAVE_FUZZER),$(addprefix build/fuzz/,$(addsuffix .check,$(FUZZERS))))

# Header checks: each header alone (C99 under gcc and clang, C++ under g++ and
# clang++), static mode, include orders, double inclusion, and a two-unit link.
HDR_NAMES  := lm delaunay plateau
HDR_CHECKS := $(foreach h,$(HDR_NAMES),build/hdr/$(h).gcc.o build/hdr/$(h).clang.o \
                build/hdr/$(h).gxx.o build/hdr/$(h).gxx98.o build/hdr/$(h).clangxx.o) \
              build/hdr/static.gcc.o build/hdr/static.clang.o build/hdr/static.gxx.o \
              build/hdr/order_lm_first.o build/hdr/order_delaunay_first.o \
              build/hdr/twice.o build/hdr/index64.o build/hdr/link build/hdr/late_link \
              build/hdr/freestanding.gcc.o build/hdr/freestanding.clang.o \
              build/hdr/freestanding.clangxx.o build/hdr/strict.gcc.o build/hdr/strict.clang.o

# The switches (CONFIGURATION in plateau.h): tests/hdr/switches.c with the
# implementation, built once per configuration (each switch alone, all of
# them, none) as C99 under gcc and as C++ under g++ at -O1, and run: a plain
# film whose mesh must be the full library's bit for bit (the digest line of
# build/hdr/switch-none.*.ok), and every request for a feature compiled out
# refused naming its macro.  The command-line tool must build with all of
# them but PLATEAU_NO_PATTERNS, which removes declarations it uses
# (build/hdr/switch-cli.o).
SWITCH_CONFIGS   := stability membranes loops c2f svg plyoffstl parsers sparse constraints supports sliding \
                    accuracy quality extras pextras all
switch_stability := -DPLATEAU_NO_STABILITY
switch_membranes := -DPLATEAU_NO_MEMBRANES
switch_loops     := -DPLATEAU_NO_LOOPS
switch_c2f       := -DPLATEAU_NO_COARSE_TO_FINE
switch_svg       := -DPLATEAU_NO_SVG
switch_plyoffstl := -DPLATEAU_NO_PLY_OFF_STL
switch_parsers   := -DPLATEAU_NO_PARSERS
switch_sparse    := -DPLATEAU_LM_NO_SPARSE
switch_constraints := -DPLATEAU_LM_NO_CONSTRAINTS
switch_patterns  := -DPLATEAU_NO_PATTERNS
switch_supports  := -DPLATEAU_NO_SUPPORTS
switch_sliding   := -DPLATEAU_NO_SLIDING
switch_accuracy  := -DPLATEAU_NO_ACCURACY
switch_quality   := -DPLATEAU_NO_QUALITY_SEEDING
switch_extras    := -DPLATEAU_LM_NO_EXTRAS
switch_pextras   := -DPLATEAU_NO_EXTRAS
switch_all       := $(foreach c,stability membranes loops c2f svg plyoffstl parsers sparse constraints patterns \
                      supports sliding accuracy quality extras pextras,$(switch_$(c)))
switch_none      :=
SWITCH_CHECKS    := $(foreach c,none $(SWITCH_CONFIGS),build/hdr/switch-$(c).gcc.ok build/hdr/switch-$(c).gxx.ok) \
                    build/hdr/switch-cli.o
HDR_CHECKS += $(SWITCH_CHECKS)
.SECONDARY: $(foreach c,none $(SWITCH_CONFIGS),build/hdr/switch-$(c).gcc build/hdr/switch-$(c).gxx)

hdr_file_lm       := plateau_lm.h
hdr_file_delaunay := plateau_delaunay.h
hdr_file_plateau  := plateau.h
hdr_impl_lm       := PLATEAU_LM_IMPLEMENTATION
hdr_impl_delaunay := PLATEAU_DELAUNAY_IMPLEMENTATION
hdr_impl_plateau  := PLATEAU_IMPLEMENTATION

# The web build (examples/web): clang --target=wasm32 and wasm-ld, no C
# library.  `make test` adds the browser check build/web/web_check when the
# two and Chromium are present, and says "skipped" otherwise.
WASM_LD    ?= wasm-ld
CHROMIUM   ?= chromium
WASM_FLAGS := --target=wasm32 -nostdlib -ffreestanding -mbulk-memory -O2 $(WARN)
HAVE_WASM  := $(shell printf 'int f(void) { return 0; }\n' | $(CLANG) --target=wasm32 -ffreestanding \
                -x c -c -o /dev/null - >/dev/null 2>&1 && command -v $(WASM_LD) >/dev/null && echo yes)
HAVE_CHROMIUM := $(shell command -v $(CHROMIUM) >/dev/null 2>&1 && echo yes)
WEB_SRC    := examples/web/plateau_wasm.c examples/web/web_libc.h $(HEADERS)
WEB_PAGE   := examples/web/index.html examples/web/plateau_web.js
WEB_CHECKS := $(if $(HAVE_WASM),$(if $(HAVE_CHROMIUM),build/web/web_check))
WEB_SKIP   := $(if $(HAVE_WASM),$(if $(HAVE_CHROMIUM),,$(CHROMIUM) not found),clang has no wasm32 target or $(WASM_LD) is missing)

.PHONY: all test test-build test-full test-full-build demo bench examples cli clean valgrind fuzz web web-check
.DELETE_ON_ERROR:

all: cli examples

# ---------------------------------------------------------------- tests
# Three tiers (make test, make test-full, make check), built the same way:
# with -k, so one broken test does not hide the others (tests/run.sh counts
# a binary that failed to build as a failure), and never silent: the build
# prints a line every 20 s (how many targets exist), each binary's result
# as it finishes (a line after 25 s without one), then the closing line
# "N passed, N failed".  The tests read PLATEAU_TEST_FULL (tests/harness.h):
# 1 in make test-full, where the slow tests run their full sizes; 0 in
# make test and make check, where they run smaller ones.
#
# make test-full: every test under gcc -O2, clang and ASan+UBSan, the FMA
# build, the fuzzers, the header checks, the quick starts and make install.
test-full:
	@mkdir -p build
	@echo "make test-full: building $(words $(TEST_BINS)) test binaries, $(words $(FUZZ_CHECKS)) fuzz targets, $(words $(HDR_CHECKS)) header checks, the quick starts and make install (make -j2, log in build/test-build.log) ..."
	@t0=$$(date +%s); sh tests/progress.sh build build/test-build.log 20 $(TEST_TARGETS) -- \
	  $(MAKE) --no-print-directory -k -j2 test-full-build || true; \
	  echo "built in $$(( $$(date +%s) - t0 )) s"
	@$(if $(WEB_CHECKS),,echo "  web check: skipped: $(WEB_SKIP)")
	@PLATEAU_TEST_FULL=1 sh tests/progress.sh pass 25 -- sh tests/run.sh build/test-build.log $(TEST_BINS) \
	  build/quickstart/run_test build/install/check $(WEB_CHECKS) $(FUZZ_CHECKS) -- $(HDR_CHECKS)

TEST_TARGETS := $(TEST_BINS) $(QS_TEST) build/quickstart/run_test build/install/check \
                $(WEB_CHECKS) $(FUZZ_CHECKS) $(HDR_CHECKS)
test-full-build: $(TEST_TARGETS)

# The README's quick starts, compiled as a user would (the header's
# implementation in the program itself), as C and as C++ (where
# `plateau_options opt = {0};` would fail: -Wmissing-field-initializers),
# and run by tests/quickstart_check.sh: make test with gcc and g++ at -O2
# (the README's compile lines, with warnings as errors) and clang and
# clang++ at -O0; make check with gcc and g++ at -O0.
QS_CXXWARN := $(CXXWARN) -Wmissing-field-initializers

build/quickstart/%.gcc: examples/%.c $(HEADERS)
	@mkdir -p $(@D)
	$(CC) $(WARN) -O2 -I. -o $@ $< $(LDLIBS)

build/quickstart/%.gxx: examples/%.c $(HEADERS)
	@mkdir -p $(@D)
	$(CXX) -x c++ $(QS_CXXWARN) -O2 -I. -o $@ $< $(LDLIBS)

build/quickstart/%.clang: examples/%.c $(HEADERS)
	@mkdir -p $(@D)
	$(CLANG) $(WARN) -O0 -I. -o $@ $< $(LDLIBS)

build/quickstart/%.clangxx: examples/%.c $(HEADERS)
	@mkdir -p $(@D)
	$(CLANGXX) -x c++ $(QS_CXXWARN) -O0 -I. -o $@ $< $(LDLIBS)

build/quickstart/%.gcc-O0: examples/%.c $(HEADERS)
	@mkdir -p $(@D)
	$(CC) $(WARN) -O0 -I. -o $@ $< $(LDLIBS)

build/quickstart/%.gxx-O0: examples/%.c $(HEADERS)
	@mkdir -p $(@D)
	$(CXX) -x c++ $(QS_CXXWARN) -O0 -I. -o $@ $< $(LDLIBS)

# The wrappers tests/run.sh runs; they do not depend on the binaries, so a
# quick start that fails to build is reported by name, not as a missing check.
build/quickstart/run_test: tests/quickstart_check.sh
	@mkdir -p $(@D)
	@printf '#!/bin/sh\nexec sh tests/quickstart_check.sh %s\n' '$(QS_TEST)' >$@
	@chmod +x $@

build/quickstart/run_check: tests/quickstart_check.sh
	@mkdir -p $(@D)
	@printf '#!/bin/sh\nexec sh tests/quickstart_check.sh %s\n' '$(QS_CHECK)' >$@
	@chmod +x $@

# make install into build/install/prefix, at build time; the check reads it.
build/install/check: build/plateau $(HEADERS) tests/install_check.sh
	@rm -rf build/install/prefix
	@$(MAKE) --no-print-directory install PREFIX='$(CURDIR)/build/install/prefix' >/dev/null
	@printf '#!/bin/sh\nexec sh tests/install_check.sh %s %s\n' '$(CURDIR)/build/install/prefix' '$(CC)' >$@
	@chmod +x $@

# Tests that use only the public API with the default configuration say so
# (#ifndef PLATEAU_TEST_LINKED around their PLATEAU_IMPLEMENTATION) and link
# the implementation compiled once per compiler (tests/impl.c), which saves
# most of the suite's build time; the others compile it themselves.
LINKED_TESTS := $(patsubst tests/%.c,%,$(shell grep -l PLATEAU_TEST_LINKED tests/test_*.c))
linked = $(if $(filter $(notdir $@),$(LINKED_TESTS)),-DPLATEAU_TEST_LINKED $(@D)/impl.o)
$(addprefix build/gcc/,$(LINKED_TESTS)): build/gcc/impl.o
$(addprefix build/clang/,$(LINKED_TESTS)): build/clang/impl.o
$(addprefix build/san/,$(LINKED_TESTS)): build/san/impl.o

# make test: every test file once, gcc -O2, the slow tests at their
# smaller sizes, one implementation object per configuration.  That of the
# default configuration, build/quick/impl.o (tests/whitebox.c), also holds
# the white-box tests that read plateau.h's private functions (QUICK_WHITE:
# the files tests/whitebox.c includes), whose mains are renamed there; each
# is that object and tests/whitebox_main.c.  The linked tests are compiled
# to objects, so that make -j2 compiles them while impl.o compiles, and link
# it.  The tests that set a configuration macro, or compile only a small
# header, compile theirs once each (QUICK_OWN, in build/gcc/ as make
# test-full builds them).
QUICK_WHITE := $(shell sed -n 's/^\#include "\(test_[a-z0-9_]*\)\.c".*/\1/p' tests/whitebox.c)
QUICK_OWN   := $(filter-out $(LINKED_TESTS) $(QUICK_WHITE),$(TESTS))
QUICK_BINS  := $(addprefix build/quick/,$(filter $(LINKED_TESTS) $(QUICK_WHITE),$(TESTS))) \
               $(addprefix build/gcc/,$(QUICK_OWN))
.SECONDARY: $(addprefix build/quick/,$(addsuffix .o,$(LINKED_TESTS)))

test:
	@mkdir -p build
	@echo "make test: every test file once, gcc -O2, quick sizes (make test-full: the whole matrix)"
	@echo "building $(words $(QUICK_BINS)) test binaries (make -j2, log in build/quick-build.log) ..."
	@t0=$$(date +%s); sh tests/progress.sh build build/quick-build.log 20 $(QUICK_BINS) -- \
	  $(MAKE) --no-print-directory -k -j2 test-build || true; \
	  echo "built in $$(( $$(date +%s) - t0 )) s"
	@PLATEAU_TEST_FULL=0 sh tests/progress.sh pass 25 -- sh tests/run.sh build/quick-build.log $(QUICK_BINS) --
# (impl.o first: the longest compile, which every other one waits for)
test-build: build/quick/impl.o $(QUICK_BINS)

build/quick/impl.o: tests/whitebox.c $(HEADERS)
	@mkdir -p $(@D); rm -f $@
	$(CC) $(WARN) $(OPT) $(DEP) -I. -c -o $@ $<

build/quick/%.o: tests/%.c $(HEADERS)
	@mkdir -p $(@D); rm -f $@
	$(CC) $(WARN) $(OPT) $(DEP) -I. -DPLATEAU_TEST_LINKED -c -o $@ $<

$(addprefix build/quick/,$(LINKED_TESTS)): build/quick/%: build/quick/%.o build/quick/impl.o
	$(CC) -o $@ $^ $(LDLIBS) -pthread

$(addprefix build/quick/,$(QUICK_WHITE)): build/quick/%: tests/whitebox_main.c build/quick/impl.o
	$(CC) $(WARN) $(OPT) -DWHITEBOX_TEST='"$*"' -o $@ $^ $(LDLIBS) -pthread

# make check: the inner loop, make test less the tests that compile a
# configuration of their own (all but CHECK_OWN, which compile only a small
# header) and the seven slowest to run (CHECK_SLOW: 3 to 25 s of CPU each
# at make test's sizes; test_accuracy's solves of 10^4 points,
# test_cli_run's runs of the tool and test_stability's reports are the
# three largest).  It shares make test's binaries.
CHECK_OWN  := test_delaunay test_web_libc test_api_index
CHECK_SLOW := test_membrane test_solve_loops test_work_bounds test_examples test_accuracy test_stability \
              test_cli_run
CHECK_BINS := $(filter-out $(addprefix %/,$(CHECK_SLOW) $(filter-out $(CHECK_OWN),$(QUICK_OWN))),$(QUICK_BINS))
.PHONY: check check-build
check:
	@mkdir -p build
	@echo "make check: building $(words $(CHECK_BINS)) test binaries, gcc -O2 (make -j2, log in build/check-build.log) ..."
	@t0=$$(date +%s); sh tests/progress.sh build build/check-build.log 20 $(CHECK_BINS) -- \
	  $(MAKE) --no-print-directory -k -j2 check-build || true; \
	  echo "built in $$(( $$(date +%s) - t0 )) s"
	@PLATEAU_TEST_FULL=0 sh tests/progress.sh pass 25 -- sh tests/run.sh build/check-build.log $(CHECK_BINS) --
check-build: build/quick/impl.o $(CHECK_BINS)

build/gcc/impl.o: tests/impl.c $(HEADERS)
	@mkdir -p $(@D); rm -f $@
	$(CC) $(WARN) $(OPT) $(DEP) -I. -c -o $@ $<

build/clang/impl.o: tests/impl.c $(HEADERS)
	@mkdir -p $(@D); rm -f $@
	$(CLANG) $(WARN) $(OPT) $(DEP) -I. -c -o $@ $<

build/san/impl.o: tests/impl.c $(HEADERS)
	@mkdir -p $(@D); rm -f $@
	$(CLANG) $(WARN) $(SAN) $(DEP) -I. -c -o $@ $<

build/gcc/%: tests/%.c $(HEADERS)
	@mkdir -p $(@D); rm -f $@
	$(CC) $(WARN) $(OPT) $(DEP) -I. $(linked) -o $@ $< $(LDLIBS) -pthread

# Under clang, tests that compile the implementation themselves are built at
# -O0: clang's warnings come from its front end, the same at every level,
# and its -O0 compiles the implementation about 20 times as fast as -O2
# (gcc -O2 keeps the flow warnings).  Those that run long keep -O2
# (CLANG_O2_OWN_TESTS: 10 to 30 s of CPU each at -O2, which -O0 would
# multiply by about 3; the others run in under 5 s).
CLANG_O2_OWN_TESTS := test_alloc_fail test_manual test_solve_coarse_to_fine test_solve_paths
clang_opt = $(if $(filter $(notdir $@),$(LINKED_TESTS) $(CLANG_O2_OWN_TESTS)),$(OPT),-O0)

build/clang/%: tests/%.c $(HEADERS)
	@mkdir -p $(@D); rm -f $@
	$(CLANG) $(WARN) $(clang_opt) $(DEP) -I. $(linked) -o $@ $< $(LDLIBS) -pthread

# Tests that compile the implementation themselves are built at -O0 under the
# sanitizers: instrumented -O1 takes clang about 7 times as long to compile
# the implementation as -O0, more than the slower runs cost (these run 1.5
# to 2.5 times as long).  test_alloc_fail keeps -O1: its thousands of
# refused allocations, each a solve, would take longer to run than to build.
SAN_O1_OWN_TESTS := test_alloc_fail
san_opt = $(if $(filter $(notdir $@),$(LINKED_TESTS) $(SAN_O1_OWN_TESTS)),,-O0)

build/san/%: tests/%.c $(HEADERS)
	@mkdir -p $(@D); rm -f $@
	$(CLANG) $(WARN) $(SAN) $(san_opt) $(DEP) -DPLATEAU_TEST_SANITIZED -I. $(linked) -o $@ $< $(LDLIBS) -pthread

build/fma/%: tests/%.c $(HEADERS)
	@mkdir -p $(@D); rm -f $@
	$(CC) $(FMA_FLAGS) $(DEP) -I. -o $@ $< $(LDLIBS) -pthread

build/hdr/%.gcc.o: tests/hdr/standalone.c $(HEADERS)
	@mkdir -p $(@D); rm -f $@
	$(CC) $(WARN) -I. -D'PLATEAU_CHECK_HEADER="$(hdr_file_$*)"' -D$(hdr_impl_$*) -c $< -o $@

build/hdr/%.clang.o: tests/hdr/standalone.c $(HEADERS)
	@mkdir -p $(@D); rm -f $@
	$(CLANG) $(WARN) -I. -D'PLATEAU_CHECK_HEADER="$(hdr_file_$*)"' -D$(hdr_impl_$*) -c $< -o $@

build/hdr/%.gxx.o: tests/hdr/standalone.c $(HEADERS)
	@mkdir -p $(@D); rm -f $@
	$(CXX) -x c++ $(CXXWARN) -I. -D'PLATEAU_CHECK_HEADER="$(hdr_file_$*)"' -D$(hdr_impl_$*) -c $< -o $@

# C++98, the oldest standard some legacy code bases still build with: no
# `long long` and no ULL constants anywhere (PLATEAU__U64 builds them).
build/hdr/%.gxx98.o: tests/hdr/standalone.c $(HEADERS)
	@mkdir -p $(@D); rm -f $@
	$(CXX) -x c++ -std=c++98 $(CXXWARN) -I. -D'PLATEAU_CHECK_HEADER="$(hdr_file_$*)"' -D$(hdr_impl_$*) -c $< -o $@

build/hdr/%.clangxx.o: tests/hdr/standalone.c $(HEADERS)
	@mkdir -p $(@D); rm -f $@
	$(CLANGXX) -x c++ $(CXXWARN) -I. -D'PLATEAU_CHECK_HEADER="$(hdr_file_$*)"' -D$(hdr_impl_$*) -c $< -o $@

# The static and freestanding checks compile all three headers' implementations:
# gcc and g++ at -O2, where their flow warnings (-Wmaybe-uninitialized) run;
# clang's and clang++'s warnings come from the front end, the same at every
# optimisation level, so theirs compile at -O0, several times faster.
build/hdr/static.gcc.o: tests/hdr/static_mode.c $(HEADERS)
	@mkdir -p $(@D); rm -f $@
	$(CC) $(WARN) $(OPT) -c $< -o $@

build/hdr/static.clang.o: tests/hdr/static_mode.c $(HEADERS)
	@mkdir -p $(@D); rm -f $@
	$(CLANG) $(WARN) -O0 -c $< -o $@

build/hdr/static.gxx.o: tests/hdr/static_mode.c $(HEADERS)
	@mkdir -p $(@D); rm -f $@
	$(CXX) -x c++ $(CXXWARN) $(OPT) -c $< -o $@

build/hdr/order_%.o: tests/hdr/order_%.c $(HEADERS)
	@mkdir -p $(@D); rm -f $@
	$(CC) $(WARN) -c $< -o $@

build/hdr/index64.o: tests/hdr/index64.c $(HEADERS)
	@mkdir -p $(@D); rm -f $@
	$(CC) $(WARN) -c $< -o $@

build/hdr/twice.o: tests/hdr/twice.c $(HEADERS)
	@mkdir -p $(@D); rm -f $@
	$(CLANG) $(WARN) -c $< -o $@

# PLATEAU_FREESTANDING: clang sees only its own freestanding headers
# (-nostdlibinc); gcc's limits.h needs the C library's, so gcc checks the
# warnings only.
build/hdr/freestanding.gcc.o: tests/hdr/freestanding.c $(HEADERS)
	@mkdir -p $(@D); rm -f $@
	$(CC) $(WARN) $(OPT) -ffreestanding -c $< -o $@

build/hdr/freestanding.clang.o: tests/hdr/freestanding.c $(HEADERS)
	@mkdir -p $(@D); rm -f $@
	$(CLANG) $(WARN) -O0 -ffreestanding -nostdlibinc -c $< -o $@

build/hdr/freestanding.clangxx.o: tests/hdr/freestanding.c $(HEADERS)
	@mkdir -p $(@D); rm -f $@
	$(CLANGXX) -x c++ $(CXXWARN) -O0 -ffreestanding -nostdlibinc -c $< -o $@

# The warnings an integrator's stricter build adds (all three headers'
# implementations, through plateau.h): front-end warnings, so -O0.
STRICT_WARN := -Wshadow -Wconversion -Wcast-qual -Wstrict-prototypes
build/hdr/strict.gcc.o: tests/hdr/standalone.c $(HEADERS)
	@mkdir -p $(@D); rm -f $@
	$(CC) $(WARN) $(STRICT_WARN) -O0 -I. -D'PLATEAU_CHECK_HEADER="plateau.h"' -DPLATEAU_IMPLEMENTATION -c $< -o $@

build/hdr/strict.clang.o: tests/hdr/standalone.c $(HEADERS)
	@mkdir -p $(@D); rm -f $@
	$(CLANG) $(WARN) $(STRICT_WARN) -O0 -I. -D'PLATEAU_CHECK_HEADER="plateau.h"' -DPLATEAU_IMPLEMENTATION -c $< -o $@

# The two-unit links check which symbols each unit defines, not speed: -O0.
build/hdr/late_link: tests/hdr/late_impl.c tests/hdr/link_use.c $(HEADERS)
	@mkdir -p $(@D); rm -f $@
	$(CC) $(WARN) -o $@ tests/hdr/late_impl.c tests/hdr/link_use.c $(LDLIBS)

build/hdr/link: tests/hdr/link_impl.c tests/hdr/link_use.c $(HEADERS)
	@mkdir -p $(@D); rm -f $@
	$(CC) $(WARN) -o $@ tests/hdr/link_impl.c tests/hdr/link_use.c $(LDLIBS)

build/hdr/switch-%.gcc: tests/hdr/switches.c $(HEADERS)
	@mkdir -p $(@D); rm -f $@
	$(CC) $(WARN) -O1 -I. $(switch_$*) -o $@ $< $(LDLIBS)

build/hdr/switch-%.gxx: tests/hdr/switches.c $(HEADERS)
	@mkdir -p $(@D); rm -f $@
	$(CXX) -x c++ $(CXXWARN) -O1 -I. $(switch_$*) -o $@ $< $(LDLIBS)

# the run; a switched configuration's mesh lines must be the full
# library's (all five, or the two of the fan's seeding without the quality
# seeding, whose default seeding is the fan)
build/hdr/switch-none.%.ok: build/hdr/switch-none.%
	./$< >$@.out || { cat $@.out; exit 1; }
	mv $@.out $@

define switch_run
	./$< >$@.out || { cat $@.out; exit 1; }
	@grep '^mesh ' $@.out >$@.mesh; grep '^mesh ' $(word 2,$^) >$@.full; \
	  if grep -v -x -F -f $@.full $@.mesh || [ $$(wc -l <$@.mesh) -lt 2 ]; then \
	    echo "$<: the plain film differs from the full library's"; rm -f $@.mesh $@.full; exit 1; fi
	@rm -f $@.mesh $@.full; mv $@.out $@
endef
$(foreach c,$(SWITCH_CONFIGS),build/hdr/switch-$(c).gcc.ok): build/hdr/switch-%.gcc.ok: \
  build/hdr/switch-%.gcc build/hdr/switch-none.gcc.ok
	$(switch_run)
$(foreach c,$(SWITCH_CONFIGS),build/hdr/switch-$(c).gxx.ok): build/hdr/switch-%.gxx.ok: \
  build/hdr/switch-%.gxx build/hdr/switch-none.gxx.ok
	$(switch_run)

build/hdr/switch-cli.o: $(CLI_SRC) $(CLI_HDR) $(HEADERS)
	@mkdir -p $(@D); rm -f $@
	$(CC) $(WARN) -O0 -I. $(filter-out $(switch_patterns),$(switch_all)) -c -o $@ cli/plateau.c

# A leak and invalid-access check of the gcc test binaries.
valgrind: $(addprefix build/gcc/,$(TESTS))
	@for t in $^; do echo "valgrind $$t"; \
	  valgrind -q --error-exitcode=99 --leak-check=full --errors-for-leak-kinds=definite,indirect \
	    $$t >/dev/null || exit 1; done; echo "valgrind: clean"

# libFuzzer binaries, and the wrapper that makes a short run of one a test
# that tests/run.sh counts.
# (the five link one implementation object, instrumented for coverage the
# same way, instead of compiling it into each)
build/fuzz/impl.o: tests/impl.c $(HEADERS)
	@mkdir -p $(@D); rm -f $@
	$(CLANG) $(subst -fsanitize=fuzzer$(comma),-fsanitize=fuzzer-no-link$(comma),$(FUZZ_FLAGS)) $(DEP) -I. -c -o $@ $<

build/fuzz/%: tests/fuzz/%.c build/fuzz/impl.o $(HEADERS)
	@mkdir -p $(@D); rm -f $@
	$(CLANG) $(FUZZ_FLAGS) $(DEP) -DPLATEAU_TEST_LINKED -I. -Itests -o $@ $< build/fuzz/impl.o $(LDLIBS)

build/fuzz/%.check: build/fuzz/% tests/fuzz/check.sh
	@printf '#!/bin/sh\nexec sh tests/fuzz/check.sh %s build/fuzz/%s $(FUZZ_TEST_SECONDS) short\n' $* $* >$@
	@chmod +x $@

fuzz: $(addprefix build/fuzz/,$(FUZZERS))
	@for f in $(FUZZERS); do sh tests/fuzz/check.sh $$f build/fuzz/$$f $(FUZZ_SECONDS) || exit 1; done

# ---------------------------------------------------------------- web
# out/web/ (make web) and build/web/page/ (the copy make test checks): the
# module, the page, and the module again as base64 in a script, so that the
# page works opened from file:// (browsers refuse fetch() there).  The stack
# (1 MiB) comes first in memory, so that overflowing it traps instead of
# writing over the data.
web:
	@if [ -z "$(HAVE_WASM)" ]; then \
	  echo "make web: skipped: $(WEB_SKIP) (Debian: clang, lld)"; \
	else $(MAKE) --no-print-directory out/web/index.html && \
	  echo "out/web/index.html: open it in a browser; out/web/plateau.wasm $$(wc -c <out/web/plateau.wasm) bytes, imports: $$(sh tests/web_imports.sh out/web/plateau.wasm)"; fi

out/web/plateau.wasm build/web/page/plateau.wasm: $(WEB_SRC)
	@mkdir -p $(@D)
	$(CLANG) $(WASM_FLAGS) -c $< -o $(@D)/plateau_wasm.o
	$(WASM_LD) --no-entry --export-dynamic --strip-all --stack-first -z stack-size=1048576 \
	  -o $@ $(@D)/plateau_wasm.o
	@rm -f $(@D)/plateau_wasm.o

out/web/plateau_wasm_base64.js build/web/page/plateau_wasm_base64.js: %/plateau_wasm_base64.js: %/plateau.wasm
	@{ printf 'window.PLATEAU_WASM_BASE64 = "'; base64 <$< | tr -d '\n'; printf '";\n'; } >$@

out/web/index.html build/web/page/index.html: %/index.html: $(WEB_PAGE) %/plateau_wasm_base64.js
	cp $(WEB_PAGE) $(@D)/

# The browser check: headless Chromium solves in the page, the command-line
# tool on the same boundary; one result line as the test binaries print.
build/web/web_check: build/web/page/index.html build/plateau tests/web_check.sh
	@printf '#!/bin/sh\nexec sh tests/web_check.sh build/web/page build/plateau $(CHROMIUM)\n' >$@
	@chmod +x $@

web-check:
	@if [ -z "$(WEB_CHECKS)" ]; then echo "web check: skipped: $(WEB_SKIP)"; \
	else $(MAKE) --no-print-directory build/web/web_check && ./build/web/web_check; fi

# ---------------------------------------------------------------- programs
# The examples and the command-line tool that use only the public API with
# the default configuration say so (#ifndef PLATEAU_IMPL_LINKED around their
# PLATEAU_IMPLEMENTATION) and link the implementation object the gcc tests
# link (build/gcc/impl.o, compiled once: the ~13 000 lines of the three
# headers are most of the build time); the others compile it themselves.
# Each program is compiled to an object first, so that make -j2 compiles
# them while impl.o compiles.  The quick starts (examples/*_quickstart.c,
# the README's programs) are built and run by make check and make test, as
# C and as C++, each compiling its header itself as a user would.
LINKED_PROGRAMS := $(patsubst examples/%.c,%,$(shell grep -l PLATEAU_IMPL_LINKED examples/*.c)) \
                   $(if $(shell grep -l PLATEAU_IMPL_LINKED cli/plateau.c 2>/dev/null),plateau)
impl_flag = $(if $(filter $(1),$(LINKED_PROGRAMS)),-DPLATEAU_IMPL_LINKED)
impl_obj  = $(if $(filter $(1),$(LINKED_PROGRAMS)),build/gcc/impl.o)
EXAMPLE_OBJS := $(addprefix build/examples/,$(addsuffix .o,$(EXAMPLES)))
.SECONDARY: $(EXAMPLE_OBJS) build/cli/plateau.o

examples: $(addprefix build/examples/,$(EXAMPLES))

build/examples/%.o: examples/%.c $(HEADERS)
	@mkdir -p $(@D)
	$(CC) $(WARN) $(OPT) $(DEP) -I. $(call impl_flag,$*) -c -o $@ $<

build/examples/%: build/examples/%.o
	$(CC) -o $@ $< $(call impl_obj,$*) $(LDLIBS)

$(addprefix build/examples/,$(filter-out plateau,$(LINKED_PROGRAMS))): build/gcc/impl.o

cli: $(if $(CLI_SRC),build/plateau)

build/cli/plateau.o: $(CLI_SRC) $(CLI_HDR) $(HEADERS)
	@mkdir -p $(@D)
	$(CC) $(WARN) $(OPT) $(DEP) -I. $(call impl_flag,plateau) -c -o $@ cli/plateau.c

build/plateau: build/cli/plateau.o $(call impl_obj,plateau)
	$(CC) -o $@ $^ $(LDLIBS)

# The main job: run every example in turn (they write into out/), the
# paper's Section III first, in its order (they write out/table.md and the
# README's pictures in examples/pictures/).
DEMO_ORDER := helicoid catenoid scherk membrane
DEMO_RUN   := $(foreach e,$(DEMO_ORDER),$(filter $(e),$(EXAMPLES))) \
              $(filter-out $(DEMO_ORDER),$(EXAMPLES))
demo:
	@$(MAKE) --no-print-directory -j2 examples
	@mkdir -p out examples/pictures build; touch build/demo.stamp
	@for e in $(DEMO_RUN); do echo "== $$e"; ./build/examples/$$e || exit 1; done
	@new() { find $$1 -maxdepth 1 -type f -newer build/demo.stamp -name "$$2" | wc -l | tr -d ' '; }; \
	 echo "== done: wrote $$(new out '*') files in out/ ($$(new out '*.obj') meshes as OBJ, $$(new out '*.svg') pictures as SVG,"; \
	 echo "   $$(new out '*.md') tables as Markdown) and $$(new examples/pictures '*') pictures in examples/pictures/ (the README's)."; \
	 echo "   Open out/walkthrough.html in a browser (the algorithm step by step), out/table.md (the paper's"; \
	 echo "   Section III, the three methods side by side) and any out/*.svg; out/*.obj open in MeshLab or Blender."

# make readme-check: every number and program text of the README is what
# the code produces now (examples/readme_check.sh says how): the demo's
# tables (out/table.md, out/catenoid-rings.md), the quick starts (their
# files, and what their README compile lines and runs print) and the
# command-line tool's sessions (examples/readme_outputs.sh writes them to
# out/readme/) and the switches' table (tests/size_table.sh writes
# out/size-table.md).  make readme-update rewrites those README blocks from a
# fresh run, for the day results change; make readme-table is its old name.
# (One step after the other: make demo builds with -j2 inside, and the tool
# links the same implementation object.)
# It then checks the numbers of the three headers' manuals the same way
# (make manual-check: tests/test_manual.c checks each against the code and
# prints it; examples/manual_check.sh finds every manual number in that
# output or in its list of numbers no code has, with their sources).
.PHONY: readme-check readme-update readme-table readme-outputs manual-check
readme-check:
	@$(MAKE) --no-print-directory demo
	@$(MAKE) --no-print-directory readme-outputs
	@sh examples/readme_check.sh README.md
	@$(MAKE) --no-print-directory manual-check
manual-check: build/gcc/test_manual
	@mkdir -p out/readme
	@./build/gcc/test_manual >out/readme/manual-numbers.txt || { cat out/readme/manual-numbers.txt; exit 1; }
	@sh examples/manual_check.sh out/readme/manual-numbers.txt
readme-update readme-table:
	@$(MAKE) --no-print-directory demo
	@$(MAKE) --no-print-directory readme-outputs
	@sh examples/readme_check.sh --update README.md
readme-outputs: build/plateau build/gcc/test_lm_fit out/size-table.md
	@echo "readme-outputs: the README's commands, run into out/readme/ ..."
	@sh examples/readme_outputs.sh
# The README's table of the switches' costs (text bytes, compile seconds):
# 32 compiles of the implementation, one at a time, redone when a header
# changes.
out/size-table.md: tests/size_table.sh tests/impl.c $(HEADERS)
	@echo "size-table: the implementation compiled in 16 configurations at -O2 and -Os ..."
	@sh tests/size_table.sh $@

bench: $(addprefix build/bench/,$(BENCHES))
	@for b in $(filter-out bench_evolver,$(BENCHES)); do echo "== $$b"; ./build/bench/$$b || exit 1; done
	@echo "== bench_evolver"; ./build/bench/bench_evolver $(EVOLVER_BENCH)
	@echo "== bench_evolver equal"; ./build/bench/bench_evolver equal $(EVOLVER_BENCH)
	@if [ -f /usr/include/CGAL/Delaunay_triangulation_2.h ]; then $(MAKE) --no-print-directory bench-cgal; \
	 else echo "== cgal_delaunay: skipped (optional peer: apt-get install libcgal-dev)"; fi

# bench_evolver: time against excess, plateau's defaults (coarse to fine)
# and its rounds at full size against Surface Evolver, whose rows say
# "skipped" unless an `evolver` is on PATH (optional peer: Debian's
# apt-get install evolver); nothing needs it.  About 12 minutes of CPU;
# `make bench EVOLVER_BENCH=quick` stops at 10^4 interior vertices.  Its
# mode "equal": the CPU for given true errors on the demo's helicoid,
# catenoid and Scherk polygons and a four-corner tent, plateau's series
# over n and its accuracy request next to Evolver's lean script.
EVOLVER_BENCH ?=

# Optional peer for bench_delaunay: CGAL's Delaunay_triangulation_2 (Epick)
# on the same points.  Only when libcgal-dev is installed; nothing needs it.
# The ratio table (time and bytes per point, alternating fresh processes);
# `make bench-cgal CGAL_BENCH=full` adds 10^7 uniform points.
CGAL_BENCH ?=
.PHONY: bench-cgal
bench-cgal: build/bench/cgal_delaunay build/bench/bench_delaunay
	@echo "== cgal_delaunay"; ./build/bench/bench_delaunay cgal $(CGAL_BENCH)

build/bench/cgal_delaunay: bench/cgal_delaunay.cpp
	@mkdir -p $(@D)
	$(CXX) -O3 -DNDEBUG -o $@ $< -lgmp -lmpfr

build/bench/%: bench/%.c $(HEADERS)
	@mkdir -p $(@D)
	$(CC) $(WARN) -O3 $(DEP) -I. -o $@ $< $(LDLIBS)

# Optional peer for bench_sparse: UMFPACK and CHOLMOD on the same matrices,
# compiled in only when Debian's libsuitesparse-dev is installed (the bench
# says "skipped" otherwise); nothing needs it.
SUITESPARSE := $(if $(wildcard /usr/include/suitesparse/umfpack.h),yes)
build/bench/bench_sparse: bench/bench_sparse.c $(HEADERS)
	@mkdir -p $(@D)
	$(CC) $(WARN) -O3 $(DEP) -I. $(if $(SUITESPARSE),-DPLATEAU_BENCH_SUITESPARSE -I/usr/include/suitesparse) \
	  -o $@ $< $(LDLIBS) $(if $(SUITESPARSE),-lumfpack -lcholmod)

# Optional peer for bench_lm: levmar 2.6, which Debian does not package.
# Give the directory of a levmar build (levmar.h, liblevmar.a made with its
# own defaults, LAPACK on) as LEVMAR_DIR; without it the bench says
# "skipped".  Nothing needs it.
LEVMAR_DIR  ?=
LEVMAR_LIBS ?= -llevmar -llapack -lblas
build/bench/bench_lm: bench/bench_lm.c $(HEADERS)
	@mkdir -p $(@D)
	$(CC) $(WARN) -O3 $(DEP) -I. $(if $(LEVMAR_DIR),-DPLATEAU_BENCH_LEVMAR -I$(LEVMAR_DIR)) \
	  -o $@ $< $(if $(LEVMAR_DIR),-L$(LEVMAR_DIR) $(LEVMAR_LIBS)) $(LDLIBS)
# ---------------------------------------------------------------- install
# make install [PREFIX=/usr/local] [DESTDIR=]: the three headers into
# PREFIX/include, the command-line tool into PREFIX/bin, and plateau.pc into
# PREFIX/share/pkgconfig (the library is header-only: its flags are the
# include directory and -lm), so that `pkg-config --cflags --libs plateau`
# works, and a CMake package into PREFIX/share/cmake/plateau, so that
# `find_package(plateau)` gives the imported target plateau::plateau (an
# interface library: the include directory and libm; still one source
# file defines PLATEAU_IMPLEMENTATION).  make uninstall removes them.
PREFIX  ?= /usr/local
DESTDIR ?=
VERSION := $(shell sed -n 's/^\#define PLATEAU_VERSION "\([^"]*\)".*/\1/p' plateau.h)
# The CMake package's two files, a line per word (found from the
# installed file's own directory, so the prefix can move).
CMAKE_CONFIG := \
  '\# find_package(plateau): the imported target plateau::plateau (header-only).' \
  'get_filename_component(_plateau_prefix "$${CMAKE_CURRENT_LIST_DIR}/../../.." ABSOLUTE)' \
  'if(NOT TARGET plateau::plateau)' \
  '  add_library(plateau::plateau INTERFACE IMPORTED)' \
  '  set_target_properties(plateau::plateau PROPERTIES' \
  '    INTERFACE_INCLUDE_DIRECTORIES "$${_plateau_prefix}/include")' \
  '  if(UNIX)' \
  '    set_property(TARGET plateau::plateau PROPERTY INTERFACE_LINK_LIBRARIES m)' \
  '  endif()' \
  'endif()' \
  'set(plateau_INCLUDE_DIRS "$${_plateau_prefix}/include")' \
  'unset(_plateau_prefix)'
CMAKE_VERSION_FILE := \
  'set(PACKAGE_VERSION "$(VERSION)")' \
  '\# 0.x releases: compatible within the same minor version; later ones within a major.' \
  'string(REGEX MATCH "^[0-9]+" _plateau_major "$${PACKAGE_VERSION}")' \
  'string(REGEX MATCH "^[0-9]+\\.[0-9]+" _plateau_minor "$${PACKAGE_VERSION}")' \
  'if(PACKAGE_FIND_VERSION VERSION_GREATER PACKAGE_VERSION)' \
  '  set(PACKAGE_VERSION_COMPATIBLE FALSE)' \
  'elseif(_plateau_major STREQUAL "0" AND NOT PACKAGE_FIND_VERSION_MAJOR STREQUAL "0")' \
  '  set(PACKAGE_VERSION_COMPATIBLE FALSE)' \
  'elseif(_plateau_major STREQUAL "0" AND NOT "$${PACKAGE_FIND_VERSION_MAJOR}.$${PACKAGE_FIND_VERSION_MINOR}" STREQUAL _plateau_minor)' \
  '  set(PACKAGE_VERSION_COMPATIBLE FALSE)' \
  'elseif(NOT PACKAGE_FIND_VERSION_MAJOR STREQUAL _plateau_major)' \
  '  set(PACKAGE_VERSION_COMPATIBLE FALSE)' \
  'else()' \
  '  set(PACKAGE_VERSION_COMPATIBLE TRUE)' \
  '  if(PACKAGE_FIND_VERSION STREQUAL PACKAGE_VERSION)' \
  '    set(PACKAGE_VERSION_EXACT TRUE)' \
  '  endif()' \
  'endif()'
.PHONY: install uninstall
install: build/plateau
	install -d '$(DESTDIR)$(PREFIX)/include' '$(DESTDIR)$(PREFIX)/bin' '$(DESTDIR)$(PREFIX)/share/pkgconfig'
	install -m 644 $(HEADERS) '$(DESTDIR)$(PREFIX)/include/'
	install -m 755 build/plateau '$(DESTDIR)$(PREFIX)/bin/plateau'
	printf 'prefix=%s\nincludedir=$${prefix}/include\n\nName: plateau\nDescription: %s\nVersion: %s\nCflags: -I$${includedir}\nLibs: -lm\n' \
	  '$(PREFIX)' 'minimal triangle meshes spanning a closed 3-D polygon (header-only C99)' '$(VERSION)' \
	  >'$(DESTDIR)$(PREFIX)/share/pkgconfig/plateau.pc'
	install -d '$(DESTDIR)$(PREFIX)/share/cmake/plateau'
	printf '%s\n' $(CMAKE_CONFIG) >'$(DESTDIR)$(PREFIX)/share/cmake/plateau/plateau-config.cmake'
	printf '%s\n' $(CMAKE_VERSION_FILE) >'$(DESTDIR)$(PREFIX)/share/cmake/plateau/plateau-config-version.cmake'

uninstall:
	rm -f $(addprefix '$(DESTDIR)$(PREFIX)/include/,$(addsuffix ',$(HEADERS))) \
	  '$(DESTDIR)$(PREFIX)/bin/plateau' '$(DESTDIR)$(PREFIX)/share/pkgconfig/plateau.pc' \
	  '$(DESTDIR)$(PREFIX)/share/cmake/plateau/plateau-config.cmake' \
	  '$(DESTDIR)$(PREFIX)/share/cmake/plateau/plateau-config-version.cmake'
	-rmdir '$(DESTDIR)$(PREFIX)/share/cmake/plateau' 2>/dev/null

clean:
	rm -rf build out

# The header dependencies the compiler wrote (DEP above).
-include $(shell find build -name '*.d' 2>/dev/null)
