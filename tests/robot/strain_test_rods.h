/* strain_test_rods.h: the uniform test rod of the strain leg's unit tests (test_strain_model,
 * test_strain_vprod): a 10 x 10 mm square section, E = 1 MPa, shear modulus G (MPa), density
 * 1e-9 t/mm³, and a model of such pieces at the default rod parameters, clamped in the
 * identity frame. */
#ifndef CS_TESTS_STRAIN_TEST_RODS_H
#define CS_TESTS_STRAIN_TEST_RODS_H

#include <stdio.h>
#include <string.h>

#include "core_math.h"
#include "cs_test.h"
#include "robot_strain_internal.h"

static inline csrRodPiece strainTestPiece(double L, double G) {
  csrRodPiece p;
  memset(&p, 0, sizeof p);
  const double A = 100, I = 1e4 / 12, E = 1.0, k = 10.0 * 1.5 / (12 + 5.5);
  p.length = L;
  p.nelem = 1;
  p.segment = -1;
  p.section.EA = E * A;
  p.section.GA[0] = p.section.GA[1] = k * G * A;
  p.section.EI[0] = p.section.EI[1] = E * I;
  p.section.GJ = G * 0.1406 * 1e4;
  p.rhoA = 1e-9 * A;
  p.rhoI[0] = p.rhoI[1] = 1e-9 * I;
  p.rhoI[2] = 2e-9 * I;
  return p;
}


/* NULL (and a failed expectation, the error printed) if the model is refused */
static inline csrStrainModel* strainTestRod(const csrRodPiece* pc, const int* order, int np,
                                            const csrStrainParams* sp) {
  csrRodParams rp = csr_rodDefaultParams(NULL);
  csrStrainSpec spec;
  memset(&spec, 0, sizeof spec);
  spec.rod_params = &rp;
  spec.params = sp;
  csu_eye3(spec.frame);
  csError err;
  cs_errorClear(&err);
  csrStrainModel* m = csr_strainModelCreatePieces(pc, order, np, &spec, &err);
  if (!m) {
    fprintf(stderr, "  %s\n", err.msg);
  }
  CS_EXPECT(m != NULL);
  return m;
}

#endif
