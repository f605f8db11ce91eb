/* bench_fem_bend.c: benchmark command (not a ctest): one FE bend sweep with per-step timing.
 * Usage: bench_fem_bend [actuator] [l_soft] [p_max] [p_step] [until_angle|nan] [chambers]
 *   [--set N=V]... [--vtu F] [--inp F] [--p2] [--no-fibres] [--fibre-size MM] [--tension-only]
 *   [--fibre-compression]
 *   [--geo-tension] [--ls-energy] [--trace] [--lu] [--stem S] [--rtol R]
 * Default: baseline, l_soft 4 mm, 0 -> 0.4 MPa in 0.05 MPa steps, chambers 1,2 (the issue's
 * benchmark). Prints time per load step and per Newton iteration, then the summary. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fem_bend.h"

static void progress(void* user, const csfBendStep* s) {
  (void)user;
  if (s->volume_control) {
    printf("volume-control step: V %.6g mm^3  p %.6f MPa (dp %+.6f)  iters %2d  wall %7.2f s  "
           "angles %7.2f %7.2f %7.2f  total %7.2f deg  neg. pivots %d\n", s->volume, s->p, s->dp,
           s->newton_iters, s->wall, s->angle_deg[0], s->angle_deg[1], s->angle_deg[2],
           s->angle_total, s->neg_pivots);
    fflush(stdout);
    return;
  }
  printf("step p %.5f MPa (dp %.5f)  iters %2d  cutbacks %d  wall %7.2f s  (%.2f s/iter)  "
         "angles %7.2f %7.2f %7.2f  total %7.2f deg  neg. pivots %d\n",
         s->p, s->dp, s->newton_iters, s->cutbacks, s->wall,
         s->newton_iters ? s->wall / s->newton_iters : 0.0, s->angle_deg[0], s->angle_deg[1],
         s->angle_deg[2], s->angle_total, s->neg_pivots);
  fflush(stdout);
}

static void newtonMonitor(void* user, const csfNewtonIter* it) {
  (void)user;
  printf("  newton load %.5f it %2d  alpha %.3f (%d evals)  g0 %10.3e g1 %10.3e  |R| %9.3e  "
         "fnorm %9.3e  neg. pivots %d  fibres: %4d switched, %4d smoothing, %4d taut  "
         "J_min %.4f at (%.2f, %.2f, %.2f) mm  largest |R_a| %.3e N at node %d "
         "(%.2f, %.2f, %.2f) mm\n",
         it->load, it->iter, it->alpha, it->n_eval, it->g0, it->g1, it->rnorm, it->fnorm,
         it->neg_pivots, it->fib_switch, it->fib_smooth, it->fib_taut, it->jmin, it->jmin_X[0],
         it->jmin_X[1], it->jmin_X[2], it->rmax, it->rmax_node, it->rmax_X[0], it->rmax_X[1],
         it->rmax_X[2]);
  fflush(stdout);
}


int main(int argc, char** argv) {
  csError err = {0};
  csrActuator act;
  const char* name = argc > 1 ? argv[1] : "baseline";
  if (csr_actuatorPreset(&act, name, &err) != CS_OK) {
    fprintf(stderr, "%s\n", err.msg);
    return 1;
  }
  csfBendOptions o = csf_bendDefault();
  csfBendInfo info;
  memset(&info, 0, sizeof info);
  o.info = &info;
  o.progress = progress;
  o.spec.mesh_size = argc > 2 ? atof(argv[2]) : 4.0;
  o.p_max = argc > 3 ? atof(argv[3]) : 0.4;
  o.p_step = argc > 4 ? atof(argv[4]) : 0.05;
  o.until_angle = argc > 5 ? atof(argv[5]) : NAN;
  if (argc > 6 && csf_bendSetChambers(&o, argv[6], &err) != CS_OK) {
    fprintf(stderr, "%s\n", err.msg);
    return 1;
  }
  for (int i = 7; i < argc; i++) {
    if (!strcmp(argv[i], "--set") && i + 1 < argc) {
      if (csr_actuatorSetString(&act, argv[++i], &err) != CS_OK) {
        fprintf(stderr, "%s\n", err.msg);
        return 1;
      }
    } else if (!strcmp(argv[i], "--vtu") && i + 1 < argc) {
      o.vtu_path = argv[++i];
    } else if (!strcmp(argv[i], "--inp") && i + 1 < argc) {
      o.inp_path = argv[++i];
    } else if (!strcmp(argv[i], "--fibre-size") && i + 1 < argc) {
      o.spec.fibre_size = atof(argv[++i]);
    } else if (!strcmp(argv[i], "--rtol") && i + 1 < argc) {
      o.newton_rtol = atof(argv[++i]);
    } else if (!strcmp(argv[i], "--stem") && i + 1 < argc) {
      o.spec.work_stem = argv[++i];
    } else if (!strcmp(argv[i], "--p2")) {
      o.spec.form = CSF_FORM_DISPLACEMENT; /* plain P2, as CalculiX's C3D10 */
    } else if (!strcmp(argv[i], "--no-fibres")) {
      o.spec.fibres = 0;
    } else if (!strcmp(argv[i], "--fibre-compression")) {
      o.spec.fibre_compression = 1;
    } else if (!strcmp(argv[i], "--tension-only")) {
      o.spec.fibre_compression = 0;
    } else if (!strcmp(argv[i], "--geo-tension")) {
      o.spec.fibre_geo_tension = 1;
    } else if (!strcmp(argv[i], "--ls-energy")) {
      o.line_search = CSF_LS_ENERGY;
    } else if (!strcmp(argv[i], "--krylov")) {
      o.krylov = 1;
    } else if (!strcmp(argv[i], "--lu")) {
      o.symmetric = 0; /* unsymmetric LU even where the tangent is symmetric */
    } else if (!strcmp(argv[i], "--no-split")) {
      o.spec.fibre_split = 0;
    } else if (!strcmp(argv[i], "--trace")) {
      o.newton_monitor = newtonMonitor;
    }
  }
  csrBendCurve bc;
  csr_bendCurveInit(&bc, 16, &err);
  csStatus st = csf_bend(&act, &o, &bc, &err);
  if (st != CS_OK) {
    fprintf(stderr, "csf_bend: %s\n", err.msg);
  }
  printf("mesh: %d Tet10, %d nodes, %d dofs, %d fibre elements (%d fibre points projected onto "
         "the meshed surface); l_soft %.2f mm\n", info.ntet, info.nnode, info.ndof, info.nfibre,
         info.nfibre_projected, o.spec.mesh_size);
  printf("time: total %.2f s = mesh %.2f + setup %.2f + assembly %.2f + factorisation %.2f + "
         "solves %.2f (+ rest); %d steps, %ld Newton iterations, %d cutbacks; factor nnz %.3g\n",
         info.t_total, info.t_mesh, info.t_setup, info.t_assemble, info.t_factor, info.t_solve,
         info.n_steps, info.n_newton, info.n_cutbacks, info.factor_nnz);
  printf("linear solves: %s, %ld factorisations (%d redone with pivoting), %ld GMRES solves "
         "(%ld iterations, %.1f per solve)\n", info.solver, info.n_factor, info.n_repivot,
         info.n_krylov, info.n_krylov_iter,
         info.n_krylov ? (double)info.n_krylov_iter / (double)info.n_krylov : 0.0);
  printf("newton: %ld watchdog returns to the best iterate, %ld repeated iterates (cycles)\n",
         info.n_restore, info.n_repeat);
  printf("max |theta - 1| = %.3e; smallest pointwise J %.4f (element at %.2f, %.2f, %.2f mm); "
         "p_limit = %g MPa\n", info.max_j_dev, info.j_min, info.j_min_X[0], info.j_min_X[1],
         info.j_min_X[2], info.p_limit);
  if (info.n_volume_steps > 0) {
    printf("%s: p_limit %.6g MPa at %.3f deg; %d volume-controlled steps; %d hard "
           "stretches (pressure rising); %s\n",
           info.limit_shown ? "limit point" : "no limit point shown", info.p_limit,
           info.angle_limit, info.n_volume_steps, info.n_hard_passed, isnan(info.p_resume)
           ? "no stable branch above it found: sweep ended" : "resumed");
    if (isfinite(info.p_indefinite)) {
      printf("inertia: tangent indefinite from %.6g MPa (last positive definite %.6g MPa), up to "
             "%d negative pivots\n", info.p_indefinite, info.p_definite, info.neg_pivots_max);
    }
    if (!isnan(info.p_resume)) {
      printf("limit point: resumed at %.6g MPa, %.3f deg (snap %.3f -> %.3f deg)\n",
             info.p_resume, info.angle_resume, info.angle_limit, info.angle_resume);
    }
  }
  if (info.n_until_trials > 0) {
    printf("until-angle refinement: %d trials, %d failed%s%s\n", info.n_until_trials,
           info.n_until_failed, info.until_note[0] ? "; last failure: " : "", info.until_note);
  }
  for (size_t i = 0; i < bc.m; i++) {
    printf("p %.5f MPa  angles %8.3f %8.3f %8.3f  total %8.3f deg  tip %8.3f %8.3f %8.3f mm\n",
           bc.pressure[i], bc.angle_deg[3 * i], bc.angle_deg[3 * i + 1], bc.angle_deg[3 * i + 2],
           bc.angle_total[i], bc.tip[3 * i], bc.tip[3 * i + 1], bc.tip[3 * i + 2]);
  }
  if (isfinite(bc.p_until_angle)) {
    printf("p_until_angle = %.5f MPa\n", bc.p_until_angle);
  }
  csr_bendCurveFree(&bc);
  return st == CS_OK ? 0 : 1;
}
