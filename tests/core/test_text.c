/* test_text.c: the shared text readers (core_text.h): the line reader on good and bad files
 * (empty, LF/CRLF, no newline at the end, a byte-order mark, NUL bytes, stray CRs, lines at and
 * past the limit, a directory), word splitting, and the chamber-list parser on every kind of
 * bad list ("", "0", "5", "1,,2", "1,", " 1", "+1", "2,2", huge numbers), and the statement-file
 * driver (csu_statementFileRead). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core_text.h"
#include "cs_test.h"


/* write n bytes to path (binary: "\r\n" and "\0" stay as given) */
static void writeBytes(const char* path, const char* bytes, size_t n) {
  FILE* f = fopen(path, "wb");
  CS_EXPECT(f != NULL);
  if (f) {
    CS_EXPECT(fwrite(bytes, 1, n, f) == n);
    fclose(f);
  }
}


/* read every line of `path` (limit max_line) into lines[] ("|"-joined); returns the last
 * csu_lineNext result (0 at a clean end) and fills err */
static int readAll(const char* path, size_t max_line, char* joined, size_t size, long* nlines,
                   csError* err) {
  csuLineReader r;
  joined[0] = '\0';
  *nlines = 0;
  if (csu_lineOpen(&r, path, max_line, "test file", err) != CS_OK) {
    return err->status;
  }
  int got;
  while ((got = csu_lineNext(&r, err)) > 0) {
    CS_EXPECT(r.len == strlen(r.line));
    CS_EXPECT(r.lineno == *nlines + 1);
    size_t n = strlen(joined);
    snprintf(joined + n, size - n, "%s%s", n ? "|" : "", r.line);
    (*nlines)++;
  }
  csu_lineClose(&r);
  csu_lineClose(&r); /* idempotent */
  return got;
}


/* good files: line endings, empty lines, a missing final newline, a BOM on line 1 only */
static void test_lines_good_files(void) {
  csError err;
  char j[256];
  long n;
  writeBytes("text_lf.txt", "a b\n\nc\n", 7);
  CS_EXPECT(readAll("text_lf.txt", 16, j, sizeof j, &n, &err) == 0);
  CS_EXPECT(n == 3 && !strcmp(j, "a b||c"));
  writeBytes("text_crlf.txt", "a\r\n\r\nc\r\n", 8);
  CS_EXPECT(readAll("text_crlf.txt", 16, j, sizeof j, &n, &err) == 0);
  CS_EXPECT(n == 3 && !strcmp(j, "a||c"));
  /* no newline at the end: the last line still counts */
  writeBytes("text_noeol.txt", "a\nlast", 6);
  CS_EXPECT(readAll("text_noeol.txt", 16, j, sizeof j, &n, &err) == 0);
  CS_EXPECT(n == 2 && !strcmp(j, "a|last"));
  /* empty file: no line at all */
  writeBytes("text_empty.txt", "", 0);
  CS_EXPECT(readAll("text_empty.txt", 16, j, sizeof j, &n, &err) == 0);
  CS_EXPECT(n == 0 && j[0] == '\0');
  /* a UTF-8 byte-order mark on line 1 is dropped, one on line 2 is text */
  writeBytes("text_bom.txt", "\xEF\xBB\xBFx\n\xEF\xBB\xBFy\n", 10);
  CS_EXPECT(readAll("text_bom.txt", 16, j, sizeof j, &n, &err) == 0);
  CS_EXPECT(n == 2 && !strcmp(j, "x|\xEF\xBB\xBFy"));
  /* exactly at the limit, with LF and with CRLF (the CR is not counted) */
  writeBytes("text_limit.txt", "12345\n12345\r\n", 13);
  CS_EXPECT(readAll("text_limit.txt", 5, j, sizeof j, &n, &err) == 0);
  CS_EXPECT(n == 2 && !strcmp(j, "12345|12345"));
  remove("text_lf.txt");
  remove("text_crlf.txt");
  remove("text_noeol.txt");
  remove("text_empty.txt");
  remove("text_bom.txt");
  remove("text_limit.txt");
}


/* expect the file to fail at `line` with `status` and a message containing `cause` */
static void expectBad(const char* path, const char* bytes, size_t nbytes, size_t max_line,
                      csStatus status, const char* where, const char* cause) {
  writeBytes(path, bytes, nbytes);
  csError err;
  cs_errorClear(&err);
  char j[256];
  long n;
  int rc = readAll(path, max_line, j, sizeof j, &n, &err);
  CS_EXPECT(rc == (int)status);
  CS_EXPECT(err.status == status);
  CS_EXPECT(strstr(err.msg, where) == err.msg);
  CS_EXPECT(strstr(err.msg, cause) != NULL);
  /* one line, no raw control characters in the message */
  CS_EXPECT(strchr(err.msg, '\n') == NULL && strchr(err.msg, '\r') == NULL);
  if (rc != (int)status || !strstr(err.msg, cause)) {
    fprintf(stderr, "  %s: got %d '%s'\n", path, rc, err.msg);
  }
  remove(path);
}


static void test_lines_bad_files(void) {
  /* one byte past the limit, on line 2 */
  expectBad("text_long.txt", "ok\n123456\n", 10, 5, CS_ERR_RANGE, "text_long.txt:2: ",
            "line longer than 5 bytes");
  /* a CR that is not part of a CRLF ending counts as a byte of the line */
  expectBad("text_long_cr.txt", "12345\r6\n", 8, 5, CS_ERR_RANGE, "text_long_cr.txt:1: ",
            "longer than 5 bytes");
  expectBad("text_nul.txt", "a\nb\0c\n", 6, 16, CS_ERR_PARSE, "text_nul.txt:2: ",
            "byte 2: NUL byte");
  expectBad("text_cr.txt", "a\rb\n", 4, 16, CS_ERR_PARSE, "text_cr.txt:1: ",
            "byte 2: carriage return inside a line");
  /* classic-Mac endings: the whole file is one line with CRs inside */
  expectBad("text_mac.txt", "a\rb\r", 4, 16, CS_ERR_PARSE, "text_mac.txt:1: ",
            "carriage return");
  /* a missing file and a directory */
  csuLineReader r;
  csError err;
  CS_EXPECT(csu_lineOpen(&r, "text_does_not_exist.txt", 16, "test file", &err) == CS_ERR_IO);
  CS_EXPECT(strstr(err.msg, "text_does_not_exist.txt: cannot open test file: ") == err.msg);
  csu_lineClose(&r); /* safe after a failed open */
  CS_EXPECT(csu_lineOpen(&r, ".", 16, "test file", &err) == CS_OK);
  CS_EXPECT(csu_lineNext(&r, &err) == CS_ERR_IO && strstr(err.msg, ".:1: read error") != NULL);
  csu_lineClose(&r);
  /* a limit of 0 and a NULL path are caller errors, reported, not crashes */
  CS_EXPECT(csu_lineOpen(&r, "x", 0, "test file", &err) == CS_ERR_ARG);
  CS_EXPECT(csu_lineOpen(&r, NULL, 16, "test file", &err) == CS_ERR_ARG);
  CS_EXPECT(csu_lineNext(&r, &err) == CS_ERR_ARG); /* on a closed reader */
}


static void test_words(void) {
  char line[] = "  box\t1  2\v3 \r";
  char* w[2];
  CS_EXPECT(csu_splitWords(line, w, 2) == 4); /* counted past the two it stores */
  CS_EXPECT(!strcmp(w[0], "box") && !strcmp(w[1], "1"));
  char blank[] = " \t ";
  CS_EXPECT(csu_splitWords(blank, w, 2) == 0);
  char empty[] = "";
  CS_EXPECT(csu_splitWords(empty, w, 2) == 0);
}


/* parse `text` and expect failure with a message "<label> '<text>': ... cause" */
static void expectBadList(const char* text, const char* cause) {
  unsigned mask = 77;
  csError err;
  CS_EXPECT(csu_chamberListParse(text, 4, "--chambers", &mask, &err) == CS_ERR_PARSE);
  CS_EXPECT(mask == 0);
  char head[64];
  snprintf(head, sizeof head, "--chambers '%s': ", text);
  CS_EXPECT(strstr(err.msg, head) == err.msg);
  CS_EXPECT(strstr(err.msg, cause) != NULL);
  if (!strstr(err.msg, cause)) {
    fprintf(stderr, "  '%s': %s\n", text, err.msg);
  }
}


static void test_chamber_lists(void) {
  unsigned mask = 0;
  csError err;
  char buf[16];
  CS_EXPECT(csu_chamberListParse("1,2", 4, "chambers", &mask, &err) == CS_OK && mask == 3u);
  CS_EXPECT(csu_chamberListParse("4,1", 4, "chambers", &mask, &err) == CS_OK && mask == 9u);
  csu_chamberListFormat(mask, buf, sizeof buf);
  CS_EXPECT(!strcmp(buf, "1,4")); /* canonical order */
  CS_EXPECT(csu_chamberListParse("3", 4, "chambers", &mask, &err) == CS_OK && mask == 4u);
  CS_EXPECT(csu_chamberListParse("1,2,3,4", 4, "chambers", &mask, &err) == CS_OK &&
            mask == 15u);
  csu_chamberListFormat(mask, buf, sizeof buf);
  CS_EXPECT(!strcmp(buf, "1,2,3,4"));
  csu_chamberListFormat(0, buf, sizeof buf);
  CS_EXPECT(buf[0] == '\0');
  csu_chamberListFormat(15u, buf, 4); /* truncated, still a string */
  CS_EXPECT(strlen(buf) <= 3);
  expectBadList("", "expected a comma-separated list");
  expectBadList("0", "chamber 0 is not in 1..4");
  expectBadList("5", "chamber 5 is not in 1..4");
  expectBadList("1,5", "chamber 5 is not in 1..4");
  expectBadList("99999999999999999999", "is not in 1..4"); /* no overflow */
  expectBadList("1,,2", "expected a comma-separated list");
  expectBadList("1,", "expected a comma-separated list");
  expectBadList(",1", "expected a comma-separated list");
  expectBadList(" 1", "expected a comma-separated list");
  expectBadList("+1", "expected a comma-separated list");
  expectBadList("1.5", "expected a comma-separated list");
  expectBadList("1;2", "expected a comma-separated list");
  expectBadList("2,2", "chamber 2 is repeated");
  CS_EXPECT(csu_chamberListParse(NULL, 4, "chambers", &mask, &err) == CS_ERR_ARG);
  CS_EXPECT(csu_chamberListParse("1", 0, "chambers", &mask, &err) == CS_ERR_ARG);
}


/* csu_statementFileRead's callback for the tests: records each statement's keyword and word
 * count; a statement "stop" ends the read with CS_ERR_PARSE naming its line */
typedef struct {
  char seen[128];
  int nstatement;
} statementLog;

static csStatus logStatement(void* ctx, char** word, int nword, const char* path, int line,
                             csError* err) {
  statementLog* g = ctx;
  if (!strcmp(word[0], "stop")) {
    return cs_errorSet(err, CS_ERR_PARSE, "%s:%d: stop", path, line);
  }
  size_t n = strlen(g->seen);
  snprintf(g->seen + n, sizeof g->seen - n, "%s%s:%d", n ? "|" : "", word[0], nword);
  g->nstatement++;
  return CS_OK;
}


/* the statement-file driver: comments and blank lines skipped, statements in order with their
 * word counts, the last line reported, too many words refused at their line, the callback's
 * status stops the read at once, a missing file and bad arguments refused */
static void test_statement_files(void) {
  csError err;
  statementLog g;
  int last = -1;
  const char ok[] = "# head\n\na 1 2 # tail\n  b\n\n";
  writeBytes("text_st.txt", ok, sizeof ok - 1);
  memset(&g, 0, sizeof g);
  CS_EXPECT(csu_statementFileRead("text_st.txt", 64, "test file", 4, logStatement, &g, &last,
                                  &err) == CS_OK);
  CS_EXPECT(!strcmp(g.seen, "a:3|b:1") && g.nstatement == 2);
  CS_EXPECT(last == 5);
  const char many[] = "a 1\nb 1 2 3 4\nc\n";
  writeBytes("text_st_many.txt", many, sizeof many - 1);
  memset(&g, 0, sizeof g);
  CS_EXPECT(csu_statementFileRead("text_st_many.txt", 64, "test file", 4, logStatement, &g, &last,
                                  &err) == CS_ERR_PARSE);
  CS_EXPECT(strstr(err.msg, "text_st_many.txt:2: more than 4 words") != NULL);
  CS_EXPECT(!strcmp(g.seen, "a:2") && last == 2);
  const char stop[] = "a\nstop\nc\n";
  writeBytes("text_st_stop.txt", stop, sizeof stop - 1);
  memset(&g, 0, sizeof g);
  CS_EXPECT(csu_statementFileRead("text_st_stop.txt", 64, "test file", 4, logStatement, &g, NULL,
                                  &err) == CS_ERR_PARSE);
  CS_EXPECT(strstr(err.msg, "text_st_stop.txt:2: stop") != NULL && g.nstatement == 1);
  /* a line past the limit is the line reader's error, at its line */
  const char longl[] = "a\nbbbbbbbbbbbbbbbbbbbb\n";
  writeBytes("text_st_long.txt", longl, sizeof longl - 1);
  CS_EXPECT(csu_statementFileRead("text_st_long.txt", 8, "test file", 4, logStatement, &g, &last,
                                  &err) == CS_ERR_RANGE);
  CS_EXPECT(strstr(err.msg, "text_st_long.txt:2:") != NULL);
  CS_EXPECT(csu_statementFileRead("text_st_none.txt", 64, "test file", 4, logStatement, &g, &last,
                                  &err) == CS_ERR_IO && last == 0);
  CS_EXPECT(strstr(err.msg, "cannot open test file") != NULL);
  CS_EXPECT(csu_statementFileRead("text_st.txt", 64, "test file", 0, logStatement, &g, &last,
                                  &err) == CS_ERR_ARG);
  CS_EXPECT(csu_statementFileRead("text_st.txt", 64, "test file", CSU_STATEMENT_MAX_WORDS + 1,
                                  logStatement, &g, &last, &err) == CS_ERR_ARG);
  CS_EXPECT(csu_statementFileRead("text_st.txt", 64, "test file", 4, NULL, &g, &last, &err) ==
            CS_ERR_ARG);
}


int main(int argc, char** argv) {
  cs_testInit(argc, argv);
  CS_RUN(test_lines_good_files);
  CS_RUN(test_lines_bad_files);
  CS_RUN(test_words);
  CS_RUN(test_chamber_lists);
  CS_RUN(test_statement_files);
  return cs_testSummary();
}
