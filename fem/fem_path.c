/* fem_path.c: volume-controlled continuation past pressure limit points (see fem_path.h).
 *
 * Rationale. Under pressure control a limit point shows as a load step that collapses: past the
 * maximum there is no nearby equilibrium at a higher pressure. Prescribing the chamber volume
 * instead makes the path single-valued through the maximum (Crisfield 1991, Sec. 9.4, with the
 * chamber volume as the constraint; for a fluid-filled chamber this is also what a volume- or
 * mass-controlled supply does). The constraint is the weighted sum over all pressurised chambers;
 * where several chambers in parallel could balloon alone, the path follows the one the mesh
 * and geometry favour, as a real actuator does. */
#include "fem_path.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

/* "not a limit point": this many consecutive rising volume steps, ending this fraction above the
 * pressure where pressure control gave up */
#define CSF_PATH_RISING 5
#define CSF_PATH_RISE 0.01

csfLimitOptions csf_limitDefault(void) {
  csfLimitOptions o;
  memset(&o, 0, sizeof o);
  o.max_steps = 200;
  o.max_vol_ratio = 20.0;
  o.min_dv_rel = 1e-4;
  return o;
}


csStatus csf_passLimit(const csfModel* m, csfData* d, double* s_prev, double* s_conv,
                       double* s_tmp, double V_prev, double V_conv, double p_conv,
                       const csfNewtonOptions* nopt, const csfLimitOptions* opt,
                       csfLimitResult* res, csError* err) {
  const size_t ns = csf_stateSize(m);
  memset(res, 0, sizeof *res);
  res->p_limit = p_conv;
  res->V_limit = V_conv;
  res->p_resume = NAN;
  res->p_before = p_conv;
  /* first volume step: the last pressure step's volume change (large near the limit, where
   * dV/dp grows without bound) */
  const double dV0 = V_conv > V_prev ? V_conv - V_prev : 1e-3 * fabs(V_conv);
  double dV = dV0, V = V_conv, Vp = V_prev, p_last = p_conv;
  int fell = 0, rising = 0;
  csError lerr = {0};
  for (;;) {
    if (res->n_steps >= opt->max_steps || V > opt->max_vol_ratio * fabs(V_conv)) {
      csf_stateSet(m, d, s_conv);
      return cs_errorSet(err, CS_ERR_DIVERGED, "fem: no stable branch above the limit %.6g MPa "
                         "within %d volume steps / %.3g x the volume (at %.6g MPa)",
                         res->p_limit, res->n_steps, V / V_conv, p_last);
    }
    const double t0 = csf_wallTime();
    const double Vt = V + dV;
    const double f = V > Vp ? (Vt - V) / (V - Vp) : 0.0; /* secant predictor in the volume */
    for (size_t i = 0; i < ns; i++) {
      s_tmp[i] = s_conv[i] + f * (s_conv[i] - s_prev[i]);
    }
    csf_stateSet(m, d, s_tmp);
    int it = 0;
    const csStatus st = csf_newtonSolveVolume(m, d, Vt, nopt, &it, &lerr);
    res->n_newton += it;
    if (st != CS_OK) {
      dV *= 0.5;
      if (dV < opt->min_dv_rel * dV0) {
        csf_stateSet(m, d, s_conv);
        return cs_errorSet(err, CS_ERR_DIVERGED, "fem: volume step collapsed at %.6g MPa past "
                           "the limit %.6g MPa: %.200s", p_last, res->p_limit, lerr.msg);
      }
      continue;
    }
    res->n_steps++;
    const double pl = d->load;
    memcpy(s_prev, s_conv, ns * sizeof(double));
    csf_stateGet(m, d, s_conv);
    Vp = V, V = Vt;
    csfPathPoint pt = {pl, pl - p_last, Vt, it, csf_wallTime() - t0, 0, 0};
    if (!fell && pl >= res->p_limit) {
      res->p_limit = pl, res->V_limit = Vt;
      pt.is_max = 1;
    } else if (pl < res->p_limit) {
      fell = 1;
    }
    pt.past_limit = fell;
    res->fell = fell;
    res->p_before = p_last;
    p_last = pl;
    if (opt->callback && opt->callback(opt->user, m, d, &pt)) {
      res->stopped = 1;
      return CS_OK;
    }
    if (fell && pl > res->p_limit) {
      res->p_resume = pl;
      return CS_OK;
    }
    /* still rising well above where pressure control gave up: that was no limit point (Newton
     * failed for another reason), the path is stable under pressure control */
    rising = pt.dp > 0 ? rising + 1 : 0;
    if (!fell && rising >= CSF_PATH_RISING && pl > (1.0 + CSF_PATH_RISE) * p_conv) {
      res->p_resume = pl;
      res->no_limit = 1;
      return CS_OK;
    }
    if (it <= 5) {
      dV = fmin(1.5 * dV, 8.0 * dV0);
    } else if (it > 10) {
      dV *= 0.7;
    }
  }
}
