/* crawl_controller.c: the smallest program over libcrawlsim (docs/reference/api.md).
 *
 * Builds the flat road with the scene's defaults (or the leg level given as argv[1], and the
 * end time argv[2] in s), settles it, then steps it with a controller that replays the scene's
 * gait table with every pressure scaled by 0.9: a controller sees the time and may read the
 * state (here the support's pose) through the cs_sim* read-outs. Prints the support's track
 * every 0.1 s and the feet's load at the end.
 *
 * Build against the installed library:
 *   cc crawl_controller.c $(pkg-config --cflags --libs crawlsim) -o crawl_controller
 * Run: ./crawl_controller [rod|strain] [T_END_S] */
#include <crawlsim/crawlsim.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

/* what the controller keeps between calls (the caller's memory) */
typedef struct {
  double gain;     /* multiplies the table's pressures */
  long calls;      /* how often the driver asked */
} Ctrl;

/* p_cmd [96] MPa for time t: the gait table's command, scaled */
static int replayScaled(csSim* s, double t, double* p_cmd, void* user) {
  Ctrl* c = user;
  cs_simGaitCommand(s, t, p_cmd);
  for (int i = 0; i < cs_simChamberCount(s); i++) {
    p_cmd[i] *= c->gain;
  }
  c->calls++;
  return 0;
}

int main(int argc, char** argv) {
  csRunDef def = cs_defaultRunDef();
  def.scene = "flat-road";
  def.legs = argc > 1 ? argv[1] : NULL; /* NULL: the scene's (rod) */
  double t_end = argc > 2 ? atof(argv[2]) : 1.0;
  csError err;
  csSim* s = cs_simCreate(&def, &err);
  if (!s) {
    fprintf(stderr, "crawl_controller: %s\n", err.msg);
    return 1;
  }
  Ctrl c = {0.9, 0};
  cs_simSetController(s, replayScaled, &c, NULL);
  printf("crawlsim %s: flat road, %s legs, macro step %g s, %d chambers, %d legs\n",
         cs_version(), def.legs, cs_simMacroStep(s), cs_simChamberCount(s), cs_simLegCount(s));
  printf("t_s x_mm y_mm z_mm\n");
  int rc = 0;
  for (double t_out = 0; t_out <= t_end + 1e-9; t_out += 0.1) {
    if (cs_simRunUntil(s, t_out, &err) != CS_OK) {
      fprintf(stderr, "crawl_controller: %s\n", err.msg);
      rc = 1;
      break;
    }
    double x[3], q[4];
    cs_simSupportPose(s, x, q);
    printf("%.3f %.3f %.3f %.3f\n", cs_simTime(s), x[0], x[1], x[2]);
  }
  double f[8][3], load = 0;
  cs_simFootForces(s, &f[0][0]);
  for (int k = 0; k < cs_simLegCount(s); k++) {
    load += f[k][1];
  }
  printf("feet carry %.3f N; the controller was asked %ld times in %ld steps\n", load, c.calls,
         cs_simStepCount(s));
  cs_simDestroy(s);
  return rc;
}
