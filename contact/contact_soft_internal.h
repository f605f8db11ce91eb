/* contact_soft_internal.h: what contact_soft.c (model, state layout, per-shape driver) and
 * contact_soft_law.c (the force and friction kernels) share. Internal: not part of the API.
 *
 * State layout of a shape (cscSoftModel.zoff / nz): its slots' history one after the other;
 *   integrated: capsule slot z (3); foot-point slot z (3); foot-patch slot z (3), phi (1)
 *   step:       every slot anchor a (3), tag (1): -1 free, else the capsule's anchored axis
 *               parameter (foot points: 0). */
#ifndef CS_CONTACT_SOFT_INTERNAL_H
#define CS_CONTACT_SOFT_INTERNAL_H

#include "contact_soft.h"

enum {
  CSC_SOFT_MAX_QUAD = 8, /* Gauss-Legendre points per capsule-box line load */
  CSC_SOFT_MIN_SIDE = 2, /* Gauss-Lobatto sole points per side */
  CSC_SOFT_MAX_SIDE = 5,
  CSC_HF_SAMPLES = 16    /* axis samples of a capsule's stretch on a heightfield (law.c) */
};

/* tag of a slot without an anchor (step mode) */
#define CSC_SOFT_FREE (-1.0)

struct cscSoftModel_ {
  cscSoftParams p;
  cstTerrain terrain; /* copy of the boxes */
  int nshape, nslot, nstate;
  cscShape* shape;    /* (nshape) */
  int* first;         /* (nshape + 1) first slot of each shape */
  int* zoff;          /* (nshape + 1) first history double of each shape */
  int* patch;         /* (nshape) 1: a foot with one patch slot (z, phi) */
  double gl_x[CSC_SOFT_MAX_QUAD], gl_w[CSC_SOFT_MAX_QUAD]; /* Gauss-Legendre on [-1, 1] */
};

/* What one slot collected from its samples (sphere centres or axis points) against boxes. */
typedef struct cscSoftAcc_ {
  double Fn[3];    /* N: sum of the normal forces (with damping) */
  double Fel_n[3]; /* N: sum of the elastic normal forces as vectors */
  double W;        /* N: sum of the elastic force magnitudes */
  double xw[3];    /* N mm: elastic-force-weighted sum of the sample centres */
  double sw;       /* N: elastic-force-weighted sum of the axis parameters (capsules) */
  double muW;      /* N: elastic-force-weighted sum of the touched surfaces' friction */
  double dmax;     /* mm: deepest sample (-INFINITY: no box within reach) */
  int deep;        /* samples whose centre is inside a box */
} cscSoftAcc;

/* The finished contact of one slot. */
typedef struct cscSoftGeom_ {
  double N;    /* N: normal force, projected resultant */
  double n[3]; /* unit normal, terrain -> shape */
  double xc[3]; /* mm: centroid of the sample centres (sphere centres / axis points) */
  double sc;   /* -: axis parameter of xc (capsules) */
} cscSoftGeom;

/* One slot's friction result. */
typedef struct cscSoftFriction_ {
  double ft[3];  /* N: tangential force */
  double T;      /* N mm: torsional couple about the normal (foot patch) */
  double ratio;  /* -: friction ratio of the translational bristle (integrated: u = |z_t| /
                    (mu delta_t); step: s = |z_r + tau_t w| / (mu delta_t)) */
  int sliding;
} cscSoftFriction;

/* nodes (ascending) and weights of n-point Gauss-Legendre quadrature on [-1, 1] */
void csc_softGaussLegendre(int n, double* x, double* w);

/* point and velocity on a capsule's axis at parameter s */
void csc_softAxisPoint(const cscShapeState* st, double s, double x[3], double v[3]);
/* velocity of a point x of a (rigid) foot */
void csc_softFootVelocity(const cscShapeState* st, const double x[3], double v[3]);
/* add force f acting at point x of a shape to its load (capsule: split at axis parameter s) */
void csc_softAddForce(const cscShape* sh, const cscShapeState* st, double s, const double x[3],
                      const double f[3], cscShapeLoad* load);

/* normal line load of one capsule into acc (the slot) and load */
void csc_softCapsuleNormal(const cscSoftModel* m, const cscShape* sh, const cscShapeState* st,
                           cscSoftAcc* acc, cscShapeLoad* load);
/* sole point (i, j) of a foot: sphere centre c (mm) and pressure element A (mm^2) */
void csc_softSolePoint(const cscShape* sh, const cscShapeState* st, int i, int j, double c[3],
                       double* A);
/* normal force of one sole point (centre c, element A) into acc and load; the elastic force
 * against each terrain box near it (in the order of cst_terrainBoxesNear), then against the
 * heightfield when within reach, into el (NULL: not wanted; room for CST_MAX_BOXES + 1);
 * returns how many */
int csc_softSolePointNormal(const cscSoftModel* m, double rho, double A, const double c[3],
                            const cscShapeState* st, cscSoftAcc* acc, cscShapeLoad* load,
                            double* el);
/* a foot's sole points as csc_softSolePointNormal saw them: their centres and elastic forces
 * per near box (npt <= CSC_SOFT_MAX_SIDE^2) */
typedef struct cscSoleLoads_ {
  int npt;
  double c[CSC_SOFT_MAX_SIDE * CSC_SOFT_MAX_SIDE][3];
  int nel[CSC_SOFT_MAX_SIDE * CSC_SOFT_MAX_SIDE];
  double el[CSC_SOFT_MAX_SIDE * CSC_SOFT_MAX_SIDE][CST_MAX_BOXES + 1]; /* + the heightfield */
} cscSoleLoads;
/* second moments of a foot's elastic sole loads (sl, radius rho) about the centroid xc in the
 * plane normal to n: Jel = sum el |r|^2 (N mm^2), R1el = sum el sqrt(|r|^2 + rho^2) (N mm).
 * (It once recomputed every point's box query and distance: the same numbers; reusing them
 * cut the flat road's first 0.8 s on rod legs by 1.5 % of its instructions, callgrind, gs at
 * 1 ms, 7.657e9 -> 7.542e9, and 3.7 % of the settling, all feet down.) */
void csc_softFootTorsionMoments(const cscSoleLoads* sl, double rho, const double xc[3],
                                const double n[3], double* Jel, double* R1el);
/* the law's parameters for one slot's friction: p itself, or (a terrain with friction per
 * surface, terrains_terrain.h) a copy in *buf whose mu is the touched surfaces' mean weighted
 * by their elastic loads, so a slot on one surface takes exactly that surface's mu */
const cscSoftParams* csc_softSlotParams(const cscSoftModel* m, const cscSoftAcc* acc,
                                        cscSoftParams* buf);
/* direction, load and centroid of a slot; returns 1 if it touches */
int csc_softSlotFinish(const cscSoftAcc* acc, cscSoftGeom* g);

/* integrated-mode translational friction of a slot whose contact point moves at vc: fills f
 * and the bristle rate zd (3) from the bristle z (3) */
void csc_softFrictionIntegrated(const cscSoftParams* p, const cscSoftAcc* acc,
                                const cscSoftGeom* g, int touching, const double vc[3],
                                const double z[3], double zd[3], cscSoftFriction* f);
/* integrated-mode torsional friction of a foot patch spinning at wn (rad/s) about the normal,
 * with sole moments Jel, R1el and elastic load W: couple f->T and the rate of phi */
void csc_softFrictionTorsion(const cscSoftParams* p, const cscSoftAcc* acc,
                             const cscSoftGeom* g, int touching, double wn, double Jel,
                             double R1el, double phi, double* phid, cscSoftFriction* f);
/* Step-mode friction of an anchored slot at material point xm moving at vm, anchor a: fills
 * f->ft (N), f->ratio = s below and f->sliding = s > 1.
 *
 * The slot's bristle is a Kelvin-Voigt element (stiffness N / delta_t, dashpot tau_t N /
 * delta_t) in series with a Coulomb slider (the anchor a). Within a step the anchor is fixed,
 * so the bristle's tangential deflection is z_r = (xm - a)_t and its rate the slip rate
 * w = (vm)_t: the stuck bristle's trial force is F_tr = -(N / delta_t) g, with the damped
 * deflection g = z_r + tau_t w. Were the slider to move by da over a step h (backward Euler:
 * at the rate da / h), the force would be -(N / delta_t) (g - (1 + tau_t / h) da); Coulomb's
 * |F| <= mu N with the slip against the force (maximum dissipation) then gives the radial
 * return F = F_tr if |F_tr| <= mu N, else mu N F_tr / |F_tr|, whatever h, since the slip only
 * shortens g along its own direction (the return map of elastoplasticity: Simo & Hughes,
 * Computational Inelasticity, Springer 1998, ch. 1 and 3, the closest-point projection of the
 * trial state onto the admissible set, radial for a disc; for Coulomb friction with a
 * tangential penalty: Wriggers, Computational Contact Mechanics, 2nd ed., Springer 2006). The
 * law smooths that projection with the saturation m it always used (contact_soft_law.c
 * stepSaturation: m(s) = s up to u_elastic, 1 from 2 - u_elastic, a parabola between; C1, so an
 * implicit step's Newton passes converge):
 *   F_t = -(N / delta_t) mu delta_t m(s) g / |g|,   s = |g| / (mu delta_t),
 * so |F_t| <= mu N whatever the slip rate; -(N / delta_t)(z_r + tau_t w) in elastic stick;
 * mu N against g in a slide. (The law was once F_t = -(N / delta_t)(e + tau_t ė)
 * with e = mu delta_t m(u) û, u = |z_r| / (mu delta_t): the saturation of z_r alone, its rate
 * added after it. That is this law's expansion to first order in tau_t w about z_r, and it
 * passes mu N wherever tau_t ė is not small: a foot sliding at 0.5 m/s over an anchor in the
 * parabola has tau_t w = 60 stick ranges.) */
void csc_softFrictionStep(const cscSoftParams* p, const cscSoftGeom* g, const double xm[3],
                          const double vm[3], const double a[3], cscSoftFriction* f);

#endif
