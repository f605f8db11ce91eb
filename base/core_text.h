/* core_text.h: the text readers every crawlsim input file goes through.
 *
 * Owns: csuLineReader (one line at a time, 1-based line numbers, a line-length limit checked
 * before anything grows, LF or CRLF endings, a UTF-8 byte-order mark ignored, NUL bytes and
 * stray carriage returns refused at their line and byte), csu_splitWords (whitespace words in
 * place), and the chamber-list parser ("1,2" -> bit mask) of `--chambers` and calibration
 * files, and the statement-file driver (csu_statementFileRead) of the gate, foothold and gait
 * design readers. Used by gaits/, terrains_terrain.c, robot_calibration.c and tools/cmd_bend.c.
 * Also the one closing check of every text file written with stdio (csu_writeClose).
 *
 * Why not fgets: it cannot tell an embedded NUL from the end of a line, and an overlong line
 * comes back in pieces that parse as separate lines. The reader pulls the file through a fixed
 * chunk into one line buffer of max_line + 2 bytes (the line, a CR of a CRLF ending, the NUL),
 * allocated once when the file is opened.
 *
 * Errors (csError, the library never prints): "<file>: cannot open <what>: <reason>"
 * (CS_ERR_IO), "<file>:<line>: read error: <reason>" (CS_ERR_IO), "<file>:<line>: line longer
 * than N bytes (...)" (CS_ERR_RANGE), "<file>:<line>: byte B: NUL byte (...)" and "...: byte B:
 * carriage return inside a line (...)" (CS_ERR_PARSE). */
#ifndef CS_CORE_TEXT_H
#define CS_CORE_TEXT_H

#include <stddef.h>
#include <stdio.h>

#include "core_status.h"

#ifdef __cplusplus
extern "C" {
#endif

/* bytes pulled from the file per fread */
#define CSU_LINE_CHUNK 8192

/* A line reader over one open file. Read `line`, `len` and `lineno`; the rest is internal. */
typedef struct csuLineReader_ {
  char* line;          /* (max_line + 2) the current line, NUL-terminated, ending removed */
  size_t len;          /* bytes in `line` */
  long lineno;         /* 1-based number of the current line; 0 before the first read */
  const char* path;    /* the file name as given (borrowed), for messages */
  const char* what;    /* what the file is ("gait CSV"), for messages (borrowed) */
  size_t max_line;     /* bytes: longest accepted line, ending excluded */
  FILE* f;
  char chunk[CSU_LINE_CHUNK];
  size_t pos, nchunk;  /* unread bytes are chunk[pos..nchunk) */
} csuLineReader;

/* Open `path` for reading lines of at most max_line bytes (>= 1; the line ending is not
 * counted). `what` names the kind of file in messages ("terrain file"). On failure r is left
 * closed (csu_lineClose is still safe) and err says why. */
csStatus csu_lineOpen(csuLineReader* r, const char* path, size_t max_line, const char* what,
                      csError* err);

/* Read the next line into r->line. Returns 1 when a line was read (also an empty line or a last
 * line without a newline), 0 at the end of the file, or a negative csStatus with err naming the
 * file, line and cause. A UTF-8 byte-order mark at the start of line 1 is dropped. */
int csu_lineNext(csuLineReader* r, csError* err);

/* Close the file and free the line buffer. NULL-safe and idempotent. */
void csu_lineClose(csuLineReader* r);

/* Split `line` in place at whitespace (isspace). Stores pointers to at most `max` words in
 * word[] and returns the number of words on the line, which may exceed max (the extra words
 * are counted, not stored: a caller checks the count against what its statement takes). */
int csu_splitWords(char* line, char** word, int max);

/* The words of a statement line: drops a '#' comment (to the line's end) in place, then
 * csu_splitWords. 0 for a blank or comment-only line. */
int csu_statementWords(char* line, char** word, int max);

/* the most words a statement file's statement may hold (csu_statementFileRead's max_words) */
#define CSU_STATEMENT_MAX_WORDS 64

/* One statement of a statement file: its words (word[0] the keyword, nword <= the reader's
 * max_words), the file and the 1-based line for messages. Returns CS_OK to go on, or a status
 * with err filled to stop the read. */
typedef csStatus (*csuStatementFn)(void* ctx, char** word, int nword, const char* path,
                                   int line, csError* err);

/* Read a statement file (one statement per line, '#' comments, blank lines skipped: the gate,
 * foothold and gait design files): opens `path` (lines of at most max_line bytes, `what` names
 * the kind of file in messages), calls fn for every statement in order and stops at the first
 * status other than CS_OK. A statement of more than max_words words (1..CSU_STATEMENT_MAX_WORDS)
 * is refused as "<file>:<line>: more than N words". *last_line (may be NULL) gets the number of
 * the last line read (0 for an empty file), for the caller's end-of-file checks. */
csStatus csu_statementFileRead(const char* path, size_t max_line, const char* what, int max_words,
                               csuStatementFn fn, void* ctx, int* last_line, csError* err);

/* Trim spaces and tabs at both ends of s in place; returns the first kept byte (inside s). */
char* csu_trimBlanks(char* s);

/* "<N> bytes free on the file system of <path>'s directory" (statvfs, for messages about a
 * write that fell short), or "free space unknown" into buf[size]. */
void csu_freeSpace(const char* path, char* buf, size_t size);

/* Close a text file written with stdio and check it: a write error anywhere (the stream's
 * error flag), a failed flush or close gives CS_ERR_IO "<path>: cannot write <what>: <reason>"
 * with strerror (no space left on device, read-only file system, ...), and the incomplete
 * file is removed. The stream is closed in every case. */
csStatus csu_writeClose(FILE* f, const char* path, const char* what, csError* err);

/* Parse a chamber list: chamber numbers 1..nmax separated by commas, each once, in any order
 * ("1,2", "4,1"). Sets bit j-1 of *mask for chamber j. Refused, with err = "<label> '<text>':
 * <cause>" (CS_ERR_PARSE): an empty list or item ("", "1,,2", "1,"), anything but digits in an
 * item (" 1", "+1", "1.5"), a chamber outside 1..nmax ("0", "5"), a repeat ("2,2").
 * nmax is 1..31. On failure *mask is 0. */
csStatus csu_chamberListParse(const char* text, int nmax, const char* label, unsigned* mask,
                              csError* err);

/* The canonical text of a mask in chamber order ("1,2"); "" for 0. Truncated to size - 1. */
void csu_chamberListFormat(unsigned mask, char* buf, size_t size);

#ifdef __cplusplus
}
#endif
#endif /* CS_CORE_TEXT_H */
