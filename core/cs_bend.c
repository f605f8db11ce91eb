/* cs_bend.c: one actuator's pressure -> bend by the mesh-free models (cs_bend.h, the solver
 * `crawlsim bend --model analytic|rod|strain` and cs_bend share) and the public cs_bend of crawlsim.h
 * (its definition, defaults and validation, and the sweep into the caller's arrays). */
#include "cs_bend.h"

#include <math.h>
#include <string.h>

#include "core_math.h"
#include "core_text.h"
#include "crawlsim.h"
#include "cs_rundef.h"
#include "robot_analytic.h"
#include "robot_leg.h"

static const double kDefaultPMax = 0.4;  /* MPa, the paper's multi-segment sweep (Sec. 3.3) */
static const double kDefaultPStep = 0.05; /* MPa, the paper's increment */
static const double kSweepEps = 1e-9;    /* relative slack when p-max is a multiple of step */
enum { MAX_SETS = 64 };
/* steps of rest arc length per segment over which the strain leg's bend is summed: the sum of
 * the steps' relative rotation vectors is exact for plane bending whatever the count (each
 * step's rotation is far below π); out of plane it converges as the rod's over its elements */
enum { STRAIN_ANGLE_STEPS = 64 };


/* the analytic model as the rod's calibration: bend θ towards φ, stretch λ0 */
static int analyticBendMap(const void* ctx, int seg, const double p[4], double bend[2],
                           double* stretch) {
  const csBendSolver* s = ctx;
  csrSegmentStrain st;
  if (csr_analyticSegment(&s->map_act, seg, p, &st, NULL) != CS_OK) {
    return -1;
  }
  bend[0] = st.theta * cos(st.phi);
  bend[1] = st.theta * sin(st.phi);
  *stretch = st.lambda0;
  return 0;
}


/* the rod's and the strain leg's calibration (what `bend --model rod` has always built): the
 * map, a mode table's strains and probed stiffness, the sweep's ceiling */
static csStatus calibrationOpen(csBendSolver* s, csError* err) {
  csBendSpec* sp = &s->spec;
  s->map_act = sp->act;
  if (sp->calibration && !strcmp(sp->calibration, "analytic")) {
    s->map.eval = analyticBendMap;
    s->map.ctx = s;
    s->map.name = "analytic";
    s->map.p_max = INFINITY;
  } else {
    const char* path = sp->calibration ? sp->calibration : sp->default_path;
    /* the mission's table under the mission's rule unless told otherwise; a table given by
     * --calibration alone keeps its own default rule (as crawlsim run) */
    if (!sp->calibration && sp->cal_rule < 0) {
      csrCalRule rule;
      if (!csr_calRuleParse(CS_MISSION_CAL_RULE, &rule)) {
        return cs_errorSet(err, CS_ERR_ARG, "unknown default rule '%s'", CS_MISSION_CAL_RULE);
      }
      sp->cal_rule = (int)rule;
    }
    csrCalOptions cal_opt = csr_calModelDefaultOptions();
    cal_opt.rule = (csrCalRule)sp->cal_rule;
    s->cal = csr_calibrationOpenWith(path, &sp->act, sp->cal_rule >= 0 ? &cal_opt : NULL, err);
    if (!s->cal) {
      if (!sp->calibration) {
        char cause[sizeof err->msg];
        memcpy(cause, err->msg, sizeof cause);
        cs_errorSet(err, err->status, "%.400s (--calibration analytic works for any actuator)",
                    cause);
      }
      return err->status != CS_OK ? err->status : CS_ERR_IO;
    }
    s->map = csr_calibrationMap(s->cal);
    /* a mode table's probed EI, EA as well as its strains, as the rod legs of crawlsim run
     * take both (csr_calibrationRodFromMap) */
    s->has_rodcal = csr_calibrationRod(s->cal, &s->rodcal);
  }
  /* the sweep must stay inside the calibrated pressures (they are not extrapolated) */
  double rmax = 0;
  for (int j = 0; j < CSR_NCHAMBER; j++) {
    rmax = fmax(rmax, sp->ratio[j]);
  }
  if (isfinite(s->map.p_max)) {
    if (sp->p_max * rmax > s->map.p_max * (1 + 1e-12)) {
      return cs_errorSet(err, CS_ERR_ARG, "--p-max %g MPa puts a chamber at %g MPa, above the "
                         "calibration's range (%g MPa, %s): lower --p-max or use --calibration "
                         "analytic", sp->p_max, sp->p_max * rmax, s->map.p_max, s->map.name);
    }
    s->p_ceiling = s->map.p_max / rmax;
  }
  return CS_OK;
}


/* the nodal rod's model and data on the calibration */
static csStatus rodOpen(csBendSolver* s, csError* err) {
  csBendSpec* sp = &s->spec;
  csStatus st = calibrationOpen(s, err);
  if (st != CS_OK) {
    return st;
  }
  /* elements: --mesh-size is the element length in the segments (and joints) */
  csrRodParams par = csr_rodDefaultParams(&sp->act);
  par.cal_drop = sp->cal_drop;
  if (!isnan(sp->mesh_size)) {
    double smax = fmax(sp->act.S[0], fmax(sp->act.S[1], sp->act.S[2]));
    double lmax = fmax(sp->act.LS[0], sp->act.LS[1]);
    par.elements_per_segment = (int)ceil(smax / sp->mesh_size - 1e-9);
    par.elements_per_joint = (int)ceil(lmax / sp->mesh_size - 1e-9);
    if (par.elements_per_segment > 1000) {
      return cs_errorSet(err, CS_ERR_ARG, "--mesh-size %g mm gives more than 1000 rod elements "
                         "per segment", sp->mesh_size);
    }
  }
  csrRodSpec rs;
  memset(&rs, 0, sizeof rs);
  rs.act = &sp->act;
  rs.params = &par;
  rs.map = &s->map;
  rs.calib = s->has_rodcal ? &s->rodcal : NULL;
  csu_eye3(rs.frame); /* the base frame: the tip is in it */
  rs.weightless = 1;  /* gravity off, as for the other models */
  s->m = csr_rodModelCreate(&rs, err);
  s->d = s->m ? csr_rodDataCreate(s->m, err) : NULL;
  if (!s->d) {
    return err->status != CS_OK ? err->status : CS_ERR_MEMORY;
  }
  s->mesh_size = fmax(sp->act.S[0], fmax(sp->act.S[1], sp->act.S[2])) /
                 par.elements_per_segment;
  s->n_elements = csr_rodElements(s->m);
  return CS_OK;
}


/* the strain level's default of one of its settings (robot_strain_leg.c), by name, so that a
 * bend runs the leg `crawlsim run --legs strain` runs */
static double strainSetting(const char* name) {
  const csrLegSetting* k = csr_legSettingFind(&csr_leg_strain, name);
  return k ? k->value : NAN;
}


/* the strain-coordinate leg on the calibration: the basis of the strain level's defaults
 * (bending modes, joints, shear, Magnus sub-intervals), the rod's material and sections,
 * clamped at the base frame, weightless and without terrain, as the rod */
static csStatus strainOpen(csBendSolver* s, csError* err) {
  csBendSpec* sp = &s->spec;
  csStatus st = calibrationOpen(s, err);
  if (st != CS_OK) {
    return st;
  }
  int links = sp->links > 0 ? sp->links : (int)strainSetting("links");
  if (links < 1 || links > CSR_STRAIN_MAX_ORDER + 1) {
    return cs_errorSet(err, CS_ERR_RANGE, "--links %d: the strain leg takes 1..%d bending "
                       "modes per segment", links, CSR_STRAIN_MAX_ORDER + 1);
  }
  csrRodParams rp = csr_rodDefaultParams(&sp->act);
  rp.cal_drop = sp->cal_drop;
  csrStrainParams par = csr_strainDefaultParams();
  par.bend_order = links - 1;
  par.joint_order = (int)strainSetting("joints");
  par.shear = (int)strainSetting("shear");
  par.nsub = csr_strainSubIntervals(links, (int)strainSetting("sub"));
  csrStrainSpec ss;
  memset(&ss, 0, sizeof ss);
  ss.act = &sp->act;
  ss.rod_params = &rp;
  ss.params = &par;
  ss.map = &s->map;
  ss.calib = s->has_rodcal ? &s->rodcal : NULL;
  csu_eye3(ss.frame); /* the base frame: the tip is in it */
  ss.weightless = 1;  /* gravity off, as for the other models */
  s->sm = csr_strainModelCreate(&ss, err);
  s->sd = s->sm ? csr_strainDataCreate(s->sm, err) : NULL;
  if (!s->sd) {
    return err->status != CS_OK ? err->status : CS_ERR_MEMORY;
  }
  /* the segments' spans of rest arc length: the rod's pieces, which the strain leg takes */
  csrRodPiece pieces[CSR_ROD_MAX_PIECES];
  int np = csr_rodLegPieces(&sp->act, &rp, pieces);
  double X = 0;
  for (int k = 0; k < np; k++) {
    int seg = pieces[k].segment;
    if (seg >= 0 && seg < CSR_NSEG) {
      s->seg_X[seg][0] = X;
      s->seg_X[seg][1] = X + pieces[k].length;
    }
    X += pieces[k].length;
  }
  s->links = links;
  s->n_dofs = csr_strainDofs(s->sm);
  return CS_OK;
}


/* the strain leg's static equilibrium at the pressures P (segment-major) and the tip load:
 * the segments' angles and the tip in the base frame */
static csStatus strainPoint(csBendSolver* s, const double P[12], double angle_deg[CSR_NSEG],
                            double tip[3], csError* err) {
  csrRodStaticLoad ld;
  memset(&ld, 0, sizeof ld);
  memcpy(ld.p, P, sizeof ld.p);
  memcpy(ld.tip_force, s->spec.tip_load, sizeof ld.tip_force); /* base frame = world here */
  csStatus st = csr_strainStatic(s->sm, s->sd, &ld, NULL, err);
  if (st != CS_OK) {
    return st;
  }
  for (int seg = 0; seg < CSR_NSEG; seg++) {
    double X0 = s->seg_X[seg][0], X1 = s->seg_X[seg][1];
    double x[3], Ra[9], Rb[9], tot[3] = {0, 0, 0};
    csr_strainPose(s->sm, s->sd, X0, x, Ra);
    for (int i = 1; i <= STRAIN_ANGLE_STEPS; i++) {
      csr_strainPose(s->sm, s->sd, X0 + (X1 - X0) * i / STRAIN_ANGLE_STEPS, x, Rb);
      double RaT[9], Rrel[9], v[3];
      /* Rrel = Raᵀ Rb: the step's rotation in the frame at its start */
      csu_transpose3(RaT, Ra);
      csu_mulMat3(Rrel, RaT, Rb);
      csu_mat3ToRotVec(v, Rrel);
      csu_add3(tot, tot, v);
      memcpy(Ra, Rb, sizeof Ra);
    }
    angle_deg[seg] = csu_norm3(tot) / CS_DEG;
  }
  double x0[3], xL[3], R[9];
  csr_strainPose(s->sm, s->sd, 0, x0, R);
  csr_strainPose(s->sm, s->sd, csr_strainLength(s->sm), xL, R);
  csu_sub3(tip, xL, x0);
  return CS_OK;
}


csStatus cs_bendSolverOpen(csBendSolver* s, const csBendSpec* spec, csError* err) {
  memset(s, 0, sizeof *s);
  s->spec = *spec;
  s->mesh_size = NAN; /* mesh-free until the rod says otherwise */
  s->p_ceiling = NAN;
  return spec->kind == CS_BEND_ROD      ? rodOpen(s, err)
         : spec->kind == CS_BEND_STRAIN ? strainOpen(s, err)
                                        : CS_OK;
}


csStatus cs_bendSolverPoint(csBendSolver* s, double p, double angle_deg[CSR_NSEG],
                            double tip[3], csError* err) {
  double P[CSR_NSEG * CSR_NCHAMBER]; /* (segment x chamber), row-major */
  for (int i = 0; i < CSR_NSEG; i++) {
    for (int j = 0; j < CSR_NCHAMBER; j++) {
      P[CSR_NCHAMBER * i + j] = s->spec.ratio[j] * p;
    }
  }
  if (s->spec.kind == CS_BEND_ROD) {
    return csr_rodBendPoint(s->m, s->d, P, s->spec.tip_load, angle_deg, tip, err);
  }
  if (s->spec.kind == CS_BEND_STRAIN) {
    return strainPoint(s, P, angle_deg, tip, err);
  }
  /* the analytic model (robot_analytic.h): three segment equilibria and the FK */
  csrSegmentStrain st[CSR_NSEG];
  csStatus rc = csr_analyticActuator(&s->spec.act, P, st, err);
  if (rc != CS_OK) {
    return rc;
  }
  for (int i = 0; i < CSR_NSEG; i++) {
    angle_deg[i] = st[i].theta / CS_DEG;
  }
  return csr_ccForwardKinematics(&s->spec.act, st, 1, NULL, tip, NULL, err);
}


void cs_bendSolverClose(csBendSolver* s) {
  if (!s) {
    return;
  }
  csr_rodDataDestroy(s->d);
  csr_rodModelDestroy(s->m);
  csr_strainDataDestroy(s->sd);
  csr_strainModelDestroy(s->sm);
  s->sd = NULL;
  s->sm = NULL;
  csr_calibrationClose(s->cal);
  s->d = NULL;
  s->m = NULL;
  s->cal = NULL;
}


const char* cs_bendSolverRuleName(const csBendSolver* s) {
  return s->cal ? csr_calibrationRuleName(s->cal) : "none";
}


int cs_bendSolverProbedStiffness(const csBendSolver* s) {
  return s->has_rodcal && !(s->spec.cal_drop & CSR_CAL_DROP_STIFFNESS);
}


size_t cs_bendSweepSteps(double p_max, double p_step) {
  return (size_t)floor(p_max / p_step * (1 + kSweepEps));
}


size_t cs_bendSweepRows(double p_max, double p_step) {
  size_t nstep = cs_bendSweepSteps(p_max, p_step);
  /* p_max off the grid adds a last row at p_max */
  return nstep + 1 + (p_max - (double)nstep * p_step > kSweepEps * p_max ? 1 : 0);
}


double cs_bendSweepPressure(double p_max, double p_step, size_t i) {
  /* i x step may round above p-max (6 x 0.05 > 0.3): never beyond it (a calibrated range
   * ends there) */
  return i <= cs_bendSweepSteps(p_max, p_step) ? fmin((double)i * p_step, p_max) : p_max;
}


/* ---- the public definition and sweep (crawlsim.h) ----------------------------------------- */

csBendDef cs_defaultBendDef(void) {
  csBendDef d;
  memset(&d, 0, sizeof d);
  d.p_max = d.p_step = d.mesh_size = d.links = NAN;
  return d;
}


/* def's solver spec (the actuator built, the chambers parsed): every check of
 * cs_bendDefValidate is here, once */
static csStatus bendSpec(const csBendDef* def, csBendSpec* sp, double* p_step, csError* err) {
  if (!def) {
    return cs_errorSet(err, CS_ERR_ARG, "bend: NULL definition");
  }
  memset(sp, 0, sizeof *sp);
  const char* model = def->model ? def->model : "analytic";
  if (!strcmp(model, "analytic")) {
    sp->kind = CS_BEND_ANALYTIC;
  } else if (!strcmp(model, "rod")) {
    sp->kind = CS_BEND_ROD;
  } else if (!strcmp(model, "strain")) {
    sp->kind = CS_BEND_STRAIN;
  } else {
    return cs_errorSet(err, CS_ERR_ARG, "unknown --model '%.60s' (the library has analytic, rod "
                       "and strain; fe and rom are in `crawlsim bend`)", model);
  }
  /* rod and strain legs: a calibration, a tip load; the actuator is the default table's */
  int rod = sp->kind == CS_BEND_ROD || sp->kind == CS_BEND_STRAIN;
  const char* actuator = def->actuator ? def->actuator : rod ? CS_MISSION_ACTUATOR : "baseline";
  csStatus st = csr_actuatorPreset(&sp->act, actuator, err);
  if (st != CS_OK) {
    return st;
  }
  if (def->n_actuator_set < 0 || def->n_actuator_set > MAX_SETS ||
      (def->n_actuator_set > 0 && !def->actuator_set)) {
    return cs_errorSet(err, CS_ERR_ARG, "--set: n_actuator_set %d must be 0..%d with as many "
                       "strings", def->n_actuator_set, MAX_SETS);
  }
  for (int k = 0; k < def->n_actuator_set; k++) {
    if (!def->actuator_set[k]) {
      return cs_errorSet(err, CS_ERR_ARG, "--set: string %d is NULL", k);
    }
    st = csr_actuatorSetString(&sp->act, def->actuator_set[k], err);
    if (st != CS_OK) {
      return st;
    }
  }
  st = csr_actuatorValidate(&sp->act, err);
  if (st != CS_OK) {
    return st;
  }
  unsigned mask = 0;
  st = csu_chamberListParse(def->chambers ? def->chambers : "1,2", CSR_NCHAMBER, "--chambers",
                            &mask, err);
  if (st != CS_OK) {
    return st;
  }
  for (int j = 0; j < CSR_NCHAMBER; j++) {
    sp->ratio[j] = (mask >> j) & 1u ? 1.0 : 0.0;
  }
  sp->p_max = isnan(def->p_max) ? kDefaultPMax : def->p_max;
  *p_step = isnan(def->p_step) ? kDefaultPStep : def->p_step;
  if (!isfinite(sp->p_max) || !(sp->p_max > 0) || !isfinite(*p_step) || !(*p_step > 0)) {
    return cs_errorSet(err, CS_ERR_RANGE, "%s %g must be a finite number > 0 MPa",
                       !isfinite(sp->p_max) || !(sp->p_max > 0) ? "--p-max" : "--p-step",
                       !isfinite(sp->p_max) || !(sp->p_max > 0) ? sp->p_max : *p_step);
  }
  /* a sweep of more rows than an int counts is a mistake, not a request */
  if (sp->p_max / *p_step > 1e7) {
    return cs_errorSet(err, CS_ERR_RANGE, "--p-step %g MPa: more than 1e7 rows up to --p-max "
                       "%g MPa", *p_step, sp->p_max);
  }
  for (int k = 0; k < 3; k++) {
    if (!isfinite(def->tip_load[k])) {
      return cs_errorSet(err, CS_ERR_RANGE, "--tip-load: component %d is not finite", k + 1);
    }
    sp->tip_load[k] = def->tip_load[k];
  }
  sp->cal_rule = -1;
  if (def->cal_rule) {
    csrCalRule rule;
    if (!csr_calRuleParse(def->cal_rule, &rule)) {
      return cs_errorSet(err, CS_ERR_ARG, "unknown --cal-rule '%.60s' (expected prism, rbf or "
                         "rbf-pair)", def->cal_rule);
    }
    sp->cal_rule = (int)rule;
  }
  if (def->cal_drop && !csr_calDropParse(def->cal_drop, &sp->cal_drop)) {
    return cs_errorSet(err, CS_ERR_ARG, "bad --cal-drop '%.60s' (expected stretch, stiffness, "
                       "stretch,stiffness or none)", def->cal_drop);
  }
  if (def->calibration && !def->calibration[0]) {
    return cs_errorSet(err, CS_ERR_ARG, "--calibration needs a file name or 'analytic'");
  }
  sp->calibration = def->calibration;
  sp->mesh_size = def->mesh_size;
  if (!isnan(sp->mesh_size) && !(isfinite(sp->mesh_size) && sp->mesh_size > 0)) {
    return cs_errorSet(err, CS_ERR_RANGE, "--mesh-size %g must be > 0 mm", sp->mesh_size);
  }
  int tip = sp->tip_load[0] != 0 || sp->tip_load[1] != 0 || sp->tip_load[2] != 0;
  int links = !isnan(def->links);
  if (!rod && (tip || def->calibration || def->cal_rule || sp->cal_drop ||
               !isnan(sp->mesh_size) || links)) {
    const char* flag = tip                ? "--tip-load"
                       : def->calibration ? "--calibration"
                       : def->cal_rule    ? "--cal-rule"
                       : sp->cal_drop     ? "--cal-drop"
                       : links            ? "--links"
                                          : "--mesh-size";
    return cs_errorSet(err, CS_ERR_ARG, "%s is for --model %s (the analytic model has none)",
                       flag, !strcmp(flag, "--links")       ? "strain"
                             : !strcmp(flag, "--mesh-size") ? "rod"
                                                            : "rod or strain");
  }
  if (sp->kind == CS_BEND_STRAIN && !isnan(sp->mesh_size)) {
    return cs_errorSet(err, CS_ERR_ARG, "--mesh-size is for --model rod (the strain leg's "
                       "resolution is --links, its bending modes per segment)");
  }
  if (sp->kind == CS_BEND_ROD && links) {
    return cs_errorSet(err, CS_ERR_ARG, "--links is for --model strain (the rod's elements are "
                       "--mesh-size)");
  }
  if (links && !(def->links >= 1 && def->links <= CSR_STRAIN_MAX_ORDER + 1 &&
                 def->links == floor(def->links))) {
    return cs_errorSet(err, CS_ERR_RANGE, "--links %g: the strain leg takes a whole number "
                       "1..%d of bending modes per segment", def->links, CSR_STRAIN_MAX_ORDER + 1);
  }
  sp->links = links ? (int)def->links : 0;
  return CS_OK;
}


csStatus cs_bendDefValidate(const csBendDef* def, csError* err) {
  csBendSpec sp;
  double p_step;
  return bendSpec(def, &sp, &p_step, err);
}


int cs_bendRowCount(const csBendDef* def, csError* err) {
  csBendSpec sp;
  double p_step;
  if (bendSpec(def, &sp, &p_step, err) != CS_OK) {
    return -1;
  }
  return (int)cs_bendSweepRows(sp.p_max, p_step);
}


csStatus cs_bend(const csBendDef* def, int capacity, double* pressure, double* angle_deg,
                 double* tip, int* n, csError* err) {
  if (n) {
    *n = 0;
  }
  csBendSpec sp;
  double p_step;
  csStatus st = bendSpec(def, &sp, &p_step, err);
  if (st != CS_OK) {
    return st;
  }
  if (!pressure || !angle_deg || !tip || !n) {
    return cs_errorSet(err, CS_ERR_ARG, "cs_bend: NULL output array or count");
  }
  size_t rows = cs_bendSweepRows(sp.p_max, p_step);
  if (capacity < 0 || (size_t)capacity < rows) {
    return cs_errorSet(err, CS_ERR_RANGE, "cs_bend: capacity %d below the sweep's %zu rows",
                       capacity, rows);
  }
  char path[1024];
  if ((sp.kind == CS_BEND_ROD || sp.kind == CS_BEND_STRAIN) && !sp.calibration) {
    csRunDef rd = cs_defaultRunDef();
    rd.data_dir = def->data_dir;
    sp.default_path = cs_runDataPath(&rd, CS_MISSION_CALIBRATION, path, sizeof path);
  }
  csBendSolver s;
  st = cs_bendSolverOpen(&s, &sp, err);
  for (size_t i = 0; st == CS_OK && i < rows; i++) {
    double p = cs_bendSweepPressure(sp.p_max, p_step, i);
    st = cs_bendSolverPoint(&s, p, &angle_deg[3 * i], &tip[3 * i], err);
    if (st != CS_OK) {
      char cause[sizeof err->msg];
      memcpy(cause, err->msg, sizeof cause);
      cs_errorSet(err, st, "%s model failed at p = %.6g MPa (row %zu of %zu; the rows before "
                  "it are kept): %.300s", sp.kind == CS_BEND_ROD      ? "rod"
                                          : sp.kind == CS_BEND_STRAIN ? "strain"
                                                                      : "analytic", p, i,
                  rows, cause);
      break;
    }
    pressure[i] = p;
    *n = (int)i + 1;
  }
  cs_bendSolverClose(&s);
  return st;
}
