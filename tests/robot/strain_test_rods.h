/* strain_test_rods.h: small strain-coordinate rods for the strain leg's unit tests (tests only):
 * uniform square pieces of a soft material, a bent three-piece rod and the default leg's
 * five-piece layout. */
#ifndef CS_TESTS_STRAIN_TEST_RODS_H
#define CS_TESTS_STRAIN_TEST_RODS_H

#include <stdio.h>
#include <string.h>

#include "core_math.h"
#include "cs_test.h"
#include "robot_strain_internal.h"

/* a uniform 10 x 10 mm square piece, E = 1 MPa, shear modulus G (MPa), density 1e-9 t/mm³ */
static inline csrRodPiece uniformPieceG(double L, double G) {
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


/* the same with G = E/3 */
static inline csrRodPiece uniformPiece(double L) { return uniformPieceG(L, 1.0 / 3); }


static inline csrStrainModel* makeRod(const csrRodPiece* pc, const int* order, int np,
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


/* a three-piece rod (flexible, rigid, flexible) with linear axial modes, bent, twisted,
 * stretched and sheared: q_j = (j % 7 - 3) x 0.007 (κ, τ modes) or 0.02 (σ modes) */
static inline csrStrainModel* bentRod(void) {
  csrRodPiece pc[3] = {uniformPiece(50), uniformPiece(8), uniformPiece(40)};
  const int order[3] = {2, -1, 2}; /* the middle piece rigid */
  csrStrainParams sp = csr_strainDefaultParams();
  sp.axial_order = 1;
  sp.nsub = 3;
  return makeRod(pc, order, 3, &sp);
}


/* the default leg's layout: five pieces (bend order 2 in the segments, constant joints) */
static inline csrStrainModel* legLayout(void) {
  csrRodPiece pc[5] = {uniformPiece(50), uniformPiece(8), uniformPiece(50), uniformPiece(8),
                       uniformPiece(50)};
  const int order[5] = {2, 0, 2, 0, 2};
  csrStrainParams sp = csr_strainDefaultParams();
  return makeRod(pc, order, 5, &sp);
}

#endif
