/* cmd_run.c: `crawlsim run`: simulate a gait on a terrain and write the run HDF5 file.
 * Contract (DESIGN.md): crawlsim run [--scene flat-road|obstacle] [--gait FILE.csv]
 *   [--legs auto|prb|rod|rom] [--friction MU] [--pressure-scale K] [--t-end S] [--out FILE.h5]
 * Extra options: --terrain FILE, --dt S, --output-dt S, --ramp S, --tau S, --support-mass KG,
 *   --links N, --iterations N, --calibration FILE, --quiet. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cs_commands.h"
#include "cs_paths.h"
#include "robot_calibration.h"
#include "sim_model.h"

static const char kRunUsage[] =
    "usage: crawlsim run [--scene flat-road|obstacle] [--gait FILE.csv] [--legs auto|prb|rod|rom]\n"
    "                    [--friction MU] [--pressure-scale K] [--t-end S] [--out FILE.h5]\n"
    "                    [--terrain FILE] [--dt S] [--output-dt S] [--ramp S] [--tau S]\n"
    "                    [--support-mass KG] [--links N] [--iterations N] [--gravity M/S2]\n"
    "                    [--calibration FILE] [--quiet]\n";


/* parse a finite number or report the flag */
static int parseNum(const char* flag, const char* s, double* v) {
  char* end;
  if (!s) {
    fprintf(stderr, "crawlsim run: %s needs a value\n", flag);
    return 0;
  }
  *v = strtod(s, &end);
  if (end == s || *end != '\0' || !isfinite(*v)) {
    fprintf(stderr, "crawlsim run: %s '%s' is not a number\n", flag, s);
    return 0;
  }
  return 1;
}


int csx_cmdRun(int argc, char** argv) {
  const char* scene = "flat-road";
  const char* gait = NULL;
  const char* terrain = NULL;
  const char* legs = "prb";
  const char* out = "run.h5";
  const char* calib = NULL;
  double friction = NAN, scale = 1.0, t_end = 0, dt = NAN, out_dt = NAN, ramp = NAN, tau = NAN;
  double support_kg = NAN, links = NAN, iters = NAN, gravity = NAN;
  int quiet = 0;
  for (int i = 1; i < argc; i++) {
    const char* a = argv[i];
    const char* v = (i + 1 < argc) ? argv[i + 1] : NULL;
    int ok = 1;
    if (!strcmp(a, "--help") || !strcmp(a, "-h")) {
      fputs(kRunUsage, stdout);
      return 0;
    } else if (!strcmp(a, "--quiet")) {
      quiet = 1;
      continue;
    } else if (!v) {
      fprintf(stderr, "crawlsim run: %s needs a value (see crawlsim run --help)\n", a);
      return 1;
    } else if (!strcmp(a, "--scene")) {
      scene = v;
    } else if (!strcmp(a, "--gait")) {
      gait = v;
    } else if (!strcmp(a, "--terrain")) {
      terrain = v;
    } else if (!strcmp(a, "--legs")) {
      legs = v;
    } else if (!strcmp(a, "--out")) {
      out = v;
    } else if (!strcmp(a, "--calibration")) {
      calib = v;
    } else if (!strcmp(a, "--friction")) {
      ok = parseNum(a, v, &friction);
    } else if (!strcmp(a, "--pressure-scale")) {
      ok = parseNum(a, v, &scale);
    } else if (!strcmp(a, "--t-end")) {
      ok = parseNum(a, v, &t_end);
    } else if (!strcmp(a, "--dt")) {
      ok = parseNum(a, v, &dt);
    } else if (!strcmp(a, "--output-dt")) {
      ok = parseNum(a, v, &out_dt);
    } else if (!strcmp(a, "--ramp")) {
      ok = parseNum(a, v, &ramp);
    } else if (!strcmp(a, "--tau")) {
      ok = parseNum(a, v, &tau);
    } else if (!strcmp(a, "--support-mass")) {
      ok = parseNum(a, v, &support_kg);
    } else if (!strcmp(a, "--links")) {
      ok = parseNum(a, v, &links);
    } else if (!strcmp(a, "--gravity")) {
      ok = parseNum(a, v, &gravity);
    } else if (!strcmp(a, "--iterations")) {
      ok = parseNum(a, v, &iters);
    } else {
      fprintf(stderr, "crawlsim run: unknown option '%s' (see crawlsim run --help)\n", a);
      return 1;
    }
    if (!ok) {
      return 1;
    }
    i++;
  }

  /* scene -> default terrain and gait */
  char terrain_buf[512], gait_buf[512], calib_buf[512];
  if (!strcmp(scene, "flat-road")) {
    if (!terrain) terrain = csx_dataPath("terrains/flat_road.terrain", terrain_buf, sizeof terrain_buf);
    if (!gait) gait = csx_dataPath("gaits/flat_road.csv", gait_buf, sizeof gait_buf);
  } else if (!strcmp(scene, "obstacle")) {
    fprintf(stderr, "crawlsim run: scene 'obstacle' is not available yet (flat-road only)\n");
    return 1;
  } else {
    fprintf(stderr, "crawlsim run: unknown scene '%s' (expected flat-road or obstacle)\n", scene);
    return 1;
  }
  if (!strcmp(legs, "auto")) {
    /* only the prb level exists so far: auto has nothing cheaper or dearer to choose from */
    legs = "prb";
  } else if (!strcmp(legs, "rod") || !strcmp(legs, "rom")) {
    fprintf(stderr, "crawlsim run: leg model '%s' is not available yet (prb only)\n", legs);
    return 1;
  } else if (strcmp(legs, "prb")) {
    fprintf(stderr, "crawlsim run: unknown leg model '%s' (expected auto, prb, rod or rom)\n",
            legs);
    return 1;
  }
  if (!calib) calib = csx_dataPath("robot/calibration_provisional.txt", calib_buf, sizeof calib_buf);

  csError err;
  cs_errorClear(&err);
  csModel m;
  cs_modelInit(&m);
  int rc = 1;
  csData* d = NULL;
  m.opt.progress = !quiet;
  snprintf(m.leg_level, sizeof m.leg_level, "%s", legs);
  if (!isnan(friction)) m.contact.mu = friction;
  m.sched.pressure_scale = scale;
  if (!isnan(ramp)) m.sched.ramp = ramp;
  if (!isnan(dt)) m.opt.h = dt;
  if (!isnan(out_dt)) m.opt.output_dt = out_dt;
  if (!isnan(tau)) m.opt.pneumatic_tau = tau;
  if (!isnan(iters)) m.opt.solver_iterations = (int)iters;
  if (!isnan(gravity)) m.opt.gravity = gravity * 1e3; /* m/s^2 -> mm/s^2 */
  m.opt.t_end = t_end;
  if (!(t_end >= 0)) {
    cs_errorSet(&err, CS_ERR_RANGE, "--t-end %g must be >= 0", t_end);
    goto done;
  }
  if (!isnan(support_kg)) {
    if (!(support_kg > 0)) {
      cs_errorSet(&err, CS_ERR_RANGE, "--support-mass %g kg must be > 0", support_kg);
      goto done;
    }
    m.robot.support_mass = support_kg * 1e-3;
  }
  if (!isnan(links)) {
    if (links != floor(links) || links < 1 || links > 64) {
      cs_errorSet(&err, CS_ERR_RANGE, "--links %g must be an integer in 1..64", links);
      goto done;
    }
    m.robot.leg_params.links_per_segment = (int)links;
  }
  if (!isnan(iters) && (iters != floor(iters) || iters < 1 || iters > 10000)) {
    cs_errorSet(&err, CS_ERR_RANGE, "--iterations %g must be an integer in 1..10000", iters);
    goto done;
  }
  if (csc_contactParamsValidate(&m.contact, &err) != CS_OK ||
      csg_scheduleCheckOptions(&m.sched, &err) != CS_OK) {
    goto done;
  }
  if (cs_modelLoad(&m, scene, terrain, gait, calib, &err) != CS_OK) goto done;
  if (m.gait) {
    csgGaitSummary gs;
    csg_gaitComputeSummary(m.gait, &gs, NULL);
    if (gs.p_max * scale > csg_defaultReadOptions().max_pressure) {
      cs_errorSet(&err, CS_ERR_RANGE, "--pressure-scale %g takes %s to %g MPa, above the %g MPa "
                  "limit of gait pressures", scale, gait, gs.p_max * scale,
                  csg_defaultReadOptions().max_pressure);
      goto done;
    }
  }

  d = cs_dataCreate(&m, &err);
  if (!d) goto done;
  if (!quiet) {
    fprintf(stderr, "crawlsim run: scene %s, gait %s, legs %s, friction %.3g, t_end %.3g s, "
            "robot mass %.1f g\n", scene, gait, legs, m.contact.mu, m.opt.t_end,
            cs_robotMass(d) * 1e6);
    double load, pcr;
    cs_modelStanceCheck(&m, cs_robotMass(d), &load, &pcr);
    fprintf(stderr, "crawlsim run: stance check: %.2f N per leg on half the legs vs sway-buckling "
            "load %.2f N per leg (%.0f %%)%s\n", load, pcr, 100 * load / pcr,
            load > 0.5 * pcr ? ": expect the stance legs to sway and fold" : "");
  }
  if (cs_settle(&m, d, &err) != CS_OK) goto done;
  double wall = 0;
  csStatus st = cs_run(&m, d, out, &wall, &err);
  double x[3], q[4];
  cs_supportDisplacement(d, x);
  cs_supportOrientation(d, q);
  /* tilt: angle between the support's up axis and world up */
  double tilt = acos(fmin(1.0, 1 - 2 * (q[1] * q[1] + q[3] * q[3]))) * 180 / 3.14159265358979;
  printf("final t = %.3f s: support displacement x = %.2f mm, y = %.2f mm, z = %.2f mm, "
         "tilt %.2f deg\n", cs_time(d), x[0], x[1], x[2], tilt);
  printf("wall time %.2f s, real-time factor %.2f (simulated s per wall s), output %s\n", wall,
         wall > 0 ? cs_time(d) / wall : 0, out);
  if (st != CS_OK) goto done;
  rc = 0;

done:
  if (rc != 0) {
    fprintf(stderr, "crawlsim run: %s\n", err.msg[0] ? err.msg : "failed");
  }
  cs_dataDestroy(d);
  cs_modelDestroy(&m);
  return rc;
}
