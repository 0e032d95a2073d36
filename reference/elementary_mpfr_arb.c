/* Cost per call of MPFR's correctly rounded exp and sin against Arb's arb_exp and
   arb_sin at 64-400 bits (the figures quoted in src/ball/fixed/mod.rs), 200000 calls
   each at arguments 0.001 + k 1e-6.

   cc -O2 reference/elementary_mpfr_arb.c -o /tmp/eb -lflint-arb -lflint -lmpfr -lgmp && /tmp/eb
   (Debian's libflint-arb-dev) */
#include <stdio.h>
#include <time.h>
#include <mpfr.h>
#include <arb.h>
static double now(){struct timespec t;clock_gettime(CLOCK_MONOTONIC,&t);return t.tv_sec+1e-9*t.tv_nsec;}
int main(){
  int precs[]={64,84,128,333,353,400};
  for(int i=0;i<6;i++){int p=precs[i]; int N=200000;
    mpfr_t x,y; mpfr_init2(x,p); mpfr_init2(y,p);
    double t0=now(); for(int k=0;k<N;k++){mpfr_set_d(x,0.001+k*1e-6,MPFR_RNDN); mpfr_exp(y,x,MPFR_RNDN);} double t1=now();
    for(int k=0;k<N;k++){mpfr_set_d(x,0.001+k*1e-6,MPFR_RNDN); mpfr_sin(y,x,MPFR_RNDN);} double t2=now();
    arb_t a,b; arb_init(a); arb_init(b);
    double t3=now(); for(int k=0;k<N;k++){arb_set_d(a,0.001+k*1e-6); arb_exp(b,a,p);} double t4=now();
    for(int k=0;k<N;k++){arb_set_d(a,0.001+k*1e-6); arb_sin(b,a,p);} double t5=now();
    printf("prec %d: mpfr exp %.0f ns sin %.0f ns | arb exp %.0f ns sin %.0f ns\n",p,(t1-t0)/N*1e9,(t2-t1)/N*1e9,(t4-t3)/N*1e9,(t5-t4)/N*1e9);
  }}
