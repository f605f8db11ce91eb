/* fem_rom_snap.h: the full-FE snapshots a reduced-order leg is trained on (issue 34, stage 1).
 *
 * Owns: csfRomRay (one load ray: chamber pressures per segment, gravity and a dead tip force,
 * all scaled together by a ray parameter t in [0, 1]), the built-in ray list (training rays
 * and held-out rays), csf_romSnapRay (the ray solved by the full FE with adaptive steps, each
 * converged output state handed to a callback) and the snapshot files: one HDF5 file per ray
 * (written whole when the ray is done, so a stopped production resumes ray by ray) and one mesh
 * file per snapshot directory (what the offline basis needs: nodes, elements, the clamp).
 *
 * Ray file layout (format CSF_ROM_SNAP_FORMAT):
 *   root attributes: format, name, kind ("train" / "test"), about, status ("complete" or why
 *     the ray ended early), t_end (the last converged t), fe_mesh_size_mm, fe_mesh_symmetric,
 *     fe_fibre_law, fe_newton_rtol, ndof, wall_time_s, newton_iterations, steps, cutbacks;
 *     pressure_end [3,4] (MPa at t = 1), gravity_end [3] (mm/s^2), tip_force_end [3] (N);
 *   datasets t [M] (-), u [M, ndof] (mm, node-major x y z), pressure [M,3,4] (MPa),
 *     gravity [M,3] (mm/s^2), tip_force [M,3] (N), bend [M,3,2] (rad, each segment's bend
 *     vector in its base-face frame, csfSegmentState), stretch [M,3] (-), tip [M,3] (mm),
 *     chamber_volume [M,3,4] (mm^3, the enclosed volume of each chamber).
 * Mesh file (CSF_ROM_MESH_FORMAT): x [nnode,3] (mm), tet [ntet,10], face [nface,6],
 *   face_tag [nface], fixed [ndof] (1 = clamped dof), tip_unit [ndof] (nodal weights of a unit
 *   tip force), rho (attribute, t/mm^3), and the same FE attributes as a ray file.
 * Units: mm, MPa, N, s, rad. Frame: the actuator's base frame, e3 along the leg from the
 * clamped base (fem_actuator.h). */
#ifndef CS_FEM_ROM_SNAP_H
#define CS_FEM_ROM_SNAP_H

#include <signal.h>

#include "core_status.h"
#include "fem_actuator.h"
#include "fem_newton.h"
#include "robot_actuator.h"

#ifdef __cplusplus
extern "C" {
#endif

#define CSF_ROM_SNAP_FORMAT "crawlsim-rom-snapshots 1"
#define CSF_ROM_MESH_FORMAT "crawlsim-rom-mesh 1"
#define CSF_ROM_MAX_RAYS 64
#define CSF_ROM_NAME_SIZE 32
#define CSF_ROM_ABOUT_SIZE 160

typedef enum csfRomRayKind_ {
  CSF_ROM_TRAIN = 0, /* a training ray: its snapshots enter the basis and the element weights */
  CSF_ROM_TEST = 1,  /* held out: never used in training; the reduced model is compared on it */
} csfRomRayKind;

/* One load ray: at ray parameter t the chamber pressures are t p, gravity t g, the tip force
 * t F (all loads grow together from the unloaded leg). */
typedef struct csfRomRay_ {
  char name[CSF_ROM_NAME_SIZE];
  csfRomRayKind kind;
  double p[CSR_NSEG][CSR_NCHAMBER]; /* MPa at t = 1 */
  double gravity[3];   /* mm/s^2 at t = 1, base frame */
  double tip_force[3]; /* N at t = 1, base frame (uniform traction on the tip face) */
  int nout;            /* output states at t = k / nout, k = 1..nout */
  char about[CSF_ROM_ABOUT_SIZE];
} csfRomRay;

/* The built-in ray list (training rays first, then the held-out ones, then the sparse random
 * training rays RS1-RS6 and the squeezed-chamber training rays SQ1-SQ6, appended later so that
 * no earlier ray's draw changed) written to `rays`
 * (capacity cap >= CSF_ROM_MAX_RAYS); returns the count. The random rays are drawn from a
 * fixed seed (fem_rom_snap.c), so the list is the same on every machine. */
int csf_romRays(csfRomRay* rays, int cap);

/* Settings of a snapshot production (shared by every ray of one directory). */
typedef struct csfRomSnapSettings_ {
  double mesh_size;   /* l_soft, mm */
  double newton_rtol; /* Newton's test |R| <= rtol (|f_int| + |f_ext|) */
  int fibre_tension_only; /* 1: the fibres' smoothed tension-only law (the FE's default) */
  int threads;        /* the FE's threads (0: OpenMP's default) */
  double dt_min;      /* smallest step in t before the ray is ended (-) */
  const char* work_stem; /* scratch path prefix of gmsh's files */
  const volatile sig_atomic_t* cancel; /* NULL, or a signal flag: the ray ends after its step */
  /* optional, after every converged step: the ray, t, its Newton iterations and wall time (s) */
  void (*progress)(void* user, const char* ray, double t, int iters, double wall);
  void* progress_user;
} csfRomSnapSettings;

csfRomSnapSettings csf_romSnapDefault(void);

/* What a ray's solve did. */
typedef struct csfRomSnapInfo_ {
  double t_end;        /* last converged t */
  int complete;        /* 1: t reached 1 */
  int steps, cutbacks; /* converged steps, failed attempts */
  long newton;         /* Newton iterations */
  double wall;         /* s */
  char why[CS_ERROR_MSG_SIZE]; /* why the ray ended early ("" when complete) */
} csfRomSnapInfo;

/* Called at every output state of a ray (t = k / nout) with the converged model and data. */
typedef csStatus (*csfRomSnapSink)(void* user, const csfActuatorFE* fe, const csfData* d,
                                   double t, csError* err);

/* The FE model a snapshot production solves on: the actuator's mesh (symmetric), every chamber
 * tagged for pressure (csf_romSnapRay sets their values ray by ray), fibres, no loads. The
 * caller destroys fe (csf_actuatorFEDestroy) and the data (csf_dataDestroy). */
csStatus csf_romSnapSetup(const csrActuator* act, const csfRomSnapSettings* s, csfActuatorFE* fe,
                          csfData** d, csError* err);

/* Solve one ray from the unloaded state `s0` (csf_stateGet of the fresh data) with adaptive
 * steps in t (grow after easy steps, halve on failure down to s->dt_min, a secant predictor on
 * the whole Newton state). Each output state goes to `sink`. Returns CS_OK also when the ray
 * ended early at a step that did not converge (info->complete = 0, info->why says why); a
 * sink's failure or a cancel is returned as such. fe's loads are left at the ray's last state. */
csStatus csf_romSnapRay(csfActuatorFE* fe, csfData* d, const double* s0, const csfRomRay* ray,
                        const csfRomSnapSettings* s, csfRomSnapSink sink, void* user,
                        csfRomSnapInfo* info, csError* err);

/* Write the mesh file of a snapshot directory (layout above). */
csStatus csf_romMeshWrite(const csfActuatorFE* fe, const csfRomSnapSettings* s, const char* path,
                          csError* err);

/* Solve `ray` and write its file at `path` (truncated; complete when this returns CS_OK). */
csStatus csf_romSnapRun(csfActuatorFE* fe, csfData* d, const double* s0, const csrActuator* act,
                        const csfRomRay* ray, const csfRomSnapSettings* s, const char* path,
                        csfRomSnapInfo* info, csError* err);

/* What a ray file holds besides the displacements (csf_romSnapRead). */
#define CSF_ROM_MAX_OUT 16
typedef struct csfRomSnapFile_ {
  csfRomRay ray;       /* name, kind, end loads, nout (= m) */
  int m;               /* output states */
  double t[CSF_ROM_MAX_OUT];
  double bend[CSF_ROM_MAX_OUT][CSR_NSEG][2]; /* rad */
  double tip[CSF_ROM_MAX_OUT][3];            /* mm */
  double vol[CSF_ROM_MAX_OUT][12];           /* mm^3 */
  double wall;         /* the FE's wall time of the ray, s */
  double newton;       /* its Newton iterations */
} csfRomSnapFile;

/* Read a ray file's loads and measurements (not u). */
csStatus csf_romSnapRead(const char* path, csfRomSnapFile* s, csError* err);

/* The enclosed volume of every chamber (segment s, chamber j at 4 s + j; mm^3) at the
 * displacement u (ndof, mm): the sum of csf_faceKernel's shares over the chamber's faces. */
void csf_romChamberVolumes(const csfMesh* me, const double* u, double vol[12]);

/* 1 when `path` is a finished ray file of `ray` with the settings `s` (a resumed production
 * skips it), 0 otherwise. */
int csf_romSnapDone(const char* path, const csfRomRay* ray, const csfRomSnapSettings* s);

#ifdef __cplusplus
}
#endif
#endif /* CS_FEM_ROM_SNAP_H */
