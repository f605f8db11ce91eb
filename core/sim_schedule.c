/* sim_schedule.c: the scheduled chamber pressures p_cmd(t) (docs/design.md "Data flow"): the
 * model's pressure source (a controller, crawlsim.h) if it has one, else the gait table's
 * schedule (held by the landing gate, sim_gate.c, with its footholds, sim_foothold.c). Its own unit because the life cycle (sim_driver.c), the state (sim_state.c, which
 * re-reads p_cmd after a restore) and the stages (sim_step.c) all ask it, and none of them
 * should ask another for it. */
#include <string.h>

#include "sim_internal.h"


int cs_schedule(const csModel* m, csData* d, double t, double* p_cmd) {
  if (t >= 0 && m->pressure_source) {
    if (m->pressure_source(m->pressure_ctx, t, p_cmd) == 0) {
      return 0;
    }
    memset(p_cmd, 0, CSR_NCHAMBER_TOTAL * sizeof(double));
    return -1;
  }
  if (t < 0 || !m->gait) {
    memset(p_cmd, 0, CSR_NCHAMBER_TOTAL * sizeof(double));
    return 0;
  }
  /* the table, its rows held by the landing gate's waits if it has waited (sim_gate.c) */
  cs_gateEval(m, d, m->gait, t, p_cmd);
  if (m->foothold) {
    cs_footholdApply(m, d, t, p_cmd);
  }
  return 0;
}
