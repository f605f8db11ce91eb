/* fuzz_libfuzzer.c: libFuzzer's entry points around a harness (fuzz_common.h). Linked only into
 * the fuzzers (CS_BUILD_FUZZERS=ON, clang -fsanitize=fuzzer). */
#include <stdio.h>
#include <stdlib.h>

#include "fuzz_common.h"

int LLVMFuzzerInitialize(int* argc, char*** argv);
int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size);


int LLVMFuzzerInitialize(int* argc, char*** argv) {
  (void)argc;
  (void)argv;
  if (csz_harnessInit() != 0) {
    fprintf(stderr, "fuzz: harness initialisation failed\n");
    exit(2);
  }
  return 0;
}


int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  csError err;
  cs_errorClear(&err);
  (void)csz_harnessRun(data, size, &err);
  return 0;
}
