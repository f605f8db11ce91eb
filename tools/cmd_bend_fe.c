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
#include "core_clock.h"
#include "core_h5.h"
#include "fem_actuator.h"
#include "fem_bend.h"
#include "robot_bend_io.h"

/* a pointwise J below this at a stall: the r1 2 / b 3 and r1 1.5 / b 3 sweeps stalled with
 * their worst element at 0.41 and 0.28, and refining (l_soft 4 -> 3) moved the first stall from
 * 0.459 to 0.468 MPa, where J had again fallen to 0.43 (README, "Design studies") */
#define CSX_J_DISTORTED 0.5

/* the FE sweep's report lines: one per converged step, and a heartbeat at least every
 * kHeartbeatS seconds while Newton works inside a step (cut-backs, continuation), so that a long
 * step never leaves the user without a line for more than a minute */
typedef struct {
  double t_last; /* wall time of the last line printed, s */
  long iters;    /* Newton iterations since then */
} FeReport;

static const double kHeartbeatS = 50.0;

static void feHeartbeat(void* user, const csfNewtonIter* it) {
  FeReport* rep = user;
  rep->iters++;
  const double now = csu_wallSeconds();
  if (now - rep->t_last >= kHeartbeatS) {
    fprintf(stderr, "  fe: working at load %.5f MPa: Newton iteration %d, |R| %.3g N (of %.3g), "
            "%ld iterations in the last %.0f s\n", it->load, it->iter, it->rnorm, it->fnorm,
            rep->iters, now - rep->t_last);
    rep->t_last = now;
    rep->iters = 0;
  }
}


static void feProgress(void* user, const csfBendStep* st) {
  FeReport* rep = user;
  rep->t_last = csu_wallSeconds();
  rep->iters = 0;
  if (st->note) {
    fprintf(stderr, "  fe: %s\n", st->note); /* a bifurcation and the branch switched to */
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
  if (st->volume_control) {
    fprintf(stderr, "  fe: volume control: V %.1f mm^3, p = %.5f MPa (dp %+.5f), %d Newton "
            "iterations, %.2f s, total %.2f deg%s\n", st->volume, st->p, st->dp,
            st->newton_iters, st->wall, st->angle_total, inertia);
    return;
  }
  fprintf(stderr, "  fe: p = %.4f MPa (dp %.4f), %d Newton iterations, %d cut-backs, %.2f s, "
          "total %.2f deg%s\n", st->p, st->dp, st->newton_iters, st->cutbacks, st->wall,
          st->angle_total, inertia);
}


static csStatus feSweep(BendRun* run, csrBendCurve* bc, csError* err) {
  csfBendOptions o = csf_bendDefault();
  /* chamber j of every segment at ratio[j] x p (--chambers: 1 or 0; --pressures: R_j) */
  for (int s = 0; s < CSR_NSEG; s++) {
    for (int j = 0; j < CSR_NCHAMBER; j++) {
      o.spec.ratio[s][j] = run->ratio[j];
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
  FeReport report = {csu_wallSeconds(), 0};
  o.progress = feProgress;
  o.progress_user = &report;
  o.newton_monitor = feHeartbeat;
  csfBendInfo info;
  o.info = &info;
  st = csf_bend(&run->act, &o, bc, err);
  if (st == CS_OK) {
    run->mesh_size = o.spec.mesh_size;
    run->fibre_size = o.spec.fibres ? csf_actuatorFibreSize(&o.spec) : NAN;
    run->fibre_split = o.spec.fibre_split;
    run->fibre_tension_only = !o.spec.fibre_compression;
    run->p_indefinite = info.p_indefinite;
    run->neg_pivots_max = info.neg_pivots_max;
    run->n_elements_soft = info.ntet;
    run->n_elements_fibre = info.nfibre;
    run->p_limit = info.p_limit;
    run->limit_shown = info.limit_shown;
    run->p_resume = info.p_resume;
    fprintf(stderr, "crawlsim bend: fe: %d tets, %d nodes, %d fibre elements, %d steps, %ld Newton "
            "iterations; assembly %.1f s, factorisation %.1f s, solves %.1f s, total %.1f s; "
            "deformed mesh %s, deck %s\n", info.ntet, info.nnode, info.nfibre, info.n_steps,
            info.n_newton, info.t_assemble, info.t_factor, info.t_solve, info.t_total, vtu, inp);
    if (info.n_until_trials > 0) {
      fprintf(stderr, "crawlsim bend: fe: until-angle refinement: %d equilibrium trials, %d "
              "failed%s%s\n", info.n_until_trials, info.n_until_failed,
              info.until_note[0] ? "; last failure: " : "", info.until_note);
    }
    if (info.bifurcation_note[0]) {
      fprintf(stderr, "crawlsim bend: fe: %s\n", info.bifurcation_note);
    }
    if (!isnan(info.p_indefinite)) {
      fprintf(stderr, "crawlsim bend: fe: the tangent stiffness lost positive definiteness "
              "between %.5f and %.5f MPa (up to %d negative pivots of LDL^T): the pressure-"
              "controlled path crossed a critical point there (a limit point if the pressure "
              "falls under volume control, otherwise a bifurcation: a lower-energy branch "
              "exists)\n", info.p_definite, info.p_indefinite, info.neg_pivots_max);
    } else if (info.neg_pivots_max == 0) {
      fprintf(stderr, "crawlsim bend: fe: every converged state had a positive definite "
              "tangent (stable under pressure control)\n");
    }
    if (info.n_hard_passed > 0) {
      fprintf(stderr, "crawlsim bend: fe: %d hard stretch%s of the path (pressure control failed, "
              "the pressure kept rising under chamber-volume control: no limit point) followed "
              "by volume%s\n", info.n_hard_passed, info.n_hard_passed > 1 ? "es" : "",
              info.n_rows_skipped > 0 && isnan(info.p_resume) ? "; some output pressures have "
              "no row" : "");
    }
    if (!isnan(info.p_limit) && !isnan(info.p_resume)) {
      fprintf(stderr, "crawlsim bend: fe: pressure limit point at %.5f MPa (%.2f deg): passed "
              "by chamber-volume control (%d steps); stable again at %.5f MPa (%.2f deg), where "
              "the sweep resumed: under pressure control the actuator snaps across, the curve "
              "has no rows in between\n", info.p_limit, info.angle_limit, info.n_volume_steps,
              info.p_resume, info.angle_resume);
    } else if (!isnan(info.p_limit) && info.limit_shown) {
      fprintf(stderr, "crawlsim bend: fe: pressure limit point at %.5f MPa (%.2f deg)%s%s: the "
              "sweep ends there\n", info.p_limit, info.angle_limit,
              info.limit_note[0] ? "; past it: " : "", info.limit_note);
    } else if (!isnan(info.p_limit)) {
      fprintf(stderr, "crawlsim bend: fe: the sweep ends at %.5f MPa (%.2f deg): pressure control "
              "failed there and the pressure did not fall under volume control (no limit point "
              "shown)%s%s; the most distorted element (reference centroid %.2f, %.2f, %.2f mm) "
              "has a pointwise J of %.3f%s\n",
              info.p_limit, info.angle_limit, info.limit_note[0] ? "; " : "", info.limit_note,
              info.j_min_X[0], info.j_min_X[1], info.j_min_X[2], info.j_min,
              info.j_min < CSX_J_DISTORTED ? " (its elements fold: a finer mesh moves such a "
                                             "stall, README \"Design studies\")" : "");
    }
  }
  return st;
}

int csx_bendFe(BendRun* run) {
  csError ferr;
  cs_errorClear(&ferr);
  csH5File* ff = cs_h5Create(run->out, &ferr);
  csrBendCurve fbc;
  memset(&fbc, 0, sizeof fbc);
  double t0 = csu_wallSeconds();
  csStatus fst = ff ? csr_bendCurveInit(&fbc, 16, &ferr) : ferr.status;
  if (fst == CS_OK) {
    fst = feSweep(run, &fbc, &ferr);
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
                        run->limit_shown ? NAN : run->p_limit};
    fst = csr_bendCurveWriteH5(ff, &run->act, &fbc, &meta, &ferr);
  }
  cs_h5Close(ff);
  if (fst != CS_OK) {
    fprintf(stderr, "crawlsim bend: %s\n", ferr.msg);
    if (ff) {
      remove(run->out);
    }
    csr_bendCurveFree(&fbc);
    return 1;
  }
  printf("crawlsim bend: model fe, actuator %s, chambers %s in II1-II3\n", run->act.name,
         run->chambers);
  printf("%9s %9s %9s %9s %10s\n", "p (MPa)", "II1 (deg)", "II2 (deg)", "II3 (deg)",
         "total(deg)");
  for (size_t i = 0; i < fbc.m; i++) {
    const double* a = &fbc.angle_deg[3 * i];
    printf("%9.4f %9.3f %9.3f %9.3f %10.3f\n", fbc.pressure[i], a[0], a[1], a[2],
           fbc.angle_total[i]);
  }
  if (!isnan(run->until_angle)) {
    if (isnan(fbc.p_until_angle) && fbc.m > 0 &&
        fbc.angle_total[fbc.m - 1] >= run->until_angle) {
      /* bracketed by converged states, but the refinement did not reach the angle tolerance */
      printf("until-angle: total angle %g deg passed (%.3f deg at %.6f MPa) but not refined to "
             "the angle tolerance: no pressure reported\n",
             run->until_angle, fbc.angle_total[fbc.m - 1], fbc.pressure[fbc.m - 1]);
    } else if (isnan(fbc.p_until_angle) && fbc.m > 0 &&
               fbc.pressure[fbc.m - 1] < run->p_max * (1.0 - 1e-9) && !isnan(run->p_limit)) {
      /* the sweep ended below p-max (a limit point without a stable branch, or both controls
       * failed: the report line above says which) */
      printf("until-angle: total angle %g deg not reached: the sweep ended at %.5f MPa, below "
             "p-max %g MPa (last row %.2f deg at %.4f MPa)\n", run->until_angle, run->p_limit,
             run->p_max, fbc.angle_total[fbc.m - 1], fbc.pressure[fbc.m - 1]);
    } else if (isnan(fbc.p_until_angle)) {
      printf("until-angle: total angle %g deg not reached up to %g MPa\n", run->until_angle,
             run->p_max);
    } else {
      printf("until-angle: total angle %g deg at p = %.6f MPa\n", run->until_angle,
             fbc.p_until_angle);
    }
  }
  csr_bendCurveFree(&fbc);
  return 0;
}
#else
typedef int csxBendFeUnused; /* ISO C: a translation unit must not be empty */
#endif
