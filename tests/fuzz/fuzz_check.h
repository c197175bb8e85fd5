#pragma once
// FUZZ_CHECK: a property every input must keep. A violation prints what failed and aborts, which
// libFuzzer reports as a crash and keeps the input (scripts/fuzz moves it to tests/fuzz/regressions).
#include <cstdio>
#include <cstdlib>

#define FUZZ_CHECK(condition, what)                                                                      \
  do {                                                                                                   \
    if (!(condition)) {                                                                                  \
      std::fprintf(stderr, "%s:%d: property violated: %s (%s)\n", __FILE__, __LINE__, #condition, what); \
      std::abort();                                                                                      \
    }                                                                                                    \
  } while (0)
