/* The integrands shared by reference/arb_integrals.c and reference/arb_first_call.c
   (C Arb's acb_calc_integrate side of the speed comparisons): each counts its
   evaluations in `evals`.  Include after <acb_calc.h> and <acb_hypgeom.h>. */

#include <time.h>

static long evals;

static inline int f_atanderiv(acb_ptr res, const acb_t z, void *param, slong order, slong prec)
{
    evals++;
    acb_mul(res, z, z, prec);
    acb_add_ui(res, res, 1, prec);
    acb_inv(res, res, prec);
    return 0;
}

static inline int f_rump(acb_ptr res, const acb_t z, void *param, slong order, slong prec)
{
    evals++;
    acb_exp(res, z, prec);
    acb_add(res, res, z, prec);
    acb_sin(res, res, prec);
    return 0;
}

static inline int f_exp(acb_ptr res, const acb_t z, void *param, slong order, slong prec)
{
    evals++;
    acb_exp(res, z, prec);
    return 0;
}

static inline int f_sqrt(acb_ptr res, const acb_t z, void *param, slong order, slong prec)
{
    evals++;
    acb_sqrt_analytic(res, z, order != 0, prec);
    return 0;
}

static inline int f_xj0(acb_ptr res, const acb_t z, void *param, slong order, slong prec)
{
    acb_t nu;
    evals++;
    acb_init(nu);
    acb_hypgeom_bessel_j(res, nu, z, prec);
    acb_mul(res, res, z, prec);
    acb_clear(nu);
    return 0;
}

static inline int f_sin(acb_ptr res, const acb_t z, void *param, slong order, slong prec)
{
    evals++;
    acb_sin(res, z, prec);
    return 0;
}

typedef struct
{
    const char *id;
    acb_calc_func_t f;
    int a, b;
} integral_t;

static inline int f_gauss(acb_ptr res, const acb_t z, void *param, slong order, slong prec)
{
    evals++;
    acb_mul(res, z, z, prec);
    acb_neg(res, res);
    acb_exp(res, res, prec);
    return 0;
}

static inline double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return t.tv_sec + 1e-9 * t.tv_nsec;
}
