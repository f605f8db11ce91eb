/* cmd_rom_legfile.c: `crawlsim rom leg-file`: one HDF5 file holding everything the `rom` leg
 * level needs (robot/rom/robot_rom_file.h, format "crawlsim-rom-leg 1"), built here where gmsh
 * may run: the actuator is meshed again on the basis' mesh (fem_rom_act.h checks its
 * signature), the reduced model is made with the weights when given, and its chambers' cubic
 * forms are computed once (the set-up's dominant cost) and written, so that a run reads the
 * file and builds its reduced model without gmsh or the tensors' n + 1 passes. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cmd_rom_common.h"
#include "core_clock.h"
#include "cs_opts.h"
#include "fem_rom_act.h"
#include "robot_actuator.h"
#include "robot_rom_file.h"

static const csxOpt kLegOpts[] = {
    {"--basis", "BASIS.h5", NULL,
     "the reduced basis of tools/rom_basis.py (required unless --leg-file)"},
    {"--leg-file", "SRC.h5", "none",
     "another leg file instead of --basis (its every-element model, say): its model read back "
     "without gmsh and the chamber forms' n + 1 passes, --weights then replacing its sets' "
     "weights; the hyper-reduced leg files of one basis from one set-up"},
    {"--weights", "W.h5", "none (every element at weight 1)",
     "the ECSW element weights of tools/rom_ecsw.py for that basis"},
    {"--out", "LEG.h5", NULL, "the leg file (required)"},
    {"--work", "DIR", ".", "where gmsh's files of the basis' mesh are written"},
    ROM_OPT_ACTUATOR,
    ROM_OPT_SET,
};

static const csxOptTable kLegTable = {
    "rom leg-file", "",
    "One HDF5 file with the reduced leg of a basis: the FE mesh (nodes, Tet10s, boundary faces "
    "and their tags), the clamp, the fibre elements, the basis V, the element pressure basis P, "
    "the kept elements and their weights, the chambers' pressure loads in closed form (cubic "
    "forms of q), the sole's nodes, the mass and the actuator's parameters it was built for. "
    "`crawlsim run --legs rom --rom-file LEG.h5` reads it (robot/rom/robot_rom_file.h).",
    kLegOpts, CSX_NOPT(kLegOpts), NULL};

int csx_cmdRomLegFile(int argc, char** argv) {
  const char* basis = NULL, *weights = NULL, *out = NULL, *work = ".", *actname = "leg";
  const char* src = NULL;
  const char* sets[CSX_ROM_MAX_SETS];
  int nset = 0;
  csxOptIter it;
  csx_optBegin(&it);
  for (csxOptKind k; (k = csx_optNext(&kLegTable, argc, argv, &it)) != CSX_OPT_END;) {
    const int end = csx_optReport(&kLegTable, k, &it);
    if (end >= 0) {
      return end;
    }
    if (k == CSX_OPT_OPERAND) {
      return csx_romUnexpected(&kLegTable, it.value);
    }
    const char* v = it.value;
    if (csx_optIs(it.opt, "--basis")) {
      basis = v;
    } else if (csx_optIs(it.opt, "--leg-file")) {
      src = v;
    } else if (csx_optIs(it.opt, "--weights")) {
      weights = v;
    } else if (csx_optIs(it.opt, "--out")) {
      out = v;
    } else if (csx_optIs(it.opt, "--work")) {
      work = v;
    } else if (csx_optIs(it.opt, "--actuator")) {
      actname = v;
    } else if (csx_optIs(it.opt, "--set") &&
               csx_romPushValue("--set", v, sets, &nset, CSX_ROM_MAX_SETS)) {
      return 1;
    }
  }
  if ((!basis && !src) || !out) {
    fprintf(stderr, "crawlsim rom: leg-file needs --basis and --out, or --leg-file and --out (see "
            "crawlsim rom leg-file --help)\n");
    return 1;
  }
  if (basis && src) {
    fprintf(stderr, "crawlsim rom: leg-file: --basis and --leg-file together: the model comes "
            "from one of them\n");
    return 1;
  }
  if (src && !strcmp(src, out)) {
    fprintf(stderr, "crawlsim rom: leg-file: --out %s is the --leg-file it is read from\n", out);
    return 1;
  }
  const double w0 = csu_wallSeconds();
  csrActuator act;
  csfRomActuator ra;
  double l_soft = NAN;
  if (src ? csx_romOpenLegFile(actname, sets, nset, src, weights, &act, &ra, &l_soft)
          : csx_romOpen(actname, sets, nset, basis, weights, work, "legfile_mesh", &act, &ra)) {
    return 1;
  }
  const double w1 = csu_wallSeconds();
  csError err;
  cs_errorClear(&err);
  /* the sole: the tip face's nodes (the support of its unit traction's weights) */
  const csfMesh* me = ra.fe.mesh;
  int* sole = malloc((size_t)me->nnode * sizeof(int) + 1);
  int ns = 0;
  for (int i = 0; sole && i < me->nnode; i++) {
    if (ra.fe.tip_unit[3 * i] != 0 || ra.fe.tip_unit[3 * i + 2] != 0) {
      sole[ns++] = i;
    }
  }
  const csStatus st =
      sole ? csr_romLegFileWrite(out, ra.rom, ns, sole, &act,
                                 src ? l_soft : csf_romBasisMeshSize(basis, &err),
                                 src ? src : basis, weights, &err)
           : cs_errorSet(&err, CS_ERR_MEMORY, "out of memory");
  free(sole);
  if (st != CS_OK) {
    fprintf(stderr, "crawlsim rom: %s: %s\n", out, err.msg);
  } else {
    printf("crawlsim rom: leg-file: n = %d, m = %d, %d of %d Tet10 and %d of %d fibre elements "
           "kept, %d chambers; set-up %.1f s, written in %.1f s -> %s\n", ra.rom->n, ra.rom->m,
           ra.rom->nel[0], ra.fe.mesh->ntet, ra.rom->nel[1], ra.fe.model->nfib, ra.rom->nch,
           w1 - w0, csu_wallSeconds() - w1, out);
  }
  csf_romActuatorDestroy(&ra);
  return st == CS_OK ? 0 : 1;
}
