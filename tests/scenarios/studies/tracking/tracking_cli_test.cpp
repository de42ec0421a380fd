// tactip report tracking and --pins detected: on a short run with images, and their
// refusals of a dataset recorded without them.

#include <gtest/gtest.h>

#include <filesystem>
#include <sstream>
#include <string>

#include "tests/scenarios/cli_helpers.h"

namespace tactip {
namespace {

namespace fs = std::filesystem;

// Two short one-run datasets (20 mm lift, 5 mm/s retraction, 50 frames/s), with and without
// images, generated once for the suite. At 25 frames/s the shell's sag as the lift takes the
// object's weight moves some pins 15 px between frames, past the tracker's 10 px gate.
class TrackingCliTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = fs::temp_directory_path() / ("tactip_TrackingCliTest_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
    const std::string shortened =
        " --runs 1 --quiet --set rail.lift_mm=20 --set rail.retract_speed_mm_s=5 --set sensor.frame_rate_hz=50";
    ASSERT_EQ(Run("generate rail --images --out " + P("img.h5") + shortened).code, 0);
    ASSERT_EQ(Run("generate rail --out " + P("plain.h5") + shortened).code, 0);
  }
  static void TearDownTestSuite() { fs::remove_all(dir_); }
  static testing::CliResult Run(const std::string& args) { return testing::RunTactip(args, dir_); }
  static std::string P(const std::string& name) { return (dir_ / name).string(); }

  static fs::path dir_;
};
fs::path TrackingCliTest::dir_;

TEST_F(TrackingCliTest, TheReportPrintsEachRunAndTheSensorsTotalWithEveryPinWithin1Px) {
  const auto r = Run("report tracking " + P("img.h5"));
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("within_1px"), std::string::npos) << r.out;
  // Run 0 and the total: every sample within 1 px, no miss. Some tips leave the view (the
  // outer ring's lowest pins touch the image's bottom edge while the shell carries the object).
  for (const std::string row : {"tactip           0", "tactip         all"}) {
    const size_t at = r.out.find(row);
    ASSERT_NE(at, std::string::npos) << r.out;
    std::istringstream line(r.out.substr(at, r.out.find('\n', at) - at));
    std::string sensor, run, samples, out_of_view, within, rms, max, misses;
    line >> sensor >> run >> samples >> out_of_view >> within >> rms >> max >> misses;
    EXPECT_EQ(within, "1.0000") << row;
    EXPECT_EQ(misses, "0") << row;
    EXPECT_LT(std::stod(out_of_view), 0.02 * std::stod(samples)) << row;
  }
}

TEST_F(TrackingCliTest, TheReportRefusesADatasetWithoutImages) {
  const auto r = Run("report tracking " + P("plain.h5"));
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(r.err, "tactip: dataset '" + P("plain.h5") +
                       "': run_0000/sensors/tactip has no pins/detected_px (generate it with --images)\n");
}

TEST_F(TrackingCliTest, DetectorsScoreOnDetectedPinsAndRefuseThemWhereThereAreNone) {
  ASSERT_EQ(Run("train threshold --data " + P("img.h5") + " --pins detected --out " + P("m.txt")).code, 0);
  const auto ok = Run("evaluate --model " + P("m.txt") + " --data " + P("img.h5") + " --pins detected");
  EXPECT_EQ(ok.code, 0) << ok.err;
  EXPECT_NE(ok.out.find("F1"), std::string::npos);
  const auto r = Run("evaluate --model " + P("m.txt") + " --data " + P("plain.h5") + " --pins detected");
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(r.err, "tactip: --pins detected: dataset '" + P("plain.h5") +
                       "' run_0000/sensors/tactip has no pins/detected_px (generate it with --images)\n");
}

}  // namespace
}  // namespace tactip
