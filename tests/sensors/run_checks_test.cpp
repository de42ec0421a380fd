// The checks a run read from a dataset file must pass: frames, frame times, finite values.

#include "sensors/run_checks.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "input_error.h"

namespace tactip {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

/// Three frames of two pins, every value finite.
RunRecord GoodRun() {
  RunRecord r;
  r.index = 5;
  r.n_pins = 2;
  r.time = {0.0, 0.01, 0.02};
  r.pos_px.assign(12, 1.5f);
  r.valid.assign(6, 1);
  r.pos_m.assign(18, 0.01f);
  r.normal_N.assign(6, 0.5f);
  r.tangential_N.assign(12, 0.1f);
  r.object_height_m = {0.05, 0.049, 0.048};
  return r;
}

const std::string kSource = "dataset 'd.h5'";

std::string TimesError(const RunRecord& r) {
  return InputErrorOf([&] { CheckRunTimes(r, kSource); });
}
std::string ValuesError(const RunRecord& r) {
  return InputErrorOf([&] { CheckRunValues(r, kSource); });
}

TEST(RunChecksTest, AGoodRunPasses) {
  EXPECT_EQ(TimesError(GoodRun()), "");
  EXPECT_EQ(ValuesError(GoodRun()), "");
  RunRecord one = GoodRun();
  one.time = {0.5};  // one frame: nothing to compare
  EXPECT_EQ(TimesError(one), "");
}

TEST(RunChecksTest, FrameTimesMustExistBeFiniteAndIncrease) {
  const struct {
    std::vector<double> time;
    std::string message;
  } cases[] = {
      {{}, "dataset 'd.h5': run_0005/time has no frames (a run needs at least one)"},
      {{0.0, kNaN, 0.02}, "dataset 'd.h5': run_0005/time is nan at frame 1 (must be a finite number)"},
      {{kNaN, kNaN, kNaN}, "dataset 'd.h5': run_0005/time is nan at frame 0 (must be a finite number)"},
      {{0.0, 0.01, kInf}, "dataset 'd.h5': run_0005/time is inf at frame 2 (must be a finite number)"},
      {{0.0, 0.02, 0.01},
       "dataset 'd.h5': run_0005/time is not increasing: frame 2 at 0.01 s is not after frame 1 at 0.02 s"},
      {{0.25, 0.25, 0.25},
       "dataset 'd.h5': run_0005/time is not increasing: frame 1 at 0.25 s is not after frame 0 at 0.25 s"},
  };
  for (const auto& c : cases) {
    RunRecord r = GoodRun();
    r.time = c.time;
    EXPECT_EQ(TimesError(r), c.message);
  }
}

TEST(RunChecksTest, ArraysMustBeFiniteAndFlagsZeroOrOne) {
  const float nan_f = std::numeric_limits<float>::quiet_NaN();
  const float inf_f = std::numeric_limits<float>::infinity();
  struct Case {
    void (*edit)(RunRecord&, float, float);
    std::string message;
  };
  const Case cases[] = {
      // pos_px (T, N, 2): value 7 is frame 1, pin 1, v.
      {[](RunRecord& r, float nan, float) { r.pos_px[7] = nan; },
       "dataset 'd.h5': run_0005/pins/pos_px is nan at frame 1, pin 1 (must be a finite number)"},
      {[](RunRecord& r, float, float inf) { r.pos_px[0] = -inf; },
       "dataset 'd.h5': run_0005/pins/pos_px is -inf at frame 0, pin 0 (must be a finite number)"},
      {[](RunRecord& r, float nan, float) { r.pos_m[17] = nan; },
       "dataset 'd.h5': run_0005/pins/pos_m is nan at frame 2, pin 1 (must be a finite number)"},
      {[](RunRecord& r, float, float inf) { r.normal_N[3] = inf; },
       "dataset 'd.h5': run_0005/contact/normal_N is inf at frame 1, pin 1 (must be a finite number)"},
      {[](RunRecord& r, float nan, float) { r.tangential_N[4] = nan; },
       "dataset 'd.h5': run_0005/contact/tangential_N is nan at frame 1, pin 0 (must be a finite number)"},
      {[](RunRecord& r, float nan, float) { r.object_height_m[2] = nan; },
       "dataset 'd.h5': run_0005/object/height_m is nan at frame 2 (must be a finite number)"},
      {[](RunRecord& r, float nan, float) {
         r.external_px.assign(12, 0.0f);
         r.external_px[5] = nan;
       },
       "dataset 'd.h5': run_0005/external/pos_px is nan at frame 1, pin 0 (must be a finite number)"},
      {[](RunRecord& r, float, float inf) {
         r.external_m.assign(18, 0.0f);
         r.external_m[3] = inf;
       },
       "dataset 'd.h5': run_0005/external/pos_m is inf at frame 0, pin 1 (must be a finite number)"},
      {[](RunRecord& r, float, float) { r.valid[4] = 2; },
       "dataset 'd.h5': run_0005/pins/valid is 2 at frame 2, pin 0 (must be 0 or 1)"},
  };
  for (const auto& c : cases) {
    RunRecord r = GoodRun();
    c.edit(r, nan_f, inf_f);
    EXPECT_EQ(ValuesError(r), c.message);
  }
}

}  // namespace
}  // namespace tactip
