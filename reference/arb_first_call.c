/* The C Arb side of the first-call comparison (issue 36, item 1): one integral of
   issue 36's table at one precision, in this fresh process: the first call of
   acb_calc_integrate (Arb builds and caches its Gauss-Legendre nodes then), and the
   mean of warm calls over 0.3 s (at least 3).  Prints: id, prec, first ms, warm ms,
   evaluations of the first call.  Options as in Arb's examples/integrals.c:
   goal = prec, absolute tolerance 2^-prec, the default limits.

   cc -O2 -o arb_first_call reference/arb_first_call.c -lflint-arb -lflint -lmpfr -lgmp
   ./arb_first_call ID PREC             (run by reference/bench_first_call.sh)
   FIRST_CALL_ONLY=1 ./arb_first_call ID PREC   the first call only
                                        (reference/instructions_first_call.sh)
   ./arb_first_call ID PREC CALLS       a warm-up call and CALLS more, for instruction
                                        counts of warm calls under callgrind (the
                                        difference of two runs with different CALLS;
                                        reference/instructions_warm_calls.sh); prints
                                        id, prec, evaluations of one call */

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <acb_calc.h>
#include <acb_hypgeom.h>

#include "arb_integrands.h"

/* the ids, integrands and ranges of examples/first_call.rs (and warm_calls.rs) */
static const integral_t integrals[] = {
    {"atanderiv", f_atanderiv, 0, 1},
    {"rump", f_rump, 0, 8},
    {"gauss", f_gauss, 0, 2},
    {"sqrt", f_sqrt, 1, 4},
    {"xJ0", f_xj0, 0, 10},
    {"sin_zero", f_sin, -1, 1},
};

int main(int argc, char **argv)
{
    acb_t s, a, b;
    mag_t tol;
    acb_calc_integrate_opt_t opt;
    const integral_t *in = NULL;
    slong prec;
    size_t i;
    long calls = 0, first_evals;
    double t0, first, warm;

    if (argc != 3 && argc != 4)
    {
        fprintf(stderr, "usage: arb_first_call ID PREC [CALLS]\n");
        return 2;
    }
    for (i = 0; i < sizeof(integrals) / sizeof(integrals[0]); i++)
        if (strcmp(argv[1], integrals[i].id) == 0)
            in = &integrals[i];
    if (in == NULL)
    {
        fprintf(stderr, "unknown id %s\n", argv[1]);
        return 2;
    }
    prec = atol(argv[2]);
    acb_init(s);
    acb_init(a);
    acb_init(b);
    mag_init(tol);
    acb_calc_integrate_opt_init(opt);
    mag_set_ui_2exp_si(tol, 1, -prec);
    acb_set_si(a, in->a);
    acb_set_si(b, in->b);

    evals = 0;
    t0 = now();
    acb_calc_integrate(s, in->f, NULL, a, b, prec, tol, opt, prec);
    first = now() - t0;
    first_evals = evals;
    if (argc == 4)
    {
        /* CALLS warm calls, no clock (instructions_warm_calls.sh counts them) */
        long k, n = atol(argv[3]);
        for (k = 0; k < n; k++)
            acb_calc_integrate(s, in->f, NULL, a, b, prec, tol, opt, prec);
        printf("%s\t%ld\t%ld\n", in->id, (long) prec, first_evals);
        return 0;
    }
    if (getenv("FIRST_CALL_ONLY") != NULL)
    {
        /* the first call alone (as examples/first_call.rs), for instruction counts */
        printf("%s\t%ld\t%.2f\n", in->id, (long) prec, 1e3 * first);
        return 0;
    }
    t0 = now();
    while (calls < 3 || now() - t0 < 0.3)
    {
        acb_calc_integrate(s, in->f, NULL, a, b, prec, tol, opt, prec);
        calls++;
    }
    warm = (now() - t0) / calls;
    printf("%s\t%ld\t%.2f\t%.3f\t%ld\n", in->id, (long) prec, 1e3 * first, 1e3 * warm, first_evals);

    acb_clear(s);
    acb_clear(a);
    acb_clear(b);
    mag_clear(tol);
    flint_cleanup();
    return 0;
}
