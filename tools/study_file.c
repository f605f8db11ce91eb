/* study_file.c: the study-file reader (see study_file.h).
 *
 * Each command's options are listed once here with the kind of value they take, so a typo in
 * a study of twenty 30-minute FE cases is refused at its line before the first case starts
 * instead of failing an hour later. The lists mirror the commands' parsers (tools/cmd_*.c);
 * those stay the final check when a step runs. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core_text.h"
#include "cs_paths.h"
#include "robot_actuator.h"
#include "study_file.h"

/* what an option's value is */
typedef enum {
  OPT_FLAG,  /* no value */
  OPT_NUM,   /* a finite number (the command checks its range) */
  OPT_WORD,  /* any word (the command checks it) */
  OPT_PATH,  /* a file that must exist (unless it is under @case/: an earlier step makes it) */
  OPT_CALIB, /* a path, or the word `analytic` (bend's rod calibration) */
  OPT_FILE_NONE, /* a path, or the word `none` (run's --foothold, --gate) */
  OPT_SET,   /* NAME=VALUE of an actuator parameter */
  OPT_ACT,   /* an actuator preset */
  OPT_OWNED  /* given by the study runner: refused in a study file */
} OptKind;

typedef struct {
  const char* name;
  OptKind kind;
} OptSpec;

typedef struct {
  const char* name;        /* in study files */
  const char* actuator;    /* the command's default actuator preset */
  int positional;          /* words that are not options (gait-design: FILE.gait) */
  const OptSpec* opts;     /* terminated by a NULL name */
} CmdSpec;

static const OptSpec kBendOpts[] = {
    {"--model", OPT_WORD},     {"--actuator", OPT_ACT},    {"--set", OPT_SET},
    {"--chambers", OPT_WORD},  {"--p-max", OPT_NUM},       {"--p-step", OPT_NUM},
    {"--until-angle", OPT_NUM}, {"--mesh-size", OPT_NUM},  {"--pressures", OPT_WORD},
    {"--fibre-size", OPT_NUM}, {"--fibre-split", OPT_WORD}, {"--fibre-law", OPT_WORD},
    {"--tip-load", OPT_WORD},  {"--calibration", OPT_CALIB}, {"--branch-switch", OPT_WORD},
    {"--cal-rule", OPT_WORD},  {"--out", OPT_OWNED},       {"--help", OPT_OWNED},
    {"--cal-drop", OPT_WORD},  {NULL, OPT_FLAG}};

static const OptSpec kRunOpts[] = {
    {"--scene", OPT_WORD},        {"--gait", OPT_PATH},          {"--terrain", OPT_PATH},
    {"--legs", OPT_WORD},         {"--calibration", OPT_PATH},   {"--friction", OPT_NUM},
    {"--pressure-scale", OPT_NUM}, {"--t-end", OPT_NUM},         {"--dt", OPT_NUM},
    {"--output-dt", OPT_NUM},     {"--ramp", OPT_NUM},           {"--tau", OPT_NUM},
    {"--support-mass", OPT_NUM},  {"--links", OPT_NUM},          {"--gravity", OPT_NUM},
    {"--macro-steps", OPT_NUM},   {"--coupling", OPT_WORD},      {"--conditions", OPT_WORD},
    {"--iterations", OPT_NUM},    {"--quiet", OPT_FLAG},         {"--set", OPT_SET},
    {"--cal-rule", OPT_WORD},     {"--rod-tol", OPT_NUM},        {"--out", OPT_OWNED},
    {"--help", OPT_OWNED},        {"--cal-drop", OPT_WORD},      {"--scene-file", OPT_PATH},
    {"--slope-deg", OPT_NUM},     {"--foothold", OPT_FILE_NONE},
    {"--gate", OPT_FILE_NONE},    {"--strain-step", OPT_WORD},   {"--step-tol", OPT_NUM},
    {"--step-order", OPT_NUM},    {NULL, OPT_FLAG}};

static const OptSpec kCalibrateOpts[] = {
    {"--case", OPT_WORD},       {"--actuator", OPT_ACT}, {"--set", OPT_SET},
    {"--mesh-size", OPT_NUM},   {"--fibre-size", OPT_NUM}, {"--fibre-split", OPT_WORD},
    {"--fibre-law", OPT_WORD},  {"--p-step", OPT_NUM},
    {"--p-max", OPT_NUM},       {"--out", OPT_OWNED},    {"--dir", OPT_OWNED},
    {"--list", OPT_OWNED},      {"--merge-only", OPT_OWNED}, {"--help", OPT_OWNED},
    {NULL, OPT_FLAG}};

static const OptSpec kGaitDesignOpts[] = {
    {"--calibration", OPT_PATH}, {"--p-max", OPT_NUM},  {"--stretch", OPT_FLAG},
    {"--check", OPT_FLAG},       {"--check-scene", OPT_WORD}, {"--check-t", OPT_NUM},
    {"--set", OPT_SET},          {"--out", OPT_OWNED},  {"--help", OPT_OWNED},
    {"--cal-rule", OPT_WORD},    {NULL, OPT_FLAG}};

static const CmdSpec kCmds[CSX_STUDY_NCMD] = {
    {"bend", "baseline", 0, kBendOpts},
    {"run", "leg", 0, kRunOpts},
    {"calibrate", "leg", 0, kCalibrateOpts},
    {"gait-design", "leg", 1, kGaitDesignOpts},
};

/* the reader's state while a file is read */
typedef struct {
  csxStudy* s;
  const char* path;
  long line;
  int have_name;
  int ndefault[CSX_STUDY_NCMD];
  char** deflt[CSX_STUDY_NCMD]; /* current defaults per command (owned copies) */
  int cap;                      /* allocated cases */
} Reader;

/* a study or case name: 1..63 of [A-Za-z0-9_.-], not starting with '.' or '-' */
static int validName(const char* w);
/* the option spec of `word` for command c, or NULL */
static const OptSpec* findOpt(csxStudyCmd c, const char* word);
/* whether option o's value v names a file (checked to exist): a path option's, a calibration
 * but `analytic`, a file-or-none but `none` */
static int namesFile(const OptSpec* o, const char* v) {
  return o->kind == OPT_PATH || (o->kind == OPT_CALIB && strcmp(v, "analytic")) ||
         (o->kind == OPT_FILE_NONE && strcmp(v, "none"));
}
/* check the words of a step (options, values, the actuator they describe) */
static csStatus checkStep(Reader* r, csxStudyCmd c, char** w, int n, csError* err);
/* the step's words: the command's defaults, then `own`; copies owned by the step */
static csStatus makeStep(Reader* r, csxStudyStep* st, csxStudyCmd c, char** own, int nown,
                         csError* err);
/* one statement (the line split into words, comment removed) */
static csStatus statement(Reader* r, char** w, int n, csError* err);
/* the signature of a finished case (its steps, one per line) */
static csStatus makeSignature(Reader* r, csxStudyCase* c, csError* err);
/* duplicate a string; NULL when out of memory */
static char* dupString(const char* s);
static void freeWords(char** w, int n);


const char* csx_studyCmdName(csxStudyCmd c) {
  return c >= 0 && c < CSX_STUDY_NCMD ? kCmds[c].name : "?";
}


static int validName(const char* w) {
  size_t n = strlen(w);
  if (n == 0 || n >= CSX_STUDY_NAME_SIZE || w[0] == '.' || w[0] == '-') {
    return 0;
  }
  for (size_t i = 0; i < n; i++) {
    char ch = w[i];
    int ok = (ch >= 'a' && ch <= 'z') || (ch >= 'A' && ch <= 'Z') || (ch >= '0' && ch <= '9') ||
             ch == '_' || ch == '.' || ch == '-';
    if (!ok) {
      return 0;
    }
  }
  return 1;
}


static const OptSpec* findOpt(csxStudyCmd c, const char* word) {
  for (const OptSpec* o = kCmds[c].opts; o->name; o++) {
    if (!strcmp(o->name, word)) {
      return o;
    }
  }
  return NULL;
}


static char* dupString(const char* s) {
  size_t n = strlen(s) + 1;
  char* d = malloc(n);
  if (d) {
    memcpy(d, s, n);
  }
  return d;
}


static void freeWords(char** w, int n) {
  if (!w) {
    return;
  }
  for (int i = 0; i < n; i++) {
    free(w[i]);
  }
  free(w);
}


int csx_studyResolvePath(const csxStudy* s, const char* case_dir, const char* word, char* out,
                         size_t size) {
  int k;
  if (!strncmp(word, "@data/", 6)) {
    char buf[CSX_STUDY_PATH_SIZE];
    csx_dataPath(word + 6, buf, sizeof buf);
    k = snprintf(out, size, "%s", buf);
  } else if (!strncmp(word, "@case/", 6)) {
    k = snprintf(out, size, "%s/%s", case_dir ? case_dir : ".", word + 6);
  } else if (word[0] == '/') {
    k = snprintf(out, size, "%s", word);
  } else {
    k = snprintf(out, size, "%s/%s", s->dir, word);
  }
  return k >= 0 && (size_t)k < size ? 0 : -1;
}


int csx_studyWordIsPath(const csxStudyStep* st, int i) {
  if (i < 0 || i >= st->nword) {
    return 0;
  }
  /* an option's value: the word before it names an option that takes a file */
  if (i > 0) {
    const OptSpec* o = findOpt(st->cmd, st->word[i - 1]);
    if (o && namesFile(o, st->word[i])) {
      return 1;
    }
    if (o && o->kind != OPT_FLAG) {
      return 0; /* another option's value */
    }
  }
  /* a positional word (gait-design's FILE.gait) */
  return kCmds[st->cmd].positional > 0 && st->word[i][0] != '-';
}


static csStatus checkStep(Reader* r, csxStudyCmd c, char** w, int n, csError* err) {
  const CmdSpec* cs = &kCmds[c];
  const char* preset = cs->actuator;
  int npos = 0, act_given = 0, model_rod = 0;
  /* pass 1: options and values */
  for (int i = 0; i < n; i++) {
    const char* a = w[i];
    if (strncmp(a, "--", 2) != 0) {
      if (npos < cs->positional) {
        npos++;
        if (strncmp(a, "@case/", 6)) {
          char p[CSX_STUDY_PATH_SIZE];
          FILE* f = NULL;
          if (csx_studyResolvePath(r->s, NULL, a, p, sizeof p) == 0) {
            f = fopen(p, "rb");
          }
          if (!f) {
            return cs_errorSet(err, CS_ERR_IO, "%s:%ld: %s: %s: no such file", r->path, r->line,
                               cs->name, a);
          }
          fclose(f);
        }
        continue;
      }
      return cs_errorSet(err, CS_ERR_PARSE, "%s:%ld: %s: unexpected word '%.80s' (options are "
                         "written --name value)", r->path, r->line, cs->name, a);
    }
    if (strchr(a, '=')) {
      return cs_errorSet(err, CS_ERR_PARSE, "%s:%ld: %s: write '%.*s VALUE', not '%.80s' (study "
                         "files take --name value)", r->path, r->line, cs->name,
                         (int)(strchr(a, '=') - a), a, a);
    }
    const OptSpec* o = findOpt(c, a);
    if (!o) {
      return cs_errorSet(err, CS_ERR_PARSE, "%s:%ld: %s: unknown option '%.80s'", r->path,
                         r->line, cs->name, a);
    }
    if (o->kind == OPT_OWNED) {
      return cs_errorSet(err, CS_ERR_PARSE, "%s:%ld: %s: %s is set by the study runner (outputs "
                         "go to the case's directory, @case/)", r->path, r->line, cs->name, a);
    }
    if (o->kind == OPT_FLAG) {
      continue;
    }
    if (i + 1 >= n || !strncmp(w[i + 1], "--", 2)) {
      return cs_errorSet(err, CS_ERR_PARSE, "%s:%ld: %s: option %s needs a value", r->path,
                         r->line, cs->name, a);
    }
    const char* v = w[++i];
    if (!strcmp(a, "--model") && !strcmp(v, "rod")) {
      model_rod = 1;
    }
    if (o->kind == OPT_NUM) {
      char* end = NULL;
      double x = strtod(v, &end);
      if (end == v || *end != '\0' || !isfinite(x)) {
        return cs_errorSet(err, CS_ERR_PARSE, "%s:%ld: %s: %s '%.80s' is not a finite number",
                           r->path, r->line, cs->name, a, v);
      }
    } else if (o->kind == OPT_ACT) {
      preset = v;
      act_given = 1;
    } else if (namesFile(o, v) && strncmp(v, "@case/", 6)) {
      char p[CSX_STUDY_PATH_SIZE];
      FILE* f = NULL;
      if (csx_studyResolvePath(r->s, NULL, v, p, sizeof p) == 0) {
        f = fopen(p, "rb");
      }
      if (!f) {
        return cs_errorSet(err, CS_ERR_IO, "%s:%ld: %s: %s %s: no such file (%s)", r->path,
                           r->line, cs->name, a, v, p);
      }
      fclose(f);
    }
  }
  if (npos < cs->positional) {
    return cs_errorSet(err, CS_ERR_PARSE, "%s:%ld: %s: missing FILE.gait", r->path, r->line,
                       cs->name);
  }
  /* `bend --model rod` defaults to its default calibration's actuator (tools/cmd_bend.c) */
  if (!act_given && model_rod && !strcmp(cs->name, "bend")) {
    preset = CSX_MISSION_ACTUATOR;
  }
  /* pass 2: the actuator the --set words describe must be a valid one */
  csrActuator act;
  csError e2;
  cs_errorClear(&e2);
  if (csr_actuatorPreset(&act, preset, &e2) != CS_OK) {
    return cs_errorSet(err, CS_ERR_PARSE, "%s:%ld: %s: %s", r->path, r->line, cs->name, e2.msg);
  }
  for (int i = 0; i + 1 < n; i++) {
    const OptSpec* o = strncmp(w[i], "--", 2) ? NULL : findOpt(c, w[i]);
    if (o && o->kind == OPT_SET) {
      if (csr_actuatorSetString(&act, w[i + 1], &e2) != CS_OK) {
        return cs_errorSet(err, CS_ERR_PARSE, "%s:%ld: %s: --set %s: %s", r->path, r->line,
                           cs->name, w[i + 1], e2.msg);
      }
    }
    if (o && o->kind != OPT_FLAG) {
      i++;
    }
  }
  if (csr_actuatorValidate(&act, &e2) != CS_OK) {
    return cs_errorSet(err, CS_ERR_RANGE, "%s:%ld: %s: the actuator (%s with the --set values) "
                       "is not valid: %s", r->path, r->line, cs->name, preset, e2.msg);
  }
  return CS_OK;
}


static csStatus makeStep(Reader* r, csxStudyStep* st, csxStudyCmd c, char** own, int nown,
                         csError* err) {
  int nd = r->ndefault[c];
  if (nd + nown > CSX_STUDY_MAX_WORDS) {
    return cs_errorSet(err, CS_ERR_RANGE, "%s:%ld: more than %d words in a step (defaults "
                       "included)", r->path, r->line, CSX_STUDY_MAX_WORDS);
  }
  st->cmd = c;
  st->line = r->line;
  st->nword = 0;
  st->word = calloc((size_t)(nd + nown) + 1, sizeof(char*));
  if (!st->word) {
    return cs_errorSet(err, CS_ERR_MEMORY, "%s:%ld: out of memory", r->path, r->line);
  }
  for (int i = 0; i < nd + nown; i++) {
    st->word[i] = dupString(i < nd ? r->deflt[c][i] : own[i - nd]);
    if (!st->word[i]) {
      return cs_errorSet(err, CS_ERR_MEMORY, "%s:%ld: out of memory", r->path, r->line);
    }
    st->nword++;
  }
  return checkStep(r, c, st->word, st->nword, err);
}


static csStatus makeSignature(Reader* r, csxStudyCase* c, csError* err) {
  size_t len = 1;
  for (int k = 0; k < c->nstep; k++) {
    len += strlen(kCmds[c->step[k].cmd].name) + 1;
    for (int i = 0; i < c->step[k].nword; i++) {
      len += strlen(c->step[k].word[i]) + 1;
    }
  }
  free(c->signature);
  c->signature = malloc(len);
  if (!c->signature) {
    return cs_errorSet(err, CS_ERR_MEMORY, "%s:%ld: out of memory", r->path, r->line);
  }
  char* p = c->signature;
  for (int k = 0; k < c->nstep; k++) {
    p += sprintf(p, "%s%s", k ? "\n" : "", kCmds[c->step[k].cmd].name);
    for (int i = 0; i < c->step[k].nword; i++) {
      p += sprintf(p, " %s", c->step[k].word[i]);
    }
  }
  return CS_OK;
}


/* the command named w, or CSX_STUDY_NCMD */
static csxStudyCmd findCmd(const char* w) {
  int c = 0;
  while (c < CSX_STUDY_NCMD && strcmp(kCmds[c].name, w)) {
    c++;
  }
  return (csxStudyCmd)c;
}


static csStatus statement(Reader* r, char** w, int n, csError* err) {
  csxStudy* s = r->s;
  const char* kw = w[0];
  if (!strcmp(kw, "study")) {
    if (n != 2) {
      return cs_errorSet(err, CS_ERR_PARSE, "%s:%ld: 'study' takes one name", r->path, r->line);
    }
    if (r->have_name || s->ncase > 0) {
      return cs_errorSet(err, CS_ERR_PARSE, "%s:%ld: 'study' %s", r->path, r->line,
                         r->have_name ? "given twice" : "must come before the first case");
    }
    if (!validName(w[1])) {
      return cs_errorSet(err, CS_ERR_PARSE, "%s:%ld: study name '%.80s': use 1-63 letters, "
                         "digits, _ . - (not starting with . or -)", r->path, r->line, w[1]);
    }
    snprintf(s->name, sizeof s->name, "%s", w[1]);
    r->have_name = 1;
    return CS_OK;
  }
  if (!strcmp(kw, "defaults")) {
    if (n < 2) {
      return cs_errorSet(err, CS_ERR_PARSE, "%s:%ld: 'defaults' needs a command (bend, run, "
                         "calibrate or gait-design)", r->path, r->line);
    }
    csxStudyCmd c = findCmd(w[1]);
    if (c == CSX_STUDY_NCMD) {
      return cs_errorSet(err, CS_ERR_PARSE, "%s:%ld: unknown command '%.80s' (expected bend, "
                         "run, calibrate or gait-design)", r->path, r->line, w[1]);
    }
    if (n - 2 > CSX_STUDY_MAX_WORDS) {
      return cs_errorSet(err, CS_ERR_RANGE, "%s:%ld: more than %d words", r->path, r->line,
                         CSX_STUDY_MAX_WORDS);
    }
    /* options only: a positional word (gait-design's file) belongs to each case */
    for (int i = 2; i < n; i++) {
      if (strncmp(w[i], "--", 2) && (i == 2 || !findOpt(c, w[i - 1]) ||
                                     findOpt(c, w[i - 1])->kind == OPT_FLAG)) {
        return cs_errorSet(err, CS_ERR_PARSE, "%s:%ld: defaults %s: unexpected word '%.80s' "
                           "(defaults hold options only)", r->path, r->line, w[1], w[i]);
      }
    }
    freeWords(r->deflt[c], r->ndefault[c]);
    r->deflt[c] = NULL;
    r->ndefault[c] = 0;
    if (n > 2) {
      r->deflt[c] = calloc((size_t)(n - 2), sizeof(char*));
      if (!r->deflt[c]) {
        return cs_errorSet(err, CS_ERR_MEMORY, "%s:%ld: out of memory", r->path, r->line);
      }
      for (int i = 2; i < n; i++) {
        r->deflt[c][i - 2] = dupString(w[i]);
        if (!r->deflt[c][i - 2]) {
          return cs_errorSet(err, CS_ERR_MEMORY, "%s:%ld: out of memory", r->path, r->line);
        }
        r->ndefault[c]++;
      }
    }
    return CS_OK;
  }
  if (!strcmp(kw, "case") || !strcmp(kw, "then")) {
    int is_case = kw[0] == 'c';
    int first = is_case ? 2 : 1; /* the command's word */
    if (n < first + 1) {
      return cs_errorSet(err, CS_ERR_PARSE, "%s:%ld: '%s' needs %s", r->path, r->line, kw,
                         is_case ? "a name and a command" : "a command");
    }
    csxStudyCmd c = findCmd(w[first]);
    if (c == CSX_STUDY_NCMD) {
      return cs_errorSet(err, CS_ERR_PARSE, "%s:%ld: unknown command '%.80s' (expected bend, "
                         "run, calibrate or gait-design)", r->path, r->line, w[first]);
    }
    csxStudyCase* cc;
    if (is_case) {
      if (!validName(w[1])) {
        return cs_errorSet(err, CS_ERR_PARSE, "%s:%ld: case name '%.80s': use 1-63 letters, "
                           "digits, _ . - (not starting with . or -)", r->path, r->line, w[1]);
      }
      int dup = csx_studyFindCase(s, w[1]);
      if (dup >= 0) {
        return cs_errorSet(err, CS_ERR_PARSE, "%s:%ld: case '%s' already defined at line %ld",
                           r->path, r->line, w[1], s->cases[dup].line);
      }
      if (s->ncase == CSX_STUDY_MAX_CASES) {
        return cs_errorSet(err, CS_ERR_RANGE, "%s:%ld: more than %d cases", r->path, r->line,
                           CSX_STUDY_MAX_CASES);
      }
      if (s->ncase == r->cap) {
        int cap = r->cap ? 2 * r->cap : 16;
        csxStudyCase* nc = realloc(s->cases, (size_t)cap * sizeof *nc);
        if (!nc) {
          return cs_errorSet(err, CS_ERR_MEMORY, "%s:%ld: out of memory", r->path, r->line);
        }
        s->cases = nc;
        r->cap = cap;
      }
      cc = &s->cases[s->ncase++];
      memset(cc, 0, sizeof *cc);
      snprintf(cc->name, sizeof cc->name, "%s", w[1]);
      cc->line = r->line;
    } else {
      if (s->ncase == 0) {
        return cs_errorSet(err, CS_ERR_PARSE, "%s:%ld: 'then' before the first case", r->path,
                           r->line);
      }
      cc = &s->cases[s->ncase - 1];
      for (int k = 0; k < cc->nstep; k++) {
        if (cc->step[k].cmd == c) {
          return cs_errorSet(err, CS_ERR_PARSE, "%s:%ld: case %s has a %s step already (line "
                             "%ld): one step per command", r->path, r->line, cc->name, w[first],
                             cc->step[k].line);
        }
      }
    }
    csStatus st = makeStep(r, &cc->step[cc->nstep], c, w + first + 1, n - first - 1, err);
    cc->nstep++; /* counted even on failure, so that destroy frees its words */
    if (st != CS_OK) {
      return st;
    }
    return makeSignature(r, cc, err);
  }
  return cs_errorSet(err, CS_ERR_PARSE, "%s:%ld: unknown statement '%.80s' (expected study, "
                     "defaults, case or then)", r->path, r->line, kw);
}


csxStudy* csx_studyRead(const char* path, csError* err) {
  csxStudy* s = calloc(1, sizeof *s);
  if (!s) {
    cs_errorSet(err, CS_ERR_MEMORY, "%s: out of memory", path);
    return NULL;
  }
  snprintf(s->path, sizeof s->path, "%s", path);
  /* the directory (relative paths in the file are relative to it) and the default name */
  const char* slash = strrchr(path, '/');
  if (slash) {
    snprintf(s->dir, sizeof s->dir, "%.*s", (int)(slash == path ? 1 : slash - path), path);
  } else {
    snprintf(s->dir, sizeof s->dir, ".");
  }
  const char* base = slash ? slash + 1 : path;
  snprintf(s->name, sizeof s->name, "%.*s", (int)strcspn(base, "."), base);
  if (!validName(s->name)) {
    snprintf(s->name, sizeof s->name, "study");
  }
  Reader r;
  memset(&r, 0, sizeof r);
  r.s = s;
  r.path = path;
  csuLineReader lr;
  csStatus st = csu_lineOpen(&lr, path, CSX_STUDY_MAX_LINE, "study file", err);
  int got;
  while (st == CS_OK && (got = csu_lineNext(&lr, err)) != 0) {
    if (got < 0) {
      st = (csStatus)got;
      break;
    }
    r.line = lr.lineno;
    char* hash = strchr(lr.line, '#');
    if (hash) {
      *hash = '\0';
    }
    char* w[CSX_STUDY_MAX_WORDS + 4];
    int n = csu_splitWords(lr.line, w, CSX_STUDY_MAX_WORDS + 4);
    if (n == 0) {
      continue;
    }
    if (n > CSX_STUDY_MAX_WORDS + 4) {
      st = cs_errorSet(err, CS_ERR_RANGE, "%s:%ld: more than %d words on a line", path, r.line,
                       CSX_STUDY_MAX_WORDS);
      break;
    }
    st = statement(&r, w, n, err);
  }
  if (st == CS_OK && s->ncase == 0) {
    /* the last line read names the end of the file; an empty file has no line 0: line 1 */
    st = cs_errorSet(err, CS_ERR_PARSE, "%s:%ld: no case (add 'case NAME COMMAND ...' lines)",
                     path, r.line > 0 ? r.line : 1);
  }
  csu_lineClose(&lr);
  for (int c = 0; c < CSX_STUDY_NCMD; c++) {
    freeWords(r.deflt[c], r.ndefault[c]);
  }
  if (st != CS_OK) {
    csx_studyDestroy(s);
    return NULL;
  }
  return s;
}


void csx_studyDestroy(csxStudy* s) {
  if (!s) {
    return;
  }
  for (int i = 0; i < s->ncase; i++) {
    for (int k = 0; k < s->cases[i].nstep; k++) {
      freeWords(s->cases[i].step[k].word, s->cases[i].step[k].nword);
    }
    free(s->cases[i].signature);
  }
  free(s->cases);
  free(s);
}


int csx_studyFindCase(const csxStudy* s, const char* name) {
  for (int i = 0; i < s->ncase; i++) {
    if (!strcmp(s->cases[i].name, name)) {
      return i;
    }
  }
  return -1;
}
