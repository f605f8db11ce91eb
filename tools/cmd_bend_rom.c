/* cmd_bend_rom.c: `crawlsim bend --model rom`: the pressure sweep of the reduced-order FE leg
 * (fem/fem_rom_act.h, issue 34), with the FE's output contract (cmd_bend_fe.c): the same rows
 * (p = 0, p-step, ..., p-max), angles measured by the FE's gauges on the reconstructed
 * displacement (csf_bendMeasure: face frames, swing-twist about the pattern's bending axis), the
 * same bend file plus the reduced model's attributes. Each row is the reduced statics ramped
 * from the previous row. --until-angle is not offered yet (refused). */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include <time.h>

#include "cmd_bend.h"
#include "core_clock.h"
#include "cs_signal.h"

#ifdef CS_HAVE_FEM
#include "fem_measure.h"
#include "fem_rom_act.h"
#include "robot_rom_file.h"

/* the reduced actuator from a leg file (robot/rom/robot_rom_file.h): the mesh, the FE model of
 * the kernels, the basis, the weights and the chambers' cubic forms as `crawlsim rom leg-file`
 * computed them, so no gmsh and no n + 1 passes over the chambers' faces (the set-up of the
 * --rom-basis path, 80 % of its command's CPU: docs/notes/rom.md, session romacc) */
static csStatus romFromFile(BendRun* run, const csfActuatorSpec* spec, csfRomActuator* ra,
                            csError* err) {
  csrRomLegFile lf;
  csStatus st = csr_romLegFileRead(run->rom_file, &lf, err);
  if (st != CS_OK) {
    return st;
  }
  st = csr_romLegFileCheckActuator(&lf, run->rom_file, &run->act, err);
  if (st == CS_OK && !isnan(run->mesh_size) &&
      fabs(run->mesh_size - lf.l_soft) > 1e-12 * lf.l_soft) {
    st = cs_errorSet(err, CS_ERR_ARG, "--mesh-size %g: the leg file %s was made on l_soft %g mm",
                     run->mesh_size, run->rom_file, lf.l_soft);
  }
  if (st != CS_OK) {
    csr_romLegFileFree(&lf);
    return st;
  }
  run->mesh_size = lf.l_soft;
  csfMesh* me = lf.mesh;
  csfModel* m = lf.model;
  csfRom* rom = lf.rom;
  lf.mesh = NULL, lf.model = NULL, lf.rom = NULL; /* ra owns them from here */
  csr_romLegFileFree(&lf);
  return csf_romActuatorFromModel(&run->act, spec, me, m, rom, run->rom_file, ra, err);
}

static csStatus romSweep(BendRun* run, csrBendCurve* bc, csfRomActuator* ra, double* t_sweep,
                         double* t_cpu, csError* err) {
  csfActuatorSpec spec = csf_actuatorSpecDefault();
  for (int s = 0; s < CSR_NSEG; s++) {
    for (int j = 0; j < CSR_NCHAMBER; j++) {
      spec.ratio[s][j] = run->ratio[j]; /* the bending axis of the angles (fem_actuator.c) */
    }
  }
  csStatus st = CS_OK;
  if (run->rom_file) {
    st = romFromFile(run, &spec, ra, err);
  } else {
    const double l = csf_romBasisMeshSize(run->rom_basis, err);
    if (isnan(l)) {
      return err->status;
    }
    if (!isnan(run->mesh_size) && fabs(run->mesh_size - l) > 1e-12 * l) {
      return cs_errorSet(err, CS_ERR_ARG, "--mesh-size %g: the basis %s was made on l_soft %g "
                         "mm", run->mesh_size, run->rom_basis, l);
    }
    spec.mesh_size = l;
    spec.mesh_symmetric = 1;
    char stem[512];
    snprintf(stem, sizeof stem, "%s", run->out);
    char* dot = strrchr(stem, '.');
    if (dot && !strchr(dot, '/')) {
      *dot = '\0';
    }
    spec.work_stem = stem;
    st = csf_romActuatorCreate(&run->act, &spec, run->rom_basis, run->rom_weights, ra, err);
    run->mesh_size = l;
  }
  if (st != CS_OK) {
    return st;
  }
  run->n_elements_soft = ra->fe.mesh->ntet;
  run->n_elements_fibre = ra->fe.model->nfib;
  run->mesh_symmetric = 1;
  const double t0 = csu_wallSeconds(); /* the sweep alone (the set-up meshes with gmsh) */
  struct timespec c0, c1; /* and its CPU time: wall times on a loaded machine say little */
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &c0);
  const size_t nstep = (size_t)floor(run->p_max / run->p_step * (1 + 1e-9));
  double prev[4] = {0, 0, 0, 0};
  for (size_t i = 0; st == CS_OK && i <= nstep + 1; i++) {
    const double p = i <= nstep ? fmin((double)i * run->p_step, run->p_max) : run->p_max;
    if (i == nstep + 1 && p - (double)nstep * run->p_step <= 1e-9 * run->p_max) {
      break; /* p-max was on the grid */
    }
    if (*csx_signalFlag()) {
      return cs_errorSet(err, CS_ERR_INTERRUPTED, "interrupted at p = %.6g MPa (%zu rows kept)",
                         p, bc->m);
    }
    double P[CSR_NSEG * CSR_NCHAMBER];
    for (int s = 0; s < CSR_NSEG; s++) {
      for (int j = 0; j < CSR_NCHAMBER; j++) {
        P[CSR_NCHAMBER * s + j] = run->ratio[j] * p;
      }
    }
    const double g[3] = {0, 0, 0}; /* gravity off, as the other models of `bend` */
    st = csf_romActuatorSolve(ra, P, g, run->tip_load, err);
    if (st != CS_OK) {
      char cause[sizeof err->msg];
      memcpy(cause, err->msg, sizeof cause);
      return cs_errorSet(err, st, "rom model failed at p = %.6g MPa (the %zu rows before it are "
                         "kept): %.400s", p, bc->m, cause);
    }
    const csfData v = csf_romActuatorView(ra);
    double ang[3], tot, tip[3];
    csf_bendMeasure(&run->act, ra->fe.gauges, ra->fe.model, &v, ra->fe.axis, prev, ang, &tot,
                    tip);
    prev[0] = ang[0], prev[1] = ang[1], prev[2] = ang[2], prev[3] = tot;
    st = csr_bendCurvePush(bc, p, ang, tip, err);
    if (st == CS_OK) {
      /* the base-to-tip rotation, joints included, as the FE's rows (fem_bend.c): the push's
       * sum of the segments leaves the joints out (0.35 deg at 0.4 MPa on the short leg) */
      bc->angle_total[bc->m - 1] = tot;
    }
  }
  *t_sweep = csu_wallSeconds() - t0;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &c1);
  *t_cpu = (double)(c1.tv_sec - c0.tv_sec) + 1e-9 * (double)(c1.tv_nsec - c0.tv_nsec);
  return st;
}


csStatus csx_bendRom(BendRun* run, csxBendResult* res, csError* err) {
  if (!run->rom_basis && !run->rom_file) {
    return cs_errorSet(err, CS_ERR_ARG, "--model rom needs --rom-basis FILE "
                       "(tools/rom_basis.py) or --rom-file LEG.h5 (crawlsim rom leg-file; "
                       "docs/notes/rom.md)");
  }
  if (!isnan(run->until_angle)) {
    return cs_errorSet(err, CS_ERR_ARG, "--until-angle is not offered by --model rom yet");
  }
  csH5File* f = cs_h5Create(run->out, err);
  csrBendCurve bc;
  memset(&bc, 0, sizeof bc);
  const double t0 = csu_wallSeconds();
  csStatus st = f ? csr_bendCurveInit(&bc, 16, err) : err->status;
  csfRomActuator ra;
  memset(&ra, 0, sizeof ra);
  double t_sweep = NAN, t_cpu = NAN;
  if (st == CS_OK) {
    st = romSweep(run, &bc, &ra, &t_sweep, &t_cpu, err);
  }
  const double wall = csu_wallSeconds() - t0;
  if (st == CS_OK) {
    csrBendMeta meta = {"rom", run->chambers, run->mesh_size, run->n_elements_soft,
                        run->n_elements_fibre, wall, NAN, NAN, NAN, 0, 0, 0, NAN, -1, NAN, 1};
    st = csr_bendCurveWriteH5(f, &run->act, &bc, &meta, err);
    const struct {
      const char* name;
      double v;
    } a[] = {
        {"rom_n", ra.rom->n},
        {"rom_tet_kept", ra.rom->nel[CSF_ROM_SET_TET]},
        {"rom_fibre_kept", ra.rom->nel[CSF_ROM_SET_FIBRE]},
        {"rom_face_kept", ra.rom->nel[CSF_ROM_SET_FACE]},
        {"rom_newton_iterations", (double)ra.n_newton},
        {"rom_steps", ra.n_steps},
        {"rom_cutbacks", ra.n_cutbacks},
        {"rom_sweep_s", t_sweep},
        {"rom_sweep_cpu_s", t_cpu},
        {"rom_tangents", (double)ra.d->n_tangent},
    };
    for (size_t k = 0; st == CS_OK && k < sizeof a / sizeof a[0]; k++) {
      st = cs_h5AttrDouble(f, "/", a[k].name, a[k].v, err);
    }
    if (st == CS_OK) {
      st = cs_h5AttrString(f, "/", "rom_basis", run->rom_basis ? run->rom_basis : "none", err);
    }
    if (st == CS_OK) {
      st = cs_h5AttrString(f, "/", "rom_weights", run->rom_weights ? run->rom_weights : "none",
                           err);
    }
    if (st == CS_OK) {
      st = cs_h5AttrString(f, "/", "rom_file", run->rom_file ? run->rom_file : "none", err);
    }
  }
  if (f) {
    st = csx_bendFileClose(f, "rom", &bc, st, err);
  }
  if (st != CS_OK) {
    csr_bendCurveFree(&bc);
    csf_romActuatorDestroy(&ra);
    return st;
  }
  csx_bendResultFill(run, &bc, res);
  fprintf(run->notes, "crawlsim bend: rom: n = %d, %d of %d Tet10, %d of %d fibre elements, %d of "
          "%d faces; %d steps, %d cut-backs, %ld reduced Newton iterations, %ld evaluations, %ld "
          "tangents; sweep %.3f s wall, %.3f s CPU (set-up included %.1f s wall)\n", ra.rom->n,
          ra.rom->nel[CSF_ROM_SET_TET], ra.fe.mesh->ntet, ra.rom->nel[CSF_ROM_SET_FIBRE],
          ra.fe.model->nfib, ra.rom->nel[CSF_ROM_SET_FACE], ra.fe.mesh->nface, ra.n_steps,
          ra.n_cutbacks, ra.n_newton, ra.d->n_eval, ra.d->n_tangent, t_sweep, t_cpu, wall);
  fprintf(run->table, "crawlsim bend: model rom, actuator %s, chambers %s in II1-II3\n",
          run->act.name, run->chambers);
  fprintf(run->table, "%9s %9s %9s %9s %10s\n", "p (MPa)", "II1 (deg)", "II2 (deg)", "II3 (deg)",
          "total(deg)");
  for (size_t i = 0; i < bc.m; i++) {
    const double* a = &bc.angle_deg[3 * i];
    fprintf(run->table, "%9.4f %9.3f %9.3f %9.3f %10.3f\n", bc.pressure[i], a[0], a[1], a[2],
            bc.angle_total[i]);
  }
  csr_bendCurveFree(&bc);
  csf_romActuatorDestroy(&ra);
  return CS_OK;
}
#else
typedef int csxBendRomUnused; /* ISO C: a translation unit must not be empty */
#endif
