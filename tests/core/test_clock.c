/* test_clock.c: the wall clock is monotonic and the stage timer accumulates what it is given
 * (no timing assertions: only order and counts, docs/style.md "No timing assertions"). */
#include "core_clock.h"
#include "cs_test.h"


static void test_clock_is_monotonic_and_timers_accumulate(void) {
  double prev = csu_wallSeconds();
  for (int i = 0; i < 10000; i++) {
    double now = csu_wallSeconds();
    CS_EXPECT(now >= prev);
    prev = now;
  }
  csuTimer t = {0, 0};
  double t0 = csu_wallSeconds();
  double t1 = csu_timerAdd(&t, t0);
  double t2 = csu_timerAdd(&t, t1);
  CS_EXPECT(t.count == 2);
  CS_EXPECT(t1 >= t0 && t2 >= t1);
  /* the sum of the two intervals is the span t0 -> t2, to round-off of the subtractions */
  CS_EXPECT_NEAR(t.wall, t2 - t0, 1e-9, 0);
  CS_EXPECT(t.wall >= 0);
}


int main(int argc, char** argv) {
  cs_testInit(argc, argv);
  CS_RUN(test_clock_is_monotonic_and_timers_accumulate);
  return cs_testSummary();
}
