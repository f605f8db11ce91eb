/* core_clock.h: the one wall clock of crawlsim and the stage timers built on it.
 *
 * Owns: csu_wallSeconds (monotonic wall time, s: CLOCK_MONOTONIC, so timings never jump with
 * NTP or DST adjustments of the calendar clock) and csuTimer (accumulated wall seconds and a
 * count, as Box2D's b2Profile / MuJoCo's mjTimerStat). Wall times are reported, never asserted
 * on by tests (compare ratios in one run if a test must). */
#ifndef CS_CORE_CLOCK_H
#define CS_CORE_CLOCK_H

#ifdef __cplusplus
extern "C" {
#endif

/* Monotonic wall time in seconds from an arbitrary origin (differences only). */
double csu_wallSeconds(void);

/* Accumulated wall time of one stage. */
typedef struct csuTimer_ {
  double wall; /* s, sum over all calls */
  long count;  /* number of calls */
} csuTimer;

/* Add the wall time since `t0` (a csu_wallSeconds value) to t and count one call; returns the
 * current time, so consecutive stages can chain: t0 = csu_timerAdd(&a, t0). */
double csu_timerAdd(csuTimer* t, double t0);

#ifdef __cplusplus
}
#endif
#endif /* CS_CORE_CLOCK_H */
