// Test support: a long physics experiment (tens of seconds of simulated contact) checks its
// property in the release suite. Built with the sanitizers, where such a run is 5-25 times
// slower, it is skipped: the code it runs is exercised there by the shorter tests beside it
// (docs/tests.md lists them and which tests cover their code).
#pragma once

#include <gtest/gtest.h>

#ifndef TACTIP_SANITIZED
#define TACTIP_SANITIZED 0
#endif

/// First statement of a long physics experiment's test body.
#define TACTIP_LONG_EXPERIMENT()                                                    \
  do {                                                                              \
    if (TACTIP_SANITIZED) GTEST_SKIP() << "a long physics experiment: it runs in the release suite"; \
  } while (0)
