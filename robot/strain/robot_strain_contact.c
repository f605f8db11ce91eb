/* robot_strain_contact.c: the strain leg's contact with the terrain inside its linearly
 * implicit step (robot_strain.h): contact_soft.h's law on the leg's shapes, its force and its
 * linearisation, assembled into the step (the shapes themselves, their law through the memo
 * and their tangent: robot_strain_shape.c).
 *
 * Shapes: a capsule on the chord of every Magnus sub-interval (its two end points) but the
 * last one of the leg, which is the foot's: the sole, a square of half side a at the tip in the
 * tip's frame (its d3 the sole's outward normal), as the nodal rod has capsules on its elements
 * and the foot box on the last (its default 4 elements per segment and this leg's 4
 * sub-intervals give the same 12.5 mm foot element).
 *
 * Friction: the law's step mode: a stick anchor per slot fixed within a step, so that within
 * the step the contact force is a smooth function of the shapes' poses and velocities (it
 * saturates smoothly at mu N), return-mapped after the step (csc_softUpdateShape): a stance
 * foot holds elastically with no creep, a pushed foot slides at the Coulomb force.
 *
 * Linearisation: per shape in contact, the load L (foot: force at the sole centre and couple;
 * capsule: the forces on its two ends) against the shape's world coordinates y (foot: sole
 * centre and a small rotation; capsule: its two ends) and their rates, K_y = ∂L/∂y and
 * C_y = ∂L/∂ẏ: the foot's from the law's own derivatives (csc_softShapeJacobian), the
 * capsules' by forward differences (12 evaluations of one shape); y moves with u through
 * S = ∂ẏ/∂u (the points' G). In the step, y1 = y0 + h S u1 and ẏ1 = S u1. The load is
 * linearised about the predicted end y_p = y0 + h S u0 (the shape moved on at its start
 * velocity), not about y0: a sliding foot moves millimetres in a step against a stick range
 * of microns, and only at y_p is the bristle where the step will take it (saturated, its
 * stiffness along the slip gone); about y0 the stick stiffness N/delta_t times the step's
 * slip overshoots (measured: a foot pushed at 2 mu N went backwards). So
 *   L1 ≈ L(y_p) + K_y (y0 + h S u0 - y_p) + (h K_y + C_y) S Δu, so
 *   h r += h Sᵀ (L(y_p) + K_y (y0 + h S u0 - y_p)),   W -= h Sᵀ (h K_y + C_y) S.
 * Iterates (csr_strainIterate): the kinematics is at the iterate's end of the step (q0 + h η1,
 * the base where the last csr_strainUpdate put it), so the load is linearised there, without a
 * prediction: L1 ≈ L_e + (h K_y + C_y) S (Δu - Δu_it); converged, the step's contact force is
 * the law's at the step's end (backward Euler), whatever the contact set did within it.
 * The prediction is tangential only (the slip along the surface and the turn about its normal):
 * predicting the normal motion too overshoots the stiff normal law (measured: a foot pressed
 * 0.5 mm bounced to 15 N); the normal part stays linearised at y0 as it was. So
 * the contact's stiffness and damping implicit in the step, the couple of a capsule's friction
 * offsets explicit.
 *
 * Active set (csrStrainParams.active_set, backward Euler): a stance foot rests ~0.6 µm deep in
 * a law far stiffer than the step's motion, so a first solve that lifts it by a fraction of a
 * micrometre left the next iterate without contact (its linearisation zero: the robot's free
 * fall for the step, then Newton walking back down the stiff law; docs/notes/strain_leg.md,
 * "Newton's contraction"). So every linearisation records each touching shape's y, L, K_y,
 * C_y (csrStrainGhost), and at a later iterate of the step a shape that touched there and is
 * out of contact is held by its ghost, the affine L + K_y Δy + C_y Δẏ (it may pull), in the
 * residual and the matrix. Converged passes drop the ghosts they held (csr_strainRelease) and
 * go on, a dropped shape never held again in the step: the step ends on the law alone. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core_math.h"
#include "robot_strain_internal.h"

void csr_strainPointG_(const csrStrainModel* m, const csrStrainData* d, int p, double* G) {
  const int n = m->n, nu = 6 + n;
  const double* J = d->J + (size_t)p * 6 * n;
  double A[36];
  csr_strainAdInv_(d->R + 9 * p, d->x + 3 * p, A);
  for (int r = 0; r < 6; r++) {
    memcpy(G + r * nu, A + 6 * r, 6 * sizeof(double));
    memcpy(G + r * nu + 6, J + r * n, (size_t)n * sizeof(double));
  }
}


/* rows of S: world velocity (rows 0..2) of point p's translation (rot = 0) or rotation (1) */
static void worldRows(const csrStrainModel* m, const csrStrainData* d, int p, int rot,
                      const double* G, double* S3) {
  const int nu = 6 + m->n;
  double Rw[9], xw[3];
  csr_strainWorld_(d, d->R + 9 * p, d->x + 3 * p, Rw, xw);
  for (int r = 0; r < 3; r++) {
    for (int k = 0; k < nu; k++) {
      double s = 0;
      for (int i = 0; i < 3; i++) {
        s += Rw[3 * r + i] * G[(i + 3 * (1 - rot)) * nu + k];
      }
      S3[r * nu + k] = s;
    }
  }
}


/* The friction's secant from the anchors (Kačanov's iteration for a saturating law) on the
 * foot's slots in a Newton iterate: a slot past the saturation (s >= 2 - u_elastic, s = |g| /
 * (mu delta_t) of the damped deflection g = z_r + tau_t w, contact_soft_internal.h
 * csc_softFrictionStep, where m(s) = 1 and m'(s) = 0) has no stiffness along its slip, so a
 * Newton pass from there does not know where the stick is and the passes cycle between slip
 * either way. Along ĝ its stiffness becomes the secant to g = 0, N m(s) / (s delta_t) =
 * mu N / |g| (the transverse one already is), against g's change in the step: h + tau_t per
 * unit of the end's slip rate (g = z_r + h ẏ1 + tau_t ẏ1 along the surface). Linearised
 * there, the force vanishes where the damped deflection does, so the next pass lands between
 * slip and stick. Only the iteration matrix changes:
 * converged, the step is the law's. Where a foot slides on, the secant converges linearly
 * where the tangent would quadratically; limiting it to a step's first 3 iterates was tried
 * and over the 9 s flat road at 5 ms halved more steps and took more passes in all (numbers in
 * docs/notes/strain_leg.md). ΔA = -(h + tau_t) Σ k_i [I; r_i^] û ûᵀ [I, -r_i^] on the
 * foot's (v, ω) (r_i from the sole centre to the slot's point, û = ĝ, opposite the force). */
/* (csrStrainParams.friction_tangent 1: no secant, the law's consistent tangent, which K_y's
 * differences already are: in stick the anchor spring N/delta_t, in slip the cone's
 * projection derivative (I - û ûᵀ) mu N / |s| with the normal coupling mu û ∂N/∂y; measured
 * worse: the flat road at 5 ms stops at 0.93 s, a foot's slots cycling across the saturation's
 * onset u = 1..1.6, docs/notes/strain_leg.md "The friction's tangent") */
static void anchorSecant(const csrStrainModel* m, double h, const cscShapeState* st,
                         const cscSlotInfo* slot, int nslot, double A[36]) {
  const cscSoftParams* p = csc_softParams(m->soft);
  if (!(p->mu > 0) || m->par.friction_tangent == 1) {
    return;
  }
  for (int i = 0; i < nslot; i++) {
    const cscSlotInfo* si = slot + i;
    double fn = csu_norm3(si->ft);
    if (!(si->depth > 0) || si->ratio < 2 - p->u_elastic || !(fn > 0)) {
      continue;
    }
    double k = si->N / (p->delta_t * si->ratio), uh[3], r[3], c[3];
    csu_scale3(uh, si->ft, -1.0 / fn);
    csu_sub3(r, si->point, st->x0);
    /* ûᵀ [I, -r^]: the slot's slip rate along û from (v, ω): û·v + (r × û)·ω */
    csu_cross3(c, r, uh);
    double row[6] = {uh[0], uh[1], uh[2], c[0], c[1], c[2]};
    /* [I; r^] û: the force along û and its couple about the sole centre */
    double col[6] = {uh[0], uh[1], uh[2], c[0], c[1], c[2]};
    for (int a = 0; a < 6; a++) {
      for (int b = 0; b < 6; b++) {
        A[6 * a + b] -= (h + p->tau_t) * k * col[a] * row[b];
      }
    }
  }
}


/* 1 when shape s's load (L, couple) is not zero: then counted in d->ntouch and its force added
 * to d->fcw (world) */
static int countTouch(const csrStrainModel* m, csrStrainData* d, int s, const double L[6],
                      const double couple[3]) {
  int touching = couple[0] != 0 || couple[1] != 0 || couple[2] != 0;
  for (int i = 0; i < 6; i++) {
    touching |= L[i] != 0;
  }
  if (!touching) {
    return 0;
  }
  d->ntouch++;
  csu_add3(d->fcw, d->fcw, L);
  if (s != m->nshape - 1) {
    csu_add3(d->fcw, d->fcw, L + 3);
  }
  return 1;
}


/* the contact's state signature of shape s's slots: bit 0 touching, bit 1 past the friction's
 * saturation (s >= 2 - u_elastic: the Newton iterates take the anchors' secant there) */
static unsigned char slotSig(const cscSoftParams* p, const cscSlotInfo* si) {
  unsigned char c = si->depth > 0;
  if (c && p->mu > 0 && si->ratio >= 2 - p->u_elastic) {
    c |= 2;
  }
  return c;
}


/* Shape s's ghost load at its state st (Active set, above): its last linearisation's
 * affine load L + K_y (y - y_lin) + C_y (ẏ - ẏ_lin), in the linearisation's coordinates (the
 * foot's rotation as the world rotation vector of R R_linᵀ, as `perturb` turns it) */
static void ghostLoad(const csrStrainModel* m, const csrStrainGhost* g, int s,
                      const cscShapeState* st, double L[6]) {
  double dy[6], dv[6];
  csu_sub3(dy, st->x0, g->y.x0);
  csu_sub3(dv, st->v0, g->y.v0);
  if (s == m->nshape - 1) {
    double Rt[9], dR[9];
    csu_transpose3(Rt, g->y.R);
    csu_mulMat3(dR, st->R, Rt);
    csu_mat3ToRotVec(dy + 3, dR);
    csu_sub3(dv + 3, st->w, g->y.w);
  } else {
    csu_sub3(dy + 3, st->x1, g->y.x1);
    csu_sub3(dv + 3, st->v1, g->y.v1);
  }
  for (int r = 0; r < 6; r++) {
    double t = g->L[r];
    for (int c = 0; c < 6; c++) {
      t += g->K[6 * r + c] * dy[c] + g->C[6 * r + c] * dv[c];
    }
    L[r] = t;
  }
}


/* the active set's ghosts are backward Euler's: with BDF2's whole residual at every iterate
 * they stopped the flat road at 0.84 s at 5 ms (a step not converged at 1/16; without them it
 * runs: docs/notes/strain_leg.md, "Active set") */
static int activeSet(const csrStrainModel* m) {
  return m->par.active_set && m->par.step_order == 1;
}


/* the active set acting in this linearisation: backward Euler's always; BDF2's until its
 * first iterate, on the start's records (csr_strainGhostStart_) */
static int activeNow(const csrStrainModel* m, const csrStrainData* d) {
  return activeSet(m) || (m->par.active_set && d->ghost_hold);
}


/* 1 when the law's load (L, couple) of a shape is zero */
static int loadZero(const double L[6], const double couple[3]) {
  int z = couple[0] == 0 && couple[1] == 0 && couple[2] == 0;
  for (int i = 0; i < 6; i++) {
    z &= L[i] == 0;
  }
  return z;
}


void csr_strainGhostReset_(const csrStrainModel* m, csrStrainData* d) {
  /* the flags alone: a record's y, L, K_y, C_y are read only where its state is 1, and
   * written when it becomes 1 (zeroing the ~10 kB of records cost 1 % of a step) */
  for (int s = 0; m->soft && s < m->nshape; s++) {
    d->ghost[s].state = 0;
    d->ghost[s].on = 0;
  }
  d->nghost = 0;
  d->fresh = 0;
  d->ghost_hold = 0;
}


/* BDF2's first iterate (the driver's, at the support's unchanged twist) evaluates the law at
 * q̄ + h_e η0 with the hips extrapolated at their start twist: on a robot whose support
 * accelerates, its stance feet land ~1 µm off their start, out of a law they rest 0.6 µm deep
 * in (the first solve saw the robot in free fall: 2.0e-2 mm moves against backward Euler's
 * 1.2e-3, 7 passes a standing step against 3). So until that iterate every shape that
 * touches at the step's start is held by its start's linearisation (the affine load, touching
 * or not there), backward Euler's linear model about the last converged state; the passes
 * after it evaluate the law (docs/notes/strain_leg.md "BDF2's passes"). */
int csr_strainGhostStart_(const csrStrainModel* m, csrStrainData* d) {
  if (!m->soft || !m->par.active_set) {
    return 0;
  }
  for (int s = 0; s < m->nshape; s++) {
    csrStrainGhost* g = d->ghost + s;
    cscShapeState st;
    csr_strainShapeState_(m, d, s, &st);
    double L0[6], couple[3];
    int rc = csr_strainShapeLoad_(m, d, s, &st, L0, couple, NULL, NULL);
    if (rc != 0) {
      return rc > 0 ? rc : 1;
    }
    if (loadZero(L0, couple)) {
      continue;
    }
    csr_strainShapeTangent_(m, d, s, &st, L0, g->K, g->C);
    g->y = st;
    memcpy(g->L, L0, sizeof g->L);
    g->state = 1;
  }
  d->ghost_hold = 1;
  return 0;
}


int csr_strainGhostRelease_(const csrStrainModel* m, csrStrainData* d) {
  int n = 0;
  for (int s = 0; m->soft && s < m->nshape; s++) {
    csrStrainGhost* g = d->ghost + s;
    if (g->on) {
      g->on = 0;
      g->state = 2;
      n++;
    }
  }
  d->nghost = 0;
  return n;
}


int csr_strainContactAssemble_(const csrStrainModel* m, csrStrainData* d, double h,
                               const double* du, double* Wbb, double* rb, double* G) {
  if (!m->soft) {
    return 0;
  }
  const int n = m->n, nu = 6 + n;
  /* G (21 x nu scratch) holds 2 points' G (12 x nu), S (6 x nu), a couple's rows (3 x nu) */
  double* Ga = G;
  double* Gb = G + 6 * nu;
  double* S = G + 12 * nu;
  memset(d->fcw, 0, sizeof d->fcw);
  d->ntouch = 0;
  d->nghost = 0;
  const int active = activeNow(m, d);
  if (!du) {
    /* the start's linear model's contact force, for the one-pass carry (its end) */
    memset(d->fcl, 0, sizeof d->fcl);
    memset(d->fcA, 0, (size_t)3 * nu * sizeof(double));
    d->fcl_ok = 1;
  }
  for (int s = 0; s < m->nshape; s++) {
    csrStrainGhost* g = d->ghost + s;
    g->on = 0;
    cscShapeState st;
    csr_strainShapeState_(m, d, s, &st);
    /* the contact normal (mean over the shape's touching slots) */
    int first, nslot;
    csc_softShapeSlots(m->soft, s, &first, &nslot);
    cscSlotInfo slot[CSR_STRAIN_MAX_SHAPE_HIST];
    double L0[6], couple[3], nrm[3] = {0, 0, 0};
    int rc = csr_strainShapeLoad_(m, d, s, &st, L0, couple,
                                  nslot <= CSR_STRAIN_MAX_SHAPE_HIST ? slot : NULL, NULL);
    if (rc != 0) {
      return rc > 0 ? rc : 1;
    }
    for (int i = 0; i < nslot && nslot <= CSR_STRAIN_MAX_SHAPE_HIST; i++) {
      if (slot[i].depth > 0) {
        csu_add3(nrm, nrm, slot[i].normal);
      }
    }
    /* the rest of the step's motion the linearisation carries (y0 + h S u0 - y_p) is formed
     * below for a shape that touches: no other reads it. The start's poses are kept for it
     * (the predicted slide moves st), the slide's velocities too */
    int foot = s == m->nshape - 1;
    double x0s[3], x1s[3], Rs[9], vt0[3], vt1[3], phi[3];
    memcpy(x0s, st.x0, sizeof x0s);
    memcpy(x1s, st.x1, sizeof x1s);
    memcpy(Rs, st.R, sizeof Rs);
    int slid = 0;
    if (!du && csu_normalize3(nrm) > 0) {
      /* the predicted end of the step: the shape slid on along the surface at its start
       * velocity (and turned about the normal); its normal motion is left to the step, whose
       * contact stiffness at y0 is what holds it (predicting it too overshoots the stiff
       * normal law: measured, a pressed foot bounced to 15 N) */
      slid = 1;
      csu_addScl3(vt0, st.v0, nrm, -csu_dot3(st.v0, nrm));
      csu_addScl3(st.x0, st.x0, vt0, h);
      csu_addScl3(vt1, st.v1, nrm, -csu_dot3(st.v1, nrm));
      csu_addScl3(st.x1, st.x1, vt1, h);
      if (foot) {
        double dR[9], Rn[9];
        csu_scale3(phi, nrm, h * csu_dot3(st.w, nrm));
        csu_rotVecToMat3(dR, phi);
        csu_mulMat3(Rn, dR, st.R);
        memcpy(st.R, Rn, sizeof Rn);
      }
      rc = csr_strainShapeLoad_(m, d, s, &st, L0, couple,
                                nslot <= CSR_STRAIN_MAX_SHAPE_HIST ? slot : NULL, NULL);
    }
    if (rc != 0) {
      return rc > 0 ? rc : 1;
    }
    /* the slots' state at the linearisation point: the iterates keep this W while it holds */
    for (int i = 0; i < nslot && nslot <= CSR_STRAIN_MAX_SHAPE_HIST; i++) {
      d->csig[first + i] = slotSig(csc_softParams(m->soft), slot + i);
    }
    /* an iterate: a shape out of contact that touched at its last linearisation of this step
     * is held by its ghost, linearised as there; until BDF2's first iterate every shape that
     * touched at the start is (csr_strainGhostStart_) */
    int ghost = 0;
    if (du && active && g->state == 1 && (loadZero(L0, couple) || d->ghost_hold)) {
      ghostLoad(m, g, s, &st, L0);
      memset(couple, 0, sizeof couple);
      ghost = 1;
    }
    if (!countTouch(m, d, s, L0, couple)) {
      continue;
    }
    if (ghost) {
      g->on = 1;
      d->nghost++;
    }
    /* the start's blocks, left uncleared while no shape touched (condenseStart) */
    csr_strainClearStart_(m, d);
    /* the rest of the motion, h S u0 at the start's velocities (each term as the slide's
     * below in the same order as before this was deferred: the same bits) */
    double rest[6];
    for (int c = 0; c < 3; c++) {
      rest[c] = h * st.v0[c];
      rest[3 + c] = h * (foot ? st.w[c] : st.v1[c]);
    }
    if (!du && d->pred) {
      /* the shape's predicted end pose (robot_strain_dyn.c csr_strainPredictShapes_, formed
       * at the first shape that touches): its motion over the step at the start's velocities
       * to second order, y(q0 + h η0) - y0 in place of h S u0 */
      if (d->pred == 2) {
        csr_strainPredictShapes_(m, d, h);
      }
      const cscShapeState* sp = d->sst + s;
      csu_sub3(rest, sp->x0, x0s);
      if (foot) {
        double Rt[9], dR[9];
        csu_transpose3(Rt, Rs);
        csu_mulMat3(dR, sp->R, Rt);
        csu_mat3ToRotVec(rest + 3, dR);
      } else {
        csu_sub3(rest + 3, sp->x1, x1s);
      }
    }
    if (slid) {
      csu_addScl3(rest, rest, vt0, -h);
      if (!foot) {
        csu_addScl3(rest + 3, rest + 3, vt1, -h);
      } else {
        csu_addScl3(rest + 3, rest + 3, phi, -1.0);
      }
    }
    int a = m->shape_a[s], b = m->shape_b[s];
    csr_strainPointG_(m, d, a, Ga);
    csr_strainPointG_(m, d, b, Gb);
    worldRows(m, d, a, 0, Ga, S);
    worldRows(m, d, foot ? a : b, foot ? 1 : 0, foot ? Ga : Gb, S + 3 * nu);
    /* K_y, C_y at this very state (shapeTangent); a ghost keeps its own */
    double Ky[36], Cy[36];
    if (!ghost) {
      csr_strainShapeTangent_(m, d, s, &st, L0, Ky, Cy);
    }
    if (ghost) {
      memcpy(Ky, g->K, sizeof Ky);
      memcpy(Cy, g->C, sizeof Cy);
    } else if (active && g->state != 2 && !(d->ghost_hold && g->state == 1)) {
      /* the shape's linearisation: its ghost if a later iterate finds it out of contact */
      g->y = st;
      memcpy(g->L, L0, sizeof g->L);
      memcpy(g->K, Ky, sizeof g->K);
      memcpy(g->C, Cy, sizeof g->C);
      g->state = 1;
    }
    /* the step's load against the shape's rates, A = h K_y + C_y (y1 = y0 + h ẏ1) */
    double A[36];
    for (int i = 0; i < 36; i++) {
      A[i] = h * Ky[i] + Cy[i];
    }
    if (du && foot && !ghost && nslot <= CSR_STRAIN_MAX_SHAPE_HIST) {
      anchorSecant(m, h, &st, slot, nslot, A);
    }
    /* the start (du NULL): h r += h Sᵀ (L(y_p) + K_y (y0 + h S u0 - y_p)); an iterate (the
     * kinematics at its end y_e, ẏ_e): h r += h Sᵀ (L_e - A S Δu_it) */
    double Lr[6], Sdu[6] = {0, 0, 0, 0, 0, 0};
    if (du) {
      for (int r = 0; r < 6; r++) {
        for (int k = 0; k < nu; k++) {
          Sdu[r] += S[r * nu + k] * du[k];
        }
      }
    }
    for (int r = 0; r < 6; r++) {
      double t = L0[r];
      for (int c = 0; c < 6; c++) {
        t += du ? -A[6 * r + c] * Sdu[c] : Ky[6 * r + c] * rest[c];
      }
      Lr[r] = t;
    }
    if (!du) {
      csu_add3(d->fcl, d->fcl, Lr);
      if (!foot) {
        csu_add3(d->fcl, d->fcl, Lr + 3);
      }
    }
    /* the capsule's couple acts on its first end's rotation */
    double* Sc = G + 18 * nu;
    int use_couple = !foot && (couple[0] != 0 || couple[1] != 0 || couple[2] != 0);
    if (use_couple) {
      worldRows(m, d, a, 1, Ga, Sc);
    }
    for (int k = 0; k < nu; k++) {
      double t = 0;
      for (int r = 0; r < 6; r++) {
        t += S[r * nu + k] * Lr[r];
      }
      if (use_couple) {
        for (int r = 0; r < 3; r++) {
          t += Sc[r * nu + k] * couple[r];
        }
      }
      if (k < 6) {
        rb[k] += t;
      } else {
        d->rl[k - 6] += t;
      }
    }
    if (d->wc_sparse == 1) {
      /* the recursion's start (artic 2; or BDF2's iterate assembled for it): this shape's S
       * and A kept, W_ll's block left out */
      memcpy(d->cS + (size_t)d->nct * 6 * nu, S, (size_t)6 * nu * sizeof(double));
      memcpy(d->cA + 36 * d->nct, A, sizeof A);
      d->ct[d->nct++] = s;
    } else if (d->wc_sparse == 2 && du) {
      /* an iterate's refactor on the recursion's start (robot_strain_woodbury.c): the same */
      memcpy(d->wS + (size_t)d->nwt * 6 * nu, S, (size_t)6 * nu * sizeof(double));
      memcpy(d->wA + 36 * d->nwt, A, sizeof A);
      d->nwt++;
    }
    csr_strainShapeW_(m, d, h, S, A, Ga, Gb, Wbb,
                      d->wc_sparse == 1 || (d->wc_sparse == 2 && du) ? 1 : 0);
    /* Ga holds A S now: its force rows, the rest of the start's linear force (A S Δu) */
    for (int r = 0; !du && r < (foot ? 3 : 6); r++) {
      for (int k = 0; k < nu; k++) {
        d->fcA[(r % 3) * nu + k] += Ga[r * nu + k];
      }
    }
  }
  return 0;
}


void csr_strainShapeW_(const csrStrainModel* m, csrStrainData* d, double h, const double* S,
                       const double A[36], double* AS, double* row, double* Wbb, int part) {
  const int n = m->n, nu = 6 + n;
  /* W -= h Sᵀ A S: AS = A S (6 x nu), then row i of Sᵀ AS, each entry Σ_r S[r][i] AS[r][k]
   * summed in r's order (a row at a time, vectorised over k); a zero entry is skipped as
   * before (W keeps its bits). part 1 leaves W_ll's block out (its rows' first 6 columns
   * alone), part 2 adds W_ll's block alone: each entry gets the same operations either way */
  for (int r = 0; r < 6; r++) {
    csr_strainRows6_(AS + r * nu, S, nu, A + 6 * r, nu, 0);
  }
  for (int i = part == 2 ? 6 : 0; i < nu; i++) {
    const double g[6] = {S[i], S[nu + i], S[2 * nu + i], S[3 * nu + i], S[4 * nu + i],
                         S[5 * nu + i]};
    csr_strainRows6_(row, AS, nu, g, part == 1 && i >= 6 ? 6 : nu, 0);
    double* wb = i < 6 ? Wbb + 6 * i : d->Wlb + 6 * (i - 6);
    double* wl = i < 6 ? d->Wbl + n * i : d->Wll + (size_t)(i - 6) * n;
    for (int k = 0; k < 6 && part != 2; k++) {
      if (row[k] != 0) {
        wb[k] += row[k] * -h;
      }
    }
    if (part == 1 && i >= 6) {
      continue;
    }
    for (int k = 6; k < nu; k++) {
      if (row[k] != 0) {
        wl[k - 6] += row[k] * -h;
      }
    }
  }
}


int csr_strainContactLoads_(const csrStrainModel* m, csrStrainData* d, double fb[6], double* fl,
                            int* same) {
  *same = 1;
  d->fcl_ok = 0;
  memset(d->fcw, 0, sizeof d->fcw);
  d->ntouch = 0;
  if (!m->soft) {
    return 0;
  }
  const int n = m->n;
  const cscSoftParams* sp = csc_softParams(m->soft);
  d->nghost = 0;
  /* without the chain points' Jacobians (a kept iterate's kinematics, want_J 0: the twists
   * by csr_strainChainTwistsNoJ_), Sᵀ L's J_pᵀ F_p by one adjoint sweep over the chain from
   * the farthest touching end: the wrenches gathered in d->Fc */
  const int noJ = !csr_strainChainJ_(d);
  int plast = 0;
  if (noJ) {
    if (!d->kst_ok || !csr_strainStepsAt_(m, d)) {
      return -1; /* the kinematics' steps are not at q (want_J 5): nothing to sweep on */
    }
    memset(d->Fc, 0, (size_t)m->np * 6 * sizeof(double));
  }
  for (int s = 0; s < m->nshape; s++) {
    csrStrainGhost* g = d->ghost + s;
    g->on = 0;
    cscShapeState st;
    csr_strainShapeState_(m, d, s, &st);
    int first, nslot;
    csc_softShapeSlots(m->soft, s, &first, &nslot);
    cscSlotInfo slot[CSR_STRAIN_MAX_SHAPE_HIST];
    int has_slot = nslot <= CSR_STRAIN_MAX_SHAPE_HIST;
    double L[6], couple[3];
    int rc = csr_strainShapeLoad_(m, d, s, &st, L, couple, has_slot ? slot : NULL, NULL);
    if (rc != 0) {
      return rc > 0 ? rc : 1;
    }
    /* out of contact after touching at its last linearisation: its ghost, whose stiffness
     * the kept matrix already holds (its slots' state does not matter) */
    const int ghost = activeNow(m, d) && g->state == 1 && loadZero(L, couple);
    if (ghost) {
      ghostLoad(m, g, s, &st, L);
      memset(couple, 0, sizeof couple);
    }
    for (int i = 0; i < nslot && has_slot && !ghost; i++) {
      if (slotSig(sp, slot + i) != d->csig[first + i]) {
        *same = 0;
      }
    }
    if (!countTouch(m, d, s, L, couple)) {
      continue;
    }
    if (ghost) {
      g->on = 1;
      d->nghost++;
    }
    int foot = s == m->nshape - 1;
    /* Sᵀ L = G_pᵀ (R_pᵀ couple; R_pᵀ f) at each end point p (R_p its world frame) */
    int pts[2] = {m->shape_a[s], m->shape_b[s]};
    for (int e = 0; e < (foot ? 1 : 2); e++) {
      const int p = pts[e];
      double Rw[9], xw[3], F[6];
      csr_strainWorld_(d, d->R + 9 * p, d->x + 3 * p, Rw, xw);
      const double* mo = foot ? L + 3 : (e == 0 ? couple : NULL);
      if (mo) {
        csu_mulMatTVec3(F, Rw, mo);
      } else {
        F[0] = F[1] = F[2] = 0;
      }
      csu_mulMatTVec3(F + 3, Rw, e == 0 ? L : L + 3);
      double A[36];
      csr_strainAdInv_(d->R + 9 * p, d->x + 3 * p, A);
      const double* J = d->J + (size_t)p * 6 * n;
      const int nc = noJ ? 0 : m->pcol[p];
      for (int r = 0; r < 6; r++) {
        if (F[r] == 0) {
          continue;
        }
        for (int c = 0; c < 6; c++) {
          fb[c] += A[6 * r + c] * F[r];
        }
        for (int j = 0; j < nc; j++) {
          fl[j] += J[r * n + j] * F[r];
        }
      }
      if (noJ) {
        for (int r = 0; r < 6; r++) {
          d->Fc[6 * p + r] += F[r];
        }
        plast = p > plast ? p : plast;
      }
    }
  }
  if (noJ && plast > 0) {
    csr_strainChainProjectNoJ_(m, d, d->Fc, plast, fl);
  }
  return 0;
}


/* Slot trust region (csrStrainParams.slot_trust). The step-mode friction of a slot is
 * F = -(N/delta_t) mu delta_t m(s) ĝ, s = |g| / (mu delta_t) its damped offset g = z_t +
 * tau_t w from the anchor over the stick range (contact_soft_internal.h): linear to
 * u_elastic, flat (m = 1, m' = 0) from 2 - u_elastic, a parabola between. The law's tangent (friction_tangent 1) has no stiffness along the slip of a
 * saturated slot, so where a foot's slots saturate, a pass's linear model lets the foot slide
 * freely: measured, passes predicted a slot to move 15-16 stick ranges and the next one back
 * (u 1.0 -> 15.6 -> 0.3, at a step of 0.3 ms), and the flat road at 5 ms stopped at 0.93 s
 * (docs/notes/strain_leg.md, "The friction's tangent"). So a trust region on the slots'
 * tangential offsets, the semismooth Newton's usual globalisation: a pass moves the whole tree
 * at most as far as takes any touching foot slot with friction CSR_STRAIN_TRUST_RADIUS stick ranges
 * along the surface (predicted linearly: its material point moves by h (δv + δω × r) for the
 * iterate's change (δv, δω) of the foot's world twist, G at the iterate). Only the passes' path
 * changes: converged, the step is the law's. (Also tried, docs/notes/strain_leg.md "Passes per
 * step": stopping a slot at the saturation band's edge when it would cross it, either way or
 * only from the flat side: the run stopped at 0.32-4.94 s; radius 1: at 0.92 s, radius 4: at
 * 7.94 s.) */
#define CSR_STRAIN_TRUST_RADIUS 2.0


double csr_strainContactLimit_(const csrStrainModel* m, csrStrainData* d, double h,
                               const double db[6], const double* dl) {
  if (!m->soft || d->ntouch == 0) {
    return 1.0;
  }
  const cscSoftParams* p = csc_softParams(m->soft);
  if (!(p->mu > 0)) {
    return 1.0;
  }
  const int n = m->n, nu = 6 + n, s = m->nshape - 1;
  int first, nslot;
  csc_softShapeSlots(m->soft, s, &first, &nslot);
  if (nslot > CSR_STRAIN_MAX_SHAPE_HIST) {
    return 1.0;
  }
  cscShapeState st;
  csr_strainShapeState_(m, d, s, &st);
  cscSlotInfo slot[CSR_STRAIN_MAX_SHAPE_HIST];
  double L[6], couple[3];
  if (csr_strainShapeLoad_(m, d, s, &st, L, couple, slot, NULL) != 0 || loadZero(L, couple)) {
    return 1.0;
  }
  /* the foot's world twist change for the move: rows of S (translation, rotation) */
  double* G = d->Gs;
  double* S = d->Gs + 6 * nu;
  const int pf = m->shape_a[s];
  csr_strainPointG_(m, d, pf, G);
  worldRows(m, d, pf, 0, G, S);
  worldRows(m, d, pf, 1, G, S + 3 * nu);
  double dvw[6];
  for (int r = 0; r < 6; r++) {
    double t = 0;
    for (int k = 0; k < nu; k++) {
      t += S[r * nu + k] * (k < 6 ? db[k] : dl[k - 6]);
    }
    dvw[r] = t;
  }
  const double rmax = CSR_STRAIN_TRUST_RADIUS * p->mu * p->delta_t;
  double alpha = 1.0;
  for (int i = 0; i < nslot; i++) {
    const cscSlotInfo* si = slot + i;
    if (!(si->depth > 0) || !(csu_norm3(si->ft) > 0)) {
      continue; /* out of contact, or no anchor yet (touched down in this step: no friction,
                   its point not reported) */
    }
    double r[3], dz[3];
    csu_sub3(r, si->point, st.x0);
    csu_cross3(dz, dvw + 3, r);
    csu_add3(dz, dz, dvw);
    csu_scale3(dz, dz, h);
    csu_addScl3(dz, dz, si->normal, -csu_dot3(dz, si->normal));
    const double len = csu_norm3(dz);
    if (len > rmax) {
      alpha = fmin(alpha, rmax / len);
    }
  }
  return alpha;
}


int csr_strainContactNone_(const csrStrainModel* m, const csrStrainData* d) {
  if (!m->soft) {
    return 1;
  }
  for (int s = 0; s < m->nshape; s++) {
    int a = m->shape_a[s], b = m->shape_b[s];
    cscShapeState st;
    memset(&st, 0, sizeof st);
    double Rb[9], xb[3];
    csr_strainWorld_(d, d->R + 9 * a, d->x + 3 * a, st.R, st.x0);
    csr_strainWorld_(d, d->R + 9 * b, d->x + 3 * b, Rb, xb);
    memcpy(st.x1, xb, sizeof xb);
    double L[6], couple[3];
    if (csr_strainShapeLaw_(m, d, s, &st, L, couple, NULL) != 0) {
      return 0;
    }
    for (int i = 0; i < 6; i++) {
      if (L[i] != 0 || (i < 3 && couple[i] != 0)) {
        return 0;
      }
    }
  }
  return 1;
}


int csr_strainContactUpdate_(const csrStrainModel* m, csrStrainData* d) {
  if (!m->soft) {
    return 0;
  }
  for (int s = 0; s < m->nshape; s++) {
    cscShapeState st;
    csr_strainShapeState_(m, d, s, &st);
    int off, cnt, first, nslot;
    csc_softShapeState(m->soft, s, &off, &cnt);
    csc_softShapeSlots(m->soft, s, &first, &nslot);
    /* the return-mapping and the law at the new anchors from one evaluation of the geometry
     * (the same bits as the two): the output's read-out and the next prepare, at this very
     * state, find them in the memo */
    csrStrainLoadMemo* mo = d->memo + s;
    memset(&mo->rep, 0, sizeof mo->rep);
    int rc = csc_softUpdateShapeLoad(m->soft, s, &st, d->z + off, &mo->ld,
                                     d->memo_slot + first, &mo->rep);
    csr_strainShapeMemoKeep_(m, d, s, &st, rc);
    if (rc != 0) {
      return rc > 0 ? rc : 1;
    }
  }
  return 0;
}


int csr_strainContactWrench(const csrStrainModel* m, csrStrainData* d, double f[3], double mo[3],
                            cscSoftReport* rep) {
  memset(f, 0, 3 * sizeof(double));
  memset(mo, 0, 3 * sizeof(double));
  if (rep) {
    memset(rep, 0, sizeof *rep);
  }
  if (!m->soft) {
    return 0;
  }
  /* the kinematics (relative to the base, a function of q alone) is usually still valid from
   * the last step's commit: recomputing it for every output sample's foot force and depth was
   * ~4 % of a run at 5 ms (docs/notes/strain_leg.md, "Fast step"); the point twists also
   * depend on the base's twist, so they are taken anew */
  if (!csr_strainChainJ_(d)) {
    csr_strainKinematics_(m, d, 1);
  }
  /* the shapes end at chain points: after BDF2's commit (its Jacobians there alone) their
   * twists alone, the same bits as csr_strainPointTwists_'s there */
  if (d->kin_valid == 2) {
    csr_strainPointTwists_(m, d);
  } else {
    csr_strainPointTwistsChain_(m, d);
  }
  int rc = 0;
  for (int s = 0; s < m->nshape; s++) {
    cscShapeState st;
    csr_strainShapeState_(m, d, s, &st);
    double L[6], couple[3];
    int r = csr_strainShapeLoad_(m, d, s, &st, L, couple, NULL, rep);
    const cscShapeLoad ld = d->memo[s].ld;
    rc = rc ? rc : r;
    /* forces at x0 and x1 and the couple, moments about the hip */
    double arm[3], t[3];
    csu_add3(f, f, ld.f0);
    csu_add3(f, f, ld.f1);
    csu_sub3(arm, st.x0, d->xb);
    csu_cross3(t, arm, ld.f0);
    csu_add3(mo, mo, t);
    csu_sub3(arm, st.x1, d->xb);
    csu_cross3(t, arm, ld.f1);
    csu_add3(mo, mo, t);
    csu_add3(mo, mo, ld.m);
  }
  return rc;
}
