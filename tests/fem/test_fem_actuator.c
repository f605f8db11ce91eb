/* test_fem_actuator.c: the actuator set-up refuses geometries the mesh cannot resolve, naming
 * the wall and the parameters, before gmsh runs; the wall thicknesses against closed forms. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "cs_test.h"
#include "fem_actuator.h"

static void test_wall_thicknesses(void) {
  csrActuator act;
  csError err;
  CS_EXPECT(csr_actuatorPreset(&act, "baseline", &err) == CS_OK);
  csfWalls w;
  csf_actuatorWalls(&act, 4.0, &w);
  /* baseline: a - b - r1 = 7.5 - 4 - 2 (the chamber centre (4, 4) is inside the fillet centre
   * (5.5, 5.5), so the straight side is nearest), 2 (b - r1) = 4, c = 5, walls meshed at
   * min(4, 2 pi 2 / 6) = 2.094 mm */
  CS_EXPECT_NEAR(w.outer, 1.5, 1e-12, 0);
  CS_EXPECT_NEAR(w.between, 4.0, 1e-12, 0);
  CS_EXPECT_NEAR(w.cap, 5.0, 1e-12, 0);
  CS_EXPECT_NEAR(w.mesh, 2.0 * 3.14159265358979323846 * 2.0 / 6.0, 1e-12, 0);
  /* a chamber beyond the fillet centre: b = 6, r2 = 3 -> fillet centre (4.5, 4.5); from the
   * chamber centre along the diagonal to the arc r2 - sqrt(2) (6 - 4.5) = 0.879 mm, so with
   * r1 = 0.5 the wall is 0.379 mm (the straight side alone would give a - b - r1 = 1.0) */
  CS_EXPECT(csr_actuatorSet(&act, "b", 6.0, &err) == CS_OK);
  CS_EXPECT(csr_actuatorSet(&act, "r1", 0.5, &err) == CS_OK);
  CS_EXPECT(csr_actuatorSet(&act, "r2", 3.0, &err) == CS_OK);
  csf_actuatorWalls(&act, 4.0, &w);
  CS_EXPECT_NEAR(w.outer, 3.0 - sqrt(2.0) * 1.5 - 0.5, 1e-12, 0);
}


static void test_unresolvable_walls_are_refused(void) {
  csrActuator act;
  csError err;
  csfActuatorSpec spec = csf_actuatorSpecDefault();
  spec.work_stem = "actuator_refused"; /* never written: refused before meshing */
  /* adjacent chambers 0.2 mm apart: 2 (3 - 2.9); walls meshed at 2 pi 2.9 / 6 = 3.04 mm */
  CS_EXPECT(csr_actuatorPreset(&act, "baseline", &err) == CS_OK);
  CS_EXPECT(csr_actuatorSet(&act, "b", 3.0, &err) == CS_OK);
  CS_EXPECT(csr_actuatorSet(&act, "r1", 2.9, &err) == CS_OK);
  csfActuatorFE fe;
  CS_EXPECT(csf_actuatorFECreate(&act, &spec, &fe, &err) == CS_ERR_RANGE);
  CS_EXPECT(strstr(err.msg, "wall between adjacent chambers is 0.2 mm thick") != NULL);
  CS_EXPECT(strstr(err.msg, "b = 3, r1 = 2.9") != NULL);
  printf("  %s\n", err.msg);
  /* a chamber 0.05 mm under the outer surface: 7.5 - 4 - 3.45 */
  CS_EXPECT(csr_actuatorPreset(&act, "baseline", &err) == CS_OK);
  CS_EXPECT(csr_actuatorSet(&act, "r1", 3.45, &err) == CS_OK);
  CS_EXPECT(csf_actuatorFECreate(&act, &spec, &fe, &err) == CS_ERR_RANGE);
  CS_EXPECT(strstr(err.msg, "between a chamber and the outer surface is 0.05 mm thick") != NULL);
  printf("  %s\n", err.msg);
}


int main(int argc, char** argv) {
  cs_testInit(argc, argv);
  CS_RUN(test_wall_thicknesses);
  CS_RUN(test_unresolvable_walls_are_refused);
  return cs_testSummary();
}
