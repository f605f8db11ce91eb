/* robot_sway.h: the sway-buckling load of one leg from its tip compliance (issue 34, the Earth
 * stance's check, docs/reference.md "sway-buckling").
 *
 * The stance check (core/sim_model.h cs_modelStanceCheck) takes each standing leg as a column
 * clamped at the hip and at a flat foot, the support free to sway: the foot may translate
 * across the leg but not turn (a sway frame of identical columns). Any model of the leg gives,
 * at an axial load P on the straight leg, the 2 x 2 compliance of its tip in one bending plane,
 *   [delta; theta] = C [H; M],  C = [c11 c12; c12 c22],
 * delta the tip's lateral displacement, theta its rotation (or any measure work-conjugate to
 * M), H the lateral force and M the moment. Holding theta = 0 (the flat foot) condenses it to
 * the guided (sway) stiffness
 *   k_sway(P) = 1 / (c11 - c12^2 / c22)   (N/mm),
 * whose first zero in P is the sway-buckling load; the clamped-free column's stiffness is
 * 1 / c11, zero at the cantilever's buckling load. For a uniform Euler-Bernoulli column
 * k_sway = 12 EI / L^3 at P = 0 and P_cr = pi^2 EI / L^2 (the rod's closed form); 1 / c11 =
 * 3 EI / L^3 and P_cr = pi^2 EI / (4 L^2) (Timoshenko and Gere 1961, Sec. 2.1-2.3).
 * Units: N, mm, N mm. */
#ifndef CS_ROBOT_SWAY_H
#define CS_ROBOT_SWAY_H

#ifdef __cplusplus
extern "C" {
#endif

/* k_sway from the compliance c11, c12, c22 (mm/N, 1/N, 1/(N mm)): the guided stiffness, N/mm
 * (negative past the buckling load; NAN when c22 is 0 or the condensed compliance is 0). */
double csr_swayGuided(double c11, double c12, double c22);

/* The first load where a stiffness k(P) tabulated at increasing loads P[0..n) changes sign,
 * by linear interpolation between the two rows around it (k is nearly linear in P: for the
 * uniform column k_sway = 12 EI / L^3 - 1.2 P / L to first order). When k stays positive, the
 * zero of the line through the last two rows (an extrapolation: *extrapolated = 1) or NAN
 * (fewer than two rows, or k not falling there). N. */
double csr_swayZero(int n, const double* P, const double* k, int* extrapolated);

/* The closed forms of the straight uniform column: the sway (clamped-guided) buckling load
 * pi^2 EI / L^2 and the cantilever's pi^2 EI / (4 L^2), N (EI in N mm^2, L in mm). */
double csr_swayEuler(double EI, double L);
double csr_cantileverEuler(double EI, double L);

#ifdef __cplusplus
}
#endif
#endif /* CS_ROBOT_SWAY_H */
