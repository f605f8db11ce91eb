/* robot_bend_io.c: HDF5 output of a bend characterisation (see robot_bend_io.h). */
#include "robot_bend_io.h"

#include <math.h>
#include <string.h>

/* state of the actuator-parameter visitor: the first failure wins */
typedef struct {
  csH5File* f;
  csError* err;
  csStatus st;
} ParamWriter;

/* csrParamVisitor writing one parameter as a root attribute */
static void writeParam(void* user, const char* name, double value);


static void writeParam(void* user, const char* name, double value) {
  ParamWriter* pw = user;
  if (pw->st == CS_OK) {
    pw->st = cs_h5AttrDouble(pw->f, "/", name, value, pw->err);
  }
}


const char* csr_fibreLawName(int tension_only) {
  return tension_only ? "tension-only" : "linear";
}


int csr_fibreLawParse(const char* name) {
  return !strcmp(name, "tension-only") ? 1 : !strcmp(name, "linear") ? 0 : -1;
}


/* the curve's datasets (M), (M x 3), (M), (M x 3), replacing earlier ones, and `samples` */
static csStatus writeRows(csH5File* f, const csrBendCurve* bc, csError* err) {
  const size_t d1[1] = {bc->m}, d3[2] = {bc->m, 3};
  csStatus st = cs_h5WriteDoubles(f, "/pressure", 1, d1, bc->pressure, err);
  if (st == CS_OK) {
    st = cs_h5WriteDoubles(f, "/angle_deg", 2, d3, bc->angle_deg, err);
  }
  if (st == CS_OK) {
    st = cs_h5WriteDoubles(f, "/angle_total_deg", 1, d1, bc->angle_total, err);
  }
  if (st == CS_OK) {
    st = cs_h5WriteDoubles(f, "/tip_position", 2, d3, bc->tip, err);
  }
  /* units and what each is (issue 36: every dataset says its units) */
  static const char* const kUnits[4][3] = {
      {"/pressure", "MPa", "the sweep's chamber pressure (gauge) at each row"},
      {"/angle_deg", "deg", "bending angle of segments II1, II2, II3 at each row"},
      {"/angle_total_deg", "deg",
       "total bending angle at each row: the base-to-tip rotation (the rod's segments' sum; FE "
       "and rom: measured, the joints included)"},
      {"/tip_position", "mm", "the tip's position in the base frame (e1, e2, e3) at each row"}};
  for (int k = 0; k < 4 && st == CS_OK; k++) {
    st = cs_h5AttrString(f, kUnits[k][0], "units", kUnits[k][1], err);
    if (st == CS_OK) st = cs_h5AttrString(f, kUnits[k][0], "description", kUnits[k][2], err);
  }
  if (st == CS_OK) {
    st = cs_h5AttrDouble(f, "/", "samples", (double)bc->m, err);
  }
  return st;
}


csStatus csr_bendCurveFlushH5(csH5File* f, const csrBendCurve* bc, csError* err) {
  if (!f || !bc) {
    return cs_errorSet(err, CS_ERR_ARG, "bend output: NULL argument");
  }
  csStatus st = writeRows(f, bc, err);
  return st == CS_OK ? cs_h5Flush(f, err) : st;
}


csStatus csr_bendCurveWriteH5(csH5File* f, const csrActuator* act, const csrBendCurve* bc,
                              const csrBendMeta* meta, csError* err) {
  if (!f || !act || !bc || !meta || !meta->model || !meta->chambers) {
    return cs_errorSet(err, CS_ERR_ARG, "bend output: NULL argument");
  }
  csStatus st = writeRows(f, bc, err);
  /* root attributes */
  const char* strings[][2] = {{"model", meta->model},
                              {"actuator", act->name},
                              {"chambers", meta->chambers},
                              {"version", CSR_OUTPUT_VERSION},
                              {"units", "length mm, pressure MPa, angle deg, time s"}};
  for (size_t i = 0; st == CS_OK && i < sizeof strings / sizeof strings[0]; i++) {
    st = cs_h5AttrString(f, "/", strings[i][0], strings[i][1], err);
  }
  const char* names[] = {"mesh_size_mm", "n_elements_soft", "n_elements_fibre", "wall_time_s"};
  const double values[] = {meta->mesh_size, meta->n_elements_soft, meta->n_elements_fibre,
                           meta->wall_time};
  for (size_t i = 0; st == CS_OK && i < sizeof values / sizeof values[0]; i++) {
    st = cs_h5AttrDouble(f, "/", names[i], values[i], err);
  }
  if (st == CS_OK && meta->model && !strcmp(meta->model, "fe")) {
    st = cs_h5AttrDouble(f, "/", "fe_mesh_symmetric", meta->mesh_symmetric, err);
  }
  if (st == CS_OK && meta->fibre_size > 0) {
    st = cs_h5AttrDouble(f, "/", "fe_fibre_size_mm", meta->fibre_size, err);
    if (st == CS_OK) {
      st = cs_h5AttrDouble(f, "/", "fe_fibre_split", meta->fibre_split, err);
    }
    if (st == CS_OK) {
      st = cs_h5AttrString(f, "/", "fe_fibre_law", csr_fibreLawName(meta->fibre_tension_only),
                           err);
    }
  }
  if (st == CS_OK && meta->neg_pivots_max >= 0) {
    st = cs_h5AttrDouble(f, "/", "fe_p_indefinite_MPa", meta->p_indefinite, err);
    if (st == CS_OK) {
      st = cs_h5AttrDouble(f, "/", "fe_neg_pivots_max", meta->neg_pivots_max, err);
    }
  }
  if (st == CS_OK && !isnan(meta->until_angle_deg)) {
    st = cs_h5AttrDouble(f, "/", "until_angle_deg", meta->until_angle_deg, err);
    if (st == CS_OK) {
      st = cs_h5AttrDouble(f, "/", "p_until_angle_MPa", bc->p_until_angle, err);
    }
  }
  /* attributes p_limit_MPa / p_resume_MPa only when the sweep met a limit point */
  if (st == CS_OK && meta->p_limit > 0) {
    st = cs_h5AttrDouble(f, "/", "p_limit_MPa", meta->p_limit, err);
  }
  if (st == CS_OK && meta->p_resume > 0) {
    st = cs_h5AttrDouble(f, "/", "p_resume_MPa", meta->p_resume, err);
  }
  if (st == CS_OK && meta->p_stalled > 0) {
    st = cs_h5AttrDouble(f, "/", "fe_p_stalled_MPa", meta->p_stalled, err);
  }
  if (st == CS_OK) {
    ParamWriter pw = {f, err, CS_OK};
    csr_actuatorVisit(act, writeParam, &pw);
    st = pw.st;
  }
  return st;
}
