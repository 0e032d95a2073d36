/* Times C Arb's acb_calc_integrate on the analytic integrals of the maugis speed
   comparison (issue 22, item 7).  Built and run by reference/bench_integrals.sh
   against Debian's libflint-arb-dev (Arb 2.x, headers <acb_calc.h>):

     cc -O2 -o arb_integrals arb_integrals.c -lflint-arb -lflint -lmpfr -lgmp

   For each integral and precision: one warm-up call (so Gauss-Legendre nodes are
   cached, as on the maugis side), then calls repeated until 0.2 s have passed; the
   mean time per call is printed with the number of integrand evaluations of one call
   and the result.  Options are those of Arb's examples/integrals.c: goal = prec,
   absolute tolerance 2^-prec, default limits.  Output: one tab-separated line per
   (integral, prec):  id  prec  mean_ms  evaluations  calls  result  */

#include <stdio.h>
#include <time.h>
#include <string.h>
#include <stdlib.h>
#include <acb_calc.h>
#include <acb_hypgeom.h>

#include "arb_integrands.h"


static const integral_t integrals[] = {
    {"atanderiv", f_atanderiv, 0, 1},
    {"rump", f_rump, 0, 8},
    {"exp", f_exp, 0, 1},
    {"sqrt", f_sqrt, 1, 4},
    {"xJ0", f_xj0, 0, 1},
    {"sin100", f_sin, 0, 100},
};


int main(int argc, char **argv)
{
    static const slong precs[] = {64, 333};
    /* as on the maugis side: MAUGIS_BENCH_CALLS=n runs exactly n timed calls,
       MAUGIS_BENCH_PREC=p only that precision, argv[1] only that integral */
    const char *calls_env = getenv("MAUGIS_BENCH_CALLS");
    const char *prec_env = getenv("MAUGIS_BENCH_PREC");
    long fixed_calls = calls_env ? atol(calls_env) : 0;
    slong only_prec = prec_env ? atol(prec_env) : 0;
    acb_t s, a, b;
    mag_t tol;
    acb_calc_integrate_opt_t opt;
    size_t i, j;

    acb_init(s);
    acb_init(a);
    acb_init(b);
    mag_init(tol);
    acb_calc_integrate_opt_init(opt);

    for (j = 0; j < sizeof(precs) / sizeof(precs[0]); j++)
    {
        slong prec = precs[j];
        if (only_prec && prec != only_prec)
            continue;
        mag_set_ui_2exp_si(tol, 1, -prec);
        for (i = 0; i < sizeof(integrals) / sizeof(integrals[0]); i++)
        {
            const integral_t *in = &integrals[i];
            long calls = 0, ev;
            double t0, t;
            char *str;

            if (argc > 1 && strcmp(argv[1], in->id) != 0)
                continue;

            acb_set_si(a, in->a);
            acb_set_si(b, in->b);
            /* warm-up: caches the nodes; also gives the evaluation count */
            evals = 0;
            acb_calc_integrate(s, in->f, NULL, a, b, prec, tol, opt, prec);
            ev = evals;
            t0 = now();
            do
            {
                acb_calc_integrate(s, in->f, NULL, a, b, prec, tol, opt, prec);
                calls++;
                t = now() - t0;
            } while (fixed_calls ? calls < fixed_calls : t < 0.2);
            str = arb_get_str(acb_realref(s), 20, 0);
            printf("%s\t%ld\t%.6f\t%ld\t%ld\t%s\n", in->id, (long) prec, 1e3 * t / calls, ev, calls, str);
            flint_free(str);
            fflush(stdout);
        }
    }
    acb_clear(s);
    acb_clear(a);
    acb_clear(b);
    mag_clear(tol);
    flint_cleanup();
    return 0;
}
