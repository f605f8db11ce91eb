/* core_text.c: line reader, word splitting, chamber lists (see core_text.h). */
#define _POSIX_C_SOURCE 200809L /* statvfs */
#include "core_text.h"

#include <ctype.h>
#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <sys/statvfs.h>

/* longest chamber-list text quoted in a message (bytes) */
#define QUOTE_MAX 40
/* largest value an item may reach while its digits are read: anything above nmax is out of
 * range anyway, so the value is capped instead of overflowing on "99999999999999999999" */
#define ITEM_CAP 1000


csStatus csu_lineOpen(csuLineReader* r, const char* path, size_t max_line, const char* what,
                      csError* err) {
  memset(r, 0, sizeof *r);
  r->path = path ? path : "(null)";
  r->what = what ? what : "file";
  if (!path || max_line < 1 || max_line > ((size_t)-1) / 2) {
    return cs_errorSet(err, CS_ERR_ARG, "%s: csu_lineOpen: NULL path or line limit %zu", r->path,
                       max_line);
  }
  r->max_line = max_line;
  errno = 0;
  r->f = fopen(path, "rb");
  if (!r->f) {
    return cs_errorSet(err, CS_ERR_IO, "%s: cannot open %s: %s", path, r->what,
                       strerror(errno));
  }
  r->line = malloc(max_line + 2);
  if (!r->line) {
    csu_lineClose(r);
    return cs_errorSet(err, CS_ERR_MEMORY, "%s: out of memory for a %zu-byte line", path,
                       max_line);
  }
  r->line[0] = '\0';
  return CS_OK;
}


void csu_lineClose(csuLineReader* r) {
  if (!r) {
    return;
  }
  if (r->f) {
    fclose(r->f);
    r->f = NULL;
  }
  free(r->line);
  r->line = NULL;
}


int csu_lineNext(csuLineReader* r, csError* err) {
  if (!r->f || !r->line) {
    return cs_errorSet(err, CS_ERR_ARG, "%s: csu_lineNext on a closed reader", r->path);
  }
  size_t n = 0;
  int got = 0; /* any byte of this line, newline included */
  r->lineno++;
  for (;;) {
    if (r->pos == r->nchunk) {
      errno = 0;
      r->nchunk = fread(r->chunk, 1, sizeof r->chunk, r->f);
      r->pos = 0;
      if (r->nchunk == 0) {
        if (ferror(r->f)) {
          return cs_errorSet(err, CS_ERR_IO, "%s:%ld: read error: %s", r->path, r->lineno,
                             strerror(errno));
        }
        break; /* end of file: the last line may lack a newline */
      }
    }
    char c = r->chunk[r->pos++];
    got = 1;
    if (c == '\n') {
      break;
    }
    if (c == '\0') {
      return cs_errorSet(err, CS_ERR_PARSE,
                         "%s:%ld: byte %zu: NUL byte (a binary file, or UTF-16 text? a %s is "
                         "ASCII/UTF-8 text)",
                         r->path, r->lineno, n + 1, r->what);
    }
    /* the limit excludes the line ending, so one CR may sit past it (buffer max_line + 2) */
    if (n >= r->max_line && !(n == r->max_line && c == '\r')) {
      return cs_errorSet(err, CS_ERR_RANGE,
                         "%s:%ld: line longer than %zu bytes (the %s reader's limit): not a %s, "
                         "or a runaway line",
                         r->path, r->lineno, r->max_line, r->what, r->what);
    }
    r->line[n++] = c;
  }
  if (!got) {
    r->lineno--; /* no line: the count stays at the last line read */
    r->len = 0;
    r->line[0] = '\0';
    return 0;
  }
  /* CRLF: drop the CR that ends the line; a CR inside it means classic-Mac line endings,
   * which would make the whole file one line and put raw CRs into messages */
  if (n > 0 && r->line[n - 1] == '\r') {
    n--;
  }
  r->line[n] = '\0';
  const char* cr = memchr(r->line, '\r', n);
  if (cr) {
    return cs_errorSet(err, CS_ERR_PARSE,
                       "%s:%ld: byte %zu: carriage return inside a line (use LF or CRLF line "
                       "endings)",
                       r->path, r->lineno, (size_t)(cr - r->line) + 1);
  }
  /* a UTF-8 byte-order mark (spreadsheet and editor exports) is not part of the text */
  static const char kBom[] = "\xEF\xBB\xBF";
  if (r->lineno == 1 && n >= 3 && !memcmp(r->line, kBom, 3)) {
    memmove(r->line, r->line + 3, n - 3 + 1);
    n -= 3;
  }
  r->len = n;
  return 1;
}


int csu_splitWords(char* line, char** word, int max) {
  int nword = 0;
  char* s = line;
  for (;;) {
    while (isspace((unsigned char)*s)) {
      s++;
    }
    if (!*s) {
      break;
    }
    if (nword < max) {
      word[nword] = s;
    }
    nword++;
    while (*s && !isspace((unsigned char)*s)) {
      s++;
    }
    if (*s) {
      *s++ = '\0';
    }
  }
  return nword;
}



int csu_statementWords(char* line, char** word, int max) {
  char* hash = strchr(line, '#');
  if (hash) {
    *hash = '\0';
  }
  return csu_splitWords(line, word, max);
}

csStatus csu_statementFileRead(const char* path, size_t max_line, const char* what, int max_words,
                               csuStatementFn fn, void* ctx, int* last_line, csError* err) {
  if (last_line) {
    *last_line = 0;
  }
  if (!path || !what || !fn || max_words < 1 || max_words > CSU_STATEMENT_MAX_WORDS) {
    return cs_errorSet(err, CS_ERR_ARG, "csu_statementFileRead: bad arguments");
  }
  csuLineReader* r = malloc(sizeof *r); /* an 8 KiB chunk: not on the stack */
  csStatus st = r ? csu_lineOpen(r, path, max_line, what, err)
                  : cs_errorSet(err, CS_ERR_MEMORY, "%s: out of memory", path);
  int got = 0;
  while (st == CS_OK && (got = csu_lineNext(r, err)) > 0) {
    const int line = (int)r->lineno;
    if (last_line) {
      *last_line = line;
    }
    char* w[CSU_STATEMENT_MAX_WORDS];
    int nw = csu_statementWords(r->line, w, max_words);
    if (nw == 0) {
      continue;
    }
    st = nw > max_words ? cs_errorSet(err, CS_ERR_PARSE, "%s:%d: more than %d words", path, line,
                                      max_words)
                        : fn(ctx, w, nw, path, line, err);
  }
  if (st == CS_OK && got < 0) {
    st = (csStatus)got;
  }
  if (r) {
    csu_lineClose(r);
    free(r);
  }
  return st;
}


csStatus csu_chamberListParse(const char* text, int nmax, const char* label, unsigned* mask,
                              csError* err) {
  const char* lab = label ? label : "chamber list";
  *mask = 0;
  if (!text || nmax < 1 || nmax > 31) {
    return cs_errorSet(err, CS_ERR_ARG, "%s: no text or chamber count %d outside 1..31", lab,
                       nmax);
  }
  unsigned m = 0;
  const char* p = text;
  for (;;) {
    /* one item: a run of digits, then ',' or the end */
    const char* q = p;
    long j = 0;
    while (isdigit((unsigned char)*q)) {
      j = j * 10 + (*q - '0');
      j = j > ITEM_CAP ? ITEM_CAP : j;
      q++;
    }
    if (q == p || (*q != ',' && *q != '\0')) {
      return cs_errorSet(err, CS_ERR_PARSE,
                         "%s '%.*s': expected a comma-separated list of chamber numbers 1..%d "
                         "(e.g. 1,2)",
                         lab, QUOTE_MAX, text, nmax);
    }
    if (j < 1 || j > nmax) {
      return cs_errorSet(err, CS_ERR_PARSE, "%s '%.*s': chamber %.*s is not in 1..%d", lab,
                         QUOTE_MAX, text, (int)(q - p > 12 ? 12 : q - p), p, nmax);
    }
    if (m & (1u << (j - 1))) {
      return cs_errorSet(err, CS_ERR_PARSE, "%s '%.*s': chamber %ld is repeated", lab,
                         QUOTE_MAX, text, j);
    }
    m |= 1u << (j - 1);
    if (*q == '\0') {
      break;
    }
    p = q + 1; /* past the comma */
  }
  *mask = m;
  return CS_OK;
}


void csu_chamberListFormat(unsigned mask, char* buf, size_t size) {
  if (size == 0) {
    return;
  }
  buf[0] = '\0';
  size_t n = 0;
  for (int j = 0; j < 31; j++) {
    if (mask & (1u << j)) {
      int w = snprintf(buf + n, size - n, "%s%d", n ? "," : "", j + 1);
      if (w < 0 || (size_t)w >= size - n) {
        return; /* truncated: snprintf kept it NUL-terminated */
      }
      n += (size_t)w;
    }
  }
}


char* csu_trimBlanks(char* s) {
  while (*s == ' ' || *s == '\t') {
    s++;
  }
  size_t n = strlen(s);
  while (n > 0 && (s[n - 1] == ' ' || s[n - 1] == '\t')) {
    s[--n] = '\0';
  }
  return s;
}


csStatus csu_writeClose(FILE* f, const char* path, const char* what, csError* err) {
  if (!f) {
    return cs_errorSet(err, CS_ERR_ARG, "%s: no stream to close", path);
  }
  /* errno still holds the cause of the first failed write (later successful calls keep it) */
  int e = errno;
  int bad = ferror(f);
  if (!bad && fflush(f) != 0) {
    bad = 1, e = errno;
  }
  if (fclose(f) != 0 && !bad) {
    bad = 1, e = errno;
  }
  if (bad) {
    remove(path);
    return cs_errorSet(err, CS_ERR_IO, "%s: cannot write %s: %s", path, what,
                       strerror(e ? e : EIO));
  }
  return CS_OK;
}


void csu_freeSpace(const char* path, char* buf, size_t size) {
  char dir[1024];
  snprintf(dir, sizeof dir, "%s", path);
  char* slash = strrchr(dir, '/');
  if (slash) {
    slash[slash == dir] = '\0'; /* "/x" -> "/", "a/b" -> "a" */
  } else {
    snprintf(dir, sizeof dir, ".");
  }
  struct statvfs v;
  if (statvfs(dir, &v) == 0) {
    snprintf(buf, size, "%llu bytes free on the file system of %s",
             (unsigned long long)v.f_bavail * (unsigned long long)v.f_frsize, dir);
  } else {
    snprintf(buf, size, "free space unknown");
  }
}
