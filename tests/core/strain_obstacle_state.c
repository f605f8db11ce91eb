/* strain_obstacle_state.c: a scene on strain legs (its defaults, as `crawlsim run --scene
 * SCENE --legs strain --links 3 [--gait GAIT --conditions COND]`) run to T seconds, its whole state
 * (cs_simStateGet) written as text: the count, then one value a line in C's exact hexadecimal
 * form (%a), so a test can restore it bit for bit. Built, not registered:
 *
 *   strain_obstacle_state T FILE [SCENE GAIT COND]   (data files from $CS_SOURCE_DIR, else
 *                                                     the build's; default: the obstacle)
 *
 * tests/core/data/strain_obstacle_26.8.state is its output at T = 26.8 from a build with the
 * tree step's old damping rule on the obstacle's default table of then (kept as
 * tests/core/data/strain_obstacle_26.8_gait.csv: give it with `obstacle GAIT paper`;
 * test_strain_obstacle_stop's header says why and when to regenerate it); tests/core/data/strain_earth_0.904.state its output at T = 0.904 with
 * `flat-road gaits/flat_road_paper.csv earth` (test_strain_earth_edge's header). */
#include <stdio.h>
#include <stdlib.h>

#include "crawlsim.h"

int main(int argc, char** argv) {
  if (argc != 3 && argc != 6) {
    fprintf(stderr, "usage: strain_obstacle_state T FILE [SCENE GAIT CONDITIONS]\n");
    return 2;
  }
  const double T = atof(argv[1]);
  csRunDef def = cs_defaultRunDef();
  def.scene = argc == 6 ? argv[3] : "obstacle";
  def.legs = "strain";
  def.links = 3; /* the basis the state files were made with (3 bending modes per segment,
                   the level's default then) */
  def.dt = 1e-3; /* the step the state files were made with (the level's default then) */
  def.strain_sub = 4; /* the sub-intervals the state files were made with (4 capsules per
                        segment in their contact history; the level's default then) */
  def.data_dir = getenv("CS_SOURCE_DIR");
  if (argc == 6) {
    def.gait = argv[4];
    def.conditions = argv[5];
  }
  csError err;
  csSim* s = cs_simCreate(&def, &err);
  if (!s) {
    fprintf(stderr, "strain_obstacle_state: %s\n", err.msg);
    return 1;
  }
  if (cs_simRunUntil(s, T, &err) != CS_OK) {
    fprintf(stderr, "strain_obstacle_state: %s\n", err.msg);
    cs_simDestroy(s);
    return 1;
  }
  const int n = cs_simStateSize(s);
  double* x = malloc((size_t)n * sizeof(double));
  FILE* f = fopen(argv[2], "w");
  if (!x || !f) {
    fprintf(stderr, "strain_obstacle_state: cannot write %s\n", argv[2]);
    free(x);
    if (f) {
      fclose(f);
    }
    cs_simDestroy(s);
    return 1;
  }
  cs_simStateGet(s, x);
  fprintf(f, "%d\n", n);
  for (int i = 0; i < n; i++) {
    fprintf(f, "%a\n", x[i]);
  }
  fclose(f);
  printf("t %.6f: %d values in %s\n", cs_simTime(s), n, argv[2]);
  free(x);
  cs_simDestroy(s);
  return 0;
}
