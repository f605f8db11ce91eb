/* test_rod_nvector.c: the CVODE vector kernels of the rod and the pressures (base/sun/core_nvector.c) give the same bits as
 * SUNDIALS' own serial ones, so replacing them changes no result.
 *
 * Cases:
 *  - kernels_match_serial: random vectors (with zeros and values of every magnitude) through
 *    every replaced operation, with the coefficients whose special cases the serial kernels
 *    treat apart (±1, a == b, a == -b, 0, other) and the aliasings CVODE uses (z == x, z == y);
 *    the result of each is compared bit for bit with the library's N_V*_Serial.
 *  - clones_inherit: a clone of a vector with the kernels installed (as CVODE makes its work
 *    vectors) carries them. */
#include <stdlib.h>
#include <string.h>

#include "cs_test.h"
#include "core_nvector.h"
#include "robot_rod_internal.h"

static double rnd(unsigned* s) {
  *s = *s * 1664525u + 1013904223u;
  return (double)(*s >> 8) / (double)(1u << 24) * 2.0 - 1.0;
}


enum { NLEN = 237 };


static void fill(N_Vector v, unsigned* s) {
  double* d = N_VGetArrayPointer(v);
  for (int i = 0; i < NLEN; i++) {
    /* magnitudes 1e-12 .. 1e6, some exact zeros and ones */
    double r = rnd(s);
    d[i] = (i % 17 == 0) ? 0.0 : (i % 19 == 0 ? 1.0 : r * pow(10.0, (int)(9 * rnd(s)) - 3));
  }
}


static int sameBits(N_Vector a, N_Vector b) {
  return memcmp(N_VGetArrayPointer(a), N_VGetArrayPointer(b), NLEN * sizeof(double)) == 0;
}


static int sameReal(double a, double b) { return memcmp(&a, &b, sizeof a) == 0; }


/* x, y, z: vectors with the project kernels; X, Y, Z: plain serial ones, same values */
typedef struct {
  N_Vector x, y, z, X, Y, Z, w, W;
} Pair;


static void reset(Pair* p, unsigned seed) {
  unsigned s = seed;
  fill(p->x, &s);
  fill(p->y, &s);
  fill(p->z, &s);
  fill(p->w, &s);
  double* w = N_VGetArrayPointer(p->w);
  for (int i = 0; i < NLEN; i++) {
    w[i] = fabs(w[i]) + 1e-3; /* weights are positive */
  }
  memcpy(N_VGetArrayPointer(p->X), N_VGetArrayPointer(p->x), NLEN * sizeof(double));
  memcpy(N_VGetArrayPointer(p->Y), N_VGetArrayPointer(p->y), NLEN * sizeof(double));
  memcpy(N_VGetArrayPointer(p->Z), N_VGetArrayPointer(p->z), NLEN * sizeof(double));
  memcpy(N_VGetArrayPointer(p->W), N_VGetArrayPointer(p->w), NLEN * sizeof(double));
}


static void kernels_match_serial(void) {
  SUNContext ctx;
#if SUNDIALS_VERSION_MAJOR >= 7
  CS_EXPECT(SUNContext_Create(SUN_COMM_NULL, &ctx) == 0);
#else
  CS_EXPECT(SUNContext_Create(NULL, &ctx) == 0);
#endif
  Pair p;
  N_Vector proto = N_VNew_Serial(NLEN, ctx);
  cs_nvectorFastOps(proto);
  p.x = N_VClone(proto);
  p.y = N_VClone(proto);
  p.z = N_VClone(proto);
  p.w = N_VClone(proto);
  p.X = N_VNew_Serial(NLEN, ctx);
  p.Y = N_VNew_Serial(NLEN, ctx);
  p.Z = N_VNew_Serial(NLEN, ctx);
  p.W = N_VNew_Serial(NLEN, ctx);
  const double coef[] = {1.0, -1.0, 0.0, 0.37, -2.5, 1e-7, 3.0};
  const int nc = (int)(sizeof coef / sizeof coef[0]);
  int checked = 0, bad = 0;
  unsigned seed = 12345u;
  for (int ia = 0; ia < nc; ia++) {
    const double a = coef[ia];
    /* every b of the list, and b = a (the c (x + y) case) and b = -a (c (x - y)) */
    for (int ib = -2; ib < nc; ib++) {
      {
        const double b = ib == -2 ? a : (ib == -1 ? -a : coef[ib]);
        /* z = a x + b y, and the aliased z == y, z == x */
        for (int alias = 0; alias < 3; alias++) {
          reset(&p, seed++);
          N_Vector z = alias == 0 ? p.z : (alias == 1 ? p.y : p.x);
          N_Vector Z = alias == 0 ? p.Z : (alias == 1 ? p.Y : p.X);
          N_VLinearSum(a, p.x, b, p.y, z);
          N_VLinearSum_Serial(a, p.X, b, p.Y, Z);
          checked++;
          if (!sameBits(z, Z)) {
            bad++;
            printf("  linear sum a = %g, b = %g, alias %d differs\n", a, b, alias);
          }
        }
      }
    }
    /* z = c x (and in place) */
    for (int alias = 0; alias < 2; alias++) {
      reset(&p, seed++);
      N_VScale(a, p.x, alias ? p.x : p.z);
      N_VScale_Serial(a, p.X, alias ? p.X : p.Z);
      checked++;
      bad += !sameBits(alias ? p.x : p.z, alias ? p.X : p.Z);
    }
    reset(&p, seed++);
    N_VConst(a, p.z);
    N_VConst_Serial(a, p.Z);
    N_VAddConst(p.x, a, p.y);
    N_VAddConst_Serial(p.X, a, p.Y);
    checked += 2;
    bad += !sameBits(p.z, p.Z) + !sameBits(p.y, p.Y);
    reset(&p, seed++);
    N_VCompare(fabs(a), p.x, p.z);
    N_VCompare_Serial(fabs(a), p.X, p.Z);
    checked++;
    bad += !sameBits(p.z, p.Z);
  }
  /* the element-wise and reduction kernels */
  for (int rep = 0; rep < 5; rep++) {
    reset(&p, seed++);
    N_VProd(p.x, p.y, p.z);
    N_VProd_Serial(p.X, p.Y, p.Z);
    bad += !sameBits(p.z, p.Z);
    N_VDiv(p.x, p.w, p.z);
    N_VDiv_Serial(p.X, p.W, p.Z);
    bad += !sameBits(p.z, p.Z);
    N_VAbs(p.x, p.z);
    N_VAbs_Serial(p.X, p.Z);
    bad += !sameBits(p.z, p.Z);
    N_VInv(p.w, p.z);
    N_VInv_Serial(p.W, p.Z);
    bad += !sameBits(p.z, p.Z);
    bad += !sameReal(N_VDotProd(p.x, p.y), N_VDotProd_Serial(p.X, p.Y));
    bad += !sameReal(N_VMaxNorm(p.x), N_VMaxNorm_Serial(p.X));
    bad += !sameReal(N_VWrmsNorm(p.x, p.w), N_VWrmsNorm_Serial(p.X, p.W));
    bad += !sameReal(N_VWSqrSumLocal(p.x, p.w), N_VWSqrSumLocal_Serial(p.X, p.W));
    bad += !sameReal(N_VMin(p.x), N_VMin_Serial(p.X));
    checked += 9;
  }
  /* the generic fused fallbacks CVODE calls (N_VLinearCombination, N_VScaleAddMulti) reach the
   * kernels through the table */
  reset(&p, seed++);
  double c3[3] = {0.5, -1.0, 2.25};
  N_Vector V[3] = {p.x, p.y, p.w}, VS[3] = {p.X, p.Y, p.W};
  CS_EXPECT(N_VLinearCombination(3, c3, V, p.z) == 0);
  CS_EXPECT(N_VLinearCombination(3, c3, VS, p.Z) == 0);
  checked++;
  bad += !sameBits(p.z, p.Z);
  printf("  %d operations compared bit for bit, %d differ\n", checked, bad);
  CS_EXPECT(bad == 0);
  CS_EXPECT(checked > 100);
  N_Vector all[] = {proto, p.x, p.y, p.z, p.w, p.X, p.Y, p.Z, p.W};
  for (size_t i = 0; i < sizeof all / sizeof all[0]; i++) {
    N_VDestroy(all[i]);
  }
  SUNContext_Free(&ctx);
}


static void clones_inherit(void) {
  SUNContext ctx;
#if SUNDIALS_VERSION_MAJOR >= 7
  CS_EXPECT(SUNContext_Create(SUN_COMM_NULL, &ctx) == 0);
#else
  CS_EXPECT(SUNContext_Create(NULL, &ctx) == 0);
#endif
  N_Vector v = N_VNew_Serial(8, ctx);
  N_Vector plain = N_VNew_Serial(8, ctx);
  cs_nvectorFastOps(v);
  N_Vector c = N_VClone(v);
  CS_EXPECT(c->ops->nvwrmsnorm == v->ops->nvwrmsnorm);
  CS_EXPECT(c->ops->nvlinearsum == v->ops->nvlinearsum);
  CS_EXPECT(c->ops->nvlinearsum != plain->ops->nvlinearsum);
  /* the plain serial vector keeps the library's kernels */
  CS_EXPECT(plain->ops->nvwrmsnorm == N_VWrmsNorm_Serial);
  N_VDestroy(c);
  N_VDestroy(v);
  N_VDestroy(plain);
  SUNContext_Free(&ctx);
}


int main(int argc, char** argv) {
  cs_testInit(argc, argv);
  CS_RUN(kernels_match_serial);
  CS_RUN(clones_inherit);
  return cs_testSummary();
}
