/* sim_state.c: the whole simulation state as a flat array (see sim_model.h, docs/style.md 5).
 *
 * Layout: [0] t (s); [1] the data's ODE random seed (sim_internal.h); [2 .. 97] the 96 chamber pressures (MPa); then the
 * robot (csr_robotStateGet: support body, then legs A..H); with co-simulated legs, then the
 * coupling's block (CS_COSIM_STATE: what the Gauss-Seidel scheme carries from one macro step
 * to the next, sim_coupling.c); with the adaptive step (opt.step_adaptive), its controller's
 * memory (CS_ADA_STATE: the next step, the last step and its change, sim_adaptive.c); with footholds (--foothold), one value per foothold: its
 * latched candidate, -1 while undecided (sim_foothold.c); with a landing gate (--gate), 3 + n
 * values: the next gate, the hold (s), the current wait (s) and the n gates' released waits
 * (s; sim_gate.c), and with the gate file's crawl 3 more: its decision boundaries passed, the
 * support's z at the last (mm) and the table's skip (s). Restoring is bit-exact for every
 * part: the bodies through robot_odebody.h, the seed as the integer it is (ODE keeps it below
 * 2^32, exact in a double), the pressures by copy, and CVODE restarted from them. */
#include <cvode/cvode.h>
#include <math.h>
#include <string.h>

#include "sim_internal.h"

enum { HEAD = 2 + CSR_NCHAMBER_TOTAL }; /* t, seed, pressures */

/* ODE's generator keeps its seed in 32 bits (dRand: seed = (1664525 seed + 1013904223) &
 * 0xffffffff); a stored seed outside that range did not come from ODE */
#define SEED_LIMIT 4294967296.0


/* the footholds' latches: one per foothold of the model */
static int footholdCount(const csModel* m) { return m->foothold ? m->foothold->n : 0; }
/* the gate's part: next gate, hold, wait, one released wait per gate; with a crawl statement
 * then the crawl's boundaries passed, z at the last (mm) and skip (s); with a walk statement
 * then the walk's, on x */
#define CRAWL_PART 3
static int crawlCount(const csModel* m) { return m->gate && m->gate->crawl_n ? CRAWL_PART : 0; }
static int walkCount(const csModel* m) { return m->gate && m->gate->walk_n ? CRAWL_PART : 0; }
static int gateCount(const csModel* m) {
  return m->gate ? 3 + m->gate->n + crawlCount(m) + walkCount(m) : 0;
}
/* a decision's three values (boundaries read, coordinate, skip) restorable for n slots */
static int endPartOk(const double* x, int n) {
  return x[0] >= 0 && x[0] <= n && x[0] == floor(x[0]) && isfinite(x[1]) && isfinite(x[2]) &&
         x[2] >= 0;
}


/* where the adaptive step's part starts: after the robot and the coupling's block */
static int adaStart(const csData* d) {
  return HEAD + csr_robotStateSize(d->robot) + (d->cosim.active ? CS_COSIM_STATE : 0);
}


int cs_stateSize(const csModel* m, const csData* d) {
  return adaStart(d) + cs_adaptiveStateSize(m) + footholdCount(m) + gateCount(m);
}


void cs_stateGet(const csModel* m, const csData* d, double* x) {
  x[0] = d->t;
  x[1] = (double)d->rng_seed;
  memcpy(x + 2, d->p, sizeof d->p);
  csr_robotStateGet(d->robot, x + HEAD);
  if (d->cosim.active) {
    cs_couplingStateGet(d, x + HEAD + csr_robotStateSize(d->robot));
  }
  if (cs_adaptiveStateSize(m) > 0) {
    cs_adaptiveStateGet(d, x + adaStart(d));
  }
  const int nfh = footholdCount(m), ng = gateCount(m);
  if (nfh > 0) {
    memcpy(x + cs_stateSize(m, d) - ng - nfh, d->fh_choice, sizeof(double) * (size_t)nfh);
  }
  if (ng > 0) {
    double* xg = x + cs_stateSize(m, d) - ng;
    xg[0] = d->gate_i;
    xg[1] = d->gate_hold;
    xg[2] = d->gate_wait;
    memcpy(xg + 3, d->gate_rel, sizeof(double) * (size_t)m->gate->n);
    if (crawlCount(m)) {
      xg[3 + m->gate->n] = d->crawl_i;
      xg[4 + m->gate->n] = d->crawl_z;
      xg[5 + m->gate->n] = d->crawl_skip;
    }
    if (walkCount(m)) {
      double* xw = xg + 3 + m->gate->n + crawlCount(m);
      xw[0] = d->walk_i;
      xw[1] = d->walk_x;
      xw[2] = d->walk_skip;
    }
  }
}


csStatus cs_stateSet(const csModel* m, csData* d, const double* x, csError* err) {
  /* everything is checked before anything changes */
  if (!isfinite(x[0]) || !(x[1] >= 0 && x[1] < SEED_LIMIT && x[1] == floor(x[1]))) {
    return cs_errorSet(err, CS_ERR_ARG, "cs_stateSet: time %g or seed %g is not a state", x[0],
                       x[1]);
  }
  for (int i = 0; i < CSR_NCHAMBER_TOTAL; i++) {
    if (!isfinite(x[2 + i])) {
      return cs_errorSet(err, CS_ERR_ARG, "cs_stateSet: pressure %d is not finite", i + 1);
    }
  }
  const double* xc = x + HEAD + csr_robotStateSize(d->robot);
  if (d->cosim.active && cs_couplingStateCheck(xc) != 0) {
    return cs_errorSet(err, CS_ERR_ARG, "cs_stateSet: the coupling's part is not finite");
  }
  if (cs_adaptiveStateSize(m) > 0 && cs_adaptiveStateCheck(m, x + adaStart(d)) != 0) {
    return cs_errorSet(err, CS_ERR_ARG, "cs_stateSet: the adaptive step's part (next step %g s, "
                       "last step %g s) is not a state of this run", x[adaStart(d)],
                       x[adaStart(d) + 1]);
  }
  const int nfh = footholdCount(m), ng = gateCount(m);
  const double* xf = x + cs_stateSize(m, d) - ng - nfh;
  const double* xg = x + cs_stateSize(m, d) - ng;
  if (ng > 0) {
    int ok = xg[0] >= 0 && xg[0] <= m->gate->n && xg[0] == floor(xg[0]) && isfinite(xg[1]) &&
             xg[1] >= 0 && isfinite(xg[2]) && xg[2] >= 0;
    for (int k = 3; k < 3 + m->gate->n; k++) {
      ok = ok && isfinite(xg[k]) && xg[k] >= 0;
    }
    if (crawlCount(m)) {
      ok = ok && endPartOk(xg + 3 + m->gate->n, m->gate->crawl_n);
    }
    if (walkCount(m)) {
      ok = ok && endPartOk(xg + 3 + m->gate->n + crawlCount(m), m->gate->walk_n);
    }
    if (!ok) {
      return cs_errorSet(err, CS_ERR_ARG, "cs_stateSet: the gate's part (next gate %g of %d, "
                         "hold %g s, wait %g s, released waits) is not a gate state", xg[0],
                         m->gate->n, xg[1], xg[2]);
    }
  }
  for (int k = 0; k < nfh; k++) {
    if (!(xf[k] == -1 || (xf[k] >= 0 && xf[k] < m->foothold->fh[k].ncand &&
                          xf[k] == floor(xf[k])))) {
      return cs_errorSet(err, CS_ERR_ARG, "cs_stateSet: foothold %d's choice %g is not -1 or a "
                         "candidate", k + 1, xf[k]);
    }
  }
  if (csr_robotStateSet(d->robot, x + HEAD) != 0) {
    return cs_errorSet(err, CS_ERR_ARG, "cs_stateSet: the robot's part is not a state of this "
                       "robot (non-finite value or non-unit quaternion)");
  }
  if (d->cosim.active) {
    cs_couplingStateSet(d, xc);
  }
  if (cs_adaptiveStateSize(m) > 0) {
    cs_adaptiveStateSet(d, x + adaStart(d));
  }
  if (nfh > 0) {
    memcpy(d->fh_choice, xf, sizeof(double) * (size_t)nfh);
  }
  if (ng > 0) {
    d->gate_i = xg[0];
    d->gate_hold = xg[1];
    d->gate_wait = xg[2];
    memcpy(d->gate_rel, xg + 3, sizeof(double) * (size_t)m->gate->n);
    if (crawlCount(m)) {
      d->crawl_i = xg[3 + m->gate->n];
      d->crawl_z = xg[4 + m->gate->n];
      d->crawl_skip = xg[5 + m->gate->n];
    }
    if (walkCount(m)) {
      const double* xw = xg + 3 + m->gate->n + crawlCount(m);
      d->walk_i = xw[0];
      d->walk_x = xw[1];
      d->walk_skip = xw[2];
    }
  }
  d->t = x[0];
  d->rng_seed = (unsigned long)x[1];
  memcpy(d->p, x + 2, sizeof d->p);
  cs_gateDecide(m, d); /* the decision the restored state makes (sim_gate.c) */
  cs_schedule(m, d, d->t, d->p_cmd);
  /* the pneumatic integrator restarts from the restored pressures (its step-size history is
   * not state, sim_model.h) */
  if (d->cvode) {
    memcpy(N_VGetArrayPointer(d->y), d->p, sizeof d->p);
    CVodeReInit(d->cvode, d->t, d->y);
  }
  return CS_OK;
}
