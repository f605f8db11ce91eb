/* robot_leg.c: a leg level's own settings by name (robot_leg.h csrLegSetting): each level
 * declares its settings with defaults and ranges in its table of operations, so that the run
 * definition and the command line set them by name and refuse a setting for a level that has
 * none of that name, without knowing the levels (docs/design.md "Model levels"). */
#include <math.h>
#include <string.h>

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
  if (!s || s->type != T) {
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
