/* cmd_rom_ckpt.c: `crawlsim rom check --checkpoint DIR`: a ray's progress after each state, so
 * a check stopped mid-ray (a real-leg ray with every element costs 35-60 min of CPU) resumes
 * after its last state instead of from the unloaded leg.
 *
 * DIR/RAY.K.ckpt (K the states solved) is text, one keyword a line, the numbers in %.17g (they
 * read back bit for bit): what the reduced statics carry from one state to the next (the reduced
 * coordinates, the predictor's last two states and loads, the element states theta and S of
 * csfRomData) and what the check has measured and printed. The lagged tangent and its BFGS pairs
 * are not kept: a checkpointed check drops them after every state, so a resumed ray takes the
 * same iterations as an uninterrupted checkpointed one (bit for bit: docs/notes/rom.md, session
 * romacc 2026-12-07). Written to RAY.K.ckpt.tmp and renamed, so a stop during the write leaves
 * the last complete file. */
#define _POSIX_C_SOURCE 200809L

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "cmd_rom_common.h"

static const char kFormat[] = "crawlsim-rom-check-checkpoint 1";

static void putArray(FILE* f, const char* key, const double* v, size_t n) {
  fprintf(f, "%s %zu", key, n);
  for (size_t i = 0; i < n; i++) {
    fprintf(f, " %.17g", v[i]);
  }
  fputc('\n', f);
}

static void ckptPath(char* out, size_t cap, const char* dir, const char* ray, int k,
                     const char* tail) {
  snprintf(out, cap, "%.480s/%.31s.%d.ckpt%s", dir, ray, k, tail);
}

int csx_romCkptWrite(const char* dir, const char* ray, const char* basis,
                     const csfRomActuator* ra, const csxRomCkpt* c) {
  char path[560], tmp[570];
  ckptPath(path, sizeof path, dir, ray, c->k, "");
  ckptPath(tmp, sizeof tmp, dir, ray, c->k, ".tmp");
  FILE* f = fopen(tmp, "w");
  if (!f) {
    fprintf(stderr, "crawlsim rom: %s: cannot write the checkpoint: %s\n", tmp, strerror(errno));
    return 1;
  }
  const csfRom* r = ra->rom;
  const size_t n = (size_t)r->n;
  double load[18];
  memcpy(load, &ra->p[0][0], 12 * sizeof(double));
  memcpy(load + 12, ra->gravity, 3 * sizeof(double));
  memcpy(load + 15, ra->tip_force, 3 * sizeof(double));
  const double meas[7] = {c->bend_deg, c->bend_rel, c->tip_mm, c->vol_rel, c->wall, c->cpu,
                          (double)c->newton};
  fprintf(f, "%s\nbasis %s\nray %s\n", kFormat, basis, ray);
  fprintf(f, "sizes %d %d %d %d %d\nstates %d\nok %d\nnhist %d\n", r->n, r->m, r->mf,
          ra->fe.mesh->ntet, ra->fe.model->nfib, c->k, c->ok, ra->nhist);
  putArray(f, "measured", meas, 7);
  putArray(f, "load", load, 18);
  putArray(f, "L_conv", ra->L_conv, 18);
  putArray(f, "L_prev", ra->L_prev, 18);
  putArray(f, "q_conv", ra->q_conv, n);
  putArray(f, "q_prev", ra->q_prev, n);
  putArray(f, "theta", ra->d->theta, (size_t)ra->fe.mesh->ntet);
  putArray(f, "fib_S", ra->d->fib_S, (size_t)ra->fe.model->nfib);
  fprintf(f, "lines\n%s", c->lines);
  const int bad = ferror(f) != 0;
  if (fclose(f) != 0 || bad || rename(tmp, path) != 0) {
    fprintf(stderr, "crawlsim rom: %s: cannot write the checkpoint: %s\n", path, strerror(errno));
    remove(tmp);
    return 1;
  }
  return 0;
}

/* the reader's state: the file, its current line and its number */
typedef struct Rd_ {
  FILE* f;
  const char* path;
  char* buf;
  size_t cap;
  int line;
} Rd;

/* the next line without its newline; NULL after one error line at the end of the file */
static char* nextLine(Rd* rd, const char* want) {
  const ssize_t len = getline(&rd->buf, &rd->cap, rd->f);
  rd->line++;
  if (len <= 0) {
    fprintf(stderr, "crawlsim rom: %s:%d: the file ends where '%s' was expected\n", rd->path,
            rd->line, want);
    return NULL;
  }
  if (rd->buf[len - 1] == '\n') {
    rd->buf[len - 1] = '\0';
  }
  return rd->buf;
}

/* the line "key value": value, or NULL after one error line */
static const char* keyed(Rd* rd, const char* key) {
  const char* s = nextLine(rd, key);
  const size_t kl = strlen(key);
  if (s && (strncmp(s, key, kl) != 0 || s[kl] != ' ')) {
    fprintf(stderr, "crawlsim rom: %s:%d: '%s' expected, not '%.40s'\n", rd->path, rd->line, key,
            s);
    return NULL;
  }
  return s ? s + kl + 1 : NULL;
}

/* the line "key n v1 ... vn" with n == want into v; 1 after one error line */
static int getArray(Rd* rd, const char* key, double* v, size_t want) {
  const char* s = keyed(rd, key);
  if (!s) {
    return 1;
  }
  char* end;
  const unsigned long long n = strtoull(s, &end, 10);
  if (end == s || n != want) {
    fprintf(stderr, "crawlsim rom: %s:%d: '%s' holds %.20s values, not %zu (another model?)\n",
            rd->path, rd->line, key, s, want);
    return 1;
  }
  for (size_t i = 0; i < want; i++) {
    const char* at = end;
    v[i] = strtod(at, &end);
    if (end == at) {
      fprintf(stderr, "crawlsim rom: %s:%d: '%s' value %zu is not a number\n", rd->path,
              rd->line, key, i + 1);
      return 1;
    }
  }
  if (strspn(end, " ") != strlen(end)) {
    fprintf(stderr, "crawlsim rom: %s:%d: '%s' has more than %zu values\n", rd->path, rd->line,
            key, want);
    return 1;
  }
  return 0;
}

static int readInts(Rd* rd, const char* key, int* v, int n) {
  const char* s = keyed(rd, key);
  if (!s) {
    return 1;
  }
  for (int i = 0; i < n; i++) {
    char* end;
    const long x = strtol(s, &end, 10);
    if (end == s) {
      fprintf(stderr, "crawlsim rom: %s:%d: '%s' needs %d whole numbers\n", rd->path, rd->line,
              key, n);
      return 1;
    }
    v[i] = (int)x;
    s = end;
  }
  return 0;
}

/* the body of one checkpoint file into ra and c; 1 after one error line */
static int readBody(Rd* rd, const char* ray, const char* basis, int k, csfRomActuator* ra,
                    csxRomCkpt* c) {
  const char* s = nextLine(rd, kFormat);
  if (!s) {
    return 1;
  }
  if (strcmp(s, kFormat) != 0) {
    fprintf(stderr, "crawlsim rom: %s:%d: not a rom check checkpoint ('%s' expected)\n",
            rd->path, rd->line, kFormat);
    return 1;
  }
  if (!(s = keyed(rd, "basis"))) {
    return 1;
  }
  if (strcmp(s, basis) != 0) {
    fprintf(stderr, "crawlsim rom: %s:%d: written for basis %.200s, not %.200s\n", rd->path,
            rd->line, s, basis);
    return 1;
  }
  if (!(s = keyed(rd, "ray"))) {
    return 1;
  }
  if (strcmp(s, ray) != 0) {
    fprintf(stderr, "crawlsim rom: %s:%d: written for ray %.31s, not %s\n", rd->path, rd->line,
            s, ray);
    return 1;
  }
  const csfRom* r = ra->rom;
  int sz[5], want[5] = {r->n, r->m, r->mf, ra->fe.mesh->ntet, ra->fe.model->nfib};
  if (readInts(rd, "sizes", sz, 5)) {
    return 1;
  }
  if (memcmp(sz, want, sizeof sz) != 0) {
    fprintf(stderr, "crawlsim rom: %s:%d: sizes n m mf Tet10 fibres %d %d %d %d %d, the model's "
            "%d %d %d %d %d\n", rd->path, rd->line, sz[0], sz[1], sz[2], sz[3], sz[4], want[0],
            want[1], want[2], want[3], want[4]);
    return 1;
  }
  int states, ok, nhist;
  if (readInts(rd, "states", &states, 1)) {
    return 1;
  }
  if (states != k) {
    fprintf(stderr, "crawlsim rom: %s:%d: %d states, its name says %d\n", rd->path, rd->line,
            states, k);
    return 1;
  }
  if (readInts(rd, "ok", &ok, 1) || readInts(rd, "nhist", &nhist, 1)) {
    return 1;
  }
  if (nhist < 0 || nhist > 2) {
    fprintf(stderr, "crawlsim rom: %s:%d: nhist %d is not 0, 1 or 2\n", rd->path, rd->line,
            nhist);
    return 1;
  }
  double meas[7], load[18];
  const size_t n = (size_t)r->n;
  if (getArray(rd, "measured", meas, 7) || getArray(rd, "load", load, 18) ||
      getArray(rd, "L_conv", ra->L_conv, 18) || getArray(rd, "L_prev", ra->L_prev, 18) ||
      getArray(rd, "q_conv", ra->q_conv, n) || getArray(rd, "q_prev", ra->q_prev, n) ||
      getArray(rd, "theta", ra->d->theta, (size_t)ra->fe.mesh->ntet) ||
      getArray(rd, "fib_S", ra->d->fib_S, (size_t)ra->fe.model->nfib)) {
    return 1;
  }
  if (!(s = nextLine(rd, "lines"))) {
    return 1;
  }
  if (strcmp(s, "lines") != 0) {
    fprintf(stderr, "crawlsim rom: %s:%d: 'lines' expected\n", rd->path, rd->line);
    return 1;
  }
  /* the printed lines: the rest of the file, as written */
  size_t used = 0;
  for (ssize_t len; (len = getline(&rd->buf, &rd->cap, rd->f)) > 0;) {
    if (used + (size_t)len + 1 > c->lines_cap) {
      fprintf(stderr, "crawlsim rom: %s:%d: more printed lines than %zu bytes\n", rd->path,
              rd->line + 1, c->lines_cap);
      return 1;
    }
    memcpy(c->lines + used, rd->buf, (size_t)len);
    used += (size_t)len;
    rd->line++;
  }
  c->lines[used] = '\0';
  memcpy(&ra->p[0][0], load, 12 * sizeof(double));
  memcpy(ra->gravity, load + 12, 3 * sizeof(double));
  memcpy(ra->tip_force, load + 15, 3 * sizeof(double));
  memcpy(ra->d->q, ra->q_conv, n * sizeof(double));
  ra->nhist = nhist;
  ra->d->lu_valid = 0;
  ra->d->bf_k = 0;
  c->k = k;
  c->ok = ok;
  c->bend_deg = meas[0], c->bend_rel = meas[1], c->tip_mm = meas[2], c->vol_rel = meas[3];
  c->wall = meas[4], c->cpu = meas[5], c->newton = (long)meas[6];
  return 0;
}

int csx_romCkptRead(const char* dir, const char* ray, const char* basis, int m,
                    csfRomActuator* ra, csxRomCkpt* c) {
  for (int k = m; k >= 1; k--) {
    char path[560];
    ckptPath(path, sizeof path, dir, ray, k, "");
    struct stat sb;
    if (stat(path, &sb) != 0) {
      continue;
    }
    Rd rd = {fopen(path, "r"), path, NULL, 0, 0};
    if (!rd.f) {
      fprintf(stderr, "crawlsim rom: %s: cannot read the checkpoint: %s\n", path,
              strerror(errno));
      return -1;
    }
    const int bad = readBody(&rd, ray, basis, k, ra, c);
    free(rd.buf);
    fclose(rd.f);
    return bad ? -1 : 1;
  }
  return 0;
}
