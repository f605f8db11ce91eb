/* fem_output.h: FE results and model export: deformed mesh for ParaView (VTU, quadratic
 * tetrahedra with displacement, Cauchy stress, von Mises stress, element dilatation) and the same
 * model as an ABAQUS / CalculiX input deck. Units: mm, MPa, N, t/mm^3. */
#ifndef CS_FEM_OUTPUT_H
#define CS_FEM_OUTPUT_H

#include "core_status.h"
#include "fem_assembly.h"
#include "robot_actuator.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Write the deformed state (points = X + u) as a VTK XML UnstructuredGrid (.vtu, ASCII):
 * point data "displacement" (mm), cell data "cauchy_stress" (xx yy zz xy yz zx, MPa),
 * "von_mises" (MPa), "theta" (v/V). Call after csf_assemble at the state (for d->pel). */
csStatus csf_writeVtu(const csfModel* m, const csfData* d, const char* path, csError* err);

/* Write the model as an ABAQUS input deck (C3D10H body, Yeoh C10 C20 with D1 = 2/kappa, clamped
 * base node set, one element-face surface per pressurised chamber with *DSLOAD at `pressure`
 * MPa, fibres as T3D2 trusses *EMBEDDED in the body, static NLGEOM step). CalculiX reads it with
 * C3D10H replaced by C3D10 (CalculiX has no hybrid elements; see the deck's header). */
csStatus csf_writeInp(const csfModel* m, const csrActuator* act, double pressure,
                      const char* path, csError* err);

#ifdef __cplusplus
}
#endif
#endif /* CS_FEM_OUTPUT_H */
