// Test support: a long physics experiment (tens of seconds of simulated contact) checks its
// property in the release suite. Built with the sanitizers, where such a run is 5-25 times
// slower, it is skipped: the code it runs is exercised there by the shorter tests beside it
// (docs/tests.md lists them and which tests cover their code). The environment variable
// TACTIP_SKIP_LONG_EXPERIMENTS=1 skips them in any build (a quick suite, the coverage of the
// sanitized selection in scripts/sanitized-coverage.sh).
#pragma once

#include <cstdlib>
#include <cstring>

#include <gtest/gtest.h>

#ifndef TACTIP_SANITIZED
#define TACTIP_SANITIZED 0
#endif

namespace tactip::testing {

/// True when this build or this process skips the long physics experiments.
inline bool SkipLongExperiments() {
  const char* env = std::getenv("TACTIP_SKIP_LONG_EXPERIMENTS");
  return TACTIP_SANITIZED || (env != nullptr && std::strcmp(env, "1") == 0);
}

}  // namespace tactip::testing

/// First statement of a long physics experiment's test body.
#define TACTIP_LONG_EXPERIMENT()                                                                  \
  do {                                                                                            \
    if (::tactip::testing::SkipLongExperiments())                                                \
      GTEST_SKIP() << "a long physics experiment: it runs in the release suite";                  \
  } while (0)
