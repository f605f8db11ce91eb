/* cs_opts.c: parsing and help of the commands' option tables (see cs_opts.h). */
#include "cs_opts.h"

#include <ctype.h>
#include <string.h>

enum { MAX_NAME = 64, HELP_WIDTH = 79, HELP_INDENT = 6 };


void csx_optBegin(csxOptIter* it) {
  memset(it, 0, sizeof *it);
  it->i = 1;
}


int csx_optIs(const csxOpt* o, const char* name) { return o && !strcmp(o->name, name); }


static const csxOpt* findExact(const csxOptTable* t, const char* name, size_t len) {
  for (int k = 0; k < t->nopt; k++) {
    if (strlen(t->opt[k].name) == len && !strncmp(t->opt[k].name, name, len)) {
      return &t->opt[k];
    }
  }
  return NULL;
}


/* Levenshtein distance of a[0..la) and b[0..lb), both at most MAX_NAME characters (one row of
 * the dynamic programme on the stack) */
static size_t editDistance(const char* a, size_t la, const char* b, size_t lb) {
  size_t row[MAX_NAME + 1];
  for (size_t j = 0; j <= lb; j++) {
    row[j] = j;
  }
  for (size_t i = 1; i <= la; i++) {
    size_t diag = row[0];
    row[0] = i;
    for (size_t j = 1; j <= lb; j++) {
      size_t up = row[j];
      size_t sub = diag + (a[i - 1] != b[j - 1]);
      size_t del = row[j] + 1, ins = row[j - 1] + 1;
      row[j] = sub < del ? (sub < ins ? sub : ins) : (del < ins ? del : ins);
      diag = up;
    }
  }
  return row[lb];
}


const csxOpt* csx_optNearest(const csxOptTable* t, const char* name, size_t len) {
  if (len > MAX_NAME) {
    return NULL;
  }
  const csxOpt* best = NULL;
  size_t best_d = (size_t)-1;
  for (int k = 0; k < t->nopt; k++) {
    size_t lo = strlen(t->opt[k].name);
    if (lo > MAX_NAME) {
      continue;
    }
    size_t d = editDistance(name, len, t->opt[k].name, lo);
    /* a prefix of one option only ("--out" for "--ou") is as good as a distance of 1 */
    if (len > 3 && len < lo && !strncmp(name, t->opt[k].name, len) && d > 1) {
      d = 1;
    }
    if (d < best_d) {
      best_d = d;
      best = &t->opt[k];
    }
  }
  /* "--" is common to all: half of the rest, at least 2 edits, is still a plausible typo */
  size_t core = len > 2 ? len - 2 : 0;
  size_t limit = core / 2 > 2 ? core / 2 : 2;
  return best_d <= limit ? best : NULL;
}


csxOptKind csx_optNext(const csxOptTable* t, int argc, char** argv, csxOptIter* it) {
  it->opt = NULL;
  it->value = NULL;
  it->error[0] = '\0';
  if (it->i >= argc) {
    return CSX_OPT_END;
  }
  const char* a = argv[it->i++];
  if (!strcmp(a, "--help") || !strcmp(a, "-h")) {
    return CSX_OPT_HELP;
  }
  /* "-x" is a mistyped option, not an operand (no command takes a negative number or a file
   * name starting with '-' as an operand) */
  if (a[0] == '-' && a[1] && a[1] != '-') {
    snprintf(it->error, sizeof it->error, "unknown option %.60s (options are --name; see "
             "crawlsim %s --help)", a, t->cmd);
    return CSX_OPT_ERROR;
  }
  if (strncmp(a, "--", 2) != 0 || !a[2]) {
    it->value = a;
    return CSX_OPT_OPERAND;
  }
  const char* eq = strchr(a, '=');
  size_t len = eq ? (size_t)(eq - a) : strlen(a);
  const csxOpt* o = findExact(t, a, len);
  if (!o) {
    const csxOpt* near = csx_optNearest(t, a, len);
    int shown = (int)(len > 60 ? 60 : len);
    if (near) {
      snprintf(it->error, sizeof it->error, "unknown option %.*s; did you mean %s? (see crawlsim "
               "%s --help)", shown, a, near->name, t->cmd);
    } else {
      snprintf(it->error, sizeof it->error, "unknown option %.*s (see crawlsim %s --help)", shown,
               a, t->cmd);
    }
    return CSX_OPT_ERROR;
  }
  it->opt = o;
  if (!o->arg) {
    if (eq) {
      snprintf(it->error, sizeof it->error, "option %s takes no value (got '%.60s')", o->name,
               eq + 1);
      return CSX_OPT_ERROR;
    }
    return CSX_OPT_OPTION;
  }
  const char* v = eq ? eq + 1 : (it->i < argc ? argv[it->i++] : NULL);
  /* a following option is not a value: `--gait --quiet` means the value was forgotten (a
   * value that really starts with "--" can be given as --name=--value) */
  if (!v || !v[0] || (!eq && !strncmp(v, "--", 2) && v[2])) {
    snprintf(it->error, sizeof it->error, "option %s needs a value %s (see crawlsim %s --help)",
             o->name, o->arg, t->cmd);
    if (v && !eq) {
      it->i--; /* the next argument was not consumed */
    }
    return CSX_OPT_ERROR;
  }
  it->value = v;
  return CSX_OPT_OPTION;
}


/* words of `text` wrapped to HELP_WIDTH, the first line continuing at column `col`, the rest
 * indented by `indent`; returns the column after the last word */
static int wrap(FILE* out, const char* text, int col, int indent) {
  const char* p = text;
  while (*p) {
    while (*p == ' ') {
      p++;
    }
    if (*p == '\n') {
      fputc('\n', out);
      fprintf(out, "%*s", indent, "");
      col = indent;
      p++;
      continue;
    }
    size_t w = strcspn(p, " \n");
    if (!w) {
      break;
    }
    if (col > indent && col + 1 + (int)w > HELP_WIDTH) {
      fprintf(out, "\n%*s", indent, "");
      col = indent;
    } else if (col > indent) {
      fputc(' ', out);
      col++;
    }
    fwrite(p, 1, w, out);
    col += (int)w;
    p += w;
  }
  return col;
}


void csx_optHelp(const csxOptTable* t, FILE* out) {
  fprintf(out, "usage: crawlsim %s%s%s [options]\n", t->cmd, t->operands[0] ? " " : "",
          t->operands);
  if (t->about && t->about[0]) {
    fputs("  ", out);
    wrap(out, t->about, 2, 2);
    fputc('\n', out);
  }
  fputs("options (--name VALUE or --name=VALUE; lengths mm, times s, pressures MPa gauge):\n",
        out);
  for (int k = 0; k < t->nopt; k++) {
    const csxOpt* o = &t->opt[k];
    fprintf(out, "  %s%s%s", o->name, o->arg ? " " : "", o->arg ? o->arg : "");
    fprintf(out, "\n%*s", HELP_INDENT, "");
    int col = wrap(out, o->help, HELP_INDENT, HELP_INDENT);
    if (o->def) {
      char d[256];
      snprintf(d, sizeof d, "[default: %s]", o->def);
      wrap(out, d, col, HELP_INDENT);
    }
    fputc('\n', out);
  }
  fputs("  --help, -h\n      this help\n", out);
  if (t->notes && t->notes[0]) {
    fputs("  ", out);
    wrap(out, t->notes, 2, 2);
    fputc('\n', out);
  }
}


int csx_optReport(const csxOptTable* t, csxOptKind kind, const csxOptIter* it) {
  if (kind == CSX_OPT_HELP) {
    csx_optHelp(t, stdout);
    return 0;
  }
  if (kind != CSX_OPT_ERROR) {
    return -1;
  }
  fprintf(stderr, "crawlsim %s: ", t->cmd);
  for (const char* c = it->error; *c; c++) {
    fputc(iscntrl((unsigned char)*c) ? '?' : *c, stderr);
  }
  fputc('\n', stderr);
  return 1;
}
