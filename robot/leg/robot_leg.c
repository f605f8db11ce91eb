/* robot_leg.c: a leg level's own settings by name (robot_leg.h csrLegSetting): each level
 * declares its settings with defaults and ranges in its table of operations, so that the run
 * definition and the command line set them by name and refuse a setting for a level that has
 * none of that name, without knowing the levels (docs/design.md "Model levels"); and what
 * every level shares: the leg's default material parameters and its section's second moment. */
#include <math.h>
#include <string.h>

#include "robot_analytic.h"
#include "robot_leg.h"


const csrLegSetting* csr_legSettingFind(const csrLegType* T, const char* name) {
  for (int i = 0; T && name && i < T->nsettings; i++) {
    if (!strcmp(T->settings[i].name, name)) {
      return &T->settings[i];
    }
  }
  return NULL;
}


void csr_legSettingsDefault(const csrLegType* T, csrLegSettings* s) {
  memset(s, 0, sizeof *s);
  s->type = T;
  for (int i = 0; T && i < T->nsettings && i < CSR_LEG_MAX_SETTINGS; i++) {
    s->v[i] = T->settings[i].value;
  }
}


void csr_legSettingsRead(const csrLegType* T, const csrLegSettings* s, double* v) {
  csrLegSettings d;
  /* a settings block of another table of operations with the same settings (a wrapper of the
   * level, as bench_strain_driver's timed copy) is the level's own */
  if (!s || !T || !s->type || (s->type != T && s->type->settings != T->settings)) {
    csr_legSettingsDefault(T, &d);
    s = &d;
  }
  memcpy(v, s->v, sizeof s->v);
}


csStatus csr_legSettingSet(const csrLegType* T, csrLegSettings* s, const char* name, double v,
                           csError* err) {
  const csrLegSetting* k = csr_legSettingFind(T, name);
  if (!k) {
    return cs_errorSet(err, CS_ERR_ARG, "legs %s have no setting %s", T ? T->name : "(none)",
                       name ? name : "(NULL)");
  }
  if (!(v >= k->lo && v <= k->hi) || (k->integer && v != floor(v))) {
    return cs_errorSet(err, CS_ERR_RANGE, "legs %s: %s %g must be %s %g..%g (%s)", T->name, name,
                       v, k->integer ? "a whole number in" : "in", k->lo, k->hi, k->what);
  }
  if (s->type != T) {
    csr_legSettingsDefault(T, s);
  }
  s->v[k - T->settings] = v;
  return CS_OK;
}


double csr_legSettingGet(const csrLegType* T, const csrLegSettings* s, const char* name,
                         double fallback) {
  const csrLegSetting* k = csr_legSettingFind(T, name);
  if (!k) {
    return fallback;
  }
  double v[CSR_LEG_MAX_SETTINGS];
  csr_legSettingsRead(T, s, v);
  return v[k - T->settings];
}


csrLegParams csr_defaultLegParams(const csrActuator* act) {
  csrLegParams p;
  /* small-strain bending modulus of the Yeoh law with the fibres holding λ2 = 1:
   * W ≈ 4 C10 ε^2 -> σ = 8 C10 ε (plane-strain-like modulus, 0.88 MPa for Elastosil) */
  p.E_bend = 8.0 * act->C10;
  /* material damping as a Kelvin-Voigt time constant. Silicone's loss is nearly rate
   * independent (loss factor η ~ 0.1-0.2) and the air in chambers and tubes adds more; a
   * time constant τ gives the loss factor ω τ at frequency ω, so τ is chosen for η ≈ 0.3 at
   * the hanging leg's first bending mode, ω1 = 3.516 sqrt(EI / (m' L^4)) ≈ 15 rad/s:
   * τ = 0.3 / 15 = 0.02 s. The 100 Hz link modes are then over-damped, which the implicit
   * joint springs handle at any step. With 5 ms the leg swung for seconds after each move. */
  p.damping_time = 0.02;
  /* the leg's half side: the capsules fill the square section's inscribed circle */
  p.contact_radius = act->a;
  return p;
}


/* second moment of area (mm^4) of the chambered section about a principal axis: the analytic
 * model's exact section quadrature (robot_analytic.h), so every level shares one section */
double csr_legSectionI(const csrActuator* a) {
  csrSectionProps sp;
  if (csr_analyticSectionCompute(a, NULL, &sp, NULL) != CS_OK) {
    return NAN; /* invalid actuator: a level validates it before use */
  }
  return sp.I_holed;
}
