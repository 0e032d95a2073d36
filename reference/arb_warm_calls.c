/* The C Arb side of reference/instructions_warm_calls.sh (issue 36, item 4): one
   integral of issue 36's table at one precision, a warm-up call of acb_calc_integrate
   (Arb builds and caches its Gauss-Legendre nodes then) and CALLS more, for
   instruction counts under callgrind (the difference of two runs with different
   CALLS is the cost of warm calls alone).  Prints: id, prec, evaluations of one call.
   Options as in Arb's examples/integrals.c: goal = prec, absolute tolerance 2^-prec.

   cc -O2 -o arb_warm_calls reference/arb_warm_calls.c -lflint-arb -lflint -lmpfr -lgmp
   ./arb_warm_calls ID PREC CALLS */

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <acb_calc.h>
#include <acb_hypgeom.h>

#include "arb_integrands.h"

/* the ids, integrands and ranges of examples/warm_calls.rs */
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
    long calls, c, first_evals;

    if (argc != 4)
    {
        fprintf(stderr, "usage: arb_warm_calls ID PREC CALLS\n");
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
    calls = atol(argv[3]);
    acb_init(s);
    acb_init(a);
    acb_init(b);
    mag_init(tol);
    acb_calc_integrate_opt_init(opt);
    mag_set_ui_2exp_si(tol, 1, -prec);
    acb_set_si(a, in->a);
    acb_set_si(b, in->b);

    evals = 0;
    acb_calc_integrate(s, in->f, NULL, a, b, prec, tol, opt, prec);
    first_evals = evals;
    for (c = 0; c < calls; c++)
        acb_calc_integrate(s, in->f, NULL, a, b, prec, tol, opt, prec);
    printf("%s\t%ld\t%ld\n", in->id, (long) prec, first_evals);

    acb_clear(s);
    acb_clear(a);
    acb_clear(b);
    mag_clear(tol);
    flint_cleanup();
    return 0;
}
