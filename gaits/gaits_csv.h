/* gaits_csv.h: the gait table (time x 96 chamber pressures), its CSV reader and writer, and
 * its validation.
 *
 * Owns: csgGait, building one in code (for gait generators), csg_gaitRead / csg_gaitWrite of
 * the CSV format below, the value rules every table obeys (csg_gaitValidate), the reader
 * limits (csgReadOptions) and the summary `crawlsim gait check` prints.
 *
 * Units: time in s, pressure in MPa (gauge: 0 = vented), as everywhere in crawlsim.
 *
 * CSV format (read and written here):
 *   # optional comment lines start with '#' (allowed anywhere; blank lines are skipped too)
 *   # @ramp 0.05
 *   time,A_II1_O1,A_II1_O2,...
 *   0,0.18,0,...
 *   1,0,0.18,...
 * - The first non-comment line is the header. Its first field is `time`; each further field
 *   names one chamber, either by name (A_II1_O1 .. H_II3_O4: leg A..H, segment II1..II3,
 *   chamber O1..O4 = Ω1..Ω4) or by label number 1..96 (gaits_labels.h). Columns come in any
 *   order and may be a subset; chambers not named are 0 MPa in every row; naming a chamber
 *   twice (also as name and number) is an error.
 * - Every further line is a data row with exactly as many fields as the header: time, then
 *   pressures. Fields are decimal numbers as strtod reads them; spaces or tabs around a field
 *   are ignored; empty fields, NaN and Inf are errors.
 * - Times are >= 0 and strictly increasing. Pressures are >= 0 and <= max_pressure.
 * - A comment whose text starts with '@' is a directive, `# @name value` (anywhere, at most
 *   once each). The one known: `# @ramp S`, the table's pressure ramp in s (>= 0, finite;
 *   gaits_schedule.h), which a run uses where --ramp is not given: a table whose rows sample a
 *   designed motion every S s states S, so it plays as designed. An unknown name, a second
 *   @ramp, a value that is not one number or out of range are errors naming the line.
 * - LF or CRLF line endings; a UTF-8 byte-order mark at the start is ignored. At least one
 *   data row. What a row means over time (holds, ramps) is gaits_schedule.h's business.
 * The writer writes a comment, the @ramp directive if the table states one, then all 96 columns by name in label order, pressures with
 * %.6g and times with the shortest %.Ng (N >= 6) that reads back exactly.
 *
 * Errors: a one-line message in csError, "<file>:<line>: column <c> (<name>): <cause>"
 * (line and column 1-based; the column part is left out when the cause concerns the whole
 * line or file). Status: CS_ERR_IO (cannot open or read), CS_ERR_PARSE (malformed: header,
 * column names, field count, not a number), CS_ERR_RANGE (NaN/Inf, negative or non-increasing
 * time, negative or too high pressure, too many rows, too long a line), CS_ERR_MEMORY,
 * CS_ERR_ARG (NULL or invalid arguments/options). The library never prints or exits. */
#ifndef CS_GAITS_CSV_H
#define CS_GAITS_CSV_H

#include <stddef.h>

#include "core_status.h"
#include "gaits_labels.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Default upper bound on any pressure in a gait (MPa). Far above any gait pressure (the
 * paper's gaits use 0.18-0.3 MPa; 360 degrees of bending takes 0.403 MPa) so it never rejects
 * a real gait, yet it catches unit slips (kPa or bar typed as MPa: 180 or 1.8 for 0.18) and
 * keeps the legs below burst-level loads that the hyperelastic models are not meant for. */
#define CSG_DEFAULT_MAX_PRESSURE 1.0

/* Default limit on data rows (count). One row costs 96 doubles = 768 B, so 1e5 rows cap a
 * table at ~77 MB; that is a 1 kHz table of 100 s, while the paper's gaits have 10-33 rows. */
#define CSG_DEFAULT_MAX_ROWS 100000L

/* Default limit on one line's length (bytes, without the line ending). A full 96-column row
 * with %.17g numbers is under 2.5 KiB; 64 KiB leaves room for comments and padding. */
#define CSG_DEFAULT_MAX_LINE_BYTES 65536

/* Limits the reader enforces (csg_gaitRead) and csg_gaitValidate checks. */
typedef struct csgReadOptions_ {
  double max_pressure;   /* MPa: largest accepted pressure (> 0) */
  long max_rows;         /* count: largest accepted number of data rows (>= 1) */
  size_t max_line_bytes; /* bytes: longest accepted line, line ending excluded (>= 64) */
} csgReadOptions;

/* The defaults above, by value (Box2D b2DefaultWorldDef style). */
csgReadOptions csg_defaultReadOptions(void);

/* A gait table. Read the fields freely; change them only through the functions below so the
 * arrays stay consistent (capacity is managed here). A table is valid when
 * csg_gaitValidate accepts it; csg_gaitRead only returns valid tables. */
typedef struct csgGait_ {
  int nrow;         /* number of rows (time nodes) */
  double* time;     /* (nrow) s: when row i takes effect; strictly increasing, time[0] >= 0 */
  double* pressure; /* (nrow x CSG_NLABEL) MPa, row-major: pressure[CSG_NLABEL*i + label-1] */
  int cap;          /* allocated rows (>= nrow); internal */
  double ramp;      /* s: the ramp the table states (`# @ramp`), NAN if none (>= 0 otherwise) */
} csgGait;

/* ---- building a table in code (gait generators) ---- */

/* Create a table of `nrow` rows (0 allowed: grow it later), every time and pressure 0.
 * Returns NULL and fills err (CS_ERR_ARG for nrow < 0, CS_ERR_MEMORY) on failure.
 * Destroy with csg_gaitDestroy. */
csgGait* csg_gaitCreate(int nrow, csError* err);

/* Free a table. NULL-safe. */
void csg_gaitDestroy(csgGait* g);

/* Change the number of rows. Existing rows keep their values; new rows are all 0 (time and
 * pressures). On failure (CS_ERR_ARG, CS_ERR_MEMORY) the table is unchanged. */
csStatus csg_gaitSetRowCount(csgGait* g, int nrow, csError* err);

/* Set the time (s) of row `row` (0-based). CS_ERR_ARG for a bad row or a non-finite time.
 * Ordering is checked by csg_gaitValidate, so rows may be filled in any order. */
csStatus csg_gaitSetTime(csgGait* g, int row, double t, csError* err);

/* Set the pressure (MPa) of chamber `label` (1..96, gaits_labels.h) in row `row` (0-based).
 * CS_ERR_ARG for a bad row or label or a non-finite pressure; sign and limit are checked by
 * csg_gaitValidate. */
csStatus csg_gaitSetPressure(csgGait* g, int row, int label, double p, csError* err);

/* Time (s) of a row, or NAN for a bad row or NULL g. */
double csg_gaitTime(const csgGait* g, int row);

/* Pressure (MPa) of chamber `label` (1..96) in row `row` (0-based), or NAN if out of range. */
double csg_gaitPressure(const csgGait* g, int row, int label);

/* Check the value rules: at least one row and at most opt->max_rows; ramp NAN or finite and
 * >= 0; finite times, time[0] >= 0, strictly increasing; finite pressures in [0, opt->max_pressure]. opt NULL = defaults.
 * Messages name the row (0-based index) and chamber, e.g.
 * "csg_gaitValidate: gait row 3 (t = 2 s), chamber A_II1_O2: negative pressure (...): -0.1 MPa".
 * Returns CS_OK, CS_ERR_RANGE or CS_ERR_ARG (NULL, no rows, bad options). */
csStatus csg_gaitValidate(const csgGait* g, const csgReadOptions* opt, csError* err);

/* ---- CSV ---- */

/* Read and validate the CSV file at `path` (format above). opt NULL = defaults. Returns a new
 * table (destroy with csg_gaitDestroy), or NULL with err filled. Memory use is bounded by the
 * options before anything is allocated: one line buffer of max_line_bytes, rows grown by
 * doubling up to max_rows. */
csgGait* csg_gaitRead(const char* path, const csgReadOptions* opt, csError* err);

/* Write `g` to the CSV file at `path`, all 96 columns by name. `comment` (may be NULL) is
 * written first as '#' lines, one per '\n'-separated line. The table must pass the value
 * rules except the reader's limits (max_pressure, max_rows): those are reading policy and are
 * enforced when the file is read back. Returns CS_OK, CS_ERR_RANGE/CS_ERR_ARG (invalid table,
 * nothing written) or CS_ERR_IO. */
csStatus csg_gaitWrite(const csgGait* g, const char* path, const char* comment, csError* err);

/* ---- summary ---- */

/* What `crawlsim gait check` reports about a table. */
typedef struct csgGaitSummary_ {
  int nrow;        /* rows */
  double t_first;  /* s: time of the first row */
  double t_last;   /* s: time of the last row */
  int nused;       /* chambers with a pressure > 0 in at least one row (0..96) */
  double p_max;    /* MPa: largest pressure in the table (0 if all vented) */
  int p_max_label; /* chamber (1..96) of the first occurrence of p_max, 0 if p_max == 0 */
  int p_max_row;   /* row (0-based) of that occurrence, -1 if p_max == 0 */
} csgGaitSummary;

/* Fill `s` from a table with at least one row. CS_ERR_ARG for NULL or an empty table. */
csStatus csg_gaitComputeSummary(const csgGait* g, csgGaitSummary* s, csError* err);

#ifdef __cplusplus
}
#endif
#endif /* CS_GAITS_CSV_H */
