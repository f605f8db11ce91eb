/* fuzz_replay.c: the fuzz harnesses without a fuzzer: runs stored inputs through a harness
 * (fuzz_common.h) in every build, so ctest replays the seeds, the minimised corpus and each
 * input that once crashed a reader.
 *
 *   fuzz_replay_<reader> [-v] [PATH...] [-r PATH...]
 * Each PATH is a file or a directory (its files, not sub-directories, in name order; names
 * starting with '.' and ending in ".expect" are not inputs). Paths after -r are regression
 * inputs: each needs a file <input>.expect beside it,
 *   status CS_ERR_PARSE            the status the reader must return (CS_OK: it accepts it)
 *   contains <text>                a text its message must contain (any number of lines)
 * ('#' lines are comments). -v prints each input's status and message. Exit 0 when every input
 * passed the harness's checks (a broken contract aborts) and met its .expect, 1 otherwise, also
 * when a PATH holds no input: a replay of nothing must not pass. */
#define _POSIX_C_SOURCE 200809L /* opendir, stat */

#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "fuzz_common.h"

/* largest input replayed (bytes): libFuzzer's -max_len of the campaigns is far below */
#define MAX_INPUT (16u << 20)
/* longest expectation line */
#define EXPECT_LINE 512

typedef struct {
  int inputs, accepted, refused, skipped, failed;
} Counts;

static const char* statusName(csStatus s) {
  switch (s) {
#define CSZ_STATUS_NAME(name, value, msg) \
  case name:                              \
    return #name;
    CS_STATUS_LIST(CSZ_STATUS_NAME)
#undef CSZ_STATUS_NAME
  }
  return "?";
}


static unsigned char* readAll(const char* path, size_t* size) {
  FILE* f = fopen(path, "rb");
  if (!f) {
    return NULL;
  }
  unsigned char* buf = malloc(MAX_INPUT + 1);
  size_t n = buf ? fread(buf, 1, MAX_INPUT + 1, f) : 0;
  fclose(f);
  if (!buf || n > MAX_INPUT) {
    free(buf);
    return NULL;
  }
  *size = n;
  return buf;
}


/* compare one result with <input>.expect; 0 = met (or no file and not required) */
static int checkExpect(const char* input, csStatus st, const csError* err, int required) {
  char path[4096];
  snprintf(path, sizeof path, "%s.expect", input);
  FILE* f = fopen(path, "r");
  if (!f) {
    if (required) {
      fprintf(stderr, "%s: regression input without %s\n", input, path);
      return 1;
    }
    return 0;
  }
  char line[EXPECT_LINE];
  int bad = 0, have_status = 0;
  while (fgets(line, sizeof line, f)) {
    line[strcspn(line, "\r\n")] = '\0';
    if (!line[0] || line[0] == '#') {
      continue;
    }
    if (!strncmp(line, "status ", 7)) {
      have_status = 1;
      if (strcmp(line + 7, statusName(st)) != 0) {
        fprintf(stderr, "%s: status %s, expected %s (%s)\n", input, statusName(st), line + 7,
                err->msg);
        bad = 1;
      }
    } else if (!strncmp(line, "contains ", 9)) {
      if (!strstr(err->msg, line + 9)) {
        fprintf(stderr, "%s: message '%s' lacks '%s'\n", input, err->msg, line + 9);
        bad = 1;
      }
    } else {
      fprintf(stderr, "%s: unknown line '%s'\n", path, line);
      bad = 1;
    }
  }
  fclose(f);
  if (!have_status) {
    fprintf(stderr, "%s: no 'status' line\n", path);
    bad = 1;
  }
  return bad;
}


static void runOne(const char* path, int regression, int verbose, Counts* c) {
  size_t size = 0;
  unsigned char* data = readAll(path, &size);
  if (!data) {
    fprintf(stderr, "%s: cannot read (or larger than %u bytes)\n", path, MAX_INPUT);
    c->failed++;
    return;
  }
  csError err;
  cs_errorClear(&err);
  csStatus st = csz_harnessRun(data, size, &err);
  free(data);
  c->inputs++;
  if (st == CS_OK && !strcmp(err.msg, "skipped")) {
    c->skipped++;
  } else if (st == CS_OK) {
    c->accepted++;
  } else {
    c->refused++;
  }
  if (verbose) {
    printf("%s: %s %s\n", path, statusName(st), err.msg);
  }
  c->failed += checkExpect(path, st, &err, regression);
}


static int isInputName(const char* name) {
  size_t n = strlen(name);
  return name[0] != '.' && !(n >= 7 && !strcmp(name + n - 7, ".expect"));
}


static int cmpStr(const void* a, const void* b) {
  return strcmp(*(char* const*)a, *(char* const*)b);
}


static void runPath(const char* path, int regression, int verbose, Counts* c) {
  struct stat sb;
  if (stat(path, &sb) != 0) {
    fprintf(stderr, "%s: no such file or directory\n", path);
    c->failed++;
    return;
  }
  if (!S_ISDIR(sb.st_mode)) {
    runOne(path, regression, verbose, c);
    return;
  }
  DIR* d = opendir(path);
  if (!d) {
    fprintf(stderr, "%s: cannot list\n", path);
    c->failed++;
    return;
  }
  size_t n = 0, cap = 0;
  char** names = NULL;
  for (struct dirent* e; (e = readdir(d)) != NULL;) {
    if (!isInputName(e->d_name)) {
      continue;
    }
    if (n == cap) {
      cap = cap ? 2 * cap : 64;
      char** grown = realloc(names, cap * sizeof *names);
      if (!grown) {
        break;
      }
      names = grown;
    }
    names[n++] = strdup(e->d_name);
  }
  closedir(d);
  qsort(names, n, sizeof *names, cmpStr);
  for (size_t i = 0; i < n; i++) {
    char full[4096];
    snprintf(full, sizeof full, "%s/%s", path, names[i]);
    if (stat(full, &sb) == 0 && S_ISREG(sb.st_mode)) {
      runOne(full, regression, verbose, c);
    }
    free(names[i]);
  }
  free(names);
}


int main(int argc, char** argv) {
  if (csz_harnessInit() != 0) {
    fprintf(stderr, "fuzz replay: harness initialisation failed\n");
    return 1;
  }
  int regression = 0, verbose = 0, failed = 0, total = 0;
  for (int i = 1; i < argc; i++) {
    if (!strcmp(argv[i], "-r")) {
      regression = 1;
      continue;
    }
    if (!strcmp(argv[i], "-v")) {
      verbose = 1;
      continue;
    }
    Counts c = {0, 0, 0, 0, 0};
    runPath(argv[i], regression, verbose, &c);
    printf("%s: %d inputs (%d accepted, %d refused, %d skipped)%s, %d failed\n", argv[i],
           c.inputs, c.accepted, c.refused, c.skipped, regression ? " against .expect" : "",
           c.failed);
    if (c.inputs == 0) {
      fprintf(stderr, "%s: no input replayed\n", argv[i]);
      c.failed++;
    }
    failed += c.failed;
    total += c.inputs;
  }
  if (total == 0) {
    fprintf(stderr, "usage: %s [PATH...] [-r PATH...]: no input given\n", argv[0]);
    return 1;
  }
  printf("%d inputs, %d failed\n", total, failed);
  return failed ? 1 : 0;
}
