/* core_nvector.c: CVODE's serial vector operations compiled with the project (core_nvector.h),
 * for every CVODE user: the rod legs (robot/rod/robot_rod_dyn.c, where they were measured
 * first) and the driver's 96 chamber pressures (core/sim_driver.c).
 *
 * ---- Why (measured) --------------------------------------------------------------------------
 * Debian's SUNDIALS 6.4.1 (libsundials-nvecserial6, also inside libsundials_cvode) is built
 * without optimisation: N_VWSqrSumLocal_Serial keeps its loop counter and sum on the stack
 * (perf annotate), and the serial vector kernels took 25-30 % of a rod leg's CPU on the flat
 * road (N_VWSqrSumLocal_Serial alone 10-12 %, N_VLinearSum, N_VScale, N_VConst the rest) for
 * vectors of 234 doubles. An N_Vector's operations are a table that every clone copies
 * (N_VCloneEmpty), so replacing the entries of the one vector CVODE is created with moves all of
 * its internal vectors to these. The 96 chamber pressures' CVODE spent 2600 instructions per
 * N_VLinearSum_Serial of 96 doubles (callgrind, docs/notes/performance.md "Fixed costs").
 *
 * They are the serial vector's operations with the same case analysis and the same arithmetic
 * in the same order (SUNDIALS v6.4.1 src/nvector/serial/nvector_serial.c, BSD-3-Clause): the
 * special cases a == b (c (x + y)) and a == -b (c (x - y)) round differently from a x + b y and
 * are kept; the reductions sum in index order (no reassociation without -ffast-math), so a run
 * gives the same bits as with the library's own kernels (tests/robot/test_rod_nvector.c
 * compares every operation bit for bit). The fused and vector-array operations are left to
 * SUNDIALS' generic fallbacks, which call the ones here. */
#include <math.h>

#include "core_nvector.h"

#define LEN(v) NV_LENGTH_S(v)
#define DAT(v) NV_DATA_S(v)

static void linearSum(sunrealtype a, N_Vector x, sunrealtype b, N_Vector y, N_Vector z) {
  const sunindextype n = LEN(x);
  const sunrealtype* xd = DAT(x);
  const sunrealtype* yd = DAT(y);
  sunrealtype* zd = DAT(z);
  if (b == 1.0 && z == y) { /* y <- a x + y */
    sunrealtype* yw = DAT(y);
    if (a == 1.0) {
      for (sunindextype i = 0; i < n; i++) {
        yw[i] += xd[i];
      }
    } else if (a == -1.0) {
      for (sunindextype i = 0; i < n; i++) {
        yw[i] -= xd[i];
      }
    } else {
      for (sunindextype i = 0; i < n; i++) {
        yw[i] += a * xd[i];
      }
    }
    return;
  }
  if (a == 1.0 && z == x) { /* x <- b y + x */
    sunrealtype* xw = DAT(x);
    if (b == 1.0) {
      for (sunindextype i = 0; i < n; i++) {
        xw[i] += yd[i];
      }
    } else if (b == -1.0) {
      for (sunindextype i = 0; i < n; i++) {
        xw[i] -= yd[i];
      }
    } else {
      for (sunindextype i = 0; i < n; i++) {
        xw[i] += b * yd[i];
      }
    }
    return;
  }
  if (a == 1.0 && b == 1.0) {
    for (sunindextype i = 0; i < n; i++) {
      zd[i] = xd[i] + yd[i];
    }
    return;
  }
  if (a == 1.0 && b == -1.0) {
    for (sunindextype i = 0; i < n; i++) {
      zd[i] = xd[i] - yd[i];
    }
    return;
  }
  if (a == -1.0 && b == 1.0) {
    for (sunindextype i = 0; i < n; i++) {
      zd[i] = yd[i] - xd[i];
    }
    return;
  }
  if (a == 1.0 || b == 1.0) { /* c v1 + v2 */
    const int ta = a == 1.0;
    const sunrealtype c = ta ? b : a;
    const sunrealtype* v1 = ta ? yd : xd;
    const sunrealtype* v2 = ta ? xd : yd;
    for (sunindextype i = 0; i < n; i++) {
      zd[i] = (c * v1[i]) + v2[i];
    }
    return;
  }
  if (a == -1.0 || b == -1.0) { /* c v1 - v2 */
    const int ta = a == -1.0;
    const sunrealtype c = ta ? b : a;
    const sunrealtype* v1 = ta ? yd : xd;
    const sunrealtype* v2 = ta ? xd : yd;
    for (sunindextype i = 0; i < n; i++) {
      zd[i] = (c * v1[i]) - v2[i];
    }
    return;
  }
  if (a == b) {
    for (sunindextype i = 0; i < n; i++) {
      zd[i] = a * (xd[i] + yd[i]);
    }
    return;
  }
  if (a == -b) {
    for (sunindextype i = 0; i < n; i++) {
      zd[i] = a * (xd[i] - yd[i]);
    }
    return;
  }
  for (sunindextype i = 0; i < n; i++) {
    zd[i] = (a * xd[i]) + (b * yd[i]);
  }
}


static void constant(sunrealtype c, N_Vector z) {
  const sunindextype n = LEN(z);
  sunrealtype* zd = DAT(z);
  for (sunindextype i = 0; i < n; i++) {
    zd[i] = c;
  }
}


static void prod(N_Vector x, N_Vector y, N_Vector z) {
  const sunindextype n = LEN(x);
  const sunrealtype *xd = DAT(x), *yd = DAT(y);
  sunrealtype* zd = DAT(z);
  for (sunindextype i = 0; i < n; i++) {
    zd[i] = xd[i] * yd[i];
  }
}


static void divide(N_Vector x, N_Vector y, N_Vector z) {
  const sunindextype n = LEN(x);
  const sunrealtype *xd = DAT(x), *yd = DAT(y);
  sunrealtype* zd = DAT(z);
  for (sunindextype i = 0; i < n; i++) {
    zd[i] = xd[i] / yd[i];
  }
}


static void scale(sunrealtype c, N_Vector x, N_Vector z) {
  const sunindextype n = LEN(x);
  const sunrealtype* xd = DAT(x);
  sunrealtype* zd = DAT(z);
  if (z == x) {
    for (sunindextype i = 0; i < n; i++) {
      zd[i] *= c;
    }
  } else if (c == 1.0) {
    for (sunindextype i = 0; i < n; i++) {
      zd[i] = xd[i];
    }
  } else if (c == -1.0) {
    for (sunindextype i = 0; i < n; i++) {
      zd[i] = -xd[i];
    }
  } else {
    for (sunindextype i = 0; i < n; i++) {
      zd[i] = c * xd[i];
    }
  }
}


static void absolute(N_Vector x, N_Vector z) {
  const sunindextype n = LEN(x);
  const sunrealtype* xd = DAT(x);
  sunrealtype* zd = DAT(z);
  for (sunindextype i = 0; i < n; i++) {
    zd[i] = fabs(xd[i]);
  }
}


static void inverse(N_Vector x, N_Vector z) {
  const sunindextype n = LEN(x);
  const sunrealtype* xd = DAT(x);
  sunrealtype* zd = DAT(z);
  for (sunindextype i = 0; i < n; i++) {
    zd[i] = 1.0 / xd[i];
  }
}


static void addConst(N_Vector x, sunrealtype b, N_Vector z) {
  const sunindextype n = LEN(x);
  const sunrealtype* xd = DAT(x);
  sunrealtype* zd = DAT(z);
  for (sunindextype i = 0; i < n; i++) {
    zd[i] = xd[i] + b;
  }
}


static sunrealtype dotProd(N_Vector x, N_Vector y) {
  const sunindextype n = LEN(x);
  const sunrealtype *xd = DAT(x), *yd = DAT(y);
  sunrealtype sum = 0;
  for (sunindextype i = 0; i < n; i++) {
    sum += xd[i] * yd[i];
  }
  return sum;
}


static sunrealtype maxNorm(N_Vector x) {
  const sunindextype n = LEN(x);
  const sunrealtype* xd = DAT(x);
  sunrealtype mx = 0;
  for (sunindextype i = 0; i < n; i++) {
    if (fabs(xd[i]) > mx) {
      mx = fabs(xd[i]);
    }
  }
  return mx;
}


static sunrealtype wSqrSumLocal(N_Vector x, N_Vector w) {
  const sunindextype n = LEN(x);
  const sunrealtype *xd = DAT(x), *wd = DAT(w);
  sunrealtype sum = 0;
  for (sunindextype i = 0; i < n; i++) {
    const sunrealtype p = xd[i] * wd[i];
    sum += p * p;
  }
  return sum;
}


static sunrealtype wrmsNorm(N_Vector x, N_Vector w) {
  return sqrt(wSqrSumLocal(x, w) / (sunrealtype)LEN(x));
}


static sunrealtype minimum(N_Vector x) {
  const sunindextype n = LEN(x);
  const sunrealtype* xd = DAT(x);
  sunrealtype mn = xd[0];
  for (sunindextype i = 1; i < n; i++) {
    if (xd[i] < mn) {
      mn = xd[i];
    }
  }
  return mn;
}


static void compare(sunrealtype c, N_Vector x, N_Vector z) {
  const sunindextype n = LEN(x);
  const sunrealtype* xd = DAT(x);
  sunrealtype* zd = DAT(z);
  for (sunindextype i = 0; i < n; i++) {
    zd[i] = (fabs(xd[i]) >= c) ? 1.0 : 0.0;
  }
}


void cs_nvectorFastOps(N_Vector v) {
  N_Vector_Ops o = v->ops;
  o->nvlinearsum = linearSum;
  o->nvconst = constant;
  o->nvprod = prod;
  o->nvdiv = divide;
  o->nvscale = scale;
  o->nvabs = absolute;
  o->nvinv = inverse;
  o->nvaddconst = addConst;
  o->nvdotprod = dotProd;
  o->nvdotprodlocal = dotProd;
  o->nvmaxnorm = maxNorm;
  o->nvmaxnormlocal = maxNorm;
  o->nvwrmsnorm = wrmsNorm;
  o->nvwsqrsumlocal = wSqrSumLocal;
  o->nvmin = minimum;
  o->nvminlocal = minimum;
  o->nvcompare = compare;
}
