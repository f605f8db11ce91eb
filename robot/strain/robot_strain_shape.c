/* robot_strain_shape.c: the strain leg's contact shapes (robot_strain_contact.c's header says
 * what they are and how the step linearises their law): their creation, each shape's state in
 * the world from the kinematics, the law's load on it through the shape's memo, and its
 * tangent (K_y, C_y). Split from robot_strain_contact.c, which assembles these into the step,
 * unchanged (a pure move, every run file bit for bit). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core_math.h"
#include "robot_strain_internal.h"

/* difference steps of the linearisation: positions (mm) well inside the law's 1 µm onset,
 * rotations (rad) likewise at the sole's 7.5 mm lever, velocities (mm/s) */
#define CSR_STRAIN_CFD_X 1e-7
#define CSR_STRAIN_CFD_PHI 1e-8
#define CSR_STRAIN_CFD_V 1e-6


int csr_strainContactCreate_(csrStrainModel* m, const csrStrainSpec* spec, csError* err) {
  cscSoftParams sp = spec->soft ? *spec->soft : csc_softDefaultParams();
  sp.history = CSC_HISTORY_STEP;
  int ncap = 0;
  for (int k = 0; k < m->npiece; k++) {
    ncap += m->nsub[k];
  }
  ncap -= 1; /* the last sub-interval is the foot's */
  m->nshape = ncap + 1;
  m->shape_a = calloc((size_t)m->nshape, sizeof(int));
  m->shape_b = calloc((size_t)m->nshape, sizeof(int));
  cscShape* shapes = calloc((size_t)m->nshape, sizeof(cscShape));
  if (!m->shape_a || !m->shape_b || !shapes) {
    free(shapes);
    return cs_errorSet(err, CS_ERR_MEMORY, "strain: out of memory");
  }
  int s = 0;
  for (int k = 0; k < m->npiece; k++) {
    for (int i = 0; i < m->nsub[k] && s < ncap; i++, s++) {
      m->shape_a[s] = m->pt0[k] + 2 * i;
      m->shape_b[s] = m->pt0[k] + 2 * i + 2;
      shapes[s] = csc_softCapsule(m->rpar.contact_radius);
    }
  }
  m->shape_a[ncap] = m->shape_b[ncap] = m->np - 1;
  /* the sole: the actuator's square section, or (pieces without an actuator) the capsules'
   * radius as half side */
  shapes[ncap] = csc_softFoot(spec->act ? spec->act->a : m->rpar.contact_radius);
  m->soft = csc_softCreate(&sp, spec->terrain, m->nshape, shapes, err);
  free(shapes);
  if (!m->soft) {
    return CS_ERR_RANGE;
  }
  m->nhist = csc_softNState(m->soft);
  for (int i = 0; i < m->nshape; i++) {
    int off, cnt;
    csc_softShapeState(m->soft, i, &off, &cnt);
    if (cnt > CSR_STRAIN_MAX_SHAPE_HIST) {
      return cs_errorSet(err, CS_ERR_RANGE, "strain: contact shape %d keeps %d history doubles "
                         "(at most %d)", i, cnt, CSR_STRAIN_MAX_SHAPE_HIST);
    }
  }
  return 0;
}


/* shape s's pose and velocity in the world from the current kinematics and point twists */
void csr_strainShapeState_(const csrStrainModel* m, const csrStrainData* d, int s,
                       cscShapeState* st) {
  int a = m->shape_a[s], b = m->shape_b[s];
  double Ra[9], Rb[9], xb[3];
  memset(st, 0, sizeof *st);
  csr_strainWorld_(d, d->R + 9 * a, d->x + 3 * a, Ra, st->x0);
  csr_strainWorld_(d, d->R + 9 * b, d->x + 3 * b, Rb, xb);
  memcpy(st->x1, xb, sizeof xb);
  memcpy(st->R, Ra, sizeof Ra);
  csu_mulMatVec3(st->v0, Ra, d->Vp + 6 * a + 3);
  csu_mulMatVec3(st->v1, Rb, d->Vp + 6 * b + 3);
  csu_mulMatVec3(st->w, Ra, d->Vp + 6 * a);
}


/* the load vector L (6) of shape s: foot (force, couple), capsule (f0, f1); couple out */
static void loadVector(const csrStrainModel* m, int s, const cscShapeLoad* ld, double L[6],
                       double couple[3]) {
  int foot = s == m->nshape - 1;
  memcpy(L, ld->f0, 3 * sizeof(double));
  memcpy(L + 3, foot ? ld->m : ld->f1, 3 * sizeof(double));
  if (couple) {
    if (foot) {
      memset(couple, 0, 3 * sizeof(double));
    } else {
      memcpy(couple, ld->m, 3 * sizeof(double));
    }
  }
}


/* the law at shape s's state st, not remembered (the linearisation's differences, a
 * query at other rates) */
int csr_strainShapeLaw_(const csrStrainModel* m, const csrStrainData* d, int s,
                   const cscShapeState* st, double L[6], double couple[3], cscSlotInfo* slot) {
  int off, cnt;
  csc_softShapeState(m->soft, s, &off, &cnt);
  cscShapeLoad ld;
  double zdot[CSR_STRAIN_MAX_SHAPE_HIST];
  (void)cnt;
  int rc = csc_softComputeShape(m->soft, s, st, d->z + off, &ld, zdot, slot, NULL);
  loadVector(m, s, &ld, L, couple);
  return rc;
}


/* 1 when shape s's memo was evaluated at st with the history d->z holds now */
static int memoHolds(const csrStrainModel* m, const csrStrainData* d, int s,
                     const cscShapeState* st) {
  const csrStrainLoadMemo* mo = d->memo + s;
  if (!mo->valid || memcmp(&mo->st, st, sizeof *st) != 0) {
    return 0;
  }
  int off, cnt;
  csc_softShapeState(m->soft, s, &off, &cnt);
  return memcmp(d->memo_z + off, d->z + off, (size_t)cnt * sizeof(double)) == 0;
}


/* shape s's memo set to the state st and the history now (its load, report and slots already
 * written) */
void csr_strainShapeMemoKeep_(const csrStrainModel* m, csrStrainData* d, int s,
                              const cscShapeState* st, int rc) {
  csrStrainLoadMemo* mo = d->memo + s;
  int off, cnt;
  csc_softShapeState(m->soft, s, &off, &cnt);
  memcpy(d->memo_z + off, d->z + off, (size_t)cnt * sizeof(double));
  mo->st = *st;
  mo->rc = rc;
  mo->valid = 1;
}


/* The law at shape s's state st (L, couple as loadVector; slot: its slots' report or NULL;
 * rep: added to, or NULL), through the shape's memo (csrStrainLoadMemo): the same bits as
 * the law evaluated anew */
int csr_strainShapeLoad_(const csrStrainModel* m, csrStrainData* d, int s,
                         const cscShapeState* st, double L[6], double couple[3],
                         cscSlotInfo* slot, cscSoftReport* rep) {
  csrStrainLoadMemo* mo = d->memo + s;
  int first, nslot;
  csc_softShapeSlots(m->soft, s, &first, &nslot);
  if (!memoHolds(m, d, s, st)) {
    int off, cnt;
    csc_softShapeState(m->soft, s, &off, &cnt);
    double zdot[CSR_STRAIN_MAX_SHAPE_HIST];
    (void)cnt;
    memset(&mo->rep, 0, sizeof mo->rep);
    int rc = csc_softComputeShape(m->soft, s, st, d->z + off, &mo->ld, zdot,
                                  d->memo_slot + first, &mo->rep);
    csr_strainShapeMemoKeep_(m, d, s, st, rc);
  }
  loadVector(m, s, &mo->ld, L, couple);
  if (slot) {
    memcpy(slot, d->memo_slot + first, (size_t)nslot * sizeof *slot);
  }
  if (rep) {
    /* as csc_softComputeShape adds a shape to a report: counts summed, maxima (>= 0) */
    rep->ncontact += mo->rep.ncontact;
    rep->nsliding += mo->rep.nsliding;
    rep->ndeep += mo->rep.ndeep;
    rep->max_depth = fmax(rep->max_depth, mo->rep.max_depth);
    rep->max_ratio = fmax(rep->max_ratio, mo->rep.max_ratio);
  }
  return mo->rc;
}


/* y ± δ along coordinate c (0..5 pose, 6..11 rate) of shape s's state */
static void perturb(const csrStrainModel* m, int s, cscShapeState* st, int c, double del) {
  int foot = s == m->nshape - 1;
  if (c < 3) {
    st->x0[c] += del;
  } else if (c < 6) {
    if (foot) {
      double phi[3] = {0, 0, 0}, dR[9], Rn[9];
      phi[c - 3] = del;
      csu_rotVecToMat3(dR, phi);
      csu_mulMat3(Rn, dR, st->R);
      memcpy(st->R, Rn, sizeof Rn);
    } else {
      st->x1[c - 3] += del;
    }
  } else if (c < 9) {
    st->v0[c - 6] += del;
  } else if (foot) {
    st->w[c - 9] += del;
  } else {
    st->v1[c - 9] += del;
  }
}


/* K_y, C_y (6 x 6 each, row-major: the load's derivatives along the shape's 6 pose and 6 rate
 * coordinates of perturb) of shape s at state st, where the law's load is L0. The foot's come
 * from the law's own derivatives (contact_soft_jac.c, within 1e-8 of central differences in
 * test_contact_soft_jac): one evaluation in place of 12 and exact where differences err by
 * delta / w; the shapes and terrains it does not cover (capsules, a heightfield, friction per
 * surface) by forward differences from L0, half the evaluations of central ones: their error is
 * delta / w relative where the law bends over a width w (its 1e-3 mm onset: 1e-4), which slows
 * the Newton passes negligibly (test_strain_friction holds creep and Coulomb). The differences
 * bypass the memo (lawLoad): a perturbed state is never asked again. */
void csr_strainShapeTangent_(const csrStrainModel* m, csrStrainData* d, int s,
                         const cscShapeState* st, const double L0[6], double Ky[36],
                         double Cy[36]) {
  const int foot = s == m->nshape - 1;
  if (foot) {
    int off, cnt;
    csc_softShapeState(m->soft, s, &off, &cnt);
    double Lj[6];
    if (csc_softShapeJacobian(m->soft, s, st, d->z + off, Lj, Ky, Cy) == 0) {
      return;
    }
  }
  for (int c = 0; c < 12; c++) {
    double del = c < 3 ? CSR_STRAIN_CFD_X
                       : (c < 6 ? (foot ? CSR_STRAIN_CFD_PHI : CSR_STRAIN_CFD_X)
                                : CSR_STRAIN_CFD_V);
    cscShapeState sp = *st;
    perturb(m, s, &sp, c, del);
    double Lp[6];
    csr_strainShapeLaw_(m, d, s, &sp, Lp, NULL, NULL);
    double* D = c < 6 ? Ky : Cy;
    for (int r = 0; r < 6; r++) {
      D[6 * r + c % 6] = (Lp[r] - L0[r]) / del;
    }
  }
}
