/* cmd_bend.h: the parsed options of `crawlsim bend` and what a model reports about itself,
 * shared by the command (cmd_bend.c: parsing, the mesh-free models, the sweep) and its full-FE
 * branch (cmd_bend_fe.c). Private to tools/: nothing below includes it. Units: mm, MPa, deg, N. */
#ifndef CS_TOOLS_CMD_BEND_H
#define CS_TOOLS_CMD_BEND_H

#include <stdio.h>

#include "core_h5.h"
#include "core_status.h"
#include "cs_bend.h"
#include "robot_actuator.h"
#include "robot_bend_io.h"

typedef enum { BEND_ANALYTIC, BEND_FE, BEND_ROD, BEND_ROM, BEND_STRAIN, BEND_NMODEL } BendModel;

/* one bend run: parsed options and what the model reports about itself */
typedef struct {
  BendModel model;
  csrActuator act;
  int inflated[CSR_NCHAMBER]; /* 1 if chamber j+1 is inflated */
  char chambers[64];          /* canonical list, e.g. "1,2", or "1:1,2:0.5" with --pressures */
  double p_max, p_step;       /* MPa */
  double until_angle;         /* deg, NAN when not requested */
  double mesh_size;           /* mm requested (NAN = model default); the model overwrites it
                                 with what it used (NAN for mesh-free models) */
  double n_elements_soft, n_elements_fibre; /* filled by mesh-based models */
  double p_limit, p_resume;   /* MPa, pressure limit point met and resume pressure (NAN: none);
                                 with limit_shown 0, p_limit is where the sweep ended because
                                 pressure and volume control both failed (no limit point) */
  int limit_shown;            /* fe: 1 the pressure fell past p_limit (csfBendInfo.limit_shown) */
  const char* out;
  double ratio[CSR_NCHAMBER]; /* chamber j at ratio[j] x p (1/0 from --chambers) */
  int unequal;                /* --pressures gave ratios other than 0/1 */
  double tip_load[3];         /* N, base frame (--tip-load) */
  const char* calibration;    /* --calibration (rod, strain), NULL = default */
  int cal_rule;               /* --cal-rule (rod, strain): csrCalRule of an FE mode table, -1 =
                                 default */
  unsigned cal_drop;          /* --cal-drop (rod, strain): CSR_CAL_DROP_* parts left out, 0 = none */
  int links;                  /* --links (strain): bending modes per segment, 0 = the level's */
  csBendSolver* solver;       /* analytic, rod, strain: the library's solver during a sweep
                                 (core/cs_bend.h) */
  double p_ceiling;           /* MPa: --until-angle searches up to max(p-max, this); NAN: 2 MPa */
  double fibre_size;          /* fe: l_fibre, mm (NAN: the model's default, l_soft / 8) */
  int fibre_split;            /* fe: 1 fibre elements split at element faces, 0 20-node ties,
                                 -1 the model's default */
  int fibre_tension_only;     /* fe: 1 tension-only fibre law, 0 linear (tension and
                                 compression), -1 the model's default (tension-only) */
  int segments;               /* fe: 1 the paper's single segment (II1 alone, its Table 1 and
                               * Fig. 3a), 3 (default, -1 unset) the whole actuator */
  int mesh_symmetric;         /* fe: 1 the mesh with the section's symmetry, 0 the whole-body
                                 mesh, -1 the model's default (0) */
  int branch_switch;          /* fe: 1 try to leave the path at a bifurcation along the critical
                                 mode, 0 stay on it, -1 the model's default (0) */
  double p_indefinite;        /* fe: first converged pressure with an indefinite tangent (NAN) */
  int neg_pivots_max;         /* fe: most negative pivots on the path (-1: LU) */
  int threads;                /* fe: --threads N (0: the thread plan's default, fem_threads.h) */
  const char* rom_basis;      /* rom: --rom-basis FILE (tools/rom_basis.py), required */
  const char* rom_weights;    /* rom: --rom-weights FILE (tools/rom_ecsw.py), NULL = every element */
  const char* rom_file;       /* rom: --rom-file LEG.h5 (crawlsim rom leg-file): the basis, weights
                                 and chambers' forms read without gmsh; replaces --rom-basis */
  FILE* table;                /* where the result table goes (the command: stdout; a study's
                                 step: the case's log) */
  FILE* notes;                /* where notes and the FE's progress lines go (stderr; the log) */
} BendRun;

/* What a bend gives back besides its file (read by the study runner instead of the text). */
typedef struct {
  double p_until;        /* MPa at --until-angle; NaN: not asked or not reached */
  double angle_total;    /* deg: the last row's total angle (NaN: no row) */
  double p_end;          /* MPa: the last row's pressure (NaN: no row) */
  char until_line[256];  /* the until-angle line of the table ("" without --until-angle) */
} csxBendResult;

/* Run the bend `run` defines (parsed and checked by the command's parser): write run->out,
 * print the table on run->table and notes on run->notes, fill *res. CS_OK, or a status with
 * err filled (the rows so far stay in the file). */
csStatus csx_bendExecute(BendRun* run, csxBendResult* res, csError* err);

/* res's numbers from a finished sweep's curve */
void csx_bendResultFill(const BendRun* run, const csrBendCurve* bc, csxBendResult* res);

/* The full FE model's sweep of `run` (fem_bend.h: adaptive load stepping over the whole sweep,
 * --until-angle found by the load stepping itself): writes run->out, prints the table on
 * run->table and the FE's report lines on run->notes, fills *res. CS_OK or a status with err.
 * Only in builds with the FE (CS_HAVE_FEM). */
csStatus csx_bendFe(BendRun* run, csxBendResult* res, csError* err);

/* The reduced-order FE model's sweep of `run` (fem/fem_rom_act.h: reduced statics by Newton on
 * the basis' coordinates, each row ramped from the last), written with the FE's output contract
 * (csr_bendCurveWriteH5) plus the rom's attributes. Returns the exit status. Only with the FE. */
csStatus csx_bendRom(BendRun* run, csxBendResult* res, csError* err);

/* End a bend file whatever happened: after a failure (st != CS_OK) the model's name and the
 * rows so far are written too (they reach the disk unless it refused already), the status
 * says how the sweep ended, and the file is closed checked. Returns the final status: st, or the
 * close's failure after a good sweep (err then filled by it). */
csStatus csx_bendFileClose(csH5File* f, const char* model, const csrBendCurve* bc, csStatus st,
                           csError* err);

/* The command's exit status for a bend that ended with st (!= CS_OK): 1, or 128 + the signal
 * when interrupted (130 when only gmsh saw Ctrl-C, system() ignoring SIGINT). */
int csx_bendExitCode(csStatus st);

#endif /* CS_TOOLS_CMD_BEND_H */
