/* core_sun.h: the SUNDIALS glue every CVODE user of crawlsim shares (the driver's chamber
 * pressures, core/sim_driver.c; the rod legs, robot/rod/robot_rod_dyn.c; the reduced FE legs,
 * robot/rom/robot_rom.c): a context that never prints, across SUNDIALS 6.4 and 7.x
 * (debian-deps.md P4: 7 takes a SUNComm where 6 takes a void* communicator, and 7 has no
 * per-solver error handler).
 *
 * It owns no state: the caller owns the context and the CVODE memory. It is a leaf room of its
 * own (docs/design.md "Rooms": base/sun) because base/ stays free of SUNDIALS. */
#ifndef CORE_SUN_H
#define CORE_SUN_H

#include <sundials/sundials_context.h>

/* Creates a SUNDIALS context (no communicator) whose error handlers print nothing: the library
 * never prints (crawlsim.h); a failure comes back as the caller's status and message. 0 = ok,
 * else non-zero and *ctx is NULL. */
int cs_sunContextCreate(SUNContext* ctx);

/* Silences a CVODE instance's error messages (SUNDIALS 6: a handler that drops them; 7: the
 * context's handlers, cleared by cs_sunContextCreate, already do). 0 = ok. */
int cs_cvodeSilence(void* cvode);

#endif
