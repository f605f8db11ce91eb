/* robot_rom_file.h: the `rom` leg level's file (format "crawlsim-rom-leg 1", written by
 * `crawlsim rom leg-file`, tools/cmd_rom_legfile.c) read back into a reduced model, without
 * gmsh and without the chambers' tensors' computation.
 *
 * Owns: csrRomLegFile (the mesh, the FE model of the kernels, the reduced model csfRom with its
 * weights, pressure basis and chambers' cubic forms, the sole's nodes, the actuator's
 * signature) and its read, free and actuator check.
 * The file (HDF5; integers stored as doubles; row-major):
 *   /mesh/x [nnode, 3] mm, /mesh/tet [ntet, 10] (VTK order), /mesh/face [nface, 6],
 *   /mesh/face_tet [nface], /mesh/face_tag [nface], /mesh/fixed [3 nnode] (1: clamped dof);
 *   /fibre/node [nfib, 20], /fibre/coef [nfib, 20], /fibre/L0 [nfib] mm, /fibre/EA [nfib] N
 *   (fem_model.h; absent: no fibres);
 *   /V [3 nnode, n] (the basis, hip frame: the clamped face at z = 0, the leg along +z, the
 *   chambers' layout in x, y as docs/reference.md's e1, e2); /P [ntet, m] (the mixed model's
 *   element pressure basis, when m > 0); /Qf [nfib, mf] (the mixed fibre field's strain
 *   basis, fem_rom.h csfRom.mf; absent: the FE's fibres; factored over the kept fibres);
 *   /weights/{tet,fibre,face}_{id,w}: the kept elements of each set and their weights;
 *   /chambers/face_ch [nface] (0..11 = 4 s + j, -1), /chambers/V0 [12] mm^3,
 *   /chambers/g0 [12, n], /chambers/H [12, n + 1, n, n] (fem_rom.h csfRom's cubic forms);
 *   /sole [nsole] the tip face's nodes; /actuator [na] the actuator's parameters in
 *   csr_actuatorVisit's order, named by the attribute actuator_names (comma-separated);
 *   attributes format, n, m, mf, C10, C20, kappa, kappa_pt, rho, form, fib_tension_only,
 *   fib_geo_tension, fib_split, mass_t, fe_mesh_size_mm, basis, weights, status ("complete").
 * Units: mm, MPa, N, t. */
#ifndef CS_ROBOT_ROM_FILE_H
#define CS_ROBOT_ROM_FILE_H

#include "core_status.h"
#include "fem_rom.h"
#include "robot_actuator.h"

#ifdef __cplusplus
extern "C" {
#endif

#define CSR_ROM_FILE_FORMAT "crawlsim-rom-leg 1"
#define CSR_ROM_FILE_NAMES 512 /* room for the actuator's parameter names */
#define CSR_ROM_FILE_MAXACT 64

typedef struct csrRomLegFile_ {
  csfMesh* mesh;      /* owned */
  csfModel* model;    /* owned: the FE model of the kernels (finalised; no solver) */
  csfRom* rom;        /* owned: weights, pressure basis and chamber forms set */
  int nsole;
  int* sole;          /* (nsole) the sole's nodes */
  double mass;        /* t, rho times the mesh's volume */
  double l_soft;      /* mm, the mesh size it was built on */
  int nact;
  double act[CSR_ROM_FILE_MAXACT];   /* the actuator's parameters */
  char act_names[CSR_ROM_FILE_NAMES];
  char basis[256], weights[256];     /* where V and the weights came from (information) */
} csrRomLegFile;

/* Read `path` into *lf (zeroed first). Every failure is a one-line error naming the file and
 * the cause (not a leg file, a missing or misshaped dataset, an index out of range, a
 * non-finite value), *lf freed. */
csStatus csr_romLegFileRead(const char* path, csrRomLegFile* lf, csError* err);
void csr_romLegFileFree(csrRomLegFile* lf); /* NULL-safe; leaves *lf zeroed */

/* Write the file of `rom` (its FE model and mesh, weights, pressure and fibre strain bases and
 * the twelve chambers' forms: csf_romChamberTensors with nch = 12), the sole's nodes, the
 * actuator it was built for, the mesh size and the names of the basis and weights files
 * (information; may be NULL). The file is complete on CS_OK (attribute status "complete"). */
csStatus csr_romLegFileWrite(const char* path, const csfRom* rom, int nsole, const int* sole,
                             const csrActuator* act, double l_soft, const char* basis,
                             const char* weights, csError* err);

/* CS_OK when `act`'s parameters are those the file was built for (relative 1e-9), else
 * CS_ERR_ARG naming the first that differs, both values and the file. */
csStatus csr_romLegFileCheckActuator(const csrRomLegFile* lf, const char* path,
                                     const csrActuator* act, csError* err);

#ifdef __cplusplus
}
#endif
#endif /* CS_ROBOT_ROM_FILE_H */
