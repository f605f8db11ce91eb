/* fem_material.h: the constitutive laws of the full FE model (material layer).
 *
 * Owns: csfMaterial (Yeoh constants, bulk modulus, density, incompressibility treatment), the
 * deviatoric Yeoh law W(F) with its first Piola-Kirchhoff stress and consistent tangent, and the
 * fibre law S(E) of the embedded trusses. Pure functions of local arrays: no mesh, no model.
 * Units: MPa, t/mm^3. Tensors are 3x3 row-major (index 3i + J); fourth-order tangents are 9x9
 * (index (3i+J)*9 + 3k+L). */
#ifndef CS_FEM_MATERIAL_H
#define CS_FEM_MATERIAL_H

#ifdef __cplusplus
extern "C" {
#endif

/* Incompressibility treatment. */
typedef enum csfFormulation_ {
  CSF_FORM_MIXED_P0 = 0,     /* P2 displacement / P0 pressure+dilatation per element, condensed */
  CSF_FORM_DISPLACEMENT = 1, /* plain P2 displacement with pointwise U(J): locks when kappa >> mu */
} csfFormulation;

/* Ratio of bulk to initial shear modulus, kappa / mu0 with mu0 = 2 C10 (MPa/MPa). 2000 gives an
 * initial Poisson ratio 0.49975; results change by < 0.1 % between 1000 and 10000 (see tests). */
#define CSF_KAPPA_RATIO 2000.0

typedef struct csfMaterial_ {
  double C10, C20;     /* Yeoh constants of W = C10 (I1b - 3) + C20 (I1b - 3)^2, MPa */
  double kappa;        /* bulk modulus of U(J) = kappa/2 (J - 1)^2, MPa */
  double kappa_pt;     /* mixed form only: extra pointwise bulk term kappa_pt/2 (J - 1)^2, MPa */
  double rho;          /* density, t/mm^3 (gravity only) */
  csfFormulation form; /* incompressibility treatment */
} csfMaterial;

/* Material with kappa = CSF_KAPPA_RATIO * 2 C10 and the mixed formulation. */
csfMaterial csf_materialDefault(double C10, double C20, double rho);

/* Deviatoric Yeoh energy of a deformation gradient F (3x3 row-major): W (MPa), first
 * Piola-Kirchhoff stress P (9, MPa) and tangent A = dP/dF (81, index (3i+J)*9 + 3k+L), either
 * output may be NULL. Returns J = det F; J <= 0 leaves P and A untouched. */
double csf_yeohDev(double C10, double C20, const double F[9], double* W, double P[9],
                   double A[81]);

/* Half width delta of the smoothed tension-only fibre law (Green strain): the force at E = 0 is
 * EA delta / 4 = 0.1 N for Kevlar, r = 0.0889 mm. Also the zone limits the Newton monitor counts
 * (slack E <= -delta, smoothing |E| < delta, taut E >= delta). */
#define CSF_FIBRE_SLACK 5e-4

/* Fibre stress measure S(E) (strain units; force = EA S) and S'(E) at Green strain E: linear
 * (S = E, both ways) or, with `tension_only`, the C1 smoothed tension-only law S = E above
 * +delta, (E + delta)^2 / (4 delta) in |E| < delta, 0 below -delta (no on/off chatter). */
void csf_fibreLaw(int tension_only, double E, double* S, double* dS);

/* det and inverse of a 3x3 row-major matrix; returns det (0: Fi untouched). */
double csf_inv3(const double F[9], double Fi[9]);

#ifdef __cplusplus
}
#endif
#endif /* CS_FEM_MATERIAL_H */
