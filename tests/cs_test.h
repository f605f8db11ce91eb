/* cs_test.h: the tiny test harness of crawlsim's ctest suite (header-only, plain C).
 *
 * CS_EXPECT(cond) and CS_EXPECT_NEAR(a, b, abs_tol, rel_tol) record a failure and print the
 * expression with %.17g values; a test passes when |a-b| <= max(abs_tol, rel_tol*|b|), and NaN
 * or Inf on either side fails (docs/style.md 22). Every tolerance at a call site carries a comment
 * saying why it is that size. A test file's main() runs its cases with CS_RUN and returns
 * cs_testSummary(), which prints "N passed, N failed". */
#ifndef CS_TEST_H
#define CS_TEST_H

#include <math.h>
#include <stdio.h>
#include <string.h>

typedef struct {
  int checks, failures, cases, failed_cases;
  const char* filter;
} csTestState;

static csTestState cs_test_state_;

#define CS_EXPECT(cond)                                                          \
  do {                                                                           \
    cs_test_state_.checks++;                                                     \
    if (!(cond)) {                                                               \
      cs_test_state_.failures++;                                                 \
      fprintf(stderr, "%s:%d: FAILED: %s\n", __FILE__, __LINE__, #cond);         \
    }                                                                            \
  } while (0)

static inline int cs_testNear_(double a, double b, double abs_tol, double rel_tol) {
  if (!isfinite(a) || !isfinite(b)) {
    return 0;
  }
  double tol = fmax(abs_tol, rel_tol * fabs(b));
  return fabs(a - b) <= tol;
}

#define CS_EXPECT_NEAR(a, b, abs_tol, rel_tol)                                                 \
  do {                                                                                         \
    double cs_a_ = (a), cs_b_ = (b);                                                           \
    cs_test_state_.checks++;                                                                   \
    if (!cs_testNear_(cs_a_, cs_b_, (abs_tol), (rel_tol))) {                                   \
      cs_test_state_.failures++;                                                               \
      fprintf(stderr, "%s:%d: FAILED: %s ~ %s: %.17g observed vs %.17g expected (abs %g, rel %g)\n", \
              __FILE__, __LINE__, #a, #b, cs_a_, cs_b_, (double)(abs_tol), (double)(rel_tol)); \
    }                                                                                          \
  } while (0)

/* the largest |a - b| over the largest |a| of n values (|a - b| where every a is 0): two
 * computations of the same numbers compared relative to their size */
static inline double cs_relDiff(const double* a, const double* b, int n) {
  double dmax = 0, amax = 0;
  for (int i = 0; i < n; i++) {
    dmax = fmax(dmax, fabs(a[i] - b[i]));
    amax = fmax(amax, fabs(a[i]));
  }
  return amax > 0 ? dmax / amax : dmax;
}

/* run one case unless a name filter (argv[1]) excludes it */
#define CS_RUN(fn)                                                              \
  do {                                                                          \
    if (!cs_test_state_.filter || strstr(#fn, cs_test_state_.filter)) {        \
      int before_ = cs_test_state_.failures;                                    \
      cs_test_state_.cases++;                                                   \
      fn();                                                                     \
      if (cs_test_state_.failures != before_) {                                 \
        cs_test_state_.failed_cases++;                                          \
        fprintf(stderr, "case %s FAILED\n", #fn);                               \
      } else {                                                                  \
        printf("case %s ok\n", #fn);                                            \
      }                                                                         \
    }                                                                           \
  } while (0)

static inline void cs_testInit(int argc, char** argv) {
  cs_test_state_.filter = argc > 1 ? argv[1] : NULL;
}

/* Write text to path (a test's input file); a file that cannot be opened is a failed check. */
static inline void cs_testWriteText(const char* path, const char* text) {
  FILE* f = fopen(path, "wb");
  CS_EXPECT(f != NULL);
  if (f) {
    fputs(text, f);
    fclose(f);
  }
}

static inline int cs_testSummary(void) {
  printf("%d passed, %d failed\n", cs_test_state_.cases - cs_test_state_.failed_cases,
         cs_test_state_.failed_cases);
  return cs_test_state_.failures == 0 && cs_test_state_.cases > 0 ? 0 : 1;
}

#endif /* CS_TEST_H */
