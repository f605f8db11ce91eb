/* robot_calibration_report.c: the calibration model against a table's cases (the errors of
 * fitted, held-out and symmetry cases, with the constant-curvature kinematics of the leg), and
 * reports of them (robot_calibration_model.h). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core_h5.h"
#include "robot_analytic.h"
#include "robot_calibration_internal.h"

/* the held-out target of issue 8: 5 % of the bend angle or 1 deg, 2 % of the leg length */
#define TARGET_BEND_REL 0.05
#define TARGET_BEND_ABS (1.0 * CS_DEG)
#define TARGET_TIP_REL 0.02

/* ---- comparison with a case ---------------------------------------------------------------- */

csStatus csr_calModelCompare(const csrCalModel* m, const csrCalCase* c, csrCalCompare* out,
                             csError* err) {
  memset(out, 0, sizeof *out);
  if (c->kind == CSR_CAL_GRAVITY) {
    return cs_errorSet(err, CS_ERR_ARG, "case %s: a gravity case has no chamber pattern",
                       c->name);
  }
  out->bend_deg = -1;
  const double L = csr_actuatorLength(&m->leg);
  /* the mirror line's direction: the pressure moment's (a zero moment with a mirror: no bend) */
  out->mirror = csr_calMirrorSymmetric_(c->ratio);
  double mv[2];
  csr_calMoment_(c->ratio, mv);
  const double mn = hypot(mv[0], mv[1]);
  const double u[2] = {mn > 0 ? mv[0] / mn : 0, mn > 0 ? mv[1] / mn : 0};
  int meets = 1;
  for (int i = 0; i < c->m && c->pressure[i] <= m->p_max + P_RANGE_TOL; i++) {
    const double p = c->pressure[i];
    double row_bend = 0, row_bend_sym = 0;
    csrSegmentStrain sm[CSR_NSEG], sf[CSR_NSEG], ss[CSR_NSEG];
    memset(sm, 0, sizeof sm);
    memset(sf, 0, sizeof sf);
    for (int s = 0; s < CSR_NSEG; s++) {
      const double P[4] = {c->ratio[0] * p, c->ratio[1] * p, c->ratio[2] * p, c->ratio[3] * p};
      csrCalSegment q;
      if (csr_calModelEval(m, s, P, &q) != 0) {
        return cs_errorSet(err, CS_ERR_SOLVER, "case %s: the model fails at %g MPa", c->name, p);
      }
      const double* bf = c->bend + 6 * i + 2 * s;
      const double d = hypot(q.bend[0] - bf[0], q.bend[1] - bf[1]), mag = hypot(bf[0], bf[1]);
      const double score = d / fmax(TARGET_BEND_REL * mag, TARGET_BEND_ABS);
      if (d / CS_DEG > out->bend_deg) {
        out->bend_deg = d / CS_DEG, out->bend_at_p = p, out->bend_at_seg = s;
        out->bend_fe_deg = mag / CS_DEG;
      }
      out->bend_score = fmax(out->bend_score, score);
      row_bend = fmax(row_bend, score);
      /* the FE bend's symmetric part: its component along the mirror line (all of it without
       * a mirror) */
      const double along = bf[0] * u[0] + bf[1] * u[1];
      const double bs[2] = {out->mirror ? along * u[0] : bf[0], out->mirror ? along * u[1] : bf[1]};
      const double ds = hypot(q.bend[0] - bs[0], q.bend[1] - bs[1]);
      row_bend_sym = fmax(row_bend_sym, ds / fmax(TARGET_BEND_REL * hypot(bs[0], bs[1]),
                                                  TARGET_BEND_ABS));
      out->stretch = fmax(out->stretch, fabs(q.stretch - c->stretch[3 * i + s]));
      const double S = m->leg.S[s];
      sm[s].lambda0 = q.stretch, sm[s].kappa[0] = -q.bend[0] / S, sm[s].kappa[1] = -q.bend[1] / S;
      sf[s].lambda0 = c->stretch[3 * i + s];
      sf[s].kappa[0] = -bf[0] / S, sf[s].kappa[1] = -bf[1] / S;
      ss[s] = sf[s];
      ss[s].kappa[0] = -bs[0] / S, ss[s].kappa[1] = -bs[1] / S;
    }
    double tm[3], tf[3], ts[3];
    if (csr_ccForwardKinematics(&m->leg, sm, 1, NULL, tm, NULL, err) != CS_OK ||
        csr_ccForwardKinematics(&m->leg, sf, 1, NULL, tf, NULL, err) != CS_OK ||
        csr_ccForwardKinematics(&m->leg, ss, 1, NULL, ts, NULL, err) != CS_OK) {
      return cs_errorSet(err, CS_ERR_SOLVER, "case %s: kinematics fail at %g MPa", c->name, p);
    }
    const double* tip = c->tip + 3 * i;
    const double dt[3] = {tm[0] - tip[0], tm[1] - tip[1], tm[2] - tip[2]};
    const double dc[3] = {tf[0] - tip[0], tf[1] - tip[1], tf[2] - tip[2]};
    out->tip_mm = fmax(out->tip_mm, csu_norm3(dt));
    out->tip_cc_mm = fmax(out->tip_cc_mm, csu_norm3(dc));
    out->tip_score = fmax(out->tip_score, csu_norm3(dt) / (TARGET_TIP_REL * L));
    /* the FE tip without its across-mirror bends: tip + (ts - tf) */
    const double dsym[3] = {dt[0] - (ts[0] - tf[0]), dt[1] - (ts[1] - tf[1]),
                            dt[2] - (ts[2] - tf[2])};
    out->tip_sym_mm = fmax(out->tip_sym_mm, csu_norm3(dsym));
    out->tip_sym_score = fmax(out->tip_sym_score, csu_norm3(dsym) / (TARGET_TIP_REL * L));
    const double row_tip = csu_norm3(dt) / (TARGET_TIP_REL * L);
    const double row_sym = csu_norm3(dsym) / (TARGET_TIP_REL * L);
    meets = meets && ((row_bend <= 1 && row_tip <= 1) ||
                      (out->mirror && row_bend_sym <= 1 && row_sym <= 1));
    if (meets) {
      out->p_meets = p;
    }
    out->rows++;
    out->p_last = p;
  }
  if (out->rows == 0) {
    out->bend_deg = 0;
    return cs_errorSet(err, CS_ERR_RANGE, "case %s: no row within the model's range", c->name);
  }
  return CS_OK;
}


/* ---- the FE against its own symmetric image ------------------------------------------------ */

/* the row of c at pressure p (to 1e-9 MPa), -1 if none */
static int rowAt(const csrCalCase* c, double p) {
  for (int i = 0; i < c->m; i++) {
    if (fabs(c->pressure[i] - p) <= 1e-9) {
      return i;
    }
  }
  return -1;
}


/* the map of the section plane from partner d's frame into c's: T = From(kc, mc) To(kd, md) */
typedef struct {
  int kc, mc, kd, md;
} Carry;

static Carry carryOf(const csrCalCase* c, const csrCalCase* d) {
  Carry T;
  double pc[4], pd[4];
  csr_calCanonical_(c->ratio, pc, &T.kc, &T.mc);
  csr_calCanonical_(d->ratio, pd, &T.kd, &T.md);
  return T;
}

/* row r of d in c's frame: its segments' bend vectors (3 x 2, rad) and its tip (mm) */
static void carryRow(const Carry* T, const csrCalCase* d, int r, double bend[6], double tip[3]) {
  for (int s = 0; s < CSR_NSEG; s++) {
    double vc[2];
    csr_calToCanonical_(d->bend + 6 * r + 2 * s, T->kd, T->md, vc);
    csr_calFromCanonical_(vc, T->kc, T->mc, bend + 2 * s);
  }
  double vc[2];
  csr_calToCanonical_(d->tip + 3 * r, T->kd, T->md, vc);
  csr_calFromCanonical_(vc, T->kc, T->mc, tip);
  tip[2] = d->tip[3 * r + 2]; /* along the leg's axis: unchanged */
}


csStatus csr_calSymmetryPair(const csrCalTable* t, const csrCalCase* c, csrCalSymPair* out,
                             csError* err) {
  memset(out, 0, sizeof *out);
  if (c->kind == CSR_CAL_GRAVITY) {
    return CS_OK;
  }
  double pc[4], pd[4];
  int kc, mc, kd, md;
  csr_calCanonical_(c->ratio, pc, &kc, &mc);
  for (int pass = 0; pass < 2 && !out->partner; pass++) {
    for (int i = 0; i < t->ncase && !out->partner; i++) {
      const csrCalCase* d = t->cases + i;
      /* first pass: fitted and held-out cases; second: another symmetry case */
      if (d == c || d->kind == CSR_CAL_GRAVITY || (d->kind == CSR_CAL_SYMMETRY) != (pass == 1)) {
        continue;
      }
      csr_calCanonical_(d->ratio, pd, &kd, &md);
      /* an image, not the same pattern again (H8 repeats H1's over a longer sweep) */
      int same = 1, repeat = 1;
      for (int j = 0; j < 4; j++) {
        same = same && fabs(pd[j] - pc[j]) <= 1e-12;
        repeat = repeat && d->ratio[j] == c->ratio[j];
      }
      if (same && !repeat) {
        out->partner = d;
      }
    }
  }
  if (!out->partner) {
    return CS_OK;
  }
  const csrCalCase* d = out->partner;
  const Carry T = carryOf(c, d);
  out->bend_deg = -1;
  for (int i = 0; i < c->m; i++) {
    const int r = rowAt(d, c->pressure[i]);
    if (r < 0) {
      continue;
    }
    double b[6], tp[3];
    carryRow(&T, d, r, b, tp);
    for (int s = 0; s < CSR_NSEG; s++) {
      const double* bc = c->bend + 6 * i + 2 * s;
      const double e = hypot(bc[0] - b[2 * s], bc[1] - b[2 * s + 1]) / CS_DEG;
      if (e > out->bend_deg) {
        out->bend_deg = e, out->bend_at_p = c->pressure[i], out->bend_at_seg = s;
        out->bend_fe_deg = hypot(bc[0], bc[1]) / CS_DEG;
      }
    }
    const double* tc = c->tip + 3 * i;
    const double dt[3] = {tc[0] - tp[0], tc[1] - tp[1], tc[2] - tp[2]};
    if (csu_norm3(dt) > out->tip_mm) {
      out->tip_mm = csu_norm3(dt), out->tip_at_p = c->pressure[i];
    }
    out->rows++;
    out->p_last = c->pressure[i];
  }
  if (out->rows == 0) {
    out->bend_deg = 0;
    return cs_errorSet(err, CS_ERR_RANGE, "cases %s and %s share no pressure row", c->name,
                       d->name);
  }
  return CS_OK;
}


csStatus csr_calModelCompareSymmetrised(const csrCalModel* m, const csrCalCase* c,
                                        const csrCalSymPair* pair, csrCalCompare* out,
                                        csError* err) {
  memset(out, 0, sizeof *out);
  if (!pair || !pair->partner || pair->rows == 0) {
    return cs_errorSet(err, CS_ERR_ARG, "case %s: no symmetric image to average with",
                       c ? c->name : "?");
  }
  const csrCalCase* d = pair->partner;
  const Carry T = carryOf(c, d);
  /* a case of the common rows, each quantity the mean of c's and the partner's carried over */
  csrCalCase a;
  memset(&a, 0, sizeof a);
  snprintf(a.name, sizeof a.name, "%s", c->name);
  a.kind = c->kind;
  memcpy(a.ratio, c->ratio, sizeof a.ratio);
  const int n = c->m;
  double* buf = malloc((size_t)n * (1 + 6 + 3 + 3) * sizeof(double));
  if (!buf) {
    return cs_errorSet(err, CS_ERR_MEMORY, "case %s: out of memory", c->name);
  }
  a.pressure = buf, a.bend = buf + n, a.stretch = buf + 7 * n, a.tip = buf + 10 * n;
  for (int i = 0; i < n; i++) {
    const int r = rowAt(d, c->pressure[i]);
    if (r < 0) {
      continue;
    }
    const int j = a.m++;
    a.pressure[j] = c->pressure[i];
    double b[6], tp[3];
    carryRow(&T, d, r, b, tp);
    for (int k = 0; k < 6; k++) {
      a.bend[6 * j + k] = 0.5 * (c->bend[6 * i + k] + b[k]);
    }
    for (int k = 0; k < 3; k++) {
      a.stretch[3 * j + k] = 0.5 * (c->stretch[3 * i + k] + d->stretch[3 * r + k]);
      a.tip[3 * j + k] = 0.5 * (c->tip[3 * i + k] + tp[k]);
    }
  }
  csStatus st = csr_calModelCompare(m, &a, out, err);
  free(buf);
  return st;
}


/* ---- the rules compared ------------------------------------------------------------------- */

/* worst scores of a model over the cases of one kind (held-out) and over the refining modes
 * left out one at a time (cross-validation on fitted data) */
typedef struct {
  double held_bend, held_tip;   /* max score over held-out cases (<= 1 meets the target) */
  double held_bend_deg, held_tip_mm;
  double loo_bend_deg, loo_tip_mm; /* max over the refining modes predicted without them */
  double p_valid; /* MPa: every held-out case meets the target up to here (INFINITY: all do
                     throughout) */
  double held_tip_sym_mm; /* the same worst tip, and the pressure all meet to, with each case */
  double p_valid_sym;     /* that has an image in the table against the symmetrised FE */
  int nsym;               /* held-out cases taken against the symmetrised FE */
  int nheld, nloo;
} RuleScore;


static void scoreRule(const csrCalTable* t, const csrActuator* leg, const csrCalOptions* o,
                      RuleScore* r) {
  memset(r, 0, sizeof *r);
  r->p_valid = r->p_valid_sym = INFINITY;
  csError err;
  csrCalModel* m = csr_calModelCreate(t, leg, o, &err);
  if (!m) {
    r->held_bend = r->held_tip = NAN;
    return;
  }
  for (int i = 0; i < t->ncase; i++) {
    csrCalCompare e;
    if (t->cases[i].kind == CSR_CAL_HOLDOUT && csr_calModelCompare(m, t->cases + i, &e, &err) == 0) {
      r->held_bend = fmax(r->held_bend, e.bend_score);
      r->held_tip = fmax(r->held_tip, e.tip_score);
      r->held_bend_deg = fmax(r->held_bend_deg, e.bend_deg);
      r->held_tip_mm = fmax(r->held_tip_mm, e.tip_mm);
      if (e.p_meets < e.p_last) {
        r->p_valid = fmin(r->p_valid, e.p_meets);
      }
      r->nheld++;
      /* against the symmetrised FE where the case has an image, else as it is */
      csrCalSymPair pair;
      csrCalCompare es;
      if (csr_calSymmetryPair(t, t->cases + i, &pair, &err) == CS_OK && pair.partner &&
          csr_calModelCompareSymmetrised(m, t->cases + i, &pair, &es, &err) == CS_OK) {
        e = es;
        r->nsym++;
      }
      r->held_tip_sym_mm = fmax(r->held_tip_sym_mm, e.tip_mm);
      if (e.p_meets < e.p_last) {
        r->p_valid_sym = fmin(r->p_valid_sym, e.p_meets);
      }
    }
  }
  for (int role = CSR_CAL_O12R05; role < CSR_CAL_NROLE; role++) {
    double ratio[CSR_NCHAMBER];
    csr_calModelModePattern((csrCalRole)role, ratio, NULL);
    /* only the modes this rule fits can be left out of its fit */
    const csrCalCase* c = csr_calModelUses(m, (csrCalRole)role)
                              ? csr_calTableFind(t, CSR_CAL_MODE, ratio)
                              : NULL;
    csrCalOptions ol = *o;
    ol.exclude |= 1u << role;
    csrCalModel* ml = c ? csr_calModelCreate(t, leg, &ol, &err) : NULL;
    csrCalCompare e;
    if (ml && csr_calModelCompare(ml, c, &e, &err) == CS_OK) {
      r->loo_bend_deg = fmax(r->loo_bend_deg, e.bend_deg);
      r->loo_tip_mm = fmax(r->loo_tip_mm, e.tip_mm);
      r->nloo++;
    }
    csr_calModelDestroy(ml);
  }
  csr_calModelDestroy(m);
}


static const char* ruleName(csrCalRule r) {
  switch (r) {
    case CSR_CAL_RULE_SUPERPOSITION: return "superposition";
    case CSR_CAL_RULE_INTERPOLATION: return "interpolation";
    case CSR_CAL_RULE_MEAN: return "mean-pressure";
    case CSR_CAL_RULE_SCALED: return "scaled superposition";
    case CSR_CAL_RULE_RBF: return "superposition + RBF";
    case CSR_CAL_RULE_RBF_PAIR: return "pair factor + RBF";
  }
  return "?";
}


/* ---- the summary -------------------------------------------------------------------------- */

csStatus csr_calReportPrint(const csrCalModel* m, const csrCalTable* t, FILE* out,
                            csError* err) {
  const csrActuator* leg = &m->leg;
  const double L = csr_actuatorLength(leg);
  fprintf(out, "calibration model: %s\n", m->name);
  double wall = 0;
  int nwall = 0;
  for (int i = 0; i < t->ncase; i++) {
    if (isfinite(t->cases[i].wall_time)) {
      wall += t->cases[i].wall_time, nwall++;
    }
  }
  fprintf(out, "  table: %d cases, FE wall time %.2f h over %d of them (l_soft %g mm%s, %s "
          "fibres, %s)\n", t->ncase, wall / 3600, nwall, t->fe_mesh_size,
          t->fe_mesh_symmetric ? " symmetric mesh" : "", t->fe_fibre_law, t->fe_solver);
  /* fitted modes: what the model returns against the FE rows (the FE's asymmetry, removed by
   * the symmetric projection; the rest is round-off) */
  fprintf(out, "  fitted modes (model - FE over the rows up to %g MPa; the bend difference is the "
          "FE's mesh asymmetry the section's symmetry removes):\n", m->p_max);
  for (int i = 0; i < t->ncase; i++) {
    const csrCalCase* c = t->cases + i;
    csrCalCompare e;
    if (c->kind != CSR_CAL_MODE || csr_calModelCompare(m, c, &e, err) != CS_OK) {
      continue;
    }
    fprintf(out, "    %-9s %2d rows  bend %7.4f deg (of %6.2f at %.3g MPa, II%d)  stretch %.1e  "
            "tip %6.3f mm\n", c->name, e.rows, e.bend_deg, e.bend_fe_deg, e.bend_at_p,
            e.bend_at_seg + 1, e.stretch, e.tip_mm);
  }
  /* the refining modes predicted without themselves */
  fprintf(out, "  left out of the fit one at a time (cross-validation of the interpolation):\n");
  for (int role = CSR_CAL_O12R05; role < CSR_CAL_NROLE; role++) {
    double ratio[CSR_NCHAMBER];
    const char* name;
    csr_calModelModePattern((csrCalRole)role, ratio, &name);
    const csrCalCase* c = csr_calTableFind(t, CSR_CAL_MODE, ratio);
    if (c && !csr_calModelUses(m, (csrCalRole)role)) {
      /* a mode this rule does not take (the RBF rules' extra nodes under the prism rule) */
      fprintf(out, "    %-9s not a node of this rule\n", name);
      continue;
    }
    csrCalOptions o = m->opt;
    o.exclude |= 1u << role;
    csError lerr;
    csrCalModel* ml = c ? csr_calModelCreate(t, leg, &o, &lerr) : NULL;
    csrCalCompare e;
    if (ml && csr_calModelCompare(ml, c, &e, &lerr) == CS_OK) {
      fprintf(out, "    %-9s bend %6.3f deg (of %6.2f at %.3g MPa, II%d)  stretch %.1e  tip %6.3f "
              "mm\n", name, e.bend_deg, e.bend_fe_deg, e.bend_at_p, e.bend_at_seg + 1, e.stretch,
              e.tip_mm);
    } else {
      fprintf(out, "    %-9s not in the table\n", name);
    }
    csr_calModelDestroy(ml);
  }
  /* held out and symmetry: the target */
  fprintf(out, "  held out (never fitted; target: bend within 5 %% or 1 deg, tip within 2 %% of "
          "%.0f mm = %.2f mm):\n", L, TARGET_TIP_REL * L);
  int nheld = 0, nsym = 0;
  double p_valid = INFINITY, p_valid_sym = INFINITY;
  for (int i = 0; i < t->ncase; i++) {
    const csrCalCase* c = t->cases + i;
    csrCalCompare e;
    if ((c->kind != CSR_CAL_HOLDOUT && c->kind != CSR_CAL_SYMMETRY) ||
        csr_calModelCompare(m, c, &e, err) != CS_OK) {
      continue;
    }
    nheld += c->kind == CSR_CAL_HOLDOUT;
    char sym[160] = "";
    if (e.mirror) {
      snprintf(sym, sizeof sym, "; against the FE's symmetric part (its bend across the mirror "
               "line removed): %.3f mm, %.2f", e.tip_sym_mm, e.tip_sym_score);
    }
    /* p_meets decides (csrCalCompare): throughout on the raw FE, or on its symmetric part */
    const char* verdict = e.bend_score <= 1 && e.tip_score <= 1 ? "meets it"
                          : e.p_meets >= e.p_last               ? "meets it on the symmetric part"
                                                                : "MISSES it";
    char upto[64] = "";
    if (e.p_meets < e.p_last) {
      snprintf(upto, sizeof upto, " (meets it up to %.3g MPa)", e.p_meets);
    }
    fprintf(out, "    %-9s %-8s to %.3g MPa: bend %6.3f deg (of %6.2f at %.3g MPa, II%d; %.2f of "
            "the target)  tip %6.3f mm (%.2f of the target%s; constant curvature of the FE's own "
            "segments: %.3f mm)  %s%s\n", c->name, csr_calKindName(c->kind), e.p_last,
            e.bend_deg, e.bend_fe_deg, e.bend_at_p, e.bend_at_seg + 1, e.bend_score, e.tip_mm,
            e.tip_score, sym, e.tip_cc_mm, verdict, upto);
    if (c->kind == CSR_CAL_HOLDOUT && e.p_meets < e.p_last) {
      p_valid = fmin(p_valid, e.p_meets); /* a case that meets it throughout does not limit */
    }
    /* the FE against its own image: the reference's resolution on this pattern */
    csrCalSymPair pair;
    csError perr;
    if (csr_calSymmetryPair(t, c, &pair, &perr) != CS_OK || !pair.partner) {
      if (c->kind == CSR_CAL_HOLDOUT && e.p_meets < e.p_last) {
        p_valid_sym = fmin(p_valid_sym, e.p_meets);
      }
      continue;
    }
    fprintf(out, "      the FE against its image %s carried over by the section's symmetry, "
            "%d rows: bend %.3f deg (of %.2f at %.3g MPa, II%d), tip %.3f mm (at %.3g MPa)\n",
            pair.partner->name, pair.rows, pair.bend_deg, pair.bend_fe_deg, pair.bend_at_p,
            pair.bend_at_seg + 1, pair.tip_mm, pair.tip_at_p);
    csrCalCompare es;
    if (c->kind != CSR_CAL_HOLDOUT) {
      continue;
    }
    if (csr_calModelCompareSymmetrised(m, c, &pair, &es, &perr) != CS_OK) {
      p_valid_sym = e.p_meets < e.p_last ? fmin(p_valid_sym, e.p_meets) : p_valid_sym;
    } else {
      nsym++;
      char up[64] = "";
      if (es.p_meets < es.p_last) {
        snprintf(up, sizeof up, " up to %.3g MPa", es.p_meets);
        p_valid_sym = fmin(p_valid_sym, es.p_meets);
      }
      fprintf(out, "      the model against the mean of the two: bend %.3f deg (%.2f of the target)"
              "  tip %.3f mm (%.2f)  meets it%s\n", es.bend_deg, es.bend_score, es.tip_mm,
              es.tip_score, up);
    }
  }
  if (nheld == 0) {
    fprintf(out, "    (no held-out case in the table)\n");
  } else if (isfinite(p_valid)) {
    fprintf(out, "    every held-out case meets the target up to %.3g MPa (each over its rows up "
            "to there)\n", p_valid);
  } else {
    fprintf(out, "    every held-out case meets the target over its whole sweep\n");
  }
  if (nsym > 0) {
    if (isfinite(p_valid_sym)) {
      fprintf(out, "    with the %d case(s) that have an image taken against the symmetrised FE: "
              "every held-out case meets the target up to %.3g MPa\n", nsym, p_valid_sym);
    } else {
      fprintf(out, "    with the %d case(s) that have an image taken against the symmetrised FE: "
              "every held-out case meets the target over its whole sweep\n", nsym);
    }
  }
  /* the rules side by side on the same table */
  fprintf(out, "  rules compared (worst over the held-out cases: bend deg / tip mm, target score; "
          "worst left-out refining mode: bend deg / tip mm; held out meet the target to MPa):\n");
  const csrCalRule bend_rules[5] = {CSR_CAL_RULE_SUPERPOSITION, CSR_CAL_RULE_SCALED,
                                    CSR_CAL_RULE_INTERPOLATION, CSR_CAL_RULE_RBF,
                                    CSR_CAL_RULE_RBF_PAIR};
  const csrCalRule scalar_rules[3] = {CSR_CAL_RULE_SUPERPOSITION, CSR_CAL_RULE_MEAN,
                                      CSR_CAL_RULE_INTERPOLATION};
  for (int b = 0; b < 5; b++) {
    for (int q = 0; q < 3; q++) {
      csrCalOptions o = csr_calModelDefaultOptions();
      o.rule = bend_rules[b], o.scalar_rule = scalar_rules[q];
      RuleScore r;
      scoreRule(t, leg, &o, &r);
      char upto[32] = "the end";
      if (isfinite(r.p_valid)) {
        snprintf(upto, sizeof upto, "%.3g MPa", r.p_valid);
      }
      const int mine = o.rule == m->opt.rule && o.scalar_rule == m->opt.scalar_rule;
      char sym[96] = "";
      if (r.nsym > 0) {
        snprintf(sym, sizeof sym, "; symmetrised FE: %.3f mm, meet to %s", r.held_tip_sym_mm,
                 isfinite(r.p_valid_sym) ? "" : "the end");
        if (isfinite(r.p_valid_sym)) {
          snprintf(sym + strlen(sym), sizeof sym - strlen(sym), "%.3g MPa", r.p_valid_sym);
        }
      }
      fprintf(out, "    %c bend %-20s stretch %-13s held out %6.3f deg / %6.3f mm (%.2f, %.2f)  "
              "left out %6.3f deg / %6.3f mm  meet to %s%s\n", mine ? '*' : ' ', ruleName(o.rule),
              ruleName(o.scalar_rule), r.held_bend_deg, r.held_tip_mm, r.held_bend, r.held_tip,
              r.loo_bend_deg, r.loo_tip_mm, upto, sym);
    }
  }
  if (m->opt.rule == CSR_CAL_RULE_SCALED) {
    for (int s = 0; s < CSR_NSEG; s++) {
      fprintf(out, "  mean-pressure factor II%d: K(p) = exp(%.4g p %+.4g p^2), K(0.25) = %.4f, "
              "fit rms %.3g (log magnitude)\n", s + 1, m->kfac[s][0], m->kfac[s][1],
              csr_calMeanFactor_(m->kfac[s], 0.25), m->kfit_rms[s]);
    }
  }
  /* the contact radius the rod's capsules would need: a + the largest radial growth */
  double rmax = m->leg.a, at = 0;
  for (int i = 0; i < t->ncase; i++) {
    const csrCalCase* c = t->cases + i;
    for (int r = 0; r < c->m && c->kind == CSR_CAL_MODE && c->pressure[r] <= m->p_max; r++) {
      for (int s = 0; s < CSR_NSEG; s++) {
        const double v = m->leg.a + c->radial_max[3 * r + s] - c->radial_max[s];
        if (v > rmax) {
          rmax = v, at = c->pressure[r];
        }
      }
    }
  }
  fprintf(out, "  contact radius a + largest radial growth: %.3g mm at rest, up to %.3g mm (at %.3g "
          "MPa)\n", m->leg.a, rmax, at);
  /* stiffness against the small-strain section (E' = 8 C10) */
  csrSectionProps sp;
  if (csr_analyticSectionCompute(leg, NULL, &sp, err) != CS_OK) {
    return err ? err->status : CS_ERR_RANGE;
  }
  const double E = 8 * leg->C10;
  fprintf(out, "  stiffness (probes; against 8 C10 I = %.0f N mm^2 and 8 C10 A = %.1f N of the "
          "chambered section; -: no reading, the probe failed or its force mostly twisted or "
          "pulled that segment, csf_calibrationReduceProbes):\n", E * sp.I_holed,
          E * sp.area_holed);
  int nprobe = 0;
  for (int i = 0; i < t->ncase; i++) {
    const csrCalCase* c = t->cases + i;
    nprobe += c->k;
    for (int k = 0; k < c->k; k++) {
      fprintf(out, "    %-6s p = %.3g MPa (mean %.3g):", c->name, c->probe_pressure[k],
              0.25 * (c->ratio[0] + c->ratio[1] + c->ratio[2] + c->ratio[3]) *
                  c->probe_pressure[k]);
      for (int s = 0; s < CSR_NSEG; s++) {
        const double ei = csr_calProbeEI_(c, k, s); /* as the model takes the probes */
        char eis[32] = "-", eas[32] = "-";
        if (isfinite(ei)) {
          snprintf(eis, sizeof eis, "%.0f (%.2f x)", ei, ei / (E * sp.I_holed));
        }
        if (isfinite(c->EA[3 * k + s])) {
          snprintf(eas, sizeof eas, "%.1f (%.2f x)", c->EA[3 * k + s],
                   c->EA[3 * k + s] / (E * sp.area_holed));
        }
        fprintf(out, "  II%d EI %s EA %s", s + 1, eis, eas);
      }
      fprintf(out, "\n");
    }
  }
  if (nprobe == 0) {
    fprintf(out, "    (no stiffness probes in the table: the legs keep E' = 8 C10)\n");
  }
  return CS_OK;
}


/* ---- predictions file ---------------------------------------------------------------------- */

csStatus csr_calReportWrite(const csrCalModel* m, const csrCalTable* t, const char* path,
                            csError* err) {
  csH5File* f = cs_h5Create(path, err);
  if (!f) {
    return err ? err->status : CS_ERR_IO;
  }
  csStatus st = cs_h5AttrString(f, "/", "model", m->name, err);
  if (st == CS_OK) st = cs_h5AttrString(f, "/", "table", t->path, err);
  if (st == CS_OK) st = cs_h5AttrDouble(f, "/", "p_max_MPa", m->p_max, err);
  if (st == CS_OK) {
    st = cs_h5AttrString(f, "/", "units", "pressure MPa; bend rad; tip, radius mm; EI N mm^2; "
                         "EA N", err);
  }
  /* the small-strain references of the chambered section, E' = 8 C10 (for the plots) */
  csrSectionProps sp;
  if (st == CS_OK) st = csr_analyticSectionCompute(&m->leg, NULL, &sp, err);
  if (st == CS_OK) st = cs_h5AttrDouble(f, "/", "EI_8C10I_Nmm2", 8 * m->leg.C10 * sp.I_holed, err);
  if (st == CS_OK) st = cs_h5AttrDouble(f, "/", "EA_8C10A_N", 8 * m->leg.C10 * sp.area_holed, err);
  for (int i = 0; i < t->ncase && st == CS_OK; i++) {
    const csrCalCase* c = t->cases + i;
    if (c->kind == CSR_CAL_GRAVITY) {
      continue;
    }
    int n = 0;
    while (n < c->m && c->pressure[n] <= m->p_max + P_RANGE_TOL) n++;
    if (n == 0) {
      continue;
    }
    double* buf = malloc((size_t)n * 16 * sizeof(double));
    if (!buf) {
      st = cs_errorSet(err, CS_ERR_MEMORY, "%s: out of memory", path);
      break;
    }
    double *p = buf, *bend = p + n, *st3 = bend + 6 * n, *rad = st3 + 3 * n, *tip = rad + 3 * n;
    for (int r = 0; r < n && st == CS_OK; r++) {
      p[r] = c->pressure[r];
      csrSegmentStrain ss[CSR_NSEG];
      memset(ss, 0, sizeof ss);
      for (int s = 0; s < CSR_NSEG; s++) {
        const double P[4] = {c->ratio[0] * p[r], c->ratio[1] * p[r], c->ratio[2] * p[r],
                             c->ratio[3] * p[r]};
        csrCalSegment q;
        if (csr_calModelEval(m, s, P, &q) != 0) {
          st = cs_errorSet(err, CS_ERR_SOLVER, "case %s: the model fails at %g MPa", c->name,
                           p[r]);
          break;
        }
        bend[6 * r + 2 * s] = q.bend[0], bend[6 * r + 2 * s + 1] = q.bend[1];
        st3[3 * r + s] = q.stretch, rad[3 * r + s] = q.radius;
        ss[s].lambda0 = q.stretch;
        ss[s].kappa[0] = -q.bend[0] / m->leg.S[s], ss[s].kappa[1] = -q.bend[1] / m->leg.S[s];
      }
      if (st == CS_OK) {
        st = csr_ccForwardKinematics(&m->leg, ss, 1, NULL, tip + 3 * r, NULL, err);
      }
    }
    char g[96], d[160];
    snprintf(g, sizeof g, "/cases/%s", c->name);
    const size_t d1[1] = {(size_t)n}, d2[2] = {(size_t)n, 3}, d3[3] = {(size_t)n, 3, 2};
    const struct {
      const char* name;
      int rank;
      const size_t* dims;
      const double* a;
    } ds[5] = {{"pressure", 1, d1, p}, {"bend", 3, d3, bend}, {"stretch", 2, d2, st3},
               {"radius", 2, d2, rad}, {"tip", 2, d2, tip}};
    for (int q = 0; q < 5 && st == CS_OK; q++) {
      snprintf(d, sizeof d, "%s/%s", g, ds[q].name);
      st = cs_h5WriteDoubles(f, d, ds[q].rank, ds[q].dims, ds[q].a, err);
    }
    if (st == CS_OK) st = cs_h5AttrString(f, g, "kind", csr_calKindName(c->kind), err);
    free(buf);
  }
  /* the stiffness curves: the merged probe points per segment */
  for (int q = 0; q < 2 && st == CS_OK && !isnan(m->k_pmax); q++) {
    for (int s = 0; s < CSR_NSEG && st == CS_OK; s++) {
      char d[96];
      const size_t dn[1] = {(size_t)m->nk[q][s]};
      snprintf(d, sizeof d, "/stiffness/II%d/%s_pbar", s + 1, q ? "EA" : "EI");
      st = cs_h5WriteDoubles(f, d, 1, dn, m->kp[q][s], err);
      snprintf(d, sizeof d, "/stiffness/II%d/%s", s + 1, q ? "EA" : "EI");
      if (st == CS_OK) st = cs_h5WriteDoubles(f, d, 1, dn, m->kv[q][s], err);
    }
  }
  csError cerr;
  csStatus cst = cs_h5CloseChecked(f, &cerr);
  if (st == CS_OK && cst != CS_OK) {
    st = cst;
    if (err) {
      *err = cerr;
    }
  }
  return st;
}
