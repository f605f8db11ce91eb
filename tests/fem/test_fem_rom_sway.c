/* test_fem_rom_sway.c: the foot's measures of `crawlsim rom sway` on the FE and reduced models
 * (fem/fem_rom_sway.h csf_swayFunctionals) against rigid motions of the tip face, whose lateral
 * displacement and turn are known in closed form.
 *
 * A tip face of 9 nodes (a 3 x 3 grid, 20 x 20 mm, at z = +166 or -166 mm) with uneven
 * consistent weights (corners 1, edges 4, centre 16: Simpson's on the square, as a Tet10 face
 * set's are uneven) and two nodes off the face (weight 0). Cases:
 *  - translation_reads_delta_not_theta: u = (a, b, c) on every node: delta = a, theta = 0.
 *  - rotation_reads_theta_not_delta: a small rotation w about e2 through the face's weighted
 *    centre tilts the leg's axis (tip side) towards +e1 by w at z = +L and by -w at z = -L
 *    (theta follows the axis towards the tip); delta = 0 to first order (exactly 0 here: the
 *    rotation's e1 part is w (z - zc) = 0 on a flat face).
 *  - rotation_about_e1_reads_nothing: a turn about e1 (the other bending plane) moves neither.
 *  - no_face_is_refused: zero weights everywhere give CS_ERR_ARG. */
#include <math.h>
#include <string.h>

#include "cs_test.h"
#include "fem_rom_sway.h"

enum { NN = 11, NDOF = 3 * NN };

typedef struct Face_ {
  csfMesh mesh;
  csfModel model;
  csfActuatorFE fe;
  double x[3 * NN], w[3 * NN];
} Face;

/* the face at z = zt with centre (cx, cy): grid nodes 0..8, two interior nodes 9, 10 */
static void makeFace(Face* f, double zt, double cx, double cy) {
  memset(f, 0, sizeof *f);
  const double simpson[3] = {1, 4, 1};
  for (int i = 0; i < 3; i++) {
    for (int j = 0; j < 3; j++) {
      const int a = 3 * i + j;
      f->x[3 * a] = cx + 10.0 * (i - 1), f->x[3 * a + 1] = cy + 10.0 * (j - 1);
      f->x[3 * a + 2] = zt;
      for (int k = 0; k < 3; k++) {
        f->w[3 * a + k] = simpson[i] * simpson[j] / 36.0;
      }
    }
  }
  f->x[27] = cx + 3.0, f->x[28] = cy - 2.0, f->x[29] = 0.5 * zt;
  f->x[30] = cx - 7.0, f->x[31] = cy + 1.0, f->x[32] = 0.25 * zt;
  f->mesh.nnode = NN;
  f->mesh.x = f->x;
  f->model.ndof = NDOF;
  f->model.mesh = &f->mesh;
  f->fe.mesh = &f->mesh;
  f->fe.model = &f->model;
  f->fe.tip_unit = f->w;
}

static double dot(const double* a, const double* b) {
  double s = 0;
  for (int i = 0; i < NDOF; i++) {
    s += a[i] * b[i];
  }
  return s;
}

static void translation_reads_delta_not_theta(void) {
  Face f;
  makeFace(&f, 166.0, 2.0, -1.0);
  double cl[NDOF], cr[NDOF], axis[3], u[NDOF];
  csError err;
  cs_errorClear(&err);
  CS_EXPECT(csf_swayFunctionals(&f.fe, cl, cr, axis, &err) == CS_OK);
  CS_EXPECT(axis[2] == 1.0);
  for (int a = 0; a < NN; a++) {
    u[3 * a] = 0.3, u[3 * a + 1] = -0.2, u[3 * a + 2] = 0.7;
  }
  CS_EXPECT_NEAR(dot(cl, u), 0.3, 1e-15, 0);
  CS_EXPECT_NEAR(dot(cr, u), 0.0, 1e-15, 0);
}

static void rotation_reads_theta_not_delta(void) {
  const double w = 1e-3;
  for (int side = 0; side < 2; side++) {
    const double zt = side ? -166.0 : 166.0;
    Face f;
    makeFace(&f, zt, 2.0, -1.0);
    double cl[NDOF], cr[NDOF], axis[3], u[NDOF];
    csError err;
    cs_errorClear(&err);
    CS_EXPECT(csf_swayFunctionals(&f.fe, cl, cr, axis, &err) == CS_OK);
    CS_EXPECT(axis[2] == (side ? -1.0 : 1.0));
    /* u = w e2 x (X - Xc): e1 part w (z - zc), e3 part -w (x - xc) */
    for (int a = 0; a < NN; a++) {
      u[3 * a] = w * (f.x[3 * a + 2] - zt);
      u[3 * a + 1] = 0.0;
      u[3 * a + 2] = -w * (f.x[3 * a] - 2.0);
    }
    /* the axis towards the tip, s e3, turns to s e3 + w s e1: towards +e1 by s w */
    CS_EXPECT_NEAR(dot(cr, u), side ? -w : w, 1e-15, 1e-12);
    CS_EXPECT_NEAR(dot(cl, u), 0.0, 1e-15, 0);
  }
}

static void rotation_about_e1_reads_nothing(void) {
  Face f;
  makeFace(&f, 166.0, 0.0, 0.0);
  double cl[NDOF], cr[NDOF], axis[3], u[NDOF];
  csError err;
  cs_errorClear(&err);
  CS_EXPECT(csf_swayFunctionals(&f.fe, cl, cr, axis, &err) == CS_OK);
  for (int a = 0; a < NN; a++) {
    u[3 * a] = 0.0;
    u[3 * a + 1] = -1e-3 * (f.x[3 * a + 2] - 166.0);
    u[3 * a + 2] = 1e-3 * f.x[3 * a + 1];
  }
  CS_EXPECT_NEAR(dot(cr, u), 0.0, 1e-15, 0);
  CS_EXPECT_NEAR(dot(cl, u), 0.0, 1e-15, 0);
}

static void no_face_is_refused(void) {
  Face f;
  makeFace(&f, 166.0, 0.0, 0.0);
  memset(f.w, 0, sizeof f.w);
  double cl[NDOF], cr[NDOF], axis[3];
  csError err;
  cs_errorClear(&err);
  CS_EXPECT(csf_swayFunctionals(&f.fe, cl, cr, axis, &err) == CS_ERR_ARG);
  CS_EXPECT(strstr(err.msg, "no tip face") != NULL);
}

int main(int argc, char** argv) {
  cs_testInit(argc, argv);
  CS_RUN(translation_reads_delta_not_theta);
  CS_RUN(rotation_reads_theta_not_delta);
  CS_RUN(rotation_about_e1_reads_nothing);
  CS_RUN(no_face_is_refused);
  return cs_testSummary();
}
