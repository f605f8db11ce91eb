/* robot_strain.c: the strain leg's model, data, actuation, generalised forces and mass, and
 * the static solver (robot_strain.h; kinematics in robot_strain_lie.c, the dense factorisations
 * in robot_strain_linalg.c).
 *
 * ---- Calibration path ---------------------------------------------------------------------
 * The rest strains and calibrated sections come from csr_rodActuationEval_ of a nodal rod built
 * from the same pieces (one element each; it is never stepped): the bend map's bend and stretch
 * turned into (u0, σ0) over the segment's length, a mode table's probed EI and EA, and
 * csrRodParams.cal_drop, exactly as the nodal rod level gets them. The nodal rod's chord
 * correction of its elements' rest length (csr_rodLoadsFromActuation_) belongs to its
 * discretisation and is not applied here: a constant strain is integrated exactly.
 *
 * ---- Quadrature ---------------------------------------------------------------------------
 * Mass matrix and weight: Simpson's rule on every Magnus sub-interval (its ends and midpoint,
 * whose poses and Jacobians the kinematics computes), 4th order like the Magnus step and exact
 * for a rigid piece (where J is linear in X and Jᵀ M_s J quadratic). K and b are exact
 * (orthogonal Legendre modes, constant section per piece).
 *
 * ---- Static solver ------------------------------------------------------------------------
 * Newton on R(q) = b - K q + Q_ext(q) = 0 with the Jacobian -∂R/∂q = K - ∂Q_ext/∂q by central
 * differences of R (2n kinematic passes, each the poses and the adjoint projection of the
 * loads: no Jacobians; n = 42 for the default leg; the statics are not on the step path) and
 * a dense LU. Load stepping as the nodal rod does (robot_rod_static.c): rest
 * strains, K, tip load and weight move linearly from the last solved load, the increment
 * doubles after a success and halves after a failure down to 1/4096. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core_math.h"
#include "robot_rod_internal.h"
#include "robot_strain_internal.h"

/* central-difference step of mode j: this fraction of its scale (rad or strain): truncation
 * ~δ² ≈ 1e-14, round-off ~ε/δ ≈ 1e-10 relative */
#define CSR_STRAIN_FD_REL 1e-6
/* a Newton update larger than this (rad or strain over a piece) is divergence: the increment
 * is halved */
#define CSR_STRAIN_MAX_UPDATE 2.0
/* smallest load increment before giving up */
#define CSR_STRAIN_MIN_DLAM (1.0 / 4096)


csrStrainParams csr_strainDefaultParams(void) {
  csrStrainParams p;
  /* bending linear along each segment plus a quadratic mode: test_strain_static measures the
   * leg's tip under a 0.05 N tip load against the nodal rod converged at 16 elements per
   * segment (the printed table chooses the order) */
  p.bend_order = 2;
  /* twist, shear and stretch constant along each piece: under the leg's loads their variation
   * is second order (test_strain_static tip_load_large_vs_nodal measures what a linear mode
   * adds on a 50° cantilever) */
  p.axial_order = 0;
  /* the joints bend at a constant curvature: rigid joints remove 1.7 mm of the leg's 0.05 N tip
   * deflection (test_strain_static leg_tip_load_vs_nodal), constant bending over 8 mm is within
   * the moment's variation over the joint */
  p.joint_order = 0;
  /* the leg's shear compliance is ~1 % of its bending compliance under a tip load: kept */
  p.shear = 1;
  /* 4 sub-intervals per segment: Magnus 4th order on a linear-quadratic strain field */
  p.nsub = 4;
  /* Newton stops when no mode moves by more than 1e-11 rad (or strain) over its piece */
  p.static_tol = 1e-11;
  p.static_max_iter = 40;
  /* backward Euler until BDF2 is chosen by measurement (docs/notes/strain_leg.md, "Second
   * order") */
  p.step_order = 1;
  /* BDF2's whole residual at every iterate (the exact step; 0 is cheaper: docs/notes/
   * strain_leg.md, "Fast step") */
  p.step_refresh = 1;
  /* the stance feet's active set in the Newton passes (docs/notes/strain_leg.md, "Active
   * set") */
  p.active_set = 1;
  /* the anchors' secant until the tangent is chosen by measurement (docs/notes/strain_leg.md,
   * "The friction's tangent") */
  p.friction_tangent = 0;
  /* the full Newton move until the slot trust region is chosen by measurement
   * (docs/notes/strain_leg.md, "Passes per step") */
  p.slot_trust = 0;
  /* a new factor every step until keeping it is chosen by measurement (docs/notes/
   * strain_leg.md, "A kept iteration matrix") */
  p.keep_matrix = 0;
  p.keep_strain = 0.05;
  /* every leg's step start condensed by the articulated recursion: without contact
   * (docs/notes/strain_leg.md, "The articulated condensation") and with it (2: section "The
   * stance legs' articulated condensation", 10 % fewer instructions, the same passes) */
  p.artic = 2;
  /* the pressures as given until a resolution is chosen by measurement */
  p.cal_quantum = 0;
  return p;
}


/* ---- model ---------------------------------------------------------------------------------- */

void csr_strainModelDestroy(csrStrainModel* m) {
  if (!m) {
    return;
  }
  csr_rodModelDestroy(m->rod);
  csc_softDestroy(m->soft);
  free(m->shape_a);
  free(m->shape_b);
  free(m->dcomp);
  free(m->dorder);
  free(m->dpiece);
  free(m->dscale);
  free(m->Ms);
  free(m->pcol);
  free(m->gleg);
  free(m);
}


csrStrainModel* csr_strainModelCreatePieces(const csrRodPiece* pieces, const int* order,
                                            int npiece, const csrStrainSpec* spec, csError* err) {
  if (!pieces || !spec || (!spec->act && !spec->rod_params)) {
    cs_errorSet(err, CS_ERR_ARG, "strain: NULL pieces or spec (or neither actuator nor rod "
                "parameters)");
    return NULL;
  }
  if (npiece < 1 || npiece > CSR_ROD_MAX_PIECES) {
    cs_errorSet(err, CS_ERR_ARG, "strain: %d pieces (need 1..%d)", npiece, CSR_ROD_MAX_PIECES);
    return NULL;
  }
  csrStrainParams par = spec->params ? *spec->params : csr_strainDefaultParams();
  int bad_order = 0;
  for (int k = 0; order && k < npiece; k++) {
    bad_order |= order[k] < -1 || order[k] > CSR_STRAIN_MAX_ORDER;
  }
  if (bad_order || par.bend_order < 0 || par.bend_order > CSR_STRAIN_MAX_ORDER ||
      par.axial_order < 0 || par.axial_order > CSR_STRAIN_MAX_ORDER || par.joint_order < -1 ||
      par.joint_order > CSR_STRAIN_MAX_ORDER || par.nsub < 1 || par.nsub > CSR_STRAIN_MAX_SUB ||
      (par.shear != 0 && par.shear != 1) || !(par.static_tol > 0) || par.static_max_iter < 1 ||
      (par.step_order != 1 && par.step_order != 2) ||
      (par.step_refresh != 0 && par.step_refresh != 1) ||
      (par.active_set != 0 && par.active_set != 1) ||
      (par.friction_tangent != 0 && par.friction_tangent != 1) ||
      (par.keep_matrix != 0 && par.keep_matrix != 1) || (par.artic < 0 || par.artic > 2) ||
      (par.keep_matrix && par.step_order != 1) || isnan(par.keep_strain) ||
      !(par.cal_quantum >= 0) || !isfinite(par.cal_quantum)) {
    cs_errorSet(err, CS_ERR_RANGE, "strain: parameters: need bend_order and axial_order 0..%d, "
                "joint_order and piece orders -1..%d, nsub 1..%d, shear 0 or 1, static_tol > 0, "
                "static_max_iter >= 1, step_order 1 or 2, step_refresh, active_set and "
                "friction_tangent 0 or 1, keep_matrix 0 or 1 (1 with step_order 1 only), artic 0, 1 or 2, "
                "keep_strain not NaN", CSR_STRAIN_MAX_ORDER, CSR_STRAIN_MAX_ORDER,
                CSR_STRAIN_MAX_SUB);
    return NULL;
  }
  csrStrainModel* m = calloc(1, sizeof *m);
  if (!m) {
    cs_errorSet(err, CS_ERR_MEMORY, "strain: out of memory");
    return NULL;
  }
  m->par = par;
  m->rpar = spec->rod_params ? *spec->rod_params : csr_rodDefaultParams(spec->act);
  m->npiece = npiece;
  /* the calibration path and the pieces' checks: a nodal rod of the same pieces */
  csrRodPiece one[CSR_ROD_MAX_PIECES];
  for (int k = 0; k < npiece; k++) {
    one[k] = pieces[k];
    one[k].nelem = 1;
  }
  csrRodSpec rs;
  memset(&rs, 0, sizeof rs);
  rs.act = spec->act;
  rs.params = &m->rpar;
  rs.map = spec->map;
  rs.calib = spec->calib;
  memcpy(rs.hip, spec->hip, sizeof rs.hip);
  memcpy(rs.frame, spec->frame, sizeof rs.frame);
  memcpy(rs.gravity, spec->gravity, sizeof rs.gravity);
  rs.weightless = spec->weightless;
  m->rod = csr_rodModelCreatePieces(one, npiece, &rs, err);
  if (!m->rod) {
    csr_strainModelDestroy(m);
    return NULL;
  }
  memcpy(m->piece, one, (size_t)npiece * sizeof *one);
  memcpy(m->hip, spec->hip, sizeof m->hip);
  memcpy(m->frame, spec->frame, sizeof m->frame);
  if (!spec->weightless) {
    memcpy(m->gravity, spec->gravity, sizeof m->gravity);
  }
  /* unknowns and quadrature points per piece */
  const int nax = par.axial_order + 1;
  int n = 0, np = 1;
  m->pmax = par.axial_order;
  for (int k = 0; k < npiece; k++) {
    m->bord[k] = order ? order[k] : par.bend_order;
    m->rigid[k] = m->bord[k] < 0;
    m->pmax = m->bord[k] > m->pmax ? m->bord[k] : m->pmax;
    m->X0[k + 1] = m->X0[k] + pieces[k].length;
    m->dof0[k] = n;
    m->ndof[k] = m->rigid[k] ? 0 : 2 * (m->bord[k] + 1) + (2 + 2 * par.shear) * nax;
    m->nsub[k] = m->rigid[k] || (m->bord[k] == 0 && nax == 1) ? 1 : par.nsub;
    m->pt0[k] = np - 1;
    n += m->ndof[k];
    np += 2 * m->nsub[k];
    m->mass += pieces[k].rhoA * pieces[k].length;
  }
  m->pt0[npiece] = np - 1;
  m->n = n;
  m->np = np;
  m->L = m->X0[npiece];
  m->dcomp = calloc((size_t)n + 1, sizeof(int));
  m->dorder = calloc((size_t)n + 1, sizeof(int));
  m->dpiece = calloc((size_t)n + 1, sizeof(int));
  m->dscale = calloc((size_t)n + 1, sizeof(double));
  m->Ms = calloc((size_t)np * 6, sizeof(double));
  m->pcol = calloc((size_t)np, sizeof(int));
  if (!m->dcomp || !m->dorder || !m->dpiece || !m->dscale || !m->Ms || !m->pcol) {
    csr_strainModelDestroy(m);
    cs_errorSet(err, CS_ERR_MEMORY, "strain: out of memory");
    return NULL;
  }
  for (int k = 0; k < npiece; k++) {
    const csrRodPiece* pc = &pieces[k];
    int j = m->dof0[k];
    for (int c = 0; c < 6 && !m->rigid[k]; c++) {
      if (!par.shear && (c == CSR_STRAIN_S1 || c == CSR_STRAIN_S2)) {
        continue;
      }
      int nm = c <= CSR_STRAIN_K2 ? m->bord[k] + 1 : nax;
      for (int o = 0; o < nm; o++, j++) {
        m->dcomp[j] = c;
        m->dorder[j] = o;
      }
    }
    for (int jj = m->dof0[k]; jj < m->dof0[k] + m->ndof[k]; jj++) {
      m->dpiece[jj] = k;
      m->dscale[jj] = m->dcomp[jj] <= CSR_STRAIN_TW ? pc->length : 1.0;
    }
    for (int p = m->pt0[k] + 1; p <= m->pt0[k + 1]; p++) {
      m->pcol[p] = m->dof0[k] + m->ndof[k];
    }
    /* Simpson weights x section mass per length at each sub-interval's ends and midpoint */
    const double ms[6] = {pc->rhoI[0], pc->rhoI[1], pc->rhoI[2], pc->rhoA, pc->rhoA, pc->rhoA};
    double h = pc->length / m->nsub[k];
    for (int i = 0; i < m->nsub[k]; i++) {
      int p = m->pt0[k] + 2 * i;
      const double w[3] = {h / 6, 4 * h / 6, h / 6};
      for (int t = 0; t < 3; t++) {
        for (int c = 0; c < 6; c++) {
          m->Ms[6 * (p + t) + c] += w[t] * ms[c];
        }
      }
    }
  }
  if (csr_strainLegendreTable_(m) != 0) {
    csr_strainModelDestroy(m);
    cs_errorSet(err, CS_ERR_MEMORY, "strain: out of memory");
    return NULL;
  }
  if (spec->terrain && csr_strainContactCreate_(m, spec, err) != 0) {
    csr_strainModelDestroy(m);
    return NULL;
  }
  return m;
}


csrStrainModel* csr_strainModelCreate(const csrStrainSpec* spec, csError* err) {
  if (!spec || !spec->act) {
    cs_errorSet(err, CS_ERR_ARG, "strain: NULL spec or actuator");
    return NULL;
  }
  if (csr_actuatorValidate(spec->act, err) != CS_OK) {
    return NULL;
  }
  csrRodParams rp = spec->rod_params ? *spec->rod_params : csr_rodDefaultParams(spec->act);
  csrRodPiece pieces[CSR_ROD_MAX_PIECES];
  int n = csr_rodLegPieces(spec->act, &rp, pieces);
  if (n == 0) {
    cs_errorSet(err, CS_ERR_RANGE, "strain: the actuator's section cannot be integrated");
    return NULL;
  }
  csrStrainParams par = spec->params ? *spec->params : csr_strainDefaultParams();
  int order[CSR_ROD_MAX_PIECES];
  for (int k = 0; k < n; k++) {
    /* the solid joints LS12, LS23 are the passive pieces */
    order[k] = pieces[k].segment < 0 ? par.joint_order : par.bend_order;
  }
  csrStrainSpec sp = *spec;
  sp.rod_params = &rp;
  sp.params = &par;
  return csr_strainModelCreatePieces(pieces, order, n, &sp, err);
}


int csr_strainDofs(const csrStrainModel* m) { return m->n; }
double csr_strainLength(const csrStrainModel* m) { return m->L; }
double csr_strainMass(const csrStrainModel* m) { return m->mass; }


void csr_strainPieceDofs(const csrStrainModel* m, int k, int* first, int* count) {
  int ok = k >= 0 && k < m->npiece;
  *first = ok ? m->dof0[k] : 0;
  *count = ok ? m->ndof[k] : 0;
}


/* ---- data ----------------------------------------------------------------------------------- */

void csr_strainDataDestroy(csrStrainData* d) {
  if (!d) {
    return;
  }
  free(d->q);
  free(d->eta);
  free(d->Kd);
  free(d->b);
  free(d->R);
  free(d->x);
  free(d->J);
  free(d->Q);
  free(d->Qp);
  free(d->Qm);
  free(d->A);
  free(d->dq);
  free(d->q_save);
  free(d->vp_eta);
  free(d->q_start);
  free(d->K1);
  free(d->b1);
  free(d->K0);
  free(d->b0);
  free(d->piv);
  free(d->Wll);
  free(d->X);
  free(d->Wlb);
  free(d->Wbl);
  free(d->z);
  free(d->sst);
  free(d->Gs);
  free(d->Rs_save);
  free(d->xs_save);
  free(d->y);
  free(d->rl);
  free(d->Vp);
  free(d->Vs);
  free(d->Fc);
  free(d->kst);
  free(d->ks);
  free(d->ks_q);
  free(d->Ab);
  free(d->q0);
  free(d->eta0);
  free(d->Wu);
  free(d->csig);
  free(d->ghost);
  free(d->memo);
  free(d->memo_z);
  free(d->memo_slot);
  free(d->ct);
  free(d->cS);
  free(d->cA);
  free(d->artLU);
  free(d->artPiv);
  free(d->artZsn);
  free(d->artY);
  free(d->artL);
  free(d->artA);
  free(d->wS);
  free(d->wA);
  free(d->wbQ);
  free(d->wbK);
  free(d->wbPiv);
  free(d->wbX);
  free(d->fl);
  free(d->R0);
  free(d->x0);
  free(d->J0);
  free(d->qf);
  free(d->Mu);
  free(d->WMll);
  free(d->WMlb);
  free(d->rMl);
  free(d->du);
  free(d->fcA);
  free(d->qm1);
  free(d->etam1);
  free(d);
}


csrStrainData* csr_strainDataCreate(const csrStrainModel* m, csError* err) {
  if (!m) {
    cs_errorSet(err, CS_ERR_ARG, "strain: NULL model");
    return NULL;
  }
  csrStrainData* d = calloc(1, sizeof *d);
  if (!d) {
    cs_errorSet(err, CS_ERR_MEMORY, "strain: out of memory");
    return NULL;
  }
  size_t n = (size_t)m->n + 1, np = (size_t)m->np;
  d->q = calloc(n, sizeof(double));
  d->eta = calloc(n, sizeof(double));
  d->Kd = calloc(n, sizeof(double));
  d->b = calloc(n, sizeof(double));
  d->R = calloc(np * 9, sizeof(double));
  d->x = calloc(np * 3, sizeof(double));
  d->J = calloc(np * 6 * n, sizeof(double));
  d->Q = calloc(n, sizeof(double));
  d->Qp = calloc(n, sizeof(double));
  d->Qm = calloc(n, sizeof(double));
  d->A = calloc(n * n, sizeof(double));
  d->dq = calloc(n, sizeof(double));
  d->q_save = calloc(n, sizeof(double));
  d->vp_eta = calloc(n, sizeof(double));
  d->vp_gen = -1;
  d->q_start = calloc(n, sizeof(double));
  d->K1 = calloc(n, sizeof(double));
  d->b1 = calloc(n, sizeof(double));
  d->K0 = calloc(n, sizeof(double));
  d->b0 = calloc(n, sizeof(double));
  d->piv = calloc(n, sizeof(int));
  d->Wll = calloc(n * n, sizeof(double));
  d->X = calloc(n * 6, sizeof(double));
  d->Wlb = calloc(n * 6, sizeof(double));
  d->Wbl = calloc(n * 6, sizeof(double));
  d->z = calloc((size_t)m->nhist + 1, sizeof(double));
  d->sst = calloc((size_t)m->nshape + 1, sizeof(cscShapeState));
  d->Gs = calloc(22 * (n + 6), sizeof(double));
  d->y = calloc(n, sizeof(double));
  d->rl = calloc(n, sizeof(double));
  d->Vp = calloc(np * 6, sizeof(double));
  d->Vs = calloc(np * 6, sizeof(double));
  d->Fc = calloc(np * 6, sizeof(double));
  d->kst = calloc((size_t)np * CSR_STRAIN_KST, sizeof(double));
  d->ks = calloc(np * 16, sizeof(double));
  d->ks_q = calloc(n, sizeof(double));
  d->Ab = calloc(np * 6, sizeof(double));
  d->Rs_save = calloc(np * 9, sizeof(double));
  d->xs_save = calloc(np * 3, sizeof(double));
  d->q0 = calloc(n, sizeof(double));
  d->eta0 = calloc(n, sizeof(double));
  d->WMll = calloc(n * n, sizeof(double));
  d->WMlb = calloc(n * 6, sizeof(double));
  d->rMl = calloc(n, sizeof(double));
  d->du = calloc(n + 6, sizeof(double));
  d->fcA = calloc(3 * (n + 6), sizeof(double));
  d->qm1 = calloc(n, sizeof(double));
  d->etam1 = calloc(n, sizeof(double));
  d->Wu = calloc(n * n, sizeof(double));
  d->fl = calloc(n, sizeof(double));
  d->R0 = calloc(np * 9, sizeof(double));
  d->x0 = calloc(np * 3, sizeof(double));
  d->J0 = calloc(np * 6 * n, sizeof(double));
  d->qf = calloc(n, sizeof(double));
  d->Mu = calloc(n + 6, sizeof(double));
  int nslot_all = 1;
  for (int s = 0; m->soft && s < m->nshape; s++) {
    int first, count;
    csc_softShapeSlots(m->soft, s, &first, &count);
    nslot_all = first + count > nslot_all ? first + count : nslot_all;
  }
  d->csig = calloc((size_t)nslot_all, 1);
  d->ghost = calloc((size_t)m->nshape + 1, sizeof(csrStrainGhost));
  d->memo = calloc((size_t)m->nshape + 1, sizeof(csrStrainLoadMemo));
  d->memo_z = calloc((size_t)m->nhist + 1, sizeof(double));
  d->memo_slot = calloc((size_t)nslot_all, sizeof(cscSlotInfo));
  d->ct = calloc((size_t)m->nshape + 1, sizeof(int));
  d->cS = calloc(((size_t)m->nshape + 1) * 6 * (n + 6), sizeof(double));
  d->cA = calloc(((size_t)m->nshape + 1) * 36, sizeof(double));
  d->artLU = calloc(n * CSR_STRAIN_MAX_PIECE_DOF + 1, sizeof(double));
  d->artPiv = calloc(n + 1, sizeof(int));
  d->artZsn = calloc(n * 6 + 1, sizeof(double));
  d->artY = calloc(n * 6 + 1, sizeof(double));
  d->artL = calloc(n * 6 + 1, sizeof(double));
  d->artA = calloc((size_t)m->npiece * 36 + 1, sizeof(double));
  const size_t mw = (size_t)12 * m->nshape + 1; /* the Woodbury update's rank bound */
  d->wS = calloc(((size_t)m->nshape + 1) * 6 * (n + 6), sizeof(double));
  d->wA = calloc(((size_t)m->nshape + 1) * 36, sizeof(double));
  d->wbQ = calloc(mw * n, sizeof(double));
  d->wbK = calloc(mw * mw + 12 * mw, sizeof(double));
  d->wbPiv = calloc(mw, sizeof(int));
  d->wbX = calloc((size_t)n * 6 + 1, sizeof(double));
  if (!d->Wu || !d->fl || !d->csig || !d->ghost || !d->memo || !d->memo_z || !d->memo_slot ||
      !d->q || !d->eta || !d->vp_eta || !d->Kd || !d->b || !d->R || !d->x || !d->J || !d->Q || !d->Qp || !d->Qm ||
      !d->A || !d->dq || !d->q_save || !d->q_start || !d->K1 || !d->b1 || !d->K0 || !d->b0 || !d->piv ||
      !d->Wll || !d->X || !d->Wlb || !d->Wbl || !d->z || !d->sst || !d->Gs || !d->y || !d->rl || !d->Vp || !d->Vs || !d->Fc || !d->kst || !d->ks || !d->ks_q || !d->Ab ||
      !d->q0 || !d->eta0 || !d->WMll || !d->WMlb || !d->rMl || !d->du || !d->fcA || !d->Rs_save || !d->xs_save ||
      !d->qm1 || !d->etam1 || !d->R0 || !d->x0 || !d->J0 || !d->qf || !d->Mu || !d->ct ||
      !d->cS || !d->cA || !d->artLU || !d->artPiv || !d->artZsn || !d->artY || !d->artL ||
      !d->artA || !d->wS || !d->wA || !d->wbQ || !d->wbK || !d->wbPiv || !d->wbX) {
    csr_strainDataDestroy(d);
    cs_errorSet(err, CS_ERR_MEMORY, "strain: out of memory");
    return NULL;
  }
  csr_strainReset(m, d);
  return d;
}


void csr_strainWorld_(const csrStrainData* d, const double Rr[9], const double xr[3],
                      double R[9], double x[3]) {
  double t[3];
  csu_mulMat3(R, d->Rb, Rr);
  csu_mulMatVec3(t, d->Rb, xr);
  csu_add3(x, d->xb, t);
}


void csr_strainReset(const csrStrainModel* m, csrStrainData* d) {
  memset(d->q, 0, (size_t)m->n * sizeof(double));
  memset(d->eta, 0, (size_t)m->n * sizeof(double));
  memcpy(d->Rb, m->frame, sizeof d->Rb);
  memcpy(d->xb, m->hip, sizeof d->xb);
  memset(d->Vb, 0, sizeof d->Vb);
  memset(&d->wbase, 0, sizeof d->wbase);
  memset(d->Dm, 0, sizeof d->Dm);
  memset(d->qm1, 0, (size_t)m->n * sizeof(double));
  memset(d->etam1, 0, (size_t)m->n * sizeof(double));
  memset(d->Vbm1, 0, sizeof d->Vbm1);
  memset(d->Xm1, 0, sizeof d->Xm1);
  memset(d->Dm1, 0, sizeof d->Dm1);
  d->kf = 0; /* a kept factor is the last state's */
  d->hprev = 0;
  memset(d->tipd_f, 0, sizeof d->tipd_f);
  if (m->soft) {
    csc_softStateInit(m->soft, d->z);
  }
  memset(d->tipd_m, 0, sizeof d->tipd_m);
  d->h = 0;
  memset(d->p, 0, sizeof d->p);
  memset(d->tip_f, 0, sizeof d->tip_f);
  memset(d->tip_m, 0, sizeof d->tip_m);
  d->grav = 0;
  /* the vented pressures' rest strains: a calibration may give a vented segment a stretch */
  char msg[8];
  if (csr_strainActuation_(m, d, d->p, d->Kd, d->b, msg, sizeof msg) != 0) {
    /* a calibration that refuses zero pressures leaves the section's stiffness, no strain */
    for (int k = 0; k < m->npiece; k++) {
      const csrRodSection* S = &m->piece[k].section;
      const double C[6] = {S->EI[0], S->EI[1], S->GJ, S->GA[0], S->GA[1], S->EA};
      for (int j = m->dof0[k]; j < m->dof0[k] + m->ndof[k]; j++) {
        d->Kd[j] = C[m->dcomp[j]] * m->piece[k].length / (2 * m->dorder[j] + 1);
        d->b[j] = 0;
      }
    }
  }
  d->kin_valid = 0;
}


void csr_strainGetQ(const csrStrainModel* m, const csrStrainData* d, double* q) {
  memcpy(q, d->q, (size_t)m->n * sizeof(double));
}


int csr_strainSetQ(const csrStrainModel* m, csrStrainData* d, const double* q) {
  for (int j = 0; j < m->n; j++) {
    if (!isfinite(q[j])) {
      return -1;
    }
  }
  memcpy(d->q, q, (size_t)m->n * sizeof(double));
  d->kin_valid = 0;
  return 0;
}


int csr_strainActuate(const csrStrainModel* m, csrStrainData* d, const double p[12],
                      csError* err) {
  /* the same pressures give the same strains and sections: the calibration's section
   * integration is the step's largest single cost when it runs every step (a held stance) */
  if (memcmp(p, d->p, sizeof d->p) == 0) {
    return 0;
  }
  char msg[256] = "";
  int rc = csr_strainActuation_(m, d, p, d->K1, d->b1, msg, sizeof msg);
  if (rc != 0) {
    cs_errorSet(err, rc == CSR_MAP_OUT_OF_RANGE ? CS_ERR_RANGE : CS_ERR_SOLVER, "strain: %s",
                msg);
    return rc;
  }
  memcpy(d->Kd, d->K1, (size_t)m->n * sizeof(double));
  memcpy(d->b, d->b1, (size_t)m->n * sizeof(double));
  memcpy(d->p, p, sizeof d->p);
  return 0;
}


/* ---- queries -------------------------------------------------------------------------------- */

static void ensureKinematics(const csrStrainModel* m, csrStrainData* d, int want_J) {
  if (d->kin_valid < (want_J ? 2 : 1)) {
    csr_strainKinematics_(m, d, want_J);
  }
}


void csr_strainPose(const csrStrainModel* m, csrStrainData* d, double X, double x[3],
                    double R[9]) {
  ensureKinematics(m, d, 0);
  X = X < 0 ? 0 : (X > m->L ? m->L : X);
  int k = 0;
  while (k < m->npiece - 1 && X > m->X0[k + 1]) {
    k++;
  }
  double s = X - m->X0[k], h = m->piece[k].length / m->nsub[k];
  int i = (int)(s / h);
  i = i < 0 ? 0 : (i >= m->nsub[k] ? m->nsub[k] - 1 : i);
  double ds = s - i * h, Om[6] = {0, 0, 0, 0, 0, ds};
  if (!m->rigid[k]) {
    csr_strainMagnus_(m, d->q, k, i * h, ds, Om, NULL);
  }
  int p = m->pt0[k] + 2 * i;
  double Re[9], pe[3], t[3];
  csr_strainExp_(Om, Re, pe);
  double Rr[9], xr[3];
  csu_mulMat3(Rr, d->R + 9 * p, Re);
  csu_mulMatVec3(t, d->R + 9 * p, pe);
  csu_add3(xr, d->x + 3 * p, t);
  csr_strainWorld_(d, Rr, xr, R, x);
}


void csr_strainCenterline(const csrStrainModel* m, csrStrainData* d, int k, double* out) {
  double R[9];
  for (int i = 0; i < k; i++) {
    csr_strainPose(m, d, m->L * i / (k - 1), out + 3 * i, R);
  }
}


void csr_strainTipJacobian(const csrStrainModel* m, csrStrainData* d, double* J) {
  ensureKinematics(m, d, 1);
  memcpy(J, d->J + (size_t)(m->np - 1) * 6 * m->n, (size_t)6 * m->n * sizeof(double));
}


void csr_strainStiffness(const csrStrainModel* m, const csrStrainData* d, double* Kdiag) {
  memcpy(Kdiag, d->Kd, (size_t)m->n * sizeof(double));
}


/* Q = b - K q + J_tipᵀ F_tip + gfac Σ weights (d's K, b; tip load f, mo world): the point
 * wrenches projected by the adjoint recursion (csr_strainProject_: the poses alone, no
 * Jacobians; the static solver's differences call this 2n + 1 times per Newton iteration) */
static void forceWith(const csrStrainModel* m, csrStrainData* d, const double f[3],
                      const double mo[3], double gfac, double* Q) {
  ensureKinematics(m, d, 0);
  const int n = m->n;
  double* F = d->Vs; /* (np x 6) scratch: body wrenches at the points */
  memset(F, 0, (size_t)6 * m->np * sizeof(double));
  /* the tip wrench in the tip's body frame, (m; f) */
  const int tp = m->np - 1;
  double Rw[9], xw[3];
  csr_strainWorld_(d, d->R + 9 * tp, d->x + 3 * tp, Rw, xw);
  csu_mulMatTVec3(F + 6 * tp, Rw, mo);
  csu_mulMatTVec3(F + 6 * tp + 3, Rw, f);
  if (gfac != 0 && csu_dot3(m->gravity, m->gravity) != 0) {
    /* weights ρA g at the Simpson points, in each point's body frame */
    double gh[3];
    csu_mulMatTVec3(gh, d->Rb, m->gravity); /* in the hip frame */
    for (int p = 0; p < m->np; p++) {
      double gb[3];
      csu_mulMatTVec3(gb, d->R + 9 * p, gh);
      for (int r = 0; r < 3; r++) {
        F[6 * p + 3 + r] += gfac * m->Ms[6 * p + 3 + r] * gb[r];
      }
    }
  }
  double Fb[6];
  csr_strainProject_(m, d->q, F, Fb, Q);
  for (int j = 0; j < n; j++) {
    Q[j] += d->b[j] - d->Kd[j] * d->q[j];
  }
}


void csr_strainForce(const csrStrainModel* m, csrStrainData* d, const double tip_force[3],
                     const double tip_moment[3], int gravity, double* Q) {
  forceWith(m, d, tip_force, tip_moment, gravity ? 1.0 : 0.0, Q);
}


void csr_strainMassMatrix(const csrStrainModel* m, csrStrainData* d, double* M) {
  ensureKinematics(m, d, 1);
  const int n = m->n;
  memset(M, 0, (size_t)n * n * sizeof(double));
  for (int p = 0; p < m->np; p++) {
    const double* Jp = d->J + (size_t)p * 6 * n;
    for (int r = 0; r < 6; r++) {
      double w = m->Ms[6 * p + r];
      const double* row = Jp + r * n;
      for (int i = 0; i < n; i++) {
        double wi = w * row[i];
        if (wi == 0) {
          continue;
        }
        for (int j = 0; j < n; j++) {
          M[i * n + j] += wi * row[j];
        }
      }
    }
  }
}


/* ---- statics -------------------------------------------------------------------------------- */

/* Newton at fixed loads (d's K, b; tip f, mo; weight factor g) from d->q: 0 converged (q
 * updated), 1 not (q undefined) */
static int newton(const csrStrainModel* m, csrStrainData* d, const double f[3],
                  const double mo[3], double g, csrRodStaticInfo* info) {
  const int n = m->n;
  for (int it = 0; it < m->par.static_max_iter; it++) {
    forceWith(m, d, f, mo, g, d->Q);
    /* A = -∂Q/∂q by central differences */
    for (int j = 0; j < n; j++) {
      double qj = d->q[j], del = CSR_STRAIN_FD_REL / m->dscale[j];
      d->q[j] = qj + del;
      d->kin_valid = 0;
      forceWith(m, d, f, mo, g, d->Qp);
      d->q[j] = qj - del;
      d->kin_valid = 0;
      forceWith(m, d, f, mo, g, d->Qm);
      d->q[j] = qj;
      for (int i = 0; i < n; i++) {
        d->A[i * n + j] = -(d->Qp[i] - d->Qm[i]) / (2 * del);
      }
    }
    d->kin_valid = 0;
    if (csr_strainLuFactor_(d->A, n, d->piv)) {
      return 1;
    }
    memcpy(d->dq, d->Q, (size_t)n * sizeof(double));
    csr_strainLuSolve_(d->A, n, d->piv, d->dq);
    double upd = 0;
    for (int j = 0; j < n; j++) {
      double u = fabs(d->dq[j]) * m->dscale[j];
      upd = isfinite(u) ? fmax(upd, u) : INFINITY;
      d->q[j] += d->dq[j];
    }
    d->kin_valid = 0;
    if (info) {
      info->newton_iters++;
      info->residual = upd;
    }
    if (!(upd <= CSR_STRAIN_MAX_UPDATE)) {
      return 1;
    }
    if (upd <= m->par.static_tol) {
      return 0;
    }
  }
  return 1;
}


csStatus csr_strainStatic(const csrStrainModel* m, csrStrainData* d, const csrRodStaticLoad* load,
                          csrRodStaticInfo* info, csError* err) {
  if (!m || !d || !load) {
    return cs_errorSet(err, CS_ERR_ARG, "strain static: NULL argument");
  }
  for (int k = 0; k < 12; k++) {
    if (!isfinite(load->p[k])) {
      return cs_errorSet(err, CS_ERR_ARG, "strain static: pressures must be finite");
    }
  }
  for (int k = 0; k < 3; k++) {
    if (!isfinite(load->tip_force[k]) || !isfinite(load->tip_moment[k])) {
      return cs_errorSet(err, CS_ERR_ARG, "strain static: the tip load must be finite");
    }
  }
  csrRodStaticInfo local;
  memset(&local, 0, sizeof local);
  const int n = m->n;
  /* the target's rest strains and stiffness (K1, b1); the start's (K0, b0) */
  char msg[256] = "";
  int rc = csr_strainActuation_(m, d, load->p, d->K1, d->b1, msg, sizeof msg);
  if (rc != 0) {
    return cs_errorSet(err, rc == CSR_MAP_OUT_OF_RANGE ? CS_ERR_RANGE : CS_ERR_SOLVER,
                       "strain static: %s", msg);
  }
  memcpy(d->K0, d->Kd, (size_t)n * sizeof(double));
  memcpy(d->b0, d->b, (size_t)n * sizeof(double));
  double* q_start = d->q_start;
  memcpy(q_start, d->q, (size_t)n * sizeof(double));
  const double g0 = d->grav ? 1.0 : 0.0, g1 = load->gravity ? 1.0 : 0.0;
  double lam = 0, dl = 1;
  while (lam < 1) {
    double l1 = fmin(1.0, lam + dl), f[3], mo[3];
    for (int j = 0; j < n; j++) {
      d->Kd[j] = d->K0[j] + l1 * (d->K1[j] - d->K0[j]);
      d->b[j] = d->b0[j] + l1 * (d->b1[j] - d->b0[j]);
    }
    for (int k = 0; k < 3; k++) {
      f[k] = d->tip_f[k] + l1 * (load->tip_force[k] - d->tip_f[k]);
      mo[k] = d->tip_m[k] + l1 * (load->tip_moment[k] - d->tip_m[k]);
    }
    memcpy(d->q_save, d->q, (size_t)n * sizeof(double));
    if (newton(m, d, f, mo, g0 + l1 * (g1 - g0), &local) == 0) {
      lam = l1;
      local.load_steps++;
      dl = fmin(1.0, 2 * dl);
      continue;
    }
    memcpy(d->q, d->q_save, (size_t)n * sizeof(double));
    d->kin_valid = 0;
    dl *= 0.5;
    local.cutbacks++;
    if (dl < CSR_STRAIN_MIN_DLAM) {
      /* nothing changes: the start's state and actuation */
      memcpy(d->q, q_start, (size_t)n * sizeof(double));
      memcpy(d->Kd, d->K0, (size_t)n * sizeof(double));
      memcpy(d->b, d->b0, (size_t)n * sizeof(double));
      d->kin_valid = 0;
      if (info) {
        *info = local;
      }
      return cs_errorSet(err, CS_ERR_SOLVER, "strain static: Newton failed at load fraction "
                         "%.4g of the new load", lam);
    }
  }
  memcpy(d->p, load->p, sizeof d->p);
  memcpy(d->tip_f, load->tip_force, sizeof d->tip_f);
  memcpy(d->tip_m, load->tip_moment, sizeof d->tip_m);
  d->grav = load->gravity ? 1 : 0;
  if (info) {
    *info = local;
  }
  return CS_OK;
}
