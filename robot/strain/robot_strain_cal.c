/* robot_strain_cal.c: the strain leg's calibration per segment (robot_strain.h, cal_quantum):
 * the pressures -> rest strains and sections map of the nodal rod's calibration path
 * (csr_rodActuationEval_), exactly with a memo of each segment's last evaluation, or
 * interpolated on a pressure lattice; and the generalised stiffness and rest terms (Kd, b) the
 * step takes from it. The callers are robot_strain.c (actuation, reset, statics). */
#include <math.h>
#include <string.h>

#include "robot_rod_internal.h"
#include "robot_strain_internal.h"


/* the exact calibration of segment s at its pressures ps, through d's memo of its last one */
static int segmentExact(const csrStrainModel* m, csrStrainData* d, int s, const double ps[4],
                        csrRodSegmentActuation* act, char* msg, size_t msg_size) {
  if (d->cal.valid[s] && memcmp(ps, d->cal.p[s], 4 * sizeof(double)) == 0) {
    *act = d->cal.act[s];
    return 0;
  }
  d->cal.valid[s] = 0;
  int rc = csr_rodActuationEval_(m->rod, s, ps, act, msg, msg_size);
  d->ncal++;
  if (rc != 0) {
    return rc;
  }
  memcpy(d->cal.p[s], ps, 4 * sizeof(double));
  d->cal.act[s] = *act;
  d->cal.valid[s] = 1;
  return 0;
}


/* the calibration of segment s at the lattice vertex key (pressures key δ), through d's vertex
 * cache */
static int segmentVertex(const csrStrainModel* m, csrStrainData* d, int s, const long key[4],
                         csrRodSegmentActuation* act, char* msg, size_t msg_size) {
  csrStrainCalMemo* c = &d->cal;
  for (int i = 0; i < c->nv[s]; i++) {
    if (memcmp(c->vkey[s][i], key, 4 * sizeof(long)) == 0) {
      *act = c->vact[s][i];
      return 0;
    }
  }
  double pv[4];
  for (int j = 0; j < 4; j++) {
    pv[j] = (double)key[j] * m->par.cal_quantum;
  }
  int rc = csr_rodActuationEval_(m->rod, s, pv, act, msg, msg_size);
  d->ncal++;
  if (rc != 0) {
    return rc;
  }
  const int slot = c->nv[s] < CSR_STRAIN_CAL_VERTS ? c->nv[s]++ : c->vnext[s];
  c->vnext[s] = (slot + 1) % CSR_STRAIN_CAL_VERTS;
  memcpy(c->vkey[s][slot], key, 4 * sizeof(long));
  c->vact[s][slot] = *act;
  return 0;
}


/* a += w b over every number of a segment's actuation */
static void actuationAxpy(csrRodSegmentActuation* a, double w, const csrRodSegmentActuation* b) {
  for (int i = 0; i < 3; i++) {
    a->u0[i] += w * b->u0[i];
    a->sigma0[i] += w * b->sigma0[i];
  }
  a->section.EA += w * b->section.EA;
  for (int i = 0; i < 2; i++) {
    a->section.GA[i] += w * b->section.GA[i];
    a->section.EI[i] += w * b->section.EI[i];
  }
  a->section.GJ += w * b->section.GJ;
}


/* segment s's calibration at its pressures ps interpolated on the lattice of spacing δ =
 * cal_quantum: with ps / δ = a + f (a integer, f in [0, 1)) and the chambers ordered by f
 * descending (c1..c4, ties by index), the simplex a, a + e_c1, a + e_c1 + e_c2, ... holds ps
 * with barycentric weights 1 - f_c1, f_c1 - f_c2, f_c2 - f_c3, f_c3 - f_c4, f_c4 (Kuhn's
 * triangulation: continuous across simplices, exact for a linear field, error O(δ²) times
 * the field's curvature). A vertex the calibration refuses (outside its range), or vertices
 * that disagree on having a calibrated section, give the exact evaluation instead. */
static int segmentLattice(const csrStrainModel* m, csrStrainData* d, int s, const double ps[4],
                          csrRodSegmentActuation* out, char* msg, size_t msg_size) {
  const double dq = m->par.cal_quantum;
  long key[4];
  double f[4];
  int ord[4] = {0, 1, 2, 3};
  for (int j = 0; j < 4; j++) {
    const double t = ps[j] / dq, a = floor(t);
    if (!(fabs(t) < 1e15)) {
      /* not finite, or past a lattice index: the calibration itself says what it is */
      return segmentExact(m, d, s, ps, out, msg, msg_size);
    }
    key[j] = (long)a;
    f[j] = t - a;
  }
  for (int i = 1; i < 4; i++) { /* insertion sort by f descending, stable */
    for (int k = i; k > 0 && f[ord[k]] > f[ord[k - 1]]; k--) {
      const int t = ord[k];
      ord[k] = ord[k - 1];
      ord[k - 1] = t;
    }
  }
  double w[5];
  w[0] = 1 - f[ord[0]];
  for (int i = 1; i < 4; i++) {
    w[i] = f[ord[i - 1]] - f[ord[i]];
  }
  w[4] = f[ord[3]];
  memset(out, 0, sizeof *out);
  int has = -1;
  for (int i = 0; i < 5; i++) {
    if (i > 0) {
      key[ord[i - 1]]++;
    }
    if (w[i] == 0) {
      continue; /* a vertex that does not count is not evaluated */
    }
    csrRodSegmentActuation v;
    char vmsg[8];
    if (segmentVertex(m, d, s, key, &v, vmsg, sizeof vmsg) != 0 ||
        (has >= 0 && has != v.has_section)) {
      return segmentExact(m, d, s, ps, out, msg, msg_size);
    }
    has = v.has_section;
    actuationAxpy(out, w[i], &v);
  }
  out->has_section = has > 0;
  return 0;
}


/* Kd, b at the pressures p (MPa) through the calibration path (robot_strain_internal.h), each segment's exactly
 * (cal_quantum 0: a segment whose pressures are bit for bit those of its last evaluation
 * reuses it) or interpolated on the pressure lattice (segmentLattice). The calibration's RBF
 * field is the step's largest fixed cost when it runs every step for every leg
 * (docs/notes/strain_leg.md "Cost per pass, sixth session": 0.30e9 instructions per simulated
 * s at 1 ms). */
int csr_strainActuation_(const csrStrainModel* m, csrStrainData* d, const double p[12],
                         double* Kd, double* b, char* msg, size_t msg_size) {
  csrRodSegmentActuation act[CSR_NSEG];
  int have[CSR_NSEG] = {0, 0, 0};
  for (int k = 0; k < m->npiece; k++) {
    int s = m->piece[k].segment;
    if (s >= 0 && !have[s]) {
      int rc = m->par.cal_quantum > 0 ? segmentLattice(m, d, s, p + 4 * s, &act[s], msg, msg_size)
                                      : segmentExact(m, d, s, p + 4 * s, &act[s], msg, msg_size);
      if (rc != 0) {
        return rc;
      }
      have[s] = 1;
    }
  }
  for (int k = 0; k < m->npiece; k++) {
    const csrRodPiece* pc = &m->piece[k];
    const csrRodSection* S = &pc->section;
    double dxi[6] = {0, 0, 0, 0, 0, 0};
    if (pc->segment >= 0) {
      const csrRodSegmentActuation* a = &act[pc->segment];
      memcpy(dxi, a->u0, sizeof a->u0);
      memcpy(dxi + 3, a->sigma0, sizeof a->sigma0);
      if (a->has_section) {
        S = &a->section;
      }
    }
    const double C[6] = {S->EI[0], S->EI[1], S->GJ, S->GA[0], S->GA[1], S->EA};
    for (int j = m->dof0[k]; j < m->dof0[k] + m->ndof[k]; j++) {
      int c = m->dcomp[j], o = m->dorder[j];
      /* ∫_0^S P_o² dX = S / (2o + 1); ∫ P_o dX = S δ_o0 */
      Kd[j] = C[c] * pc->length / (2 * o + 1);
      b[j] = o == 0 ? C[c] * pc->length * dxi[c] : 0.0;
    }
  }
  return 0;
}
