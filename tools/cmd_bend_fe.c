/* cmd_bend_fe.c: `crawlsim bend --model fe`, the full FE model's sweep (cmd_bend.h).
 *
 * Everything the FE reports while it works lives here: a line per converged load step (with
 * the tangent's inertia when it is indefinite), a heartbeat at least every minute inside a long
 * step, and the summary (mesh, timings, critical points, hard stretches, limit points, why a
 * sweep ended early). */
#ifdef CS_HAVE_FEM
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cmd_bend.h"
#include "cmd_fe_threads.h"
#include "cs_signal.h"
#include "core_clock.h"
#include "core_h5.h"
#include "fem_actuator.h"
#include "fem_bend.h"
#include "fem_bend_branch.h"
#include "robot_bend_io.h"

/* a pointwise J below this at a stall: the r1 2 / b 3 and r1 1.5 / b 3 sweeps stalled with
 * their worst element at 0.41 and 0.28 (README, "Design studies"); their vented chambers'
 * walls were then far past the crease onset and nearly closed (feWallReport) */
#define CSX_J_DISTORTED 0.5

/* the FE sweep's report lines: one per converged step, and a heartbeat at least every
 * kHeartbeatS seconds while Newton works inside a step (cut-backs, continuation), so that a long
 * step never leaves the user without a line for more than a minute */
typedef struct {
  double t_last; /* wall time of the last line printed, s */
  long iters;    /* Newton iterations since then */
  csH5File* f;   /* the output: the rows so far are flushed after every converged step */
  const csrBendCurve* bc;
  csError flush_err; /* the first flush that failed (then no more are tried) */
  FILE* notes;       /* where the lines go (BendRun.notes) */
} FeReport;

static const double kHeartbeatS = 50.0;

/* a vented chamber whose smallest opposite-wall gap fell below this fraction of its undeformed
 * gap is reported closed (its walls met): 2.5 x the gap measure's resolution, the straight
 * sub-triangles' sagitta of ~2 % of a 2 mm chamber's 3.1 mm gap (fem_wall.h); r1 2 / b 3 ends at
 * 0.1 % of it, r1 1.5 / b 3 at 19 % (fem/README.md "Creases and closing chambers") */
static const double kGapClosed = 0.05;

static void feHeartbeat(void* user, const csfNewtonIter* it) {
  FeReport* rep = user;
  rep->iters++;
  const double now = csu_wallSeconds();
  if (now - rep->t_last >= kHeartbeatS) {
    fprintf(rep->notes, "  fe: working at load %.5f MPa: Newton iteration %d, |R| %.3g N (of "
            "%.3g), %ld iterations in the last %.0f s\n", it->load, it->iter, it->rnorm, it->fnorm,
            rep->iters, now - rep->t_last);
    rep->t_last = now;
    rep->iters = 0;
  }
}


static void feWalls(const csfBendStep* st, char* out, size_t sz);


static void feProgress(void* user, const csfBendStep* st) {
  FeReport* rep = user;
  rep->t_last = csu_wallSeconds();
  rep->iters = 0;
  if (rep->f && rep->bc && rep->flush_err.status == CS_OK) {
    /* the file on disk holds every row so far, whatever stops the sweep (core_h5.h) */
    csr_bendCurveFlushH5(rep->f, rep->bc, &rep->flush_err);
  }
  if (st->note) {
    fprintf(rep->notes, "  fe: %s\n", st->note); /* a bifurcation and the branch switched to */
  }
  char inertia[128] = "";
  if (st->neg_pivots > 0) {
    snprintf(inertia, sizeof inertia, ", tangent indefinite (%d negative pivot%s)",
             st->neg_pivots, st->neg_pivots > 1 ? "s" : "");
  }
  if (st->branch) {
    /* on the switched branch: how far it is from the mirror-symmetric path */
    const size_t k = strlen(inertia);
    snprintf(inertia + k, sizeof inertia - k, ", switched branch (twin chambers differ by %.2e)",
             st->asym);
  }
  /* the free surfaces (fem_wall.h): crease and contact measures, and the worst element */
  char walls[160];
  feWalls(st, walls, sizeof walls);
  if (st->volume_control) {
    fprintf(rep->notes, "  fe: volume control: V %.1f mm^3, p = %.5f MPa (dp %+.5f), %d Newton "
            "iterations, %.2f s, total %.2f deg%s%s\n", st->volume, st->p, st->dp,
            st->newton_iters, st->wall, st->angle_total, inertia, walls);
    return;
  }
  fprintf(rep->notes, "  fe: p = %.4f MPa (dp %.4f), %d Newton iterations, %d cut-backs, %.2f s, "
          "total %.2f deg%s%s\n", st->p, st->dp, st->newton_iters, st->cutbacks, st->wall,
          st->angle_total, inertia, walls);
}


static void feWalls(const csfBendStep* st, char* out, size_t sz) {
  size_t k = (size_t)snprintf(out, sz, "; J_min %.3f", st->jmin);
  if (isfinite(st->lam_vented) && k < sz) {
    k += (size_t)snprintf(out + k, sz - k, ", vented walls lam_eq %.3f, gap %.3f mm",
                          st->lam_vented, st->gap);
  }
  if (isfinite(st->lam_skin) && k < sz) {
    snprintf(out + k, sz - k, ", skin lam_eq %.3f", st->lam_skin);
  }
}


/* the summary of the free surfaces at the sweep's end (fem_wall.h) */
static void feWallReport(FILE* notes, const csrActuator* act, const csfBendInfo* info,
                         int stalled) {
  const csfBendWall* w = &info->wall;
  if (w->vented.npoint > 0) {
    char where[160];
    csf_bendDescribePoint(act, w->vented.X, where, sizeof where);
    const int past = w->vented.lam_eq < CSF_CREASE_STRETCH;
    fprintf(notes, "crawlsim bend: fe: vented chambers' walls at the end: compressed to a "
            "plane-strain-equivalent stretch lam_c sqrt(lam_t) = %.3f (lam_c %.3f along (%.2f, "
            "%.2f, %.2f), lam_t %.3f), %s: %s the crease onset %.2f (Hong, Zhao & Suo 2009)",
            w->vented.lam_eq, w->vented.lam_c, w->vented.dir[0], w->vented.dir[1],
            w->vented.dir[2], w->vented.lam_t, where, past ? "past" : "short of",
            CSF_CREASE_STRETCH);
    if (!isnan(info->p_crease)) {
      fprintf(notes, ", passed at %.5f MPa (%.2f deg)", info->p_crease, info->angle_crease);
    }
    fprintf(notes, "; the most distorted element (J %.3f) is %.2f mm from that point\n",
            info->j_min, info->j_min_wall_dist);
    if (isfinite(w->gap.gap)) {
      csf_bendDescribePoint(act, w->gap.X, where, sizeof where);
      fprintf(notes, "crawlsim bend: fe: smallest gap between opposite walls of a vented "
              "chamber: %.3f mm (%.3f mm undeformed), %s\n", w->gap.gap, w->gap0, where);
    }
    const int closed = isfinite(w->gap.gap) && w->gap.gap < kGapClosed * w->gap0;
    if (past && stalled) {
      fprintf(notes, "crawlsim bend: fe: the sweep ended with the vented chambers' walls past "
              "the crease onset%s: a real wall folds into a self-contacting crease there%s, "
              "which this model (no self-contact) cannot follow; a limit of the model, not of "
              "its mesh (fem/README.md \"Creases and closing chambers\")\n",
              closed ? " and a chamber closed" : "",
              closed ? " and the chamber's opposite walls have met" : "");
    } else if (past) {
      fprintf(notes, "crawlsim bend: fe: past %.5f MPa the states are the smooth, creaseless "
              "solution, which a real wall leaves by creasing (this model has no self-contact)"
              "\n", info->p_crease);
    }
  }
  if (w->skin.npoint > 0) {
    fprintf(notes, "crawlsim bend: fe: the skin at the end: plane-strain-equivalent stretch "
            "%.3f (lam_c %.3f, lam_t %.3f) at (%.2f, %.2f, %.2f) mm%s", w->skin.lam_eq,
            w->skin.lam_c, w->skin.lam_t, w->skin.X[0], w->skin.X[1], w->skin.X[2],
            w->skin.lam_eq < CSF_CREASE_STRETCH ? ", past the crease onset" : "");
    if (!isnan(info->p_crease_skin)) {
      fprintf(notes, " (from %.5f MPa)", info->p_crease_skin);
    }
    fprintf(notes, "\n");
  }
}


/* the free surfaces' figures as root attributes of the bend file */
static csStatus feWallAttrs(csH5File* f, const csfBendInfo* info, csError* err) {
  const csfBendWall* w = &info->wall;
  const struct {
    const char* name;
    double v;
  } a[] = {
      {"fe_crease_stretch", CSF_CREASE_STRETCH},
      {"fe_vented_lam_eq", w->vented.npoint > 0 ? w->vented.lam_eq : NAN},
      {"fe_vented_lam_c", w->vented.npoint > 0 ? w->vented.lam_c : NAN},
      {"fe_vented_lam_t", w->vented.npoint > 0 ? w->vented.lam_t : NAN},
      {"fe_p_crease_MPa", info->p_crease},
      {"fe_skin_lam_eq", w->skin.npoint > 0 ? w->skin.lam_eq : NAN},
      {"fe_p_crease_skin_MPa", info->p_crease_skin},
      {"fe_vented_gap_mm", isfinite(w->gap.gap) ? w->gap.gap : NAN},
      {"fe_vented_gap0_mm", w->gap0},
      {"fe_j_min", info->j_min},
      {"fe_j_min_wall_dist_mm", info->j_min_wall_dist},
  };
  for (size_t k = 0; k < sizeof a / sizeof a[0]; k++) {
    csStatus st = cs_h5AttrDouble(f, "/", a[k].name, a[k].v, err);
    if (st != CS_OK) {
      return st;
    }
  }
  return CS_OK;
}


static csStatus feSweep(BendRun* run, const csfThreadPlan* plan, csrBendCurve* bc,
                        csH5File* f, csfBendInfo* infop, csError* err) {
  csfBendOptions o = csf_bendDefault();
  o.threads = plan->threads;
  o.spec.mpi_ranks = csx_feRanks(&o.spec.mpi_ranks_local); /* crawlsim-mpi under mpirun */
  /* chamber j of every segment at ratio[j] x p (--chambers: 1 or 0; --pressures: R_j) */
  if (run->segments == 1) {
    /* II1 alone: the actuator's record (the output's parameters) says S2 = S3 = 0 */
    csrActuator one;
    csr_actuatorSingleSegment(&run->act, &one);
    run->act = one;
  }
  for (int s = 0; s < CSR_NSEG; s++) {
    for (int j = 0; j < CSR_NCHAMBER; j++) {
      o.spec.ratio[s][j] = run->act.S[s] > 0 ? run->ratio[j] : 0.0;
    }
  }
  for (int i = 0; i < 3; i++) {
    o.spec.tip_force[i] = run->tip_load[i];
  }
  csStatus st = CS_OK;
  o.p_max = run->p_max;
  o.p_step = run->p_step;
  o.until_angle = run->until_angle;
  if (!isnan(run->mesh_size)) {
    o.spec.mesh_size = run->mesh_size;
  }
  if (!isnan(run->fibre_size)) {
    o.spec.fibre_size = run->fibre_size;
  }
  if (run->fibre_split >= 0) {
    o.spec.fibre_split = run->fibre_split;
  }
  if (run->fibre_tension_only >= 0) {
    o.spec.fibre_compression = !run->fibre_tension_only;
  }
  if (run->branch_switch >= 0) {
    o.branch_switch = run->branch_switch;
  }
  if (run->mesh_symmetric >= 0) {
    o.spec.mesh_symmetric = run->mesh_symmetric;
  }
  /* deformed mesh and solver deck next to the HDF5 file: FILE.h5 -> FILE.vtu, FILE.inp */
  char stem[512], vtu[520], inp[520];
  snprintf(stem, sizeof stem, "%s", run->out);
  char* dot = strrchr(stem, '.');
  if (dot && !strchr(dot, '/')) {
    *dot = '\0';
  }
  snprintf(vtu, sizeof vtu, "%s.vtu", stem);
  snprintf(inp, sizeof inp, "%s.inp", stem);
  o.spec.work_stem = stem;
  o.vtu_path = vtu;
  o.inp_path = inp;
  FeReport report = {csu_wallSeconds(), 0, f, bc, {CS_OK, ""}, run->notes};
  o.cancel = csx_signalFlag();
  o.progress = feProgress;
  o.progress_user = &report;
  o.newton_monitor = feHeartbeat;
  csfBendInfo info;
  memset(&info, 0, sizeof info);
  o.info = &info;
  if (isfinite(o.until_angle)) {
    /* the sweep's own bound: an angle the actuator never reaches ends at p-max, not never */
    fprintf(run->notes, "crawlsim bend: fe: --until-angle %g deg: the sweep stops at --p-max %g "
            "MPa (its limit) if the angle is not reached first\n", o.until_angle, o.p_max);
  }
  st = csf_bend(&run->act, &o, bc, err);
  if (st == CS_OK && report.flush_err.status != CS_OK) {
    *err = report.flush_err; /* the disk refused a row: say so, not the solver's outcome */
    st = err->status;
  }
  if (st == CS_OK) {
    run->mesh_size = o.spec.mesh_size;
    run->fibre_size = o.spec.fibres ? csf_actuatorFibreSize(&o.spec) : NAN;
    run->fibre_split = o.spec.fibre_split;
    run->mesh_symmetric = o.spec.mesh_symmetric;
    run->fibre_tension_only = !o.spec.fibre_compression;
    run->p_indefinite = info.p_indefinite;
    run->neg_pivots_max = info.neg_pivots_max;
    run->n_elements_soft = info.ntet;
    run->n_elements_fibre = info.nfibre;
    run->p_limit = info.p_limit;
    run->limit_shown = info.limit_shown;
    run->p_resume = info.p_resume;
    fprintf(run->notes, "crawlsim bend: fe: %d tets, %d nodes, %d fibre elements, %d steps, %ld "
            "Newton iterations; assembly %.1f s, factorisation %.1f s, solves %.1f s, total %.1f "
            "s; deformed mesh %s, deck %s\n", info.ntet, info.nnode, info.nfibre, info.n_steps,
            info.n_newton, info.t_assemble, info.t_factor, info.t_solve, info.t_total, vtu, inp);
    csx_feReportThreads(run->notes, "bend", plan, &info);
    if (info.n_until_trials > 0) {
      fprintf(run->notes, "crawlsim bend: fe: until-angle refinement: %d equilibrium trials, %d "
              "failed%s%s\n", info.n_until_trials, info.n_until_failed,
              info.until_note[0] ? "; last failure: " : "", info.until_note);
    }
    if (info.bifurcation_note[0]) {
      fprintf(run->notes, "crawlsim bend: fe: %s\n", info.bifurcation_note);
    }
    if (!isnan(info.p_indefinite)) {
      fprintf(run->notes, "crawlsim bend: fe: the tangent stiffness lost positive definiteness "
              "between %.5f and %.5f MPa (up to %d negative pivots of LDL^T): the pressure-"
              "controlled path crossed a critical point there (a limit point if the pressure "
              "falls under volume control, otherwise a bifurcation: a lower-energy branch "
              "exists)\n", info.p_definite, info.p_indefinite, info.neg_pivots_max);
    } else if (info.neg_pivots_max == 0) {
      fprintf(run->notes, "crawlsim bend: fe: every converged state had a positive definite "
              "tangent (stable under pressure control)\n");
    }
    if (info.n_hard_passed > 0) {
      fprintf(run->notes, "crawlsim bend: fe: %d hard stretch%s of the path (pressure control "
              "failed, the pressure kept rising under chamber-volume control: no limit point) "
              "followed by volume%s\n", info.n_hard_passed, info.n_hard_passed > 1 ? "es" : "",
              info.n_rows_skipped > 0 && isnan(info.p_resume) ? "; some output pressures have "
              "no row" : "");
    }
    if (!isnan(info.p_limit) && !isnan(info.p_resume)) {
      fprintf(run->notes, "crawlsim bend: fe: pressure limit point at %.5f MPa (%.2f deg): passed "
              "by chamber-volume control (%d steps); stable again at %.5f MPa (%.2f deg), where "
              "the sweep resumed: under pressure control the actuator snaps across, the curve "
              "has no rows in between\n", info.p_limit, info.angle_limit, info.n_volume_steps,
              info.p_resume, info.angle_resume);
    } else if (!isnan(info.p_limit) && info.limit_shown) {
      fprintf(run->notes, "crawlsim bend: fe: pressure limit point at %.5f MPa (%.2f deg)%s%s: the "
              "sweep ends there\n", info.p_limit, info.angle_limit,
              info.limit_note[0] ? "; past it: " : "", info.limit_note);
    } else if (!isnan(info.p_limit)) {
      fprintf(run->notes, "crawlsim bend: fe: the sweep ends at %.5f MPa (%.2f deg): pressure "
              "control failed there and the pressure did not fall under volume control (no limit "
              "point shown)%s%s; the most distorted element (reference centroid %.2f, %.2f, %.2f "
              "mm) has a pointwise J of %.3f%s\n", info.p_limit, info.angle_limit,
              info.limit_note[0] ? "; " : "", info.limit_note, info.j_min_X[0], info.j_min_X[1],
              info.j_min_X[2], info.j_min,
              info.j_min < CSX_J_DISTORTED ? " (its elements fold)" : "");
    }
    /* stalled (both controls failed, no limit point): the walls say why */
    const int stalled = !isnan(info.p_limit) && !info.limit_shown && isnan(info.p_resume);
    feWallReport(run->notes, &run->act, &info, stalled);
  }
  *infop = info;
  return st;
}

csStatus csx_bendFe(BendRun* run, csxBendResult* res, csError* ferr) {
  csH5File* ff = cs_h5Create(run->out, ferr);
  csrBendCurve fbc;
  memset(&fbc, 0, sizeof fbc);
  double t0 = csu_wallSeconds();
  csStatus fst = ff ? csr_bendCurveInit(&fbc, 16, ferr) : ferr->status;
  csfBendInfo info;
  memset(&info, 0, sizeof info);
  csfThreadPlan plan;
  csx_fePlanThreads(run->notes, "bend", run->threads, &plan);
  if (fst == CS_OK) {
    fst = feSweep(run, &plan, &fbc, ff, &info, ferr);
  }
  if (fst == CS_OK) {
    csrBendMeta meta = {"fe",
                        run->chambers,
                        run->mesh_size,
                        run->n_elements_soft,
                        run->n_elements_fibre,
                        csu_wallSeconds() - t0,
                        run->until_angle,
                        run->limit_shown ? run->p_limit : NAN,
                        run->p_resume,
                        run->n_elements_fibre > 0 ? run->fibre_size : 0,
                        run->fibre_split,
                        run->fibre_tension_only,
                        run->p_indefinite,
                        run->neg_pivots_max,
                        run->limit_shown ? NAN : run->p_limit,
                        run->mesh_symmetric};
    fst = csr_bendCurveWriteH5(ff, &run->act, &fbc, &meta, ferr);
    if (fst == CS_OK) {
      fst = feWallAttrs(ff, &info, ferr);
    }
    if (fst == CS_OK) {
      fst = csx_feThreadAttrs(ff, &plan, &info, ferr);
    }
  }
  if (ff) {
    fst = csx_bendFileClose(ff, "fe", &fbc, fst, ferr);
  }
  if (fst != CS_OK) {
    csr_bendCurveFree(&fbc);
    return fst;
  }
  csx_bendResultFill(run, &fbc, res);
  fprintf(run->table, "crawlsim bend: model fe, actuator %s, chambers %s in %s\n", run->act.name,
          run->chambers, csr_actuatorIsSingle(&run->act) ? "II1 alone (single segment)"
                                                        : "II1-II3");
  fprintf(run->table, "%9s %9s %9s %9s %10s\n", "p (MPa)", "II1 (deg)", "II2 (deg)", "II3 (deg)",
          "total(deg)");
  for (size_t i = 0; i < fbc.m; i++) {
    const double* a = &fbc.angle_deg[3 * i];
    fprintf(run->table, "%9.4f %9.3f %9.3f %9.3f %10.3f\n", fbc.pressure[i], a[0], a[1], a[2],
            fbc.angle_total[i]);
  }
  if (!isnan(run->until_angle)) {
    if (isnan(fbc.p_until_angle) && fbc.m > 0 &&
        fbc.angle_total[fbc.m - 1] >= run->until_angle) {
      /* bracketed by converged states, but the refinement did not reach the angle tolerance */
      snprintf(res->until_line, sizeof res->until_line, "until-angle: total angle %g deg passed "
               "(%.3f deg at %.6f MPa) but not refined to the angle tolerance: no pressure "
               "reported", run->until_angle, fbc.angle_total[fbc.m - 1], fbc.pressure[fbc.m - 1]);
    } else if (isnan(fbc.p_until_angle) && fbc.m > 0 &&
               fbc.pressure[fbc.m - 1] < run->p_max * (1.0 - 1e-9) && !isnan(run->p_limit)) {
      /* the sweep ended below p-max (a limit point without a stable branch, or both controls
       * failed: the report line above says which) */
      snprintf(res->until_line, sizeof res->until_line, "until-angle: total angle %g deg not "
               "reached: the sweep ended at %.5f MPa, below p-max %g MPa (last row %.2f deg at "
               "%.4f MPa)", run->until_angle, run->p_limit, run->p_max, fbc.angle_total[fbc.m - 1],
               fbc.pressure[fbc.m - 1]);
    } else if (isnan(fbc.p_until_angle)) {
      snprintf(res->until_line, sizeof res->until_line, "until-angle: total angle %g deg not "
               "reached up to %g MPa", run->until_angle, run->p_max);
    } else {
      snprintf(res->until_line, sizeof res->until_line, "until-angle: total angle %g deg at p = "
               "%.6f MPa", run->until_angle, fbc.p_until_angle);
    }
    fprintf(run->table, "%s\n", res->until_line);
  }
  csr_bendCurveFree(&fbc);
  return CS_OK;
}
#else
typedef int csxBendFeUnused; /* ISO C: a translation unit must not be empty */
#endif
