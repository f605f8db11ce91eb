/* fuzz_study.c: fuzz harness of the study-file reader (tools/study_file.h, csx_studyRead: the
 * table of cases `crawlsim study FILE` runs).
 *
 * Per input: the error contract (fuzz_common.h); a study the reader accepts must hold what the
 * header promises (1..4096 cases with valid unique names found by csx_studyFindCase, 1..4 steps
 * each, one per command, every word NUL-terminated, a signature with one line per step), and
 * every word of every step goes through csx_studyWordIsPath and, when it is a path,
 * csx_studyResolvePath (into a buffer of the runner's size and into a short one). The reader
 * opens the files a study names (to check they exist): @data/ paths resolve to the source tree
 * (CS_SOURCE_DIR), other relative paths to the temp file's directory. */
#define _POSIX_C_SOURCE 200809L /* strnlen */

#include <stdlib.h>
#include <string.h>

#include "fuzz_common.h"
#include "study_file.h"


int csz_harnessInit(void) { return csz_tempPath(0, ".study") ? 0 : 1; }


static int validName(const char* w) {
  size_t n = strnlen(w, CSX_STUDY_NAME_SIZE);
  if (n == 0 || n >= CSX_STUDY_NAME_SIZE || w[0] == '.' || w[0] == '-') return 0;
  return strspn(w, "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_.-") == n;
}


static void checkStudy(const csxStudy* s) {
  if (!validName(s->name) || s->ncase < 1 || s->ncase > CSX_STUDY_MAX_CASES) {
    csz_fail("accepted study: name '%.64s', %d cases", s->name, s->ncase);
  }
  for (int i = 0; i < s->ncase; i++) {
    const csxStudyCase* c = &s->cases[i];
    if (!validName(c->name) || csx_studyFindCase(s, c->name) != i || c->nstep < 1 ||
        c->nstep > CSX_STUDY_NCMD || !c->signature) {
      csz_fail("accepted study: case %d '%.64s' (%d steps)", i, c->name, c->nstep);
    }
    long lines = 1;
    for (const char* p = c->signature; *p; p++) lines += *p == '\n';
    if (lines != c->nstep) {
      csz_fail("accepted study: case %s has %d steps but a signature of %ld lines", c->name,
               c->nstep, lines);
    }
    unsigned seen = 0;
    for (int k = 0; k < c->nstep; k++) {
      const csxStudyStep* st = &c->step[k];
      if (st->cmd < 0 || st->cmd >= CSX_STUDY_NCMD || (seen & (1u << st->cmd)) ||
          st->nword < 0 || st->nword > CSX_STUDY_MAX_WORDS || (st->nword && !st->word)) {
        csz_fail("accepted study: case %s step %d: command %d, %d words", c->name, k,
                 (int)st->cmd, st->nword);
      }
      seen |= 1u << st->cmd;
      for (int w = 0; w < st->nword; w++) {
        if (!st->word[w]) csz_fail("accepted study: case %s: NULL word", c->name);
        if (csx_studyWordIsPath(st, w)) {
          char out[CSX_STUDY_PATH_SIZE], small[8];
          int rc = csx_studyResolvePath(s, "/tmp/case", st->word[w], out, sizeof out);
          int rs = csx_studyResolvePath(s, "/tmp/case", st->word[w], small, sizeof small);
          if ((rc != 0 && rc != -1) || (rs != 0 && rs != -1) ||
              !memchr(small, '\0', sizeof small)) {
            csz_fail("csx_studyResolvePath returned %d / %d", rc, rs);
          }
        }
      }
      (void)csx_studyWordIsPath(st, -1);
      (void)csx_studyWordIsPath(st, st->nword);
    }
  }
}


csStatus csz_harnessRun(const uint8_t* data, size_t size, csError* err) {
  const char* path = csz_tempPath(0, ".study");
  if (csz_writeFile(path, data, size) != 0) {
    csz_fail("cannot write %s", path);
  }
  csxStudy* s = csx_studyRead(path, err);
  csStatus st = s ? CS_OK : err->status;
  csz_checkError(st, s != NULL, err, path, data, size, CSZ_TEXT);
  if (s) {
    checkStudy(s);
    csx_studyDestroy(s);
  }
  return st;
}
