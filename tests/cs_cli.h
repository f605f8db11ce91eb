/* cs_cli.h: run the real `crawlsim` executable from a test and capture what it prints
 * (header-only, plain C; shared by the end-to-end tests test_gaits_cli, test_bend_cli and
 * test_run_cli). A test passes the executable's path as argv[1] from $<TARGET_FILE:crawlsim>.
 * system() and WEXITSTATUS need POSIX: define _POSIX_C_SOURCE 200809L before any include
 * (the project builds with C_EXTENSIONS OFF). Output goes through files named after a
 * per-test prefix in the working directory, so tests running in parallel in one build
 * directory do not share them. */
#ifndef CS_TEST_CLI_H
#define CS_TEST_CLI_H

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>

/* captured output of one run */
typedef struct {
  int status;     /* exit status, -1 if it did not exit normally (a crash) */
  char out[65536]; /* stdout, cut at the buffer size (a calibration report is ~20 KB) */
  char err[8192]; /* stderr, cut at the buffer size */
} csCliResult;


/* read at most size - 1 bytes of a file into buf (empty if it cannot be read) */
static inline void cs_cliSlurp(const char* path, char* buf, size_t size) {
  buf[0] = '\0';
  FILE* f = fopen(path, "rb");
  if (f) {
    size_t n = fread(buf, 1, size - 1, f);
    buf[n] = '\0';
    fclose(f);
  }
}


/* write a text file; 0 if it could not be written */
static inline int cs_cliWriteText(const char* path, const char* text) {
  FILE* f = fopen(path, "wb");
  if (!f) {
    return 0;
  }
  int ok = fputs(text, f) >= 0;
  return fclose(f) == 0 && ok;
}


/* run `"<exe>" <args>` through the shell, stdout and stderr captured via <prefix>_stdout.txt
 * and <prefix>_stderr.txt; args is shell text (quote paths with spaces) */
static inline void cs_cliRun(const char* exe, const char* args, const char* prefix,
                             csCliResult* r) {
  char cmd[4096], out[256], err[256];
  snprintf(out, sizeof out, "%s_stdout.txt", prefix);
  snprintf(err, sizeof err, "%s_stderr.txt", prefix);
  snprintf(cmd, sizeof cmd, "\"%s\" %s >%s 2>%s", exe, args, out, err);
  int st = system(cmd);
  r->status = st != -1 && WIFEXITED(st) ? WEXITSTATUS(st) : -1;
  cs_cliSlurp(out, r->out, sizeof r->out);
  cs_cliSlurp(err, r->err, sizeof r->err);
  remove(out);
  remove(err);
}


/* s is exactly one non-empty '\n'-terminated line */
static inline int cs_cliOneLine(const char* s) {
  const char* nl = strchr(s, '\n');
  return nl && nl[1] == '\0' && nl != s;
}


static inline int cs_cliFileExists(const char* path) {
  FILE* f = fopen(path, "rb");
  if (f) {
    fclose(f);
  }
  return f != NULL;
}

#endif /* CS_TEST_CLI_H */
