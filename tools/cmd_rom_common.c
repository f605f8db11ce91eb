/* cmd_rom_common.c: what the subcommands of `crawlsim rom` share (cmd_rom_common.h): the
 * actuator from --actuator/--set, the reduced actuator from a basis or a leg file, option
 * parsing (repeatable values, numbers, the built-in rays). The subcommand table is cmd_rom.c. */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cmd_rom_common.h"
#include "cs_opts.h"
#include "fem_rom_act.h"
#include "fem_rom_snap.h"
#include "robot_actuator.h"
#include "robot_rom_file.h"

/* one more repeatable value (--set, --ray) into list[*n]; 1 after one error line when full */
int csx_romPushValue(const char* what, const char* v, const char** list, int* n, int max) {
  if (*n == max) {
    fprintf(stderr, "crawlsim rom: more than %d %s options\n", max, what);
    return 1;
  }
  list[(*n)++] = v;
  return 0;
}

/* is `name` one of the built-in rays? 1, or 0 after one error line */
int csx_romKnownRay(const char* name) {
  csfRomRay rays[CSF_ROM_MAX_RAYS];
  const int nray = csf_romRays(rays, CSF_ROM_MAX_RAYS);
  for (int k = 0; k < nray; k++) {
    if (!strcmp(rays[k].name, name)) {
      return 1;
    }
  }
  fprintf(stderr, "crawlsim rom: --ray '%s': no such ray (see crawlsim rom snapshots --list)\n",
          name);
  return 0;
}

/* an operand where a subcommand takes none: one error line */
int csx_romUnexpected(const csxOptTable* t, const char* a) {
  fprintf(stderr, "crawlsim %s: unexpected argument '%.200s' (see crawlsim %s --help)\n", t->cmd,
          a, t->cmd);
  return 1;
}

int csx_romParseNumber(const char* flag, const char* v, double lo, double hi, double* out) {
  char* end;
  errno = 0;
  double x = strtod(v, &end);
  if (end == v || *end || errno || !isfinite(x) || x < lo || x > hi) {
    fprintf(stderr, "crawlsim rom: %s '%s' must be a number in [%g, %g]\n", flag, v, lo, hi);
    return 1;
  }
  *out = x;
  return 0;
}


/* the actuator (preset, then every --set) into *act; 1 after one error line */
int csx_romActuator(const char* name, const char* const* sets, int nset, int validate,
                    csrActuator* act) {
  csError err;
  cs_errorClear(&err);
  csStatus st = csr_actuatorPreset(act, name, &err);
  for (int k = 0; k < nset && st == CS_OK; k++) {
    st = csr_actuatorSetString(act, sets[k], &err);
  }
  if (st == CS_OK && validate) {
    st = csr_actuatorValidate(act, &err);
  }
  if (st != CS_OK) {
    fprintf(stderr, "crawlsim rom: %s\n", err.msg);
    return 1;
  }
  return 0;
}


/* the reduced actuator on the snapshots' FE model (csf_romSnapSetup's: every chamber tagged,
 * the symmetric mesh of the basis' l_soft; gmsh's files under work/stem); 1 after one error
 * line */
int csx_romOpen(const char* actname, const char* const* sets, int nset, const char* basis,
                   const char* weights, const char* work, const char* stem_name,
                   csrActuator* act, csfRomActuator* ra) {
  if (csx_romActuator(actname, sets, nset, 0, act)) {
    return 1;
  }
  csError err;
  cs_errorClear(&err);
  const double l = csf_romBasisMeshSize(basis, &err);
  if (isnan(l)) {
    fprintf(stderr, "crawlsim rom: %s\n", err.msg);
    return 1;
  }
  csfActuatorSpec spec = csf_actuatorSpecDefault();
  for (int s = 0; s < CSR_NSEG; s++) {
    for (int j = 0; j < CSR_NCHAMBER; j++) {
      spec.ratio[s][j] = 1.0;
    }
  }
  spec.mesh_size = l;
  spec.mesh_symmetric = 1;
  char stem[620];
  snprintf(stem, sizeof stem, "%.500s/%.60s", work, stem_name);
  spec.work_stem = stem;
  if (csf_romActuatorCreate(act, &spec, basis, weights, ra, &err) != CS_OK) {
    fprintf(stderr, "crawlsim rom: %s\n", err.msg);
    return 1;
  }
  return 0;
}


/* the reduced actuator from a leg file (as bend --model rom --rom-file), its weights replaced
 * by those of `weights` (may be NULL); 1 after one error line */
int csx_romOpenLegFile(const char* actname, const char* const* sets, int nset, const char* path,
                       const char* weights, csrActuator* act, csfRomActuator* ra,
                       double* l_soft) {
  if (csx_romActuator(actname, sets, nset, 0, act)) {
    return 1;
  }
  csError err;
  cs_errorClear(&err);
  csrRomLegFile lf;
  csStatus st = csr_romLegFileRead(path, &lf, &err);
  if (st == CS_OK) {
    st = csr_romLegFileCheckActuator(&lf, path, act, &err);
  }
  if (st == CS_OK) {
    csfActuatorSpec spec = csf_actuatorSpecDefault();
    for (int s = 0; s < CSR_NSEG; s++) {
      for (int j = 0; j < CSR_NCHAMBER; j++) {
        spec.ratio[s][j] = 1.0;
      }
    }
    spec.mesh_size = lf.l_soft;
    spec.mesh_symmetric = 1;
    if (l_soft) {
      *l_soft = lf.l_soft;
    }
    csfMesh* me = lf.mesh;
    csfModel* m = lf.model;
    csfRom* rom = lf.rom;
    lf.mesh = NULL, lf.model = NULL, lf.rom = NULL; /* ra owns them from here */
    st = csf_romActuatorFromModel(act, &spec, me, m, rom, path, ra, &err);
    if (st == CS_OK && weights && (st = csf_romActuatorSetWeights(ra, weights, &err)) != CS_OK) {
      csf_romActuatorDestroy(ra);
    }
  }
  csr_romLegFileFree(&lf);
  if (st != CS_OK) {
    fprintf(stderr, "crawlsim rom: %s\n", err.msg);
    return 1;
  }
  return 0;
}
