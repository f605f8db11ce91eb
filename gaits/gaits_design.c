/* gaits_design.c: the gait design description reader (see gaits_design.h).
 *
 * Same reading discipline as the terrain and gait files: lines from core_text.h's reader
 * (overlong lines and NUL bytes refused at their line), words split in place, every statement
 * checks its word count, numbers by strtod and then checked finite and in range. Strides are
 * expanded into moves as they are read, so the overlap check sees every move once. */
#include "gaits_design.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core_text.h"

enum { MAX_LINE = 1023, MAX_WORDS = 24 };

/* times beyond a day and durations beyond an hour are typos */
#define MAX_TIME_S 86400.0
#define MAX_DURATION_S 3600.0
/* a row every 1 ms at least (the ODE step), every 1 s at most */
#define MIN_SAMPLE_S 1e-3
#define MAX_SAMPLE_S 1.0
/* targets: lengths within one leg length-ish, bends within a turn, pressures of a gait table */
#define MAX_TARGET_MM 1000.0
#define MAX_TARGET_DEG 360.0
#define MAX_PRESSURE_MPA 1.0
#define MAX_STRIDES 1000

/* the stride being read: phases expand into its moves */
typedef struct {
  int active, n, line;
  double period, t0;
  unsigned legs[2];
} Stride;

static int parseNumber(const char* s, double* v);
static csStatus parseLegs(const char* s, unsigned* legs, const char* path, int line,
                          csError* err);
static csStatus parseSet(const char* s, unsigned char ch[12], const char* path, int line,
                         csError* err);
static csStatus addMove(csgDesign* d, double t0, double dur, unsigned legs, int pose, int line,
                        const char* path, csError* err);
/* a trailing profile word (linear, ease-in, ease-out): removed from the count; the profile */
static int takeLinear(char** w, int* nw);


static int parseNumber(const char* s, double* v) {
  char* end;
  *v = strtod(s, &end);
  return end != s && !*end && isfinite(*v);
}


static csStatus parseLegs(const char* s, unsigned* legs, const char* path, int line,
                          csError* err) {
  *legs = 0;
  if (!*s) {
    return cs_errorSet(err, CS_ERR_PARSE, "%s:%d: empty leg set", path, line);
  }
  for (const char* c = s; *c; c++) {
    if (*c < 'A' || *c > 'H') {
      return cs_errorSet(err, CS_ERR_PARSE, "%s:%d: leg set '%.20s': '%c' is not a leg A..H",
                         path, line, s, *c);
    }
    unsigned bit = 1u << (*c - 'A');
    if (*legs & bit) {
      return cs_errorSet(err, CS_ERR_PARSE, "%s:%d: leg set '%.20s' names leg %c twice", path,
                         line, s, *c);
    }
    *legs |= bit;
  }
  return CS_OK;
}


/* "II<s>:<chambers>" into the chamber flags (added to what is there) */
static csStatus parseSet(const char* s, unsigned char ch[12], const char* path, int line,
                         csError* err) {
  if (strncmp(s, "II", 2) != 0 || s[2] < '1' || s[2] > '3' || s[3] != ':') {
    return cs_errorSet(err, CS_ERR_PARSE, "%s:%d: chamber set '%.30s' is not II<1..3>:<chambers> "
                       "(e.g. II1:3,4)", path, line, s);
  }
  int seg = s[2] - '1';
  unsigned mask = 0;
  csError e;
  if (csu_chamberListParse(s + 4, 4, "chambers", &mask, &e) != CS_OK) {
    return cs_errorSet(err, CS_ERR_PARSE, "%s:%d: chamber set '%.30s': %s", path, line, s, e.msg);
  }
  for (int j = 0; j < 4; j++) {
    if (mask & (1u << j)) {
      if (ch[4 * seg + j]) {
        return cs_errorSet(err, CS_ERR_PARSE, "%s:%d: chamber II%d:%d is in the set twice", path,
                           line, seg + 1, j + 1);
      }
      ch[4 * seg + j] = 1;
    }
  }
  return CS_OK;
}


static csStatus addMove(csgDesign* d, double t0, double dur, unsigned legs, int pose, int line,
                        const char* path, csError* err) {
  if (d->nmove == CSG_DESIGN_MAX_MOVES) {
    return cs_errorSet(err, CS_ERR_RANGE, "%s:%d: more than %d moves", path, line,
                       CSG_DESIGN_MAX_MOVES);
  }
  if (!(t0 >= 0 && t0 + dur <= MAX_TIME_S)) {
    return cs_errorSet(err, CS_ERR_RANGE, "%s:%d: move at %g s for %g s is outside 0..%g s", path,
                       line, t0, dur, MAX_TIME_S);
  }
  /* one leg, one move at a time: a move may start when the previous one has ended */
  for (int i = 0; i < d->nmove; i++) {
    const csgDesignMove* o = &d->move[i];
    if (!(o->legs & legs)) {
      continue;
    }
    double a0 = o->t0, a1 = o->t0 + o->duration, b0 = t0, b1 = t0 + dur;
    int same_time = a0 == b0;
    if (same_time || (b0 < a1 - 1e-9 && a0 < b1 - 1e-9)) {
      char l[9];
      csg_designLegsFormat(o->legs & legs, l);
      return cs_errorSet(err, CS_ERR_RANGE, "%s:%d: legs %s move at %g..%g s, overlapping their "
                         "move of line %d (%g..%g s)", path, line, l, b0, b1, o->line, a0, a1);
    }
  }
  csgDesignMove* m = &d->move[d->nmove++];
  m->t0 = t0;
  m->duration = dur;
  m->legs = legs;
  m->pose = pose;
  m->line = line;
  m->linear = 0;
  return CS_OK;
}


static int takeLinear(char** w, int* nw) {
  static const char* const kNames[] = {"linear", "ease-in", "ease-out"};
  static const int kProfiles[] = {CSG_PROFILE_LINEAR, CSG_PROFILE_EASE_IN, CSG_PROFILE_EASE_OUT};
  for (int i = 0; i < 3 && *nw > 1; i++) {
    if (!strcmp(w[*nw - 1], kNames[i])) {
      (*nw)--;
      return kProfiles[i];
    }
  }
  return CSG_PROFILE_SMOOTH;
}


int csg_designPoseFind(const csgDesign* d, const char* name) {
  for (int i = 0; i < d->npose; i++) {
    if (!strcmp(d->pose[i].name, name)) {
      return i;
    }
  }
  return -1;
}


void csg_designLegsFormat(unsigned legs, char* buf) {
  int n = 0;
  for (int k = 0; k < 8; k++) {
    if (legs & (1u << k)) {
      buf[n++] = (char)('A' + k);
    }
  }
  buf[n] = '\0';
}


/* the statements; each returns CS_OK or fills err */
static csStatus statementPose(csgDesign* d, char** w, int nw, const char* path, int line,
                              csError* err) {
  int foot = nw >= 3 && !strcmp(w[2], "foot");
  if (foot && nw != 5 && nw != 6) {
    return cs_errorSet(err, CS_ERR_PARSE, "%s:%d: 'pose NAME foot X LIFT [plus|minus]' needs two "
                       "numbers (mm)", path, line);
  }
  if (nw < 5) {
    return cs_errorSet(err, CS_ERR_PARSE, "%s:%d: 'pose' needs NAME, chamber sets, a target and "
                       "its value (e.g. pose S II1:3,4 II2:1,2 stroke 39)", path, line);
  }
  const char* name = w[1];
  if (strlen(name) >= CSG_DESIGN_NAME) {
    return cs_errorSet(err, CS_ERR_RANGE, "%s:%d: pose name longer than %d characters", path,
                       line, CSG_DESIGN_NAME - 1);
  }
  if (!strcmp(name, "straight")) {
    return cs_errorSet(err, CS_ERR_PARSE, "%s:%d: 'straight' is the built-in vented pose", path,
                       line);
  }
  int p = csg_designPoseFind(d, name);
  if (p < 0) {
    if (d->npose == CSG_DESIGN_MAX_POSES) {
      return cs_errorSet(err, CS_ERR_RANGE, "%s:%d: more than %d poses", path, line,
                         CSG_DESIGN_MAX_POSES - 1);
    }
    p = d->npose++;
    snprintf(d->pose[p].name, sizeof d->pose[p].name, "%s", name);
    d->pose[p].line = line;
  }
  csgDesignPose* po = &d->pose[p];
  if (foot) {
    csgDesignSet s;
    memset(&s, 0, sizeof s);
    s.line = line;
    s.ref = -1;
    s.kind = CSG_TARGET_FOOT;
    if (po->nset) {
      return cs_errorSet(err, CS_ERR_PARSE, "%s:%d: pose %s: a foot pose is one line (the pose "
                         "already has a chamber set on line %d)", path, line, name,
                         po->set[0].line);
    }
    if (!parseNumber(w[3], &s.value) || !parseNumber(w[4], &s.value2)) {
      return cs_errorSet(err, CS_ERR_PARSE, "%s:%d: foot X LIFT: '%.20s %.20s' are not two finite "
                         "numbers", path, line, w[3], w[4]);
    }
    if (nw == 6) {
      /* the branch: II1 bending towards +e1 on Ω3&Ω4 (plus) or back on Ω1&Ω2 (minus) */
      if (!strcmp(w[5], "plus") || !strcmp(w[5], "minus")) {
        s.branch = !strcmp(w[5], "plus") ? 1 : -1;
      } else {
        return cs_errorSet(err, CS_ERR_PARSE, "%s:%d: foot X LIFT: '%.20s' is not plus or minus",
                           path, line, w[5]);
      }
    }
    if (fabs(s.value) > MAX_TARGET_MM || !(s.value2 >= 0 && s.value2 <= MAX_TARGET_MM)) {
      return cs_errorSet(err, CS_ERR_RANGE, "%s:%d: foot %g %g mm: X within +-%g, LIFT in 0..%g",
                         path, line, s.value, s.value2, MAX_TARGET_MM, MAX_TARGET_MM);
    }
    for (int j = 0; j < 12; j++) {
      s.chambers[j] = 1; /* the pose may use any sagittal pair of every segment */
    }
    po->set[po->nset++] = s;
    return CS_OK;
  }
  if (po->nset && po->set[0].kind == CSG_TARGET_FOOT) {
    return cs_errorSet(err, CS_ERR_PARSE, "%s:%d: pose %s is a foot pose (line %d): it takes no "
                       "chamber sets", path, line, name, po->set[0].line);
  }
  if (po->nset == CSG_DESIGN_MAX_SETS) {
    return cs_errorSet(err, CS_ERR_RANGE, "%s:%d: pose %s has more than %d chamber sets", path,
                       line, name, CSG_DESIGN_MAX_SETS);
  }
  csgDesignSet s;
  memset(&s, 0, sizeof s);
  s.line = line;
  s.ref = -1;
  for (int i = 2; i < nw - 2; i++) {
    csStatus st = parseSet(w[i], s.chambers, path, line, err);
    if (st != CS_OK) {
      return st;
    }
  }
  /* a chamber belongs to one set of a pose: its pressure is that set's */
  for (int j = 0; j < 12; j++) {
    for (int q = 0; q < po->nset; q++) {
      if (s.chambers[j] && po->set[q].chambers[j]) {
        return cs_errorSet(err, CS_ERR_PARSE, "%s:%d: chamber II%d:%d is already in pose %s's "
                           "set of line %d", path, line, j / 4 + 1, j % 4 + 1, name,
                           po->set[q].line);
      }
    }
  }
  const char* key = w[nw - 2];
  const char* val = w[nw - 1];
  static const struct {
    const char* name;
    csgTargetKind kind;
    double max;
    const char* unit;
  } kTargets[] = {
      {"pressure", CSG_TARGET_PRESSURE, MAX_PRESSURE_MPA, "MPa"},
      {"stroke", CSG_TARGET_STROKE, MAX_TARGET_MM, "mm"},
      {"side", CSG_TARGET_SIDE, MAX_TARGET_MM, "mm"},
      {"lift", CSG_TARGET_LIFT, MAX_TARGET_MM, "mm"},
      {"rise", CSG_TARGET_RISE, MAX_TARGET_MM, "mm"},
      {"bend", CSG_TARGET_BEND, MAX_TARGET_DEG, "deg"},
  };
  if (!strcmp(key, "pressure-of")) {
    int r = csg_designPoseFind(d, val);
    if (r <= 0 || d->pose[r].nset == 0 || r == p || d->pose[r].set[0].kind == CSG_TARGET_FOOT) {
      return cs_errorSet(err, CS_ERR_PARSE, "%s:%d: pressure-of '%.30s': no earlier pose with "
                         "chamber sets of that name (foot poses have none)", path, line, val);
    }
    if (r > p) {
      /* poses are solved in the order they first appear (robot_gaitdesign.c): a later pose
       * has no pressure yet when this one is solved, and 0 MPa would be taken silently */
      return cs_errorSet(err, CS_ERR_PARSE, "%s:%d: pressure-of '%.30s': pose %s (line %d) is "
                         "defined after pose %s (line %d); refer to poses defined before it",
                         path, line, val, d->pose[r].name, d->pose[r].line, name, po->line);
    }
    s.kind = CSG_TARGET_PRESSURE_OF;
    s.ref = r;
  } else {
    size_t k = 0;
    while (k < sizeof kTargets / sizeof kTargets[0] && strcmp(kTargets[k].name, key)) {
      k++;
    }
    if (k == sizeof kTargets / sizeof kTargets[0]) {
      return cs_errorSet(err, CS_ERR_PARSE, "%s:%d: unknown target '%.30s' (expected stroke, "
                         "side, lift, rise, bend, pressure or pressure-of)", path, line, key);
    }
    if (!parseNumber(val, &s.value)) {
      return cs_errorSet(err, CS_ERR_PARSE, "%s:%d: %s value '%.30s' is not a finite number",
                         path, line, key, val);
    }
    int signed_ok = kTargets[k].kind == CSG_TARGET_STROKE || kTargets[k].kind == CSG_TARGET_SIDE;
    if (fabs(s.value) > kTargets[k].max || (!signed_ok && !(s.value >= 0))) {
      return cs_errorSet(err, CS_ERR_RANGE, "%s:%d: %s %g %s is outside %s..%g", path, line, key,
                         s.value, kTargets[k].unit, signed_ok ? "-max" : "0", kTargets[k].max);
    }
    s.kind = kTargets[k].kind;
  }
  int any = 0;
  for (int j = 0; j < 12; j++) {
    any |= s.chambers[j];
  }
  if (!any) {
    return cs_errorSet(err, CS_ERR_PARSE, "%s:%d: pose %s: no chamber set given", path, line, name);
  }
  po->set[po->nset++] = s;
  return CS_OK;
}


static csStatus needNumbers(char** w, int nw, int first, int n, double* v, const char* path,
                            int line, csError* err) {
  (void)nw;
  for (int i = 0; i < n; i++) {
    if (!parseNumber(w[first + i], &v[i])) {
      return cs_errorSet(err, CS_ERR_PARSE, "%s:%d: '%s' value '%.30s' is not a finite number",
                         path, line, w[0], w[first + i]);
    }
  }
  return CS_OK;
}


static int posePeek(const csgDesign* d, const char* name) {
  return !strcmp(name, "straight") ? CSG_POSE_STRAIGHT : csg_designPoseFind(d, name);
}


/* `foothold T LEGS OFFSETS [margin MM]` (gaits_design.h) */
static csStatus statementFoothold(csgDesign* d, char** w, int nw, const char* path, int line,
                                  csError* err) {
  if (d->nfoothold >= CSG_DESIGN_MAX_FOOTHOLDS) {
    return cs_errorSet(err, CS_ERR_RANGE, "%s:%d: more than %d footholds", path, line,
                       CSG_DESIGN_MAX_FOOTHOLDS);
  }
  if ((nw != 4 && nw != 6) || (nw == 6 && strcmp(w[4], "margin"))) {
    return cs_errorSet(err, CS_ERR_PARSE, "%s:%d: 'foothold' needs T LEGS OFFSETS [margin MM]",
                       path, line);
  }
  csgDesignFoothold* f = &d->foothold[d->nfoothold];
  memset(f, 0, sizeof *f);
  f->line = line;
  f->margin = 10;
  if (!parseNumber(w[1], &f->t) || !(f->t >= 0 && f->t <= MAX_TIME_S) ||
      (nw == 6 && (!parseNumber(w[5], &f->margin) || !(f->margin >= 0)))) {
    return cs_errorSet(err, CS_ERR_RANGE, "%s:%d: foothold needs T in 0..%g s and a margin >= 0 "
                       "mm", path, line, MAX_TIME_S);
  }
  csStatus st = parseLegs(w[2], &f->legs, path, line, err);
  if (st != CS_OK) {
    return st;
  }
  const char* c = w[3];
  while (*c) {
    char* end;
    const double v = strtod(c, &end);
    if (end == c || !isfinite(v) || (*end && *end != ',') || (*end == ',' && !end[1]) ||
        f->noffset >= CSG_DESIGN_MAX_OFFSETS) {
      f->noffset = 0;
      break;
    }
    f->offset[f->noffset++] = v;
    c = *end ? end + 1 : end;
  }
  if (f->noffset == 0) {
    return cs_errorSet(err, CS_ERR_PARSE, "%s:%d: OFFSETS '%.40s' must be 1..%d numbers (mm) "
                       "separated by commas", path, line, w[3], CSG_DESIGN_MAX_OFFSETS);
  }
  d->nfoothold++;
  return CS_OK;
}


/* the reader's state between statements (csu_statementFileRead): the open stride and the
 * lines of the statements allowed once (0: not yet) */
typedef struct {
  csgDesign* d;
  Stride sd;
  int name_line, sample_line, ramp_line, end_line;
} designReader;

static csStatus designStatement(void* ctx, char** w, int nw, const char* path, int line,
                                csError* err) {
  designReader* c = ctx;
  csgDesign* d = c->d;
  csStatus st = CS_OK;
  const char* key = w[0];
  double v[3];
  if (strcmp(key, "phase") != 0) {
    c->sd.active = 0; /* any other statement closes the stride (a new one opens its own) */
  }
  if (!strcmp(key, "name")) {
    if (nw != 2 || strlen(w[1]) >= sizeof d->name || c->name_line) {
      st = cs_errorSet(err, CS_ERR_PARSE, "%s:%d: 'name' needs one word of at most %d "
                       "characters, once", path, line, (int)sizeof d->name - 1);
    } else {
      snprintf(d->name, sizeof d->name, "%s", w[1]);
      c->name_line = line;
    }
  } else if (!strcmp(key, "sample")) {
    if (nw != 2 || c->sample_line) {
      st = cs_errorSet(err, CS_ERR_PARSE, "%s:%d: 'sample' needs one number (s), once", path,
                       line);
    } else if ((st = needNumbers(w, nw, 1, 1, v, path, line, err)) == CS_OK &&
               !(v[0] >= MIN_SAMPLE_S && v[0] <= MAX_SAMPLE_S)) {
      st = cs_errorSet(err, CS_ERR_RANGE, "%s:%d: sample %g s is outside %g..%g s", path, line,
                       v[0], MIN_SAMPLE_S, MAX_SAMPLE_S);
    } else {
      d->sample = v[0];
      c->sample_line = line;
    }
  } else if (!strcmp(key, "ramp")) {
    /* the actuation time the design assumes, stated by the table (gaits_csv.h `@ramp`) */
    if (nw != 2 || c->ramp_line) {
      st = cs_errorSet(err, CS_ERR_PARSE, "%s:%d: 'ramp' needs one number (s), once", path,
                       line);
    } else if ((st = needNumbers(w, nw, 1, 1, v, path, line, err)) == CS_OK &&
               !(v[0] >= MIN_SAMPLE_S && v[0] <= MAX_SAMPLE_S)) {
      st = cs_errorSet(err, CS_ERR_RANGE, "%s:%d: ramp %g s is outside %g..%g s", path, line,
                       v[0], MIN_SAMPLE_S, MAX_SAMPLE_S);
    } else {
      d->ramp = v[0];
      c->ramp_line = line;
    }
  } else if (!strcmp(key, "pose")) {
    st = statementPose(d, w, nw, path, line, err);
  } else if (!strcmp(key, "move")) {
    int linear = takeLinear(w, &nw);
    unsigned legs = 0;
    int p = nw == 5 ? posePeek(d, w[4]) : -1;
    if (nw != 5) {
      st = cs_errorSet(err, CS_ERR_PARSE, "%s:%d: 'move' needs T0 DURATION LEGS POSE "
                       "[linear|ease-in|ease-out], got %d values", path, line, nw - 1);
    } else if ((st = needNumbers(w, nw, 1, 2, v, path, line, err)) != CS_OK) {
    } else if (!(v[1] >= 0 && v[1] <= MAX_DURATION_S)) {
      st = cs_errorSet(err, CS_ERR_RANGE, "%s:%d: duration %g s is outside 0..%g s", path, line,
                       v[1], MAX_DURATION_S);
    } else if ((st = parseLegs(w[3], &legs, path, line, err)) != CS_OK) {
    } else if (p < 0) {
      st = cs_errorSet(err, CS_ERR_PARSE, "%s:%d: unknown pose '%.30s' (define it with 'pose' "
                       "first)", path, line, w[4]);
    } else if ((st = addMove(d, v[0], v[1], legs, p, line, path, err)) == CS_OK) {
      d->move[d->nmove - 1].linear = linear;
    }
  } else if (!strcmp(key, "stride")) {
    memset(&c->sd, 0, sizeof c->sd);
    if (nw != 6) {
      st = cs_errorSet(err, CS_ERR_PARSE, "%s:%d: 'stride' needs N PERIOD T0 LEGS1 LEGS2, got "
                       "%d values", path, line, nw - 1);
    } else if ((st = needNumbers(w, nw, 1, 3, v, path, line, err)) != CS_OK) {
    } else if (!(v[0] >= 1 && v[0] <= MAX_STRIDES && v[0] == floor(v[0])) ||
               !(v[1] > 0 && v[1] <= MAX_DURATION_S) || !(v[2] >= 0 && v[2] <= MAX_TIME_S)) {
      st = cs_errorSet(err, CS_ERR_RANGE, "%s:%d: stride needs N in 1..%d, PERIOD in (0, %g] s "
                       "and T0 in 0..%g s", path, line, MAX_STRIDES, MAX_DURATION_S, MAX_TIME_S);
    } else if ((st = parseLegs(w[4], &c->sd.legs[0], path, line, err)) != CS_OK ||
               (st = parseLegs(w[5], &c->sd.legs[1], path, line, err)) != CS_OK) {
    } else if (c->sd.legs[0] & c->sd.legs[1]) {
      st = cs_errorSet(err, CS_ERR_PARSE, "%s:%d: the two leg sets of a stride share legs", path,
                       line);
    } else {
      c->sd.active = 1;
      c->sd.n = (int)v[0];
      c->sd.period = v[1];
      c->sd.t0 = v[2];
      c->sd.line = line;
      if (d->nstride++ == 0) {
        d->stride_t0 = c->sd.t0;
        d->stride_period = c->sd.period;
        d->stride_n = c->sd.n;
      }
    }
  } else if (!strcmp(key, "phase")) {
    int linear = takeLinear(w, &nw);
    int role = -1, p = -1, plast = -1;
    if (!c->sd.active) {
      st = cs_errorSet(err, CS_ERR_PARSE, "%s:%d: 'phase' outside a stride (a 'stride' line "
                       "and its phases must follow each other)", path, line);
    } else if (nw != 5 && !(nw == 7 && !strcmp(w[5], "last"))) {
      st = cs_errorSet(err, CS_ERR_PARSE, "%s:%d: 'phase' needs START DURATION ROLE POSE "
                       "[last POSE2] [linear|ease-in|ease-out]", path, line);
    } else if ((st = needNumbers(w, nw, 1, 2, v, path, line, err)) != CS_OK) {
    } else if (!(v[0] >= 0 && v[0] < c->sd.period && v[1] >= 0 && v[1] <= MAX_DURATION_S)) {
      /* a phase may outlast its stride (a stance push that overlaps the next one); the
       * overlap check keeps each leg's moves apart */
      st = cs_errorSet(err, CS_ERR_RANGE, "%s:%d: phase start %g s must lie in the stride's "
                       "period [0, %g) s and its duration %g s in 0..%g s", path, line, v[0],
                       c->sd.period, v[1], MAX_DURATION_S);
    } else if ((role = !strcmp(w[3], "swing") ? 0 : !strcmp(w[3], "stand") ? 1 : -1) < 0) {
      st = cs_errorSet(err, CS_ERR_PARSE, "%s:%d: role '%.20s' is not swing or stand", path,
                       line, w[3]);
    } else if ((p = posePeek(d, w[4])) < 0 || (nw == 7 && (plast = posePeek(d, w[6])) < 0)) {
      st = cs_errorSet(err, CS_ERR_PARSE, "%s:%d: unknown pose '%.30s'", path, line,
                       p < 0 ? w[4] : w[6]);
    } else {
      for (int k = 0; k < c->sd.n && st == CS_OK; k++) {
        /* swing = the legs with their feet forward at the stride's start */
        unsigned legs = c->sd.legs[(k + role) % 2];
        int pose = (k == c->sd.n - 1 && plast >= 0) ? plast : p;
        st = addMove(d, c->sd.t0 + k * c->sd.period + v[0], v[1], legs, pose, line, path, err);
        if (st == CS_OK) {
          d->move[d->nmove - 1].linear = linear;
        }
      }
    }
  } else if (!strcmp(key, "mirror")) {
    if (nw != 2 || d->mirror) {
      st = cs_errorSet(err, CS_ERR_PARSE, "%s:%d: 'mirror' needs one leg set (e.g. CDEF), once",
                       path, line);
    } else {
      st = parseLegs(w[1], &d->mirror, path, line, err);
    }
  } else if (!strcmp(key, "foothold")) {
    st = statementFoothold(d, w, nw, path, line, err);
  } else if (!strcmp(key, "end")) {
    if (nw != 2 || c->end_line) {
      st = cs_errorSet(err, CS_ERR_PARSE, "%s:%d: 'end' needs one time (s), once", path, line);
    } else if ((st = needNumbers(w, nw, 1, 1, v, path, line, err)) == CS_OK &&
               !(v[0] > 0 && v[0] <= MAX_TIME_S)) {
      st = cs_errorSet(err, CS_ERR_RANGE, "%s:%d: end %g s is outside (0, %g] s", path, line,
                       v[0], MAX_TIME_S);
    } else {
      d->end = v[0];
      c->end_line = line;
    }
  } else {
    st = cs_errorSet(err, CS_ERR_PARSE, "%s:%d: unknown statement '%.30s' (expected name, "
                     "sample, ramp, pose, move, stride, phase, mirror, foothold, end)", path, line,
                     key);
  }
  return st;
}


csStatus csg_designRead(csgDesign* d, const char* path, csError* err) {
  memset(d, 0, sizeof *d);
  snprintf(d->source, sizeof d->source, "%s", path);
  d->sample = 0.05;
  d->npose = 1;
  snprintf(d->pose[0].name, sizeof d->pose[0].name, "straight");
  designReader c;
  memset(&c, 0, sizeof c);
  c.d = d;
  int line = 0;
  csStatus st = csu_statementFileRead(path, MAX_LINE, "gait design", MAX_WORDS, designStatement,
                                      &c, &line, err);
  if (st != CS_OK) {
    return st;
  }
  int last = line > 0 ? line : 1;
  if (d->nmove == 0) {
    return cs_errorSet(err, CS_ERR_PARSE, "%s:%d: end of file without a 'move' or a stride's "
                       "'phase': the gait does nothing", path, last);
  }
  /* moves in time order (stable: insertion sort keeps file order at equal times) */
  for (int i = 1; i < d->nmove; i++) {
    csgDesignMove m = d->move[i];
    int j = i - 1;
    while (j >= 0 && d->move[j].t0 > m.t0) {
      d->move[j + 1] = d->move[j];
      j--;
    }
    d->move[j + 1] = m;
  }
  double t_last = 0;
  for (int i = 0; i < d->nmove; i++) {
    t_last = fmax(t_last, d->move[i].t0 + d->move[i].duration);
  }
  if (c.end_line && d->end < t_last - 1e-9) {
    return cs_errorSet(err, CS_ERR_RANGE, "%s:%d: end %g s is before the last move ends (%g s)",
                       path, c.end_line, d->end, t_last);
  }
  if (!d->name[0]) {
    snprintf(d->name, sizeof d->name, "unnamed");
  }
  return CS_OK;
}
