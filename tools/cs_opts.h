/* cs_opts.h: the option tables of the crawlsim commands.
 *
 * Owns: one table per command (csxOptTable) that both parses its arguments (csx_optNext) and
 * prints its --help (csx_optHelp), so that every option a parser accepts is listed in its help
 * with its default and units, and every command treats the command line alike:
 *   - options are "--name VALUE" or "--name=VALUE" (both, on every command); a flag (an option
 *     without a value) refuses "--flag=VALUE";
 *   - "--help" / "-h" anywhere asks for the help (exit 0);
 *   - an unknown option is one error naming the nearest valid one by edit distance
 *     ("unknown option --t-edn; did you mean --t-end?");
 *   - a value that starts with "--" after a separate "--name" is taken as a forgotten value.
 * The tables are constant data in each cmd_<name>.c; nothing here allocates or prints except
 * csx_optHelp, which writes to the stream it is given. */
#ifndef CS_TOOLS_OPTS_H
#define CS_TOOLS_OPTS_H

#include <stddef.h>
#include <stdio.h>

/* one option of a command */
typedef struct {
  const char* name; /* "--t-end" */
  const char* arg;  /* what its value is, with units ("S", "FILE.csv", "MPA"); NULL: a flag */
  const char* def;  /* its default as the user sees it ("0 = the gait's length"); NULL: none */
  const char* help; /* what it does (one sentence or a short paragraph, units stated) */
} csxOpt;

/* one command's options */
typedef struct {
  const char* cmd;      /* "run", "gait design" */
  const char* operands; /* what comes besides the options ("FILE.csv"), "" for none */
  const char* about;    /* what the command does (a paragraph, printed before the options) */
  const csxOpt* opt;
  int nopt;
  const char* notes; /* printed after the options (NULL: none) */
} csxOptTable;

#define CSX_NOPT(a) ((int)(sizeof(a) / sizeof((a)[0])))

/* what csx_optNext found */
typedef enum {
  CSX_OPT_END = 0,     /* no arguments left */
  CSX_OPT_OPTION = 1,  /* an option: it->opt, and it->value for one that takes a value */
  CSX_OPT_OPERAND = 2, /* an argument that is not an option: it->value */
  CSX_OPT_HELP = 3,    /* --help or -h */
  CSX_OPT_ERROR = -1   /* it->error holds the cause (one line, no "crawlsim cmd:" prefix) */
} csxOptKind;

typedef struct {
  int i;             /* next argv index; start at 1 (argv[0] is the command's name) */
  const csxOpt* opt; /* CSX_OPT_OPTION: the table's entry */
  const char* value; /* its value (NULL for a flag), or the operand */
  char error[256];
} csxOptIter;

/* Start iterating over argv[1..argc-1]. */
void csx_optBegin(csxOptIter* it);

/* The next argument of argv by table t (see csxOptKind). */
csxOptKind csx_optNext(const csxOptTable* t, int argc, char** argv, csxOptIter* it);

/* The table's option nearest to `name` (its first `len` characters) by edit distance, or NULL
 * when none is within about half its length (a guess that far off would mislead). */
const csxOpt* csx_optNearest(const csxOptTable* t, const char* name, size_t len);

/* The common ends of csx_optNext: CSX_OPT_HELP prints the help on stdout and returns 0 (the
 * command's exit status), CSX_OPT_ERROR prints "crawlsim <cmd>: <cause>" on stderr (control
 * characters shown as '?') and returns 1; any other kind returns -1 (the caller handles it). */
int csx_optReport(const csxOptTable* t, csxOptKind kind, const csxOptIter* it);

/* Print the command's help: usage, about, every option with its value, default and meaning,
 * notes; wrapped at 79 columns. */
void csx_optHelp(const csxOptTable* t, FILE* out);

/* Is `name` (exactly) one of the table's options? (1/0) */
int csx_optIs(const csxOpt* o, const char* name);

#endif
