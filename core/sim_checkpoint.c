/* sim_checkpoint.c: a run's checkpoint file, what a resumable run (`crawlsim run --checkpoint
 * FILE`, csRunDef.checkpoint) writes and `--resume FILE` continues from (see sim_model.h;
 * docs/notes/cli_output.md "Resumable runs").
 *
 * The file is HDF5 (core_h5.h), written to "<path>.tmp" and renamed over <path>, so the path
 * always holds a whole checkpoint, the last one or the one before. Contents:
 *   /state [n]            the whole state (cs_stateGet: time, seed, pressures, robot, coupling,
 *                         footholds and whatever later parts add): the format is generic over it
 *   /support_origin [3]   mm: the support centre at t = 0 (the output's displacement origin)
 *   /timers [CS_NTIMER,2] the stage timers so far (wall s, calls): the output's attributes go on
 *   root attributes       format, version, identity (the run definition as lines "name value",
 *                         cs_runDefIdentity), checkpoint_every_s, t_s, steps, rejected_steps,
 *                         gain_projections, samples (the output's rows at this state),
 *                         wall_time_s (the stepping loops' so far), state_size, state_fnv1a64
 *                         (FNV-1a of the state's bytes, hex: a corrupt state is refused)
 * Native-endian doubles (HDF5 converts on read). A truncated file fails HDF5's own checks (its
 * end of allocation is past the end of file); a changed byte in the state fails the checksum. */
#include <inttypes.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core_h5.h"
#include "core_h5read.h"
#include "sim_internal.h"

#ifndef CS_VERSION_STRING
#define CS_VERSION_STRING "unknown" /* set by core/CMakeLists.txt */
#endif

static const char kFormat[] = "crawlsim checkpoint 1";

/* FNV-1a, 64 bit (Fowler, Noll, Vo): offset basis 14695981039346656037, prime 1099511628211 */
#define FNV_BASIS UINT64_C(14695981039346656037)
#define FNV_PRIME UINT64_C(1099511628211)


uint64_t cs_hashBytes(uint64_t h, const void* p, size_t n) {
  const unsigned char* b = p;
  if (h == 0) {
    h = FNV_BASIS;
  }
  for (size_t i = 0; i < n; i++) {
    h = (h ^ b[i]) * FNV_PRIME;
  }
  return h;
}


int cs_hashFile(const char* path, uint64_t* h) {
  FILE* f = path && path[0] ? fopen(path, "rb") : NULL;
  if (!f) {
    return -1;
  }
  unsigned char buf[1 << 16];
  uint64_t v = 0;
  size_t n;
  while ((n = fread(buf, 1, sizeof buf, f)) > 0) {
    v = cs_hashBytes(v, buf, n);
  }
  int bad = ferror(f);
  fclose(f);
  *h = v ? v : FNV_BASIS; /* an empty file hashes to the basis */
  return bad ? -1 : 0;
}


csStatus cs_checkpointSave(const csModel* m, const csData* d, const csCheckpointInfo* info,
                           const char* path, double* x, csError* err) {
  const int n = cs_stateSize(m, d);
  cs_stateGet(m, d, x);
  char tmp[1100];
  if (snprintf(tmp, sizeof tmp, "%s.tmp", path) >= (int)sizeof tmp) {
    return cs_errorSet(err, CS_ERR_ARG, "--checkpoint %.200s: path too long", path);
  }
  csH5File* f = cs_h5Create(tmp, err);
  if (!f) {
    return err ? err->status : CS_ERR_IO;
  }
  size_t dims[2] = {(size_t)n, 2};
  double tm[2 * CS_NTIMER];
  for (int k = 0; k < CS_NTIMER; k++) {
    tm[2 * k] = d->timer[k].wall;
    tm[2 * k + 1] = (double)d->timer[k].count;
  }
  char hash[32];
  snprintf(hash, sizeof hash, "%016" PRIx64, cs_hashBytes(0, x, sizeof(double) * (size_t)n));
  csStatus st = cs_h5WriteDoubles(f, "/state", 1, dims, x, err);
  size_t three = 3, tdims[2] = {CS_NTIMER, 2};
  if (st == CS_OK) st = cs_h5WriteDoubles(f, "/support_origin", 1, &three, d->x0, err);
  if (st == CS_OK) st = cs_h5WriteDoubles(f, "/timers", 2, tdims, tm, err);
  if (st == CS_OK) st = cs_h5AttrString(f, "/", "format", kFormat, err);
  if (st == CS_OK) st = cs_h5AttrString(f, "/", "version", CS_VERSION_STRING, err);
  if (st == CS_OK) st = cs_h5AttrString(f, "/", "identity", info->identity, err);
  if (st == CS_OK) st = cs_h5AttrDouble(f, "/", "checkpoint_every_s", info->every, err);
  if (st == CS_OK) st = cs_h5AttrDouble(f, "/", "t_s", d->t, err);
  if (st == CS_OK) st = cs_h5AttrDouble(f, "/", "steps", (double)d->nstep, err);
  if (st == CS_OK) st = cs_h5AttrDouble(f, "/", "rejected_steps", (double)d->nreject, err);
  if (st == CS_OK) st = cs_h5AttrDouble(f, "/", "gain_projections", (double)d->ngain_proj, err);
  if (st == CS_OK) st = cs_h5AttrDouble(f, "/", "samples", (double)info->nsample, err);
  if (st == CS_OK) st = cs_h5AttrDouble(f, "/", "wall_time_s", info->wall_s, err);
  if (st == CS_OK) st = cs_h5AttrDouble(f, "/", "state_size", n, err);
  if (st == CS_OK) st = cs_h5AttrString(f, "/", "state_fnv1a64", hash, err);
  if (st == CS_OK) st = cs_h5AttrString(f, "/", "status", "complete", err);
  csError cerr;
  csStatus cst = cs_h5CloseChecked(f, &cerr);
  if (st == CS_OK && cst != CS_OK) {
    st = cst;
    if (err) {
      *err = cerr;
    }
  }
  if (st == CS_OK && rename(tmp, path) != 0) {
    st = cs_errorSet(err, CS_ERR_IO, "--checkpoint %.200s: cannot rename %.200s into place",
                     path, tmp);
  }
  if (st != CS_OK) {
    remove(tmp);
  }
  return st;
}


/* the first line of `a` (lines "name value") that `b` does not hold as it is, into what[]:
 * 1 when they differ, 0 when every line of each is in the other */
static int identityDiff(const char* a, const char* b, char* what, size_t size) {
  for (int pass = 0; pass < 2; pass++) {
    const char* x = pass ? b : a;
    const char* y = pass ? a : b;
    for (const char* p = x; *p;) {
      const char* e = strchr(p, '\n');
      size_t len = e ? (size_t)(e - p) : strlen(p);
      /* the same line in y (whole lines only) */
      int found = 0;
      for (const char* q = y; *q && !found;) {
        const char* qe = strchr(q, '\n');
        size_t ql = qe ? (size_t)(qe - q) : strlen(q);
        found = ql == len && !memcmp(p, q, len);
        q += ql + (qe != NULL);
      }
      if (!found) {
        /* name it by the other's line of the same name, if it has one */
        const char* sp = memchr(p, ' ', len);
        size_t nl = sp ? (size_t)(sp - p) : len;
        const char* other = NULL;
        size_t ol = 0;
        for (const char* q = y; *q && !other;) {
          const char* qe = strchr(q, '\n');
          size_t ql = qe ? (size_t)(qe - q) : strlen(q);
          if (ql > nl && q[nl] == ' ' && !memcmp(p, q, nl)) {
            other = q + nl + 1;
            ol = ql - nl - 1;
          }
          q += ql + (qe != NULL);
        }
        const char* here = pass ? other : p + nl + (sp != NULL);
        size_t hl = pass ? ol : len - nl - (sp != NULL);
        const char* there = pass ? p + nl + (sp != NULL) : other;
        size_t tl = pass ? len - nl - (sp != NULL) : ol;
        snprintf(what, size, "%.*s is %.*s here, %.*s in the checkpoint", (int)nl, p,
                 here ? (int)hl : 4, here ? here : "none", there ? (int)tl : 4,
                 there ? there : "none");
        return 1;
      }
      p += len + (e != NULL);
    }
  }
  return 0;
}


csStatus cs_checkpointLoad(const csModel* m, csData* d, const char* path,
                           csCheckpointInfo* info, double* x, csError* err) {
  csError e;
  cs_errorClear(&e);
  csH5Reader* r = cs_h5ReaderOpen(path, &e);
  if (!r) {
    return cs_errorSet(err, CS_ERR_IO, "--resume %.300s: not a readable checkpoint (%.300s)",
                       path, e.msg);
  }
  csStatus st = CS_OK;
  char text[CS_CHECKPOINT_IDENTITY];
  char what[512];
  double v = 0;
  double* xs = NULL, *org = NULL, *tm = NULL;
  const int n = cs_stateSize(m, d);
  if (cs_h5ReaderAttrString(r, "format", text, sizeof text, &e) != CS_OK ||
      strcmp(text, kFormat)) {
    st = cs_errorSet(err, CS_ERR_PARSE, "--resume %.300s: not a crawlsim checkpoint (no "
                     "format \"%s\")", path, kFormat);
  } else if (cs_h5ReaderAttrString(r, "version", text, sizeof text, &e) != CS_OK ||
             strcmp(text, CS_VERSION_STRING)) {
    st = cs_errorSet(err, CS_ERR_ARG, "--resume %.300s: written by crawlsim %.100s, this is "
                     "%.100s (a resumed run must be the same program's)", path, text,
                     CS_VERSION_STRING);
  } else if (cs_h5ReaderAttrString(r, "identity", text, sizeof text, &e) != CS_OK) {
    st = cs_errorSet(err, CS_ERR_PARSE, "--resume %.300s: %.300s", path, e.msg);
  } else if (identityDiff(info->identity, text, what, sizeof what)) {
    st = cs_errorSet(err, CS_ERR_ARG, "--resume %.300s: the run definition differs: %.400s",
                     path, what);
  } else if (cs_h5ReaderAttrDouble(r, "checkpoint_every_s", &v, &e) != CS_OK) {
    st = cs_errorSet(err, CS_ERR_PARSE, "--resume %.300s: %.300s", path, e.msg);
  } else if (isnan(info->every)) {
    info->every = v; /* the checkpoint's own interval when none is given */
  } else if (v != info->every) {
    st = cs_errorSet(err, CS_ERR_ARG, "--resume %.300s: the run definition differs: "
                     "checkpoint-every is %.17g here, %.17g in the checkpoint (the integrators "
                     "restart at each checkpoint, so it is part of the run)", path, info->every,
                     v);
  }
  if (st == CS_OK && (cs_h5ReaderAttrDouble(r, "state_size", &v, &e) != CS_OK || v != n)) {
    st = cs_errorSet(err, CS_ERR_ARG, "--resume %.300s: its state has %g values, this run's "
                     "%d", path, v, n);
  }
  size_t want = (size_t)n, three = 3, tdims[2] = {CS_NTIMER, 2};
  if (st == CS_OK && (!(xs = cs_h5ReaderDoubles(r, "/state", 1, &want, NULL, NULL, &e)) ||
                      !(org = cs_h5ReaderDoubles(r, "/support_origin", 1, &three, NULL, NULL,
                                                 &e)) ||
                      !(tm = cs_h5ReaderDoubles(r, "/timers", 2, tdims, NULL, NULL, &e)))) {
    st = cs_errorSet(err, CS_ERR_PARSE, "--resume %.300s: %.300s", path, e.msg);
  }
  if (st == CS_OK) {
    char hash[32];
    snprintf(hash, sizeof hash, "%016" PRIx64, cs_hashBytes(0, xs, sizeof(double) * want));
    if (cs_h5ReaderAttrString(r, "state_fnv1a64", text, sizeof text, &e) != CS_OK ||
        strcmp(text, hash)) {
      st = cs_errorSet(err, CS_ERR_PARSE, "--resume %.300s: corrupt: the state's checksum is "
                       "%s, the file says %.40s", path, hash, text);
    }
  }
  double steps = 0, rej = 0, proj = 0, samples = 0, wall = 0;
  if (st == CS_OK && (cs_h5ReaderAttrDouble(r, "steps", &steps, &e) != CS_OK ||
                      cs_h5ReaderAttrDouble(r, "rejected_steps", &rej, &e) != CS_OK ||
                      cs_h5ReaderAttrDouble(r, "gain_projections", &proj, &e) != CS_OK ||
                      cs_h5ReaderAttrDouble(r, "samples", &samples, &e) != CS_OK ||
                      cs_h5ReaderAttrDouble(r, "wall_time_s", &wall, &e) != CS_OK)) {
    st = cs_errorSet(err, CS_ERR_PARSE, "--resume %.300s: %.300s", path, e.msg);
  }
  /* a checkpoint of the settling (t < 0) has no output rows yet, one of the run at least t = 0's */
  if (st == CS_OK && !(samples >= (xs[0] < 0 ? 0 : 1) && samples == floor(samples) &&
                       (xs[0] >= 0 || samples == 0) && steps >= 0 && rej >= 0 && proj >= 0)) {
    st = cs_errorSet(err, CS_ERR_PARSE, "--resume %.300s: samples %g, steps %g or t = %g s is "
                     "not a run's", path, samples, steps, xs[0]);
  }
  if (st == CS_OK) {
    st = cs_stateSet(m, d, xs, &e);
    if (st != CS_OK) {
      st = cs_errorSet(err, st, "--resume %.300s: %.400s", path, e.msg);
    }
  }
  if (st == CS_OK) {
    memcpy(x, xs, sizeof(double) * want);
    memcpy(d->x0, org, sizeof d->x0);
    for (int k = 0; k < CS_NTIMER; k++) {
      d->timer[k].wall = tm[2 * k];
      d->timer[k].count = (long)tm[2 * k + 1];
    }
    d->nstep = (long)steps;
    d->nreject = (long)rej;
    d->ngain_proj = (long)proj;
    info->nsample = (long)samples;
    info->wall_s = wall;
  }
  free(xs);
  free(org);
  free(tm);
  cs_h5ReaderClose(r);
  return st;
}
