/* sim_run.c: a whole run with HDF5 output per docs/design.md's output contract (see sim_model.h).
 *
 * Layout: /time [N] s; /support/position [N,3] mm; /support/orientation [N,4] (w,x,y,z);
 * /pressure [N,96] MPa; /legs/<A..H>/centerline [N,K,3] mm; and for seeing and checking a run
 * /support/corners [N,8,3] mm (world), /contact/force [N,3] N (terrain on robot, world),
 * /contact/max_depth [N] mm (ODE), /contact/leg_max_depth [N] mm (the co-simulated legs' own soft
 * contact, cs_legContactDepth; 0 for legs in ODE), /contact/foot_force [N,8,3] N (the terrain on
 * each leg, world: cs_footForce), /contact/stance [N,8] (1 standing, 0 swinging),
 * /terrain/corners [nbox*8,3] mm; every dataset with the attributes units and description
 * (kDatasetUnits); root attributes stance_force_threshold_N, scene,
 * conditions, leg_model, gait_file, units, version, terrain, friction, pressure_scale, step_s,
 * macro_step_s, leg_step_s, leg_step_order (tree coupling), leg_step_adaptive and
 * leg_step_tol_mm (the adaptive step; at the end adaptive_steps, adaptive_rejected_steps,
 * adaptive_h_min_s, adaptive_h_median_s, adaptive_h_max_s), contact_kp_N_per_mm, contact_stiffness_scale, links_per_segment, legs_auto_choice and legs_auto_tol_mm (`--legs auto` only),
 * track_error (the configuration's measured track error as the banner says it, from the level
 * table robot/levels.csv; runs built from a definition) and track_error_mm (when it has a row),
 * coupling, support_mass_kg, and at the end wall_time_s, real_time_factor, status, steps,
 * rejected_steps, gain_projections (sim_coupling.c implicitPart), with footholds foothold_file
 * and foothold_choices ("T LEGS OFFSET; ..."), control (open loop, a caller's source, or the
 * landing gate's closed loop) with a gate gate_file, gate_held_s, gate_released, gate_waited
 * and gate_waits ("T LEGS WAIT; ..." s for the gates that waited, sim_gate.c) and the dataset
 * /gate/waits [n, 2] (each gate's table time and wait), with a gate's crawl statement crawl_skip_s,
 * crawl_boundaries_read and crawl_z_mm (its decision, sim_gate.c), with its walk statement
 * walk_skip_s, walk_boundaries_read and walk_x_mm, and per timer (sim_model.h
 * CS_TIMER_LIST) timer_<name>_s and
 * timer_<name>_calls. Samples are appended as the run goes and the file is flushed every
 * simulated second (core_h5.c: each flush writes the whole file image and renames it into
 * place, so the file on disk is complete as of its last flush even after kill -9). While the
 * run goes, status is "running" and samples / flushed_t_s say how far the file on disk
 * reaches; at the end status is "ok", "interrupted at t = ... s" (opt.cancel) or the error.
 * A flush is skipped (the next one catches up) while image writing has cost more than
 * FLUSH_WALL_SHARE of the wall time so far: the image grows with the run, so flushing every
 * second of a long run would cost a time quadratic in its length; and within FLUSH_MIN_WALL_S
 * of wall time after the last one (or the run's start): a run faster than real time would
 * otherwise write its whole image many times per wall second for a file nobody can watch that
 * fast (at 100x real time a 9 s run takes 0.09 s: one image at the end instead of nine). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core_clock.h"
#include "core_h5.h"
#include "core_h5read.h"
#include "core_xdmf.h"
#include "robot_strain.h"
#include "sim_internal.h"
#include "terrains_ccd.h"

#ifndef CS_VERSION_STRING
#define CS_VERSION_STRING "unknown" /* set by core/CMakeLists.txt */
#endif

enum { MAX_CENTERLINE = 201 };

/* at most this share of the wall time goes to writing file images at flushes */
static const double FLUSH_WALL_SHARE = 0.05;
/* and at most one flush per this much wall time (s) */
static const double FLUSH_MIN_WALL_S = 1.0;

typedef struct {
  int time, pos, quat, pres, legs[CSR_NLEG];
  int corners, cforce, cdepth, ldepth; /* support box corners; contact force and depth; the
                                        * co-simulated legs' own contact depth */
  int fforce, stance;                  /* per leg: the terrain's force, stance (1) or swing (0) */
} Series;


static csStatus writeSample(const csModel* m, const csData* d, csH5File* f, const Series* s,
                            double* buf, csError* err) {
  double t = cs_time(d), x[3], q[4];
  cs_supportDisplacement(d, x);
  cs_supportOrientation(d, q);
  csStatus st = cs_h5SeriesAppend(f, s->time, &t, err);
  if (st == CS_OK) st = cs_h5SeriesAppend(f, s->pos, x, err);
  if (st == CS_OK) st = cs_h5SeriesAppend(f, s->quat, q, err);
  if (st == CS_OK) st = cs_h5SeriesAppend(f, s->pres, cs_pressures(d), err);
  double corners[24], cf[3], depth = cs_contactDepth(d);
  cs_supportCorners(m, d, corners);
  cs_contactForce(d, cf);
  if (st == CS_OK) st = cs_h5SeriesAppend(f, s->corners, corners, err);
  if (st == CS_OK) st = cs_h5SeriesAppend(f, s->cforce, cf, err);
  if (st == CS_OK) st = cs_h5SeriesAppend(f, s->cdepth, &depth, err);
  double ldepth = cs_legContactDepth(m, d);
  if (st == CS_OK) st = cs_h5SeriesAppend(f, s->ldepth, &ldepth, err);
  double ff[CSR_NLEG * 3], stance[CSR_NLEG];
  const double f_stance = cs_stanceForceThreshold(m);
  for (int k = 0; k < CSR_NLEG; k++) {
    cs_footForce(m, d, k, ff + 3 * k);
    /* standing: the ground pushes the leg up (world y) by more than the threshold */
    stance[k] = ff[3 * k + 1] > f_stance ? 1.0 : 0.0;
  }
  if (st == CS_OK) st = cs_h5SeriesAppend(f, s->fforce, ff, err);
  if (st == CS_OK) st = cs_h5SeriesAppend(f, s->stance, stance, err);
  for (int k = 0; k < CSR_NLEG && st == CS_OK; k++) {
    cs_legCenterline(m, d, k, m->opt.centerline_points, buf);
    st = cs_h5SeriesAppend(f, s->legs[k], buf, err);
  }
  return st;
}


/* every dataset of a run file with its units and what its numbers are (attributes "units" and
 * "description", docs/reference/output.md): the world frame is x the crawl direction, y up, z
 * lateral (right-handed), origin where the terrain file puts it */
static const struct {
  const char* path;
  const char* units;
  const char* description;
} kDatasetUnits[] = {
    {"/time", "s", "simulated time of each sample"},
    {"/support/position", "mm",
     "support centre's displacement from its position at t = 0, world axes (x crawl, y up, z "
     "lateral)"},
    {"/support/orientation", "1",
     "support orientation quaternion (w, x, y, z), body to world"},
    {"/support/corners", "mm", "the support box's 8 corners, world frame (VTK hexahedron order)"},
    {"/pressure", "MPa", "the 96 chamber pressures (gauge), column label - 1 (A_II1_O1 first)"},
    {"/contact/force", "N",
     "terrain's force on the robot through ODE's contacts (the support and in-world legs; not "
     "the co-simulated legs' own soft contact), world frame"},
    {"/contact/max_depth", "mm", "deepest ODE contact penetration"},
    {"/contact/leg_max_depth", "mm",
     "deepest penetration of the co-simulated legs' own soft contact (0 for legs in ODE)"},
    {"/terrain/corners", "mm", "8 corners per terrain box, world frame"},
    {"/contact/foot_force", "N",
     "the terrain's force on each leg A..H (its foot and any other part touching), world "
     "frame: ODE's contact joints on in-world legs, the leg's own contact law for co-simulated "
     "legs"},
    {"/contact/stance", "1",
     "1 when the leg stands (the ground pushes it up, world y, by more than the root attribute "
     "stance_force_threshold_N), 0 when it swings; legs A..H"},
};


static csStatus writeUnits(const csModel* m, csH5File* f, csError* err) {
  csStatus st = CS_OK;
  for (size_t k = 0; st == CS_OK && k < sizeof kDatasetUnits / sizeof kDatasetUnits[0]; k++) {
    if (!strcmp(kDatasetUnits[k].path, "/terrain/corners") && m->terrain.nbox == 0) {
      continue;
    }
    st = cs_h5AttrString(f, kDatasetUnits[k].path, "units", kDatasetUnits[k].units, err);
    if (st == CS_OK) {
      st = cs_h5AttrString(f, kDatasetUnits[k].path, "description",
                           kDatasetUnits[k].description, err);
    }
  }
  for (int k = 0; st == CS_OK && k < CSR_NLEG; k++) {
    char path[64];
    snprintf(path, sizeof path, "/legs/%c/centerline", 'A' + k);
    st = cs_h5AttrString(f, path, "units", "mm", err);
    if (st == CS_OK) {
      st = cs_h5AttrString(f, path, "description",
                           "the leg's centreline from hip to foot, points equally spaced in arc "
                           "length, world frame", err);
    }
  }
  return st;
}


static csStatus writeHeader(const csModel* m, csH5File* f, Series* s, csError* err) {
  size_t three = 3, four = 4, n96 = CSR_NCHAMBER_TOTAL;
  size_t cl[2] = {(size_t)m->opt.centerline_points, 3}, box[2] = {8, 3};
  size_t nleg = CSR_NLEG, legs3[2] = {CSR_NLEG, 3};
  if ((s->time = cs_h5SeriesCreate(f, "/time", 0, NULL, err)) < 0 ||
      (s->corners = cs_h5SeriesCreate(f, "/support/corners", 2, box, err)) < 0 ||
      (s->cforce = cs_h5SeriesCreate(f, "/contact/force", 1, &three, err)) < 0 ||
      (s->cdepth = cs_h5SeriesCreate(f, "/contact/max_depth", 0, NULL, err)) < 0 ||
      (s->ldepth = cs_h5SeriesCreate(f, "/contact/leg_max_depth", 0, NULL, err)) < 0 ||
      (s->pos = cs_h5SeriesCreate(f, "/support/position", 1, &three, err)) < 0 ||
      (s->quat = cs_h5SeriesCreate(f, "/support/orientation", 1, &four, err)) < 0 ||
      (s->pres = cs_h5SeriesCreate(f, "/pressure", 1, &n96, err)) < 0 ||
      (s->fforce = cs_h5SeriesCreate(f, "/contact/foot_force", 2, legs3, err)) < 0 ||
      (s->stance = cs_h5SeriesCreate(f, "/contact/stance", 1, &nleg, err)) < 0) {
    return err ? err->status : CS_ERR_IO;
  }
  for (int k = 0; k < CSR_NLEG; k++) {
    char path[64];
    snprintf(path, sizeof path, "/legs/%c/centerline", 'A' + k);
    if ((s->legs[k] = cs_h5SeriesCreate(f, path, 2, cl, err)) < 0) {
      return err ? err->status : CS_ERR_IO;
    }
  }
  /* the terrain's boxes as hexahedra ((nbox * 8) x 3, world mm, 8 corners per box in the
   * order of cs_supportCorners) for the XDMF view */
  double tc[CST_MAX_BOXES * 24];
  for (int b = 0; b < m->terrain.nbox; b++) {
    const cstBox* bx = &m->terrain.box[b];
    static const int kHex[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 0, 1}, {0, 0, 1},
                                   {0, 1, 0}, {1, 1, 0}, {1, 1, 1}, {0, 1, 1}};
    for (int c = 0; c < 8; c++) {
      double y[3];
      for (int i = 0; i < 3; i++) {
        y[i] = kHex[c][i] ? bx->hi[i] : bx->lo[i];
      }
      if (bx->oriented) {
        cst_boxPointToWorld(bx, y, tc + 24 * b + 3 * c); /* its own frame to the world */
      } else {
        memcpy(tc + 24 * b + 3 * c, y, sizeof y);
      }
    }
  }
  size_t tdims[2] = {(size_t)m->terrain.nbox * 8, 3};
  csStatus st = m->terrain.nbox > 0 ? cs_h5WriteDoubles(f, "/terrain/corners", 2, tdims, tc, err)
                                    : CS_OK;
  if (st == CS_OK) st = writeUnits(m, f, err);
  if (st == CS_OK) {
    st = cs_h5AttrDouble(f, "/", "stance_force_threshold_N", cs_stanceForceThreshold(m), err);
  }
  if (st == CS_OK) st = cs_h5AttrString(f, "/", "scene", m->scene, err);
  if (st == CS_OK) st = cs_h5AttrString(f, "/", "conditions", cs_conditionsName(m->conditions),
                                        err);
  if (st == CS_OK) st = cs_h5AttrString(f, "/", "leg_model", cs_modelLegLevel(m), err);
  if (st == CS_OK) st = cs_h5AttrString(f, "/", "gait_file", m->gait_path, err);
  if (st == CS_OK) st = cs_h5AttrString(f, "/", "terrain_file", m->terrain.source, err);
  if (st == CS_OK) st = cs_h5AttrString(f, "/", "calibration", m->robot.map.name, err);
  if (st == CS_OK) {
    /* the FE mode table's rule (prism, rbf, rbf-pair), "none" for the other calibrations */
    st = cs_h5AttrString(f, "/", "calibration_rule", csr_calibrationRuleName(m->calibration),
                         err);
  }
  if (st == CS_OK) {
    st = cs_h5AttrString(f, "/", "units",
                         "time s; length mm; pressure MPa; mass t (1e3 kg); force N; "
                         "world frame x crawl direction, y up, z lateral",
                         err);
  }
  if (st == CS_OK) st = cs_h5AttrString(f, "/", "version", CS_VERSION_STRING, err);
  if (st == CS_OK) st = cs_h5AttrDouble(f, "/", "friction", m->contact.mu, err);
  /* the terrain's inclination (deg about +z, +x uphill): gravity is turned by it */
  if (st == CS_OK) st = cs_h5AttrDouble(f, "/", "slope_deg", m->terrain.slope_deg, err);
  if (st == CS_OK) st = cs_h5AttrDouble(f, "/", "pressure_scale", m->sched.pressure_scale, err);
  if (st == CS_OK) st = cs_h5AttrDouble(f, "/", "contact_kp_N_per_mm", m->contact.kp, err);
  if (st == CS_OK) {
    st = cs_h5AttrDouble(f, "/", "contact_stiffness_scale", m->contact.stiffness_scale, err);
  }
  if (st == CS_OK) st = cs_h5AttrDouble(f, "/", "ramp_s", m->sched.ramp, err);
  if (st == CS_OK) st = cs_h5AttrDouble(f, "/", "step_s", m->opt.h, err);
  if (st == CS_OK) st = cs_h5AttrDouble(f, "/", "macro_step_s", cs_modelMacroStep(m), err);
  if (st == CS_OK) {
    st = cs_h5AttrString(f, "/", "coupling",
                         m->robot.leg_type->in_world ? "in-world (ODE joints)"
                         : m->opt.coupling == CS_COUPLING_TREE         ? "tree"
                         : m->opt.coupling == CS_COUPLING_STABILISED   ? "stabilised"
                         : m->opt.coupling == CS_COUPLING_GAUSS_SEIDEL
                             ? (m->opt.coupling_carry ? "gauss-seidel"
                                                      : "gauss-seidel (no momentum carry)")
                             : "staggered",
                         err);
  }
  /* the level's own settings (robot_leg.h csrLegSetting), where it has them */
  const csrLegType* lt = m->robot.leg_type;
  const csrLegSettings* ls = &m->robot.leg_settings;
  if (st == CS_OK && csr_legSettingFind(lt, "rod_tol")) {
    /* the rod's CVODE tolerances relative to the shipped ones (0: the shipped ones) */
    const double tol = csr_legSettingGet(lt, ls, "rod_tol", 1.0);
    st = cs_h5AttrDouble(f, "/", "rod_tolerance_scale", tol > 0 ? tol : 1.0, err);
  }
  if (st == CS_OK && csr_legSettingFind(lt, "joint_links")) {
    /* the rod's elements per solid joint (1 by default; `links` refines the segments only) */
    st = cs_h5AttrDouble(f, "/", "rod_joint_elements", csr_legSettingGet(lt, ls, "joint_links", 1),
                         err);
  }
  if (st == CS_OK && csr_legSettingFind(lt, "keep_matrix")) {
    /* the strain level's iteration matrix across steps (0: a new one every step; > 0 kept
     * until a mode moves this far, rad) */
    st = cs_h5AttrDouble(f, "/", "strain_keep_matrix", csr_legSettingGet(lt, ls, "keep_matrix", 0),
                         err);
  }
  if (st == CS_OK && csr_legSettingFind(lt, "joints")) {
    /* the strain level's basis beside links_per_segment: the joints' order (-1 rigid), the
     * shears as unknowns (1) or Kirchhoff (0), the Magnus sub-intervals per flexible piece */
    st = cs_h5AttrDouble(f, "/", "strain_joint_order", csr_legSettingGet(lt, ls, "joints", 0),
                         err);
    if (st == CS_OK) {
      st = cs_h5AttrDouble(f, "/", "strain_shear", csr_legSettingGet(lt, ls, "shear", 1), err);
    }
    if (st == CS_OK) {
      /* the count the setting stands for (0: by the basis) */
      st = cs_h5AttrDouble(f, "/", "strain_sub_intervals",
                           csr_strainSubIntervals((int)csr_legSettingGet(lt, ls, "links", 2),
                                                  (int)csr_legSettingGet(lt, ls, "sub", 0)),
                           err);
    }
    if (st == CS_OK && csr_legSettingFind(lt, "cal_quantum")) {
      /* the calibration's pressure resolution (MPa; 0: the pressures as given) */
      st = cs_h5AttrDouble(f, "/", "strain_cal_quantum",
                           csr_legSettingGet(lt, ls, "cal_quantum", 0), err);
    }
  }
  if (st == CS_OK && m->robot.leg_file[0]) {
    /* the level's own file (rom: the reduced leg of `crawlsim rom leg-file`) */
    st = cs_h5AttrString(f, "/", "leg_file", m->robot.leg_file, err);
  }
  if (st == CS_OK && csr_legSettingFind(lt, "cal_drop")) {
    char drop[32];
    csr_calDropFormat((unsigned)csr_legSettingGet(lt, ls, "cal_drop", 0), drop, sizeof drop);
    st = cs_h5AttrString(f, "/", "calibration_dropped", drop, err);
  }
  if (st == CS_OK) {
    st = cs_h5AttrDouble(f, "/", "links_per_segment", (int)csr_legSettingGet(lt, ls, "links", 0),
                         err);
  }
  if (st == CS_OK) {
    /* the legs' own step: the tree coupling's one step (before any halving: steps and
     * rejected_steps say how often one was halved), a co-simulated level's exchange, an
     * in-world level's ODE step */
    st = cs_h5AttrDouble(f, "/", "leg_step_s", m->robot.leg_type->in_world ? m->opt.h
                                               : cs_modelMacroStep(m), err);
  }
  if (st == CS_OK && !m->robot.leg_type->in_world && m->opt.coupling == CS_COUPLING_TREE) {
    /* the tree step's formula: 1 backward Euler, 2 BDF2 (the level's setting step_order; a
     * level without one: its csrLegType.step_order; 0 there: backward Euler) */
    const int lvl = lt->step_order ? lt->step_order : 1;
    const int order = (int)csr_legSettingGet(lt, ls, "step_order", lvl);
    st = cs_h5AttrDouble(f, "/", "leg_step_order", order, err);
  }
  if (st == CS_OK && !m->robot.leg_type->in_world && m->opt.coupling == CS_COUPLING_TREE) {
    /* the tree step: fixed (0) or adaptive (1, sim_adaptive.c: leg_step_s is then its longest
     * step, and its tolerance is recorded) */
    st = cs_h5AttrDouble(f, "/", "leg_step_adaptive", m->opt.step_adaptive, err);
    if (st == CS_OK && m->opt.step_adaptive) {
      st = cs_h5AttrDouble(f, "/", "leg_step_tol_mm", m->opt.step_tol, err);
    }
  }
  if (st == CS_OK && m->legs_auto_choice[0]) {
    st = cs_h5AttrString(f, "/", "legs_auto_choice", m->legs_auto_choice, err);
    if (st == CS_OK) st = cs_h5AttrDouble(f, "/", "legs_auto_tol_mm", m->legs_auto_tol_mm, err);
  }
  if (st == CS_OK && m->track_error[0]) {
    /* the configuration's measured track error, as the banner says it (cs_runDefTrackError) */
    st = cs_h5AttrString(f, "/", "track_error", m->track_error, err);
    if (st == CS_OK && !isnan(m->track_error_mm)) {
      st = cs_h5AttrDouble(f, "/", "track_error_mm", m->track_error_mm, err);
    }
  }
  if (st == CS_OK) st = cs_h5AttrDouble(f, "/", "legs_weightless", m->opt.legs_weightless, err);
  if (st == CS_OK) st = cs_h5AttrDouble(f, "/", "pneumatic_tau_s", m->opt.pneumatic_tau, err);
  if (st == CS_OK) st = cs_h5AttrDouble(f, "/", "support_mass_kg", m->robot.support_mass * 1e3,
                                        err);
  return st;
}


/* the series of a run file, in the order of Series' members, with their paths (the legs'
 * centrelines after these) */
static const char* const kSeriesPath[] = {
    "/time", "/support/position", "/support/orientation", "/pressure", NULL, NULL, NULL, NULL,
    NULL, NULL, NULL, NULL, "/support/corners", "/contact/force", "/contact/max_depth",
    "/contact/leg_max_depth", "/contact/foot_force", "/contact/stance"};
enum { NSERIES = (int)(sizeof(Series) / sizeof(int)) };
_Static_assert(sizeof kSeriesPath / sizeof kSeriesPath[0] == NSERIES,
               "a path for every series of Series");


/* a resumed run's output: the first nsample rows of every series of the old file `old` into
 * the new file f (its header written: s), checked to be the rows the checkpoint counts */
static csStatus copyRows(const csModel* m, csH5File* f, const Series* s, const char* old,
                         const char* out_path, long nsample, double t_ck, csError* err) {
  csError e;
  cs_errorClear(&e);
  csH5Reader* r = cs_h5ReaderOpen(old, &e);
  if (!r) {
    return cs_errorSet(err, CS_ERR_IO, "--out %.300s: cannot read the run's output to resume "
                       "it (%.300s)", out_path, e.msg);
  }
  const int* idx = (const int*)s;
  csStatus st = CS_OK;
  for (int k = 0; k < NSERIES && st == CS_OK; k++) {
    char path[64];
    if (kSeriesPath[k]) {
      snprintf(path, sizeof path, "%s", kSeriesPath[k]);
    } else {
      /* Series' legs[] sit between pres and corners: members 4..11 */
      snprintf(path, sizeof path, "/legs/%c/centerline", 'A' + (k - 4));
    }
    size_t dims[4] = {0, 1, 1, 1};
    int rank = 0;
    double* v = cs_h5ReaderDoubles(r, path, 0, NULL, dims, &rank, &e);
    if (!v) {
      st = cs_errorSet(err, CS_ERR_IO, "--out %.300s: not this run's output (%.300s)", out_path,
                       e.msg);
      break;
    }
    const size_t width = dims[1] * (rank > 2 ? dims[2] : 1) * (rank > 3 ? dims[3] : 1);
    if (dims[0] < (size_t)nsample) {
      st = cs_errorSet(err, CS_ERR_IO, "--out %.300s: %s has %zu rows, the checkpoint counts "
                       "%ld (not this run's output, or it was cut before the checkpoint)",
                       out_path, path, dims[0], nsample);
    } else if (k == 0 && !(v[nsample - 1] <= t_ck && v[nsample - 1] > t_ck - m->opt.output_dt -
                                                        cs_modelMacroStep(m))) {
      st = cs_errorSet(err, CS_ERR_IO, "--out %.300s: its sample %ld is at t = %g s, the "
                       "checkpoint is at t = %g s (not this run's output)", out_path, nsample,
                       v[nsample - 1], t_ck);
    }
    for (long i = 0; i < nsample && st == CS_OK; i++) {
      st = cs_h5SeriesAppend(f, idx[k], v + (size_t)i * width, err);
    }
    free(v);
  }
  cs_h5ReaderClose(r);
  return st;
}


csStatus cs_runWrite(const csModel* m, csData* d, const char* out_path, double* wall_s,
                     csError* err) {
  return cs_runWriteCheckpointed(m, d, out_path, NULL, NULL, NULL, NULL, wall_s, err);
}


/* the settling of a checkpointed run (cs_settle's steps) from its step i0 (0: from the start;
 * a checkpoint's), with a checkpoint (no output rows yet) every ck_every steps; cancelled: a
 * checkpoint where it stopped and CS_ERR_INTERRUPTED */
static csStatus settleCheckpointed(const csModel* m, csData* d, long i0, long ck_every,
                                   csCheckpointInfo* ck, const char* ck_path, double* xck,
                                   csError* err) {
  const long n = cs_settleSteps(m);
  ck->nsample = 0;
  ck->wall_s = 0;
  for (long i = i0 + 1; i <= n; i++) {
    if (m->opt.cancel && *m->opt.cancel) {
      csStatus st = ck_path ? cs_checkpointSave(m, d, ck, ck_path, xck, err) : CS_OK;
      return st != CS_OK ? st
                         : cs_errorSet(err, CS_ERR_INTERRUPTED, "interrupted while settling at t "
                                       "= %.6g s", cs_time(d));
    }
    csStatus st = cs_step(m, d, err);
    if (st == CS_OK && ck_every && i % ck_every == 0 && i < n) {
      /* as the run's checkpoints: the integrators restart from the state saved */
      st = cs_checkpointSave(m, d, ck, ck_path, xck, err);
      if (st == CS_OK) st = cs_stateSet(m, d, xck, err);
    }
    if (st != CS_OK) {
      return st;
    }
  }
  cs_settleFinish(m, d);
  return CS_OK;
}


csStatus cs_runWriteCheckpointed(const csModel* m, csData* d, const char* out_path,
                                 const csCheckpointInfo* ck_in, const char* ck_path,
                                 const char* resume, int* settling, double* wall_s,
                                 csError* err) {
  double t_end = cs_modelEndTime(m);
  if (m->opt.centerline_points > MAX_CENTERLINE) {
    return cs_errorSet(err, CS_ERR_RANGE, "at most %d centreline points", MAX_CENTERLINE);
  }
  double H = cs_modelMacroStep(m);
  csCheckpointInfo ck = {"", NAN, 0, 0};
  if (ck_in) {
    ck = *ck_in;
  }
  /* the state buffer of the checkpoints: allocated once, before the loop */
  double* xck = NULL;
  if (ck_path || resume) {
    xck = malloc(sizeof(double) * (size_t)cs_stateSize(m, d));
    if (!xck) {
      return cs_errorSet(err, CS_ERR_MEMORY, "out of memory for the checkpoint's state");
    }
  }
  char prev[1100] = "";
  long i0 = 0; /* steps since t = 0 before this loop (a resumed run's) */
  long ck_every = 0; /* steps between periodic checkpoints (0: none) */
  if (resume) {
    csStatus lst = cs_checkpointLoad(m, d, resume, &ck, xck, err);
    if (lst != CS_OK) {
      free(xck);
      return lst;
    }
    if (ck_path) {
      ck_every = lround(ck.every / H) < 1 ? 1 : lround(ck.every / H);
    }
    if (cs_time(d) < 0) {
      /* a checkpoint of the settling: settle the rest, then the run starts its output */
      if (settling) {
        *settling = 1;
      }
      lst = settleCheckpointed(m, d, cs_settleSteps(m) - lround(-cs_time(d) / H), ck_every, &ck,
                               ck_path, xck, err);
      if (lst != CS_OK) {
        free(xck);
        return lst;
      }
      if (settling) {
        *settling = 0;
      }
      resume = NULL;
    }
  }
  if (resume) {
    csStatus lst = CS_OK;
    i0 = lround(cs_time(d) / H);
    if (i0 >= lround(t_end / H) || cs_runOverAt(m, d, i0)) {
      lst = cs_errorSet(err, CS_ERR_ARG, "--resume %.300s: its run is at t = %g s, at or past "
                        "--t-end %g s (nothing to continue)", resume, cs_time(d), t_end);
    }
    /* OUT.prev left by a resume that stopped before its new file's first flush is the whole
     * one (OUT then holds at most an empty image): the rows come from it */
    FILE* pf = NULL;
    if (lst == CS_OK && snprintf(prev, sizeof prev, "%s.prev", out_path) < (int)sizeof prev &&
        !(pf = fopen(prev, "rb")) && rename(out_path, prev) != 0) {
      lst = cs_errorSet(err, CS_ERR_IO, "--out %.300s: cannot move the output to resume aside "
                        "to %.300s", out_path, prev);
    }
    if (pf) {
      fclose(pf);
    }
    if (lst != CS_OK) {
      free(xck);
      return lst;
    }
  }
  if (ck_path) {
    ck_every = lround(ck.every / H) < 1 ? 1 : lround(ck.every / H);
  }
  if (settling && !resume && cs_time(d) < 0) {
    /* d as created: it settles here, checkpointed too */
    *settling = 1;
    csStatus lst = settleCheckpointed(m, d, 0, ck_every, &ck, ck_path, xck, err);
    if (lst != CS_OK) {
      free(xck);
      return lst;
    }
    *settling = 0;
  }
  csH5File* f = cs_h5Create(out_path, err);
  if (!f) {
    free(xck);
    return err ? err->status : CS_ERR_IO;
  }
  Series s;
  double buf[3 * MAX_CENTERLINE];
  csStatus st = writeHeader(m, f, &s, err);
  const long out_every = cs_modelOutputEvery(m);
  long nsteps = lround(t_end / H);
  long per_second = lround(1.0 / H);
  if (per_second < 1) {
    per_second = 1;
  }
  double w0 = csu_wallSeconds();
  const double wall_before = ck.wall_s; /* a resumed run's earlier pieces' wall time (s) */
  long nsample = 0;        /* samples appended */
  double flush_wall = 0;   /* wall time spent in flushes (s) */
  double flush_last = w0;  /* wall time of the last flush (the run's start before the first) */
  if (st == CS_OK && resume) {
    st = copyRows(m, f, &s, prev, out_path, ck.nsample, cs_time(d), err);
    nsample = ck.nsample;
    if (st == CS_OK) st = cs_h5AttrDouble(f, "/", "samples", (double)nsample, err);
    if (st == CS_OK) st = cs_h5AttrDouble(f, "/", "flushed_t_s", cs_time(d), err);
    if (st == CS_OK) st = cs_h5Flush(f, err);
    if (st == CS_OK) {
      remove(prev); /* the rows are in the new file on disk now */
    }
  } else if (st == CS_OK) {
    double wo = csu_wallSeconds();
    st = writeSample(m, d, f, &s, buf, err);
    nsample += st == CS_OK;
    csu_timerAdd(&d->timer[CS_TIMER_OUTPUT], wo);
  }
  int cancelled = 0;
  int over = 0; /* ended by cs_runOverAt before nsteps */
  long i_ck = resume ? i0 : -1; /* the step of the last checkpoint written or read */
  for (long i = i0 + 1; i <= nsteps && st == CS_OK; i++) {
    if (m->opt.cancel && *m->opt.cancel) {
      /* the caller asked to stop (a signal): between steps, so the state is a whole step */
      cancelled = 1;
      st = cs_errorSet(err, CS_ERR_INTERRUPTED, "%s: interrupted at t = %.6g s", out_path,
                       cs_time(d));
      break;
    }
    st = cs_step(m, d, err);
    if (st == CS_OK && i % out_every == 0) {
      double wo = csu_wallSeconds();
      st = writeSample(m, d, f, &s, buf, err);
      nsample += st == CS_OK;
      csu_timerAdd(&d->timer[CS_TIMER_OUTPUT], wo);
    }
    if (st == CS_OK && ck_every && i % ck_every == 0) {
      /* the output on disk first, so that it holds every row the checkpoint counts */
      double wo = csu_wallSeconds();
      st = cs_h5AttrDouble(f, "/", "samples", (double)nsample, err);
      if (st == CS_OK) st = cs_h5AttrDouble(f, "/", "flushed_t_s", cs_time(d), err);
      if (st == CS_OK) st = cs_h5Flush(f, err);
      flush_last = csu_wallSeconds();
      flush_wall += flush_last - wo;
      ck.nsample = nsample;
      ck.wall_s = wall_before + flush_last - w0;
      if (st == CS_OK) st = cs_checkpointSave(m, d, &ck, ck_path, xck, err);
      /* the integrators restart from the saved state, as a resumed run's do */
      if (st == CS_OK) st = cs_stateSet(m, d, xck, err);
      i_ck = i;
      csu_timerAdd(&d->timer[CS_TIMER_OUTPUT], wo);
    }
    if (i % per_second == 0) {
      double wo = csu_wallSeconds();
      if (st == CS_OK && flush_wall <= FLUSH_WALL_SHARE * (wo - w0) &&
          wo - flush_last >= FLUSH_MIN_WALL_S) {
        /* how far the file on disk reaches once this flush is through */
        st = cs_h5AttrDouble(f, "/", "samples", (double)nsample, err);
        if (st == CS_OK) st = cs_h5AttrDouble(f, "/", "flushed_t_s", cs_time(d), err);
        if (st == CS_OK) st = cs_h5Flush(f, err);
        flush_last = csu_wallSeconds();
        flush_wall += flush_last - wo;
      }
      csu_timerAdd(&d->timer[CS_TIMER_OUTPUT], wo);
      if (m->opt.progress) {
        double x[3];
        cs_supportDisplacement(d, x);
        double w = csu_wallSeconds() - w0;
        m->opt.progress(m->opt.progress_user, cs_time(d), x, w);
      }
    }
    if (st == CS_OK && cs_runOverAt(m, d, i)) {
      over = 1; /* the gait is over on the table's clock (a crawl's skip): the rows stop here */
      break;
    }
  }
  double wall = wall_before + csu_wallSeconds() - w0; /* this loop's and its earlier pieces' */
  if (ck_path && (st == CS_OK || cancelled) && i_ck != lround(cs_time(d) / H)) {
    /* at the end or where a signal stopped it (a whole step): a run continued from here
     * restarts its integrators here, where the uncut run did not (docs/notes/cli_output.md) */
    ck.nsample = nsample;
    ck.wall_s = wall;
    csError ce;
    csStatus cst = cs_h5AttrDouble(f, "/", "samples", (double)nsample, &ce);
    if (cst == CS_OK) cst = cs_h5AttrDouble(f, "/", "flushed_t_s", cs_time(d), &ce);
    if (cst == CS_OK) cst = cs_h5Flush(f, &ce);
    if (cst == CS_OK) cst = cs_checkpointSave(m, d, &ck, ck_path, xck, &ce);
    if (cst != CS_OK && st == CS_OK) {
      st = cst;
      if (err) {
        *err = ce;
      }
    }
  }
  free(xck);
  if (wall_s) {
    *wall_s = wall;
  }
  /* the file stays readable whatever happened: record how the run ended */
  cs_h5AttrDouble(f, "/", "wall_time_s", wall, NULL);
  cs_h5AttrDouble(f, "/", "real_time_factor", wall > 0 ? cs_time(d) / wall : 0, NULL);
  char status[CS_H5_STATUS_SIZE];
  if (cancelled) {
    snprintf(status, sizeof status, "interrupted at t = %.6g s", cs_time(d));
  } else {
    snprintf(status, sizeof status, "%s", st == CS_OK ? "ok" : (err ? err->msg : "failed"));
  }
  cs_h5AttrString(f, "/", "status", status, NULL);
  cs_h5AttrDouble(f, "/", "samples", (double)nsample, NULL);
  cs_h5AttrDouble(f, "/", "flushed_t_s", cs_time(d), NULL);
  cs_h5AttrDouble(f, "/", "steps", (double)cs_stepCount(d), NULL);
  cs_h5AttrDouble(f, "/", "rejected_steps", (double)cs_rejectCount(d), NULL);
  cs_h5AttrDouble(f, "/", "gain_projections", (double)cs_gainProjectionCount(d), NULL);
  if (m->opt.step_adaptive) {
    csAdaptiveStats as;
    cs_adaptiveStats(d, &as);
    cs_h5AttrDouble(f, "/", "adaptive_steps", (double)as.accepted, NULL);
    cs_h5AttrDouble(f, "/", "adaptive_rejected_steps", (double)as.rejected, NULL);
    cs_h5AttrDouble(f, "/", "adaptive_h_min_s", as.h_min, NULL);
    cs_h5AttrDouble(f, "/", "adaptive_h_median_s", as.h_median, NULL);
    cs_h5AttrDouble(f, "/", "adaptive_h_max_s", as.h_max, NULL);
  }
  if (m->foothold) {
    /* what each foothold chose: "T LEGS OFFSET" per foothold ("-" while undecided) */
    char fh[CS_H5_STATUS_SIZE] = "";
    size_t len = 0;
    for (int k = 0; k < m->foothold->n && len < sizeof fh; k++) {
      const csgFoothold* o = &m->foothold->fh[k];
      char legs[9];
      int n = 0;
      for (int l = 0; l < 8; l++) {
        if (o->legs & (1u << l)) legs[n++] = (char)('A' + l);
      }
      legs[n] = '\0';
      const int c = (int)d->fh_choice[k];
      if (c >= 0) {
        len += (size_t)snprintf(fh + len, sizeof fh - len, "%s%g %s %g", k ? "; " : "", o->t, legs,
                                o->cand[c].offset);
      } else {
        len += (size_t)snprintf(fh + len, sizeof fh - len, "%s%g %s -", k ? "; " : "", o->t, legs);
      }
    }
    cs_h5AttrString(f, "/", "foothold_file", m->foothold->source, NULL);
    cs_h5AttrString(f, "/", "foothold_choices", fh, NULL);
  }
  if (m->gate) {
    /* closed loop: the gate's file, its total hold and each wait ("T LEGS WAIT" per gate that
     * waited, s) */
    char gw[CS_H5_STATUS_SIZE] = "";
    size_t len = 0;
    double held;
    int rel, waited;
    cs_gateHeld(m, d, &held, &rel, &waited);
    for (int k = 0; k < rel; k++) {
      const double w = cs_gateReleasedWait(d, k);
      if (w > 0 && len + 40 >= sizeof gw) {
        snprintf(gw + len, sizeof gw - len, "; ... (all: /gate/waits)");
        break;
      }
      if (w > 0) {
        char legs[9];
        csg_gateLegs(m->gate->gate[k].legs, legs);
        len += (size_t)snprintf(gw + len, sizeof gw - len, "%s%g %s %.3f", len ? "; " : "",
                                m->gate->gate[k].t, legs, w);
      }
    }
    /* every gate: its table time and released wait (NaN: not released), s */
    double tw[2 * CSG_GATE_MAX];
    for (int k = 0; k < m->gate->n; k++) {
      tw[2 * k] = m->gate->gate[k].t;
      tw[2 * k + 1] = k < rel ? cs_gateReleasedWait(d, k) : NAN;
    }
    const size_t wdims[2] = {(size_t)m->gate->n, 2};
    if (cs_h5WriteDoubles(f, "/gate/waits", 2, wdims, tw, NULL) == CS_OK) {
      cs_h5AttrString(f, "/gate/waits", "units", "s", NULL);
      cs_h5AttrString(f, "/gate/waits", "description",
                      "each gate of the landing gate: its table time and the wait it held the "
                      "table's clock for (NaN: not released by the run's end)", NULL);
    }
    cs_h5AttrString(f, "/", "control", "closed loop: landing gate (gaits_gate.h)", NULL);
    cs_h5AttrString(f, "/", "gate_file", m->gate->source, NULL);
    cs_h5AttrDouble(f, "/", "gate_held_s", held, NULL);
    cs_h5AttrDouble(f, "/", "gate_released", rel, NULL);
    cs_h5AttrDouble(f, "/", "gate_waited", waited, NULL);
    cs_h5AttrString(f, "/", "gate_waits", gw, NULL);
    if (m->gate->crawl_n > 0) { /* the crawl's decision (gaits_gate.h `crawl`, sim_gate.c) */
      cs_h5AttrDouble(f, "/", "crawl_skip_s", d->crawl_skip, NULL);
      cs_h5AttrDouble(f, "/", "crawl_boundaries_read", d->crawl_i, NULL);
      cs_h5AttrDouble(f, "/", "crawl_z_mm", d->crawl_z, NULL);
    }
    if (m->gate->walk_n > 0) { /* the walk's decision (gaits_gate.h `walk`, sim_gate.c) */
      cs_h5AttrDouble(f, "/", "walk_skip_s", d->walk_skip, NULL);
      cs_h5AttrDouble(f, "/", "walk_boundaries_read", d->walk_i, NULL);
      cs_h5AttrDouble(f, "/", "walk_x_mm", d->walk_x, NULL);
    }
    /* why the rows stop where they do (cs_runOverAt) */
    char why[CS_H5_STATUS_SIZE];
    if (m->opt.t_end > 0) {
      snprintf(why, sizeof why, "--t-end %g s", m->opt.t_end);
    } else if (st != CS_OK || cancelled) {
      snprintf(why, sizeof why, "stopped at t = %g s (status)", cs_time(d));
    } else if (over) {
      snprintf(why, sizeof why, "the gait is over: the table's clock (t - gate hold + walk "
               "and crawl skips) reached the table's end, %g s, at t = %g s",
               cs_modelTableEnd(m), cs_time(d));
    } else {
      snprintf(why, sizeof why, "the longest the gate's holds allow, %g s, on the run's clock "
               "(the table's clock at %g s of %g)", t_end, cs_gateTableTime(m, d, cs_time(d)),
               cs_modelTableEnd(m));
    }
    cs_h5AttrString(f, "/", "end_reason", why, NULL);
  } else {
    cs_h5AttrString(f, "/", "control", m->pressure_source ? "a caller's pressure source"
                                                          : "open loop: the table on time", NULL);
  }
  for (int k = 0; k < CS_NTIMER; k++) {
    char name[64];
    snprintf(name, sizeof name, "timer_%s_s", cs_timerName((csTimerId)k));
    cs_h5AttrDouble(f, "/", name, d->timer[k].wall, NULL);
    snprintf(name, sizeof name, "timer_%s_calls", cs_timerName((csTimerId)k));
    cs_h5AttrDouble(f, "/", name, (double)d->timer[k].count, NULL);
  }
  /* on a write failure the file keeps its last flushed image, its status patched to say why */
  csError cerr;
  csStatus cst = cs_h5CloseChecked(f, &cerr);
  if (cst != CS_OK && st == CS_OK) {
    st = cst;
    if (err) {
      *err = cerr;
    }
  }
  if (st == CS_ERR_IO || st == CS_ERR_MEMORY) {
    return st; /* the disk refused the run file: no XDMF beside it */
  }
  /* the XDMF beside it (run.h5 -> run.xdmf), even for a run cut short: ParaView opens what
   * there is; at most ~600 frames keep its XML small (a 9 s run at 0.01 s: every 2nd sample) */
  char xdmf[1024];
  snprintf(xdmf, sizeof xdmf, "%s", out_path);
  char* dot = strrchr(xdmf, '.');
  char* slash = strrchr(xdmf, '/');
  if (dot && (!slash || dot > slash)) {
    *dot = '\0';
  }
  strncat(xdmf, ".xdmf", sizeof xdmf - strlen(xdmf) - 1);
  csError xe;
  csStatus xs = cs_xdmfWriteRun(out_path, xdmf, cs_xdmfStride(nsteps / out_every + 1, 600), &xe);
  if (st == CS_OK && xs != CS_OK) {
    if (err) {
      *err = xe;
    }
    st = xs;
  }
  return st;
}


csStatus cs_runRecordFailure(const csModel* m, const csData* d, const char* out_path,
                             const csError* cause, csError* err) {
  csH5File* f = cs_h5Create(out_path, err);
  if (!f) {
    return err ? err->status : CS_ERR_IO;
  }
  Series s;
  csStatus st = writeHeader(m, f, &s, err);
  if (st == CS_OK) {
    st = cs_h5AttrString(f, "/", "status", cause && cause->msg[0] ? cause->msg : "failed", err);
  }
  if (st == CS_OK) {
    st = cs_h5AttrDouble(f, "/", "failed_at_s", cs_time(d), err);
  }
  if (st == CS_OK) {
    st = cs_h5AttrDouble(f, "/", "steps", (double)cs_stepCount(d), err);
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
