/* sim_run.c: a whole run with HDF5 output per DESIGN.md's output contract (see sim_model.h).
 *
 * Layout: /time [N] s; /support/position [N,3] mm; /support/orientation [N,4] (w,x,y,z);
 * /pressure [N,96] MPa; /legs/<A..H>/centerline [N,K,3] mm; root attributes scene, leg_model,
 * gait_file, units, version, terrain, friction, pressure_scale, step_s, support_mass_kg, and at
 * the end wall_time_s, real_time_factor, status. Samples are appended as the run goes and the
 * file is flushed every simulated second. */
#define _POSIX_C_SOURCE 200809L /* clock_gettime under -std=c17 */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include <time.h>

#include "core_h5.h"
#include "sim_model.h"

enum { MAX_CENTERLINE = 201 };

typedef struct {
  int time, pos, quat, pres, legs[CSR_NLEG];
} Series;


static double wallNow(void) {
  struct timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return ts.tv_sec + 1e-9 * ts.tv_nsec;
}


static csStatus writeSample(const csModel* m, const csData* d, csH5File* f, const Series* s,
                            double* buf, csError* err) {
  double t = cs_time(d), x[3], q[4];
  cs_supportDisplacement(d, x);
  cs_supportOrientation(d, q);
  csStatus st = cs_h5SeriesAppend(f, s->time, &t, err);
  if (st == CS_OK) st = cs_h5SeriesAppend(f, s->pos, x, err);
  if (st == CS_OK) st = cs_h5SeriesAppend(f, s->quat, q, err);
  if (st == CS_OK) st = cs_h5SeriesAppend(f, s->pres, cs_pressures(d), err);
  for (int k = 0; k < CSR_NLEG && st == CS_OK; k++) {
    cs_legCenterline(m, d, k, m->opt.centerline_points, buf);
    st = cs_h5SeriesAppend(f, s->legs[k], buf, err);
  }
  return st;
}


static csStatus writeHeader(const csModel* m, csH5File* f, Series* s, csError* err) {
  size_t three = 3, four = 4, n96 = CSR_NCHAMBER_TOTAL;
  size_t cl[2] = {(size_t)m->opt.centerline_points, 3};
  if ((s->time = cs_h5SeriesCreate(f, "/time", 0, NULL, err)) < 0 ||
      (s->pos = cs_h5SeriesCreate(f, "/support/position", 1, &three, err)) < 0 ||
      (s->quat = cs_h5SeriesCreate(f, "/support/orientation", 1, &four, err)) < 0 ||
      (s->pres = cs_h5SeriesCreate(f, "/pressure", 1, &n96, err)) < 0) {
    return err ? err->status : CS_ERR_IO;
  }
  for (int k = 0; k < CSR_NLEG; k++) {
    char path[64];
    snprintf(path, sizeof path, "/legs/%c/centerline", 'A' + k);
    if ((s->legs[k] = cs_h5SeriesCreate(f, path, 2, cl, err)) < 0) {
      return err ? err->status : CS_ERR_IO;
    }
  }
  csStatus st = CS_OK;
  if (st == CS_OK) st = cs_h5AttrString(f, "/", "scene", m->scene, err);
  if (st == CS_OK) st = cs_h5AttrString(f, "/", "leg_model", m->leg_level, err);
  if (st == CS_OK) st = cs_h5AttrString(f, "/", "gait_file", m->gait_path, err);
  if (st == CS_OK) st = cs_h5AttrString(f, "/", "terrain_file", m->terrain.source, err);
  if (st == CS_OK) st = cs_h5AttrString(f, "/", "calibration", m->robot.map.name, err);
  if (st == CS_OK) {
    st = cs_h5AttrString(f, "/", "units",
                         "time s; length mm; pressure MPa; mass t (1e3 kg); force N; "
                         "world frame x crawl direction, y up, z lateral",
                         err);
  }
  if (st == CS_OK) st = cs_h5AttrString(f, "/", "version", "0.1.0", err);
  if (st == CS_OK) st = cs_h5AttrDouble(f, "/", "friction", m->contact.mu, err);
  if (st == CS_OK) st = cs_h5AttrDouble(f, "/", "pressure_scale", m->sched.pressure_scale, err);
  if (st == CS_OK) st = cs_h5AttrDouble(f, "/", "ramp_s", m->sched.ramp, err);
  if (st == CS_OK) st = cs_h5AttrDouble(f, "/", "step_s", m->opt.h, err);
  if (st == CS_OK) st = cs_h5AttrDouble(f, "/", "pneumatic_tau_s", m->opt.pneumatic_tau, err);
  if (st == CS_OK) st = cs_h5AttrDouble(f, "/", "support_mass_kg", m->robot.support_mass * 1e3,
                                        err);
  return st;
}


csStatus cs_run(const csModel* m, csData* d, const char* out_path, double* wall_s,
                csError* err) {
  double t_end = cs_modelEndTime(m);
  if (m->opt.centerline_points > MAX_CENTERLINE) {
    return cs_errorSet(err, CS_ERR_RANGE, "at most %d centreline points", MAX_CENTERLINE);
  }
  csH5File* f = cs_h5Create(out_path, err);
  if (!f) {
    return err ? err->status : CS_ERR_IO;
  }
  Series s;
  double buf[3 * MAX_CENTERLINE];
  csStatus st = writeHeader(m, f, &s, err);
  long out_every = lround(m->opt.output_dt / m->opt.h);
  if (out_every < 1) {
    out_every = 1;
  }
  long nsteps = lround(t_end / m->opt.h);
  long per_second = lround(1.0 / m->opt.h);
  double w0 = wallNow();
  if (st == CS_OK) {
    st = writeSample(m, d, f, &s, buf, err);
  }
  for (long i = 1; i <= nsteps && st == CS_OK; i++) {
    st = cs_step(m, d, err);
    if (st == CS_OK && i % out_every == 0) {
      st = writeSample(m, d, f, &s, buf, err);
    }
    if (i % per_second == 0) {
      cs_h5Flush(f);
      if (m->opt.progress) {
        double x[3];
        cs_supportDisplacement(d, x);
        double w = wallNow() - w0;
        fprintf(stderr, "  t = %5.2f s  x = %7.2f  y = %6.2f  z = %6.2f mm  (%.1f s wall)\n",
                cs_time(d), x[0], x[1], x[2], w);
      }
    }
  }
  double wall = wallNow() - w0;
  if (wall_s) {
    *wall_s = wall;
  }
  /* the file stays readable whatever happened: record how the run ended */
  cs_h5AttrDouble(f, "/", "wall_time_s", wall, NULL);
  cs_h5AttrDouble(f, "/", "real_time_factor", wall > 0 ? cs_time(d) / wall : 0, NULL);
  cs_h5AttrString(f, "/", "status", st == CS_OK ? "ok" : (err ? err->msg : "failed"), NULL);
  cs_h5Close(f);
  return st;
}
