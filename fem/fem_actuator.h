/* fem_actuator.h: the FE model of one 3D-FRSPA actuator (set-up layer between meshing and the
 * solvers).
 *
 * Owns: csfActuatorFE, what every actuator computation starts from: the Tet10 mesh of the
 * parametric geometry (fem_mesh.h, through gmsh), the model with its clamped base, the chamber
 * pressures per unit load factor (any pressure ratio per chamber and segment), the embedded
 * double-helix fibres, gravity and a dead tip force, and the measurement gauges
 * (fem_measure.h). The pressure sweeps (fem_bend.h) and the calibration (fem_calibration.h)
 * build one and then only change its load. Units: mm, MPa, N, s. */
#ifndef CS_FEM_ACTUATOR_H
#define CS_FEM_ACTUATOR_H

#include "core_status.h"
#include "fem_measure.h"
#include "fem_model.h"
#include "robot_actuator.h"

#ifdef __cplusplus
extern "C" {
#endif

/* How to discretise and load the actuator. */
typedef struct csfActuatorSpec_ {
  double ratio[CSR_NSEG][CSR_NCHAMBER]; /* pressure of chamber Omega_j of segment s per unit
                                         * load factor (MPa/MPa); 0 = vented */
  double mesh_size;    /* l_soft, mm */
  double fibre_size;   /* l_fibre, mm (0: l_soft / 8, fem_actuator.c) */
  int fibres;          /* 1 = embed the double-helix fibres (n turns per segment) */
  int fibre_compression; /* 1: linear in tension and compression; 0: smoothed tension-only */
  int fibre_geo_tension; /* 1: fibre geometric stiffness only in tension (modified tangent) */
  int fibre_split;     /* 1: fibre elements split at element faces (csfModel.fib_split) */
  int mesh_symmetric;  /* 1: the mesh has the square section's eight symmetries (an eighth
                        * meshed, mirrored and turned, csf_meshActuatorSymmetric); 0: gmsh's mesh
                        * of the whole body */
  int fibre_turn;      /* the helices' common start turned about the leg axis by this many
                        * quarter turns (-3..3; 0: both start on +e1, the model's layout). A
                        * check of the FE's symmetry: with it a turned chamber pattern is the
                        * exact image of the unturned one but for the mesh */
  csfFormulation form; /* element formulation */
  double gravity[3];   /* mm/s^2 in the base frame (zeros = off) */
  double tip_force[3]; /* N, dead load on the tip face (uniform traction), base frame */
  const char* work_stem; /* path prefix for the .geo/.msh/.log files */
  int mpi_ranks;       /* MPI ranks the factorisation is spread over (0 or 1: this process) and */
  int mpi_ranks_local; /* how many of them run on this machine: the memory estimate that refuses
                        * a too-fine mesh compares this machine's share of the factors,
                        * bytes x local / ranks, with its memory */
} csfActuatorSpec;

/* Chambers Omega1 & Omega2 of every segment at ratio 1, l_soft 4, fibres (tension-only,
 * consistent tangent, split), mixed formulation, no gravity, no tip force, stem "crawlsim_fe". */
csfActuatorSpec csf_actuatorSpecDefault(void);

/* l_fibre the spec resolves to, mm: fibre_size, or l_soft / 8 when fibre_size is 0. */
double csf_actuatorFibreSize(const csfActuatorSpec* sp);

typedef struct csfActuatorFE_ {
  csfMesh* mesh;
  csfModel* model;
  csfGauges* gauges;
  double tip_area;     /* reference area of the tip face, mm^2 */
  double* tip_unit;    /* (ndof) nodal weights w_a / A of a unit uniform traction on the tip face
                        * (times a force vector: the dead load's nodal forces) */
  double axis[3];      /* reference bending axis: e3 x (away from the pressure centroid), or e2
                        * when the chambers are balanced (elongation) */
  int ncham;           /* pressurised chambers */
} csfActuatorFE;

/* The thinnest walls of the section (mm): between a chamber and the outer surface (straight side
 * or fillet corner), between two adjacent chambers, and the solid caps c at the chamber ends. */
typedef struct csfWalls_ {
  double outer, between, cap;
  double mesh;   /* element size the mesher uses at the chamber walls, mm */
} csfWalls;

void csf_actuatorWalls(const csrActuator* act, double l_soft, csfWalls* w);

/* Walls thinner than this fraction of the chamber-wall element size cannot be resolved by the
 * mesh (fewer than 1/10 of an element across): refused at set-up with the parameters named. */
#define CSF_WALL_MIN_REL 0.1

/* What a mesh of size l_soft costs, estimated before gmsh runs (set-up refuses a mesh whose
 * factorisation would not fit in memory). Tet10 count V / (0.2 l³) (V the solid volume): a
 * lower bound, since gmsh's mean element volume was measured at 0.16-0.19 l³ (the short
 * actuator at 1.5 mm, the baseline at 1.5 and 1.2 mm: test_fem_actuator) and the chamber walls'
 * finer elements (csfWalls.mesh) add more, dominating at l_soft >= 2 mm; 1.6 nodes per Tet10
 * (1.59-1.67 measured there); the LDLᵀ factor's entries grow as dofs^(4/3) (3D nested
 * dissection), scaled from the baseline at l_soft 4 (3.4e7 entries for 75 801 dofs); memory
 * 20 bytes per entry (MUMPS's factor and workspace: ~0.68 GB there, 0.6 GB measured peak RSS
 * of its 360 deg run). */
typedef struct csfMeshEstimate_ {
  double volume;   /* solid volume, mm³ */
  double tet10;    /* elements, at least */
  double nodes;    /* about */
  double dofs;
  double entries;  /* factor entries */
  double bytes;    /* memory of one factorisation, B */
} csfMeshEstimate;

void csf_actuatorEstimate(const csrActuator* act, double l_soft, csfMeshEstimate* e);

/* Mesh the actuator and build its model (not finalised data: csf_dataCreate is the caller's).
 * Returns CS_OK or an error naming the cause (invalid parameters, a mesh whose factorisation
 * would not fit in this machine's memory (csf_actuatorEstimate, refused before gmsh runs), gmsh
 * failure, a chamber without faces, a fibre point outside the body). */
csStatus csf_actuatorFECreate(const csrActuator* act, const csfActuatorSpec* spec,
                              csfActuatorFE* fe, csError* err);
void csf_actuatorFEDestroy(csfActuatorFE* fe);

/* The same from a mesh and a finalised model built elsewhere (a reduced leg's file,
 * robot/rom/robot_rom_file.h: no gmsh): fe takes both (csf_actuatorFEDestroy frees them, also on
 * failure) and gets the tip face's weights, the gauges, the pressurised chambers' count and the
 * bending axis of spec->ratio (the model's loads are left as they are). */
csStatus csf_actuatorFEFromModel(const csrActuator* act, const csfActuatorSpec* spec,
                                 csfMesh* mesh, csfModel* model, csfActuatorFE* fe,
                                 csError* err);

/* Set the dead tip force (N, base frame) on the model's f_dead (replaces the previous one). */
void csf_actuatorSetTipForce(csfActuatorFE* fe, const double F[3]);

#ifdef __cplusplus
}
#endif
#endif /* CS_FEM_ACTUATOR_H */
