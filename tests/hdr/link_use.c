/* ... and this one uses all three headers through their declarations alone. */
#include <stdio.h>
#include "../../plateau.h"

int main(void)
{
    /* Each header's result-name function must link and name its OK code. */
    const char *a = plateau_lm_result_string(PLATEAU_LM_OK);
    const char *b = plateau_dt_result_string(PLATEAU_DT_OK);
    const char *c = plateau_result_string(PLATEAU_OK);
    if (!a || !b || !c) return 1;
    printf("linked: %s / %s / %s\n", a, b, c);
    return 0;
}
