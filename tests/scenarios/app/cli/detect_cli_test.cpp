// The detector commands end to end on a small simulated dataset: train, evaluate,
// detect (HDF5 and CSV input), bench, and their one-line errors.

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <algorithm>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "detectors/pin_csv.h"
#include "tests/scenarios/cli_helpers.h"
#include "scenarios/studies/detector_bench/detector_bench.h"
#include "sensors/slip_data.h"
#include "sensors/dataset.h"
#include "sim/config.h"

namespace fs = std::filesystem;

namespace tactip {
namespace {

using testing::CliResult;
using testing::Slurp;

using testing::SplitLines;

// One small dataset shared by all tests of the suite: 6 quick runs.
class DetectCliTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    // One folder per process: ctest runs each test in its own process, in parallel.
    dir_ = fs::temp_directory_path() / ("tactip_detect_cli_" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    const CliResult g = Run("generate rail --runs 6 --speed-mm-s 1 --set rail.lift_mm=10 --set rail.hold_s=0.1 "
                            "--seed 5 --quiet --out " + P("d.h5"));
    ASSERT_EQ(g.code, 0) << g.err;
  }
  static void TearDownTestSuite() { fs::remove_all(dir_); }

  static CliResult Run(const std::string& args) { return testing::RunTactip(args, dir_); }
  static std::string P(const std::string& name) { return (dir_ / name).string(); }

  static fs::path dir_;
};
fs::path DetectCliTest::dir_;

TEST(RunListTest, ParsesRangesAndListsSortedUnique) {
  EXPECT_EQ(ParseRunList("0-3"), (std::vector<int>{0, 1, 2, 3}));
  EXPECT_EQ(ParseRunList("5,1-2,2"), (std::vector<int>{1, 2, 5}));
  for (const char* bad : {"", "a", "3-1", "1,,2", "-2", "1-"}) {
    EXPECT_THROW(ParseRunList(bad), InputError) << bad;
  }
}

TEST_F(DetectCliTest, DatasetRunsCarryTheirOnsetFrame) {
  const auto runs = LoadDatasetRuns(P("d.h5"), {0, 5});
  ASSERT_EQ(runs.size(), 2u);
  const DatasetReader reader(P("d.h5"));
  for (const auto& r : runs) {
    // The first frame at or after the run's gross-slip onset.
    const double onset_s = reader.ReadRunSummary(r.run).attrs.at("gross_slip_onset_s");
    ASSERT_GE(r.onset_frame, r.first_frame);
    ASSERT_GT(r.onset_frame, 0);
    EXPECT_GE(r.frames[r.onset_frame].time_s, onset_s - 1e-9) << "run " << r.run;
    EXPECT_LT(r.frames[r.onset_frame - 1].time_s, onset_s - 1e-9) << "run " << r.run;
    EXPECT_NEAR(r.frame_rate_hz, 100.0, 1e-6);
    EXPECT_EQ(r.frames.front().size(), 127);
  }
}

TEST_F(DetectCliTest, TrainEvaluateAndDetectEveryKind) {
  for (const char* kind : {"threshold", "logreg", "svm-linear", "svm"}) {
    const std::string model = P(std::string(kind) + ".model");
    const CliResult t = Run(std::string("train ") + kind + " --data " + P("d.h5") + " --runs 0-3 --out " + model);
    ASSERT_EQ(t.code, 0) << kind << ": " << t.err;
    const CliResult e = Run("evaluate --model " + model + " --data " + P("d.h5") + " --runs 4-5 --per-run");
    ASSERT_EQ(e.code, 0) << kind << ": " << e.err;
    EXPECT_NE(e.out.find("F1"), std::string::npos) << e.out;
    EXPECT_NE(e.out.find("confusion (frames): TP"), std::string::npos) << e.out;
    const CliResult d = Run("detect --model " + model + " --data " + P("d.h5") + " --runs 4 --out " + P("dec.csv"));
    ASSERT_EQ(d.code, 0) << kind << ": " << d.err;
    const auto rows = SplitLines(Slurp(P("dec.csv")));
    ASSERT_GT(rows.size(), 100u);
    EXPECT_EQ(rows[0], "run,frame,time_s,slip");
    EXPECT_EQ(rows[1].rfind("4,0,0,", 0), 0u) << rows[1];
  }
}

TEST_F(DetectCliTest, CommandsReadingFlaggedRunsSaySoInOneLine) {
  // A healthy dataset: no note.
  const CliResult healthy = Run("report incipient " + P("d.h5"));
  ASSERT_EQ(healthy.code, 0) << healthy.err;
  EXPECT_EQ(healthy.err.find("flagged by run health"), std::string::npos) << healthy.err;
  // Every run flagged (the creep threshold at 0 flags the few micrometres every run has).
  const std::string flagged = P("flagged.h5");
  const CliResult g = Run("generate rail --runs 2 --speed-mm-s 1 --set rail.lift_mm=10 --set rail.hold_s=0.1 "
                          "--set health.max_stick_creep_um=0 --seed 5 --quiet --out " + flagged);
  ASSERT_EQ(g.code, 0) << g.err;
  const std::string model = P("flagged.model");
  const CliResult t = Run("train threshold --data " + flagged + " --runs 0 --out " + model);
  ASSERT_EQ(t.code, 0) << t.err;
  EXPECT_NE(t.err.find("tactip: note: 1 of the 1 run(s) read from '" + flagged +
                       "' are flagged by run health (health_ok = 0): run(s) 0; their ground truth is not to be "
                       "trusted ('tactip info " + flagged + "' gives the reasons)\n"),
            std::string::npos)
      << t.err;
  const CliResult e = Run("evaluate --model " + model + " --data " + flagged + " --runs 1");
  ASSERT_EQ(e.code, 0) << e.err;
  EXPECT_NE(e.err.find("1 of the 1 run(s) read from '" + flagged + "' are flagged by run health (health_ok = 0): run(s) 1;"),
            std::string::npos)
      << e.err;
  const CliResult d = Run("detect --model " + model + " --data " + flagged + " --out " + P("flagged.csv"));
  ASSERT_EQ(d.code, 0) << d.err;
  EXPECT_NE(d.err.find("2 of the 2 run(s) read from '" + flagged + "' are flagged by run health (health_ok = 0): run(s) 0, 1;"),
            std::string::npos)
      << d.err;
  for (const char* what : {"incipient", "signatures"}) {
    const CliResult r = Run(std::string("report ") + what + " " + flagged);
    ASSERT_EQ(r.code, 0) << what << ": " << r.err;
    EXPECT_NE(r.err.find("are flagged by run health (health_ok = 0): run(s) 0, 1;"), std::string::npos)
        << what << ": " << r.err;
  }
  const CliResult p = Run("plot " + flagged + " --run 1 --no-plots --out " + P("figs"));
  ASSERT_EQ(p.code, 0) << p.err;
  EXPECT_NE(p.err.find("1 of the 1 run(s) read from '" + flagged + "' are flagged by run health (health_ok = 0): run(s) 1;"),
            std::string::npos)
      << p.err;
}

TEST_F(DetectCliTest, SameDataAndSeedGiveTheSameModel) {
  ASSERT_EQ(Run("train svm --data " + P("d.h5") + " --runs 0-3 --seed 3 --out " + P("a.model")).code, 0);
  ASSERT_EQ(Run("train svm --data " + P("d.h5") + " --runs 0-3 --seed 3 --out " + P("b.model")).code, 0);
  EXPECT_EQ(Slurp(P("a.model")), Slurp(P("b.model")));
}

TEST_F(DetectCliTest, IncipientDetectWritesSlippingCounts) {
  const CliResult d = Run("detect incipient --data " + P("d.h5") + " --window 5 --speed-thr-px 0.2 --count-thr 4 --out " +
                          P("inc.csv"));
  ASSERT_EQ(d.code, 0) << d.err;
  const auto rows = SplitLines(Slurp(P("inc.csv")));
  EXPECT_EQ(rows[0], "run,frame,time_s,slip,n_slipping");
  const auto runs = LoadDatasetRuns(P("d.h5"), {});
  size_t frames = 0;
  for (const auto& r : runs) frames += r.frames.size();
  EXPECT_EQ(rows.size(), frames + 1) << "one row per frame of every run";
}

TEST_F(DetectCliTest, ResponseStrategyAndContactMeasureOptions) {
  ASSERT_EQ(Run("train threshold --data " + P("d.h5") + " --runs 0-3 --out " + P("r.model")).code, 0);
  const CliResult d = Run("detect --model " + P("r.model") + " --data " + P("d.h5") +
                          " --runs 4 --response 2Fr1Sen --contact-measure --out " + P("r.csv"));
  ASSERT_EQ(d.code, 0) << d.err;
  EXPECT_NE(d.err.find("threshold+2Fr1Sen"), std::string::npos) << d.err;
  const auto rows = SplitLines(Slurp(P("r.csv")));
  EXPECT_EQ(rows[0], "run,frame,time_s,slip,d_px");
  EXPECT_EQ(rows[1], "4,0,0,0,0") << "first frame: no decision, no displacement";
  const CliResult e = Run("evaluate --model " + P("r.model") + " --data " + P("d.h5") + " --runs 4-5 --response 2Fr1Sen");
  ASSERT_EQ(e.code, 0) << e.err;
  EXPECT_NE(e.out.find("detector threshold+2Fr1Sen"), std::string::npos) << e.out;
  const CliResult bad = Run("detect --model " + P("r.model") + " --data " + P("d.h5") + " --response 2Fr --out " +
                            P("x.csv"));
  EXPECT_EQ(bad.code, 2);
  EXPECT_NE(bad.err.find("2Fr"), std::string::npos) << bad.err;
}

TEST_F(DetectCliTest, RealTacTipCsvGoesThroughTheSameDetector) {
  // A CSV recording made from run 4's frames gives the same decisions as the dataset.
  ASSERT_EQ(Run("train threshold --data " + P("d.h5") + " --runs 0-3 --out " + P("t.model")).code, 0);
  const auto runs = LoadDatasetRuns(P("d.h5"), {4});
  WritePinCsv(P("rec.csv"), runs[0].frames);
  ASSERT_EQ(Run("detect --model " + P("t.model") + " --data " + P("rec.csv") + " --out " + P("c.csv")).code, 0);
  ASSERT_EQ(Run("detect --model " + P("t.model") + " --data " + P("d.h5") + " --runs 4 --out " + P("h.csv")).code, 0);
  const auto c = SplitLines(Slurp(P("c.csv"))), h = SplitLines(Slurp(P("h.csv")));
  ASSERT_EQ(c.size(), h.size());
  for (size_t i = 1; i < c.size(); ++i) {
    // Same frame, time and decision; only the run column differs (CSV input is run 0).
    EXPECT_EQ(c[i].substr(c[i].find(',')), h[i].substr(h[i].find(','))) << "row " << i;
  }
}

TEST_F(DetectCliTest, BadDetectorInputGetsOneLineAndExitCode2) {
  std::ofstream(P("bad.model")) << "tactip-detector svm-rbf 1\nC banana\n";
  std::ofstream(P("bad.csv")) << "frame,time_s,pin,x_px,y_px\n0,0.0,0,1,1\n0,0.0,1,2,2\n1,0.01,0,1,1\n";
  std::ofstream(P("back.csv")) << "frame,time_s,pin,x_px,y_px\n0,0.02,0,1,1\n1,0.01,0,1,1\n";
  std::ofstream(P("nan.csv")) << "frame,time_s,pin,x_px,y_px\n0,0.0,0,nan,1\n";
  std::ofstream(P("nan_time.csv")) << "frame,time_s,pin,x_px,y_px\n0,0.0,0,1,1\n1,nan,0,1,1\n";
  struct Case {
    std::string args, fragment;
  } cases[] = {
      {"evaluate --model " + P("bad.model") + " --data " + P("d.h5"), "bad.model"},
      {"evaluate --model " + P("missing.model") + " --data " + P("d.h5"), "missing.model"},
      {"train svm --data " + P("d.h5") + " --runs 99 --out " + P("x.model"), "has no run 99"},
      {"train svm --data " + P("d.h5") + " --runs 0-1 --features speed --out " + P("x.model"), "features 'speed'"},
      {"train logreg --data " + P("d.h5") + " --c-grid 1,-2 --out " + P("x.model"), "--c-grid"},
      {"train logreg --data " + P("d.h5") + " --c-grid 1,inf --out " + P("x.model"), "--c-grid"},
      {"train svm --data " + P("d.h5") + " --out /nonexistent/x.model", "folder '/nonexistent' does not exist"},
      {"evaluate --model " + P("bad.model") + " --data " + P("d.h5") + " --runs 0-99999999", "range larger"},
      {"detect --data " + P("d.h5") + " --out " + P("x.csv"), "needs --model"},
      {"detect incipient --window 0 --data " + P("d.h5") + " --out " + P("x.csv"), "window = 0"},
      {"detect incipient --data " + P("bad.csv") + " --out " + P("x.csv"), "frame 1 has 1 pins"},
      {"detect incipient --data " + P("back.csv") + " --out " + P("x.csv"), "time not increasing"},
      {"detect incipient --data " + P("nan.csv") + " --out " + P("x.csv"), "nan.csv"},
      {"detect incipient --data " + P("nan_time.csv") + " --out " + P("x.csv"), "time_s 'nan' is not finite"},
  };
  for (const auto& c : cases) {
    const CliResult r = Run(c.args);
    EXPECT_EQ(r.code, 2) << c.args << "\n" << r.err;
    EXPECT_EQ(SplitLines(r.err).size(), 1u) << c.args << "\n" << r.err;
    EXPECT_NE(r.err.find(c.fragment), std::string::npos) << c.args << "\n" << r.err;
    EXPECT_FALSE(fs::exists(P("x.model")) || fs::exists(P("x.csv"))) << c.args;
  }
}

TEST_F(DetectCliTest, OutputThatIsAnInputIsRefusedBeforeAnyWork) {
  ASSERT_EQ(Run("train threshold --data " + P("d.h5") + " --runs 0-3 --out " + P("o.model")).code, 0);
  ASSERT_EQ(Run("detect --model " + P("o.model") + " --data " + P("d.h5") + " --runs 4 --out " + P("o.csv")).code, 0);
  const auto runs = LoadDatasetRuns(P("d.h5"), {4});
  WritePinCsv(P("in.csv"), runs[0].frames);
  fs::create_directories(P("ob"));
  fs::copy_file(P("o.model"), P("ob/threshold.model"));
  fs::create_symlink(P("d.h5"), P("link.h5"));
  const std::string data = Slurp(P("d.h5")), model = Slurp(P("o.model")), csv = Slurp(P("in.csv"));
  struct Case {
    std::string args, message;
  } cases[] = {
      {"train threshold --data " + P("d.h5") + " --out " + P("d.h5"), "--out '" + P("d.h5") + "' is the same file as --data"},
      {"train svm --data " + P("d.h5") + " --out " + P("link.h5"), "is the same file as --data"},
      {"report incipient " + P("d.h5") + " --csv " + P("d.h5"), "--csv '" + P("d.h5") + "' is the same file as FILE"},
      {"detect incipient --data " + P("in.csv") + " --out " + P("in.csv"), "is the same file as --data"},
      {"detect --model " + P("o.model") + " --data " + P("d.h5") + " --out " + P("o.model"),
       "--out '" + P("o.model") + "' is the same file as --model"},
      {"detect --model " + P("o.model") + " --data " + P("d.h5") + " --out " + P("d.h5"), "is the same file as --data"},
      {"bench --dataset " + P("ob/threshold.model") + " --out " + P("ob"),
       "--out '" + P("ob/threshold.model") + "' is the same file as --dataset"},
  };
  for (const auto& c : cases) {
    const CliResult r = Run(c.args);
    EXPECT_EQ(r.code, 2) << c.args << "\n" << r.err;
    EXPECT_EQ(SplitLines(r.err).size(), 1u) << c.args << "\n" << r.err;
    EXPECT_NE(r.err.find(c.message), std::string::npos) << c.args << "\n" << r.err;
    EXPECT_NE(r.err.find("the output would overwrite the input"), std::string::npos) << r.err;
  }
  EXPECT_EQ(Slurp(P("d.h5")), data);
  EXPECT_EQ(Slurp(P("o.model")), model);
  EXPECT_EQ(Slurp(P("in.csv")), csv);
}

TEST_F(DetectCliTest, FoldsBeyondTheTrainingRunsAreRefused) {
  const CliResult t = Run("train svm --data " + P("d.h5") + " --runs 0-3 --folds 10 --out " + P("f.model"));
  EXPECT_EQ(t.code, 2);
  EXPECT_EQ(t.err, "tactip: --folds 10: more folds than the 4 training run(s) (a fold holds whole runs); use --folds "
                   "2 to 4\n");
  // The benchmark trains on the first half: 3 of the 6 runs.
  const CliResult b = Run("bench --dataset " + P("d.h5") + " --folds 4 --out " + P("fb"));
  EXPECT_EQ(b.code, 2);
  EXPECT_NE(b.err.find("--folds 4: more folds than the 3 training run(s)"), std::string::npos) << b.err;
  EXPECT_FALSE(fs::exists(P("fb")));
  EXPECT_FALSE(fs::exists(P("f.model")));
  // Without --folds, fewer runs than the default 4 folds still train (one fold per run).
  EXPECT_EQ(Run("train logreg --data " + P("d.h5") + " --runs 0-2 --c-grid 1,10 --out " + P("f.model")).code, 0);
}

TEST_F(DetectCliTest, TrainChecksItsOutputFolderBeforeTraining) {
  const CliResult r = Run("train svm --data " + P("d.h5") + " --out /proc/m.model");
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(r.err.rfind("tactip: cannot write '/proc/m.model': cannot create a file in folder '/proc' (", 0), 0u)
      << r.err;
  EXPECT_EQ(r.err.find("training set"), std::string::npos) << "trained first: " << r.err;
}

TEST_F(DetectCliTest, BenchOnAGivenDatasetIsReproducible) {
  const std::string common = "bench --dataset " + P("d.h5") + " --c-grid 1,10 --gamma-grid 0.25 --folds 2 --out ";
  const CliResult a = Run(common + P("b1"));
  ASSERT_EQ(a.code, 0) << a.err;
  ASSERT_EQ(Run(common + P("b2")).code, 0);
  for (const char* name : {"threshold", "logreg", "svm-linear", "svm-rbf", "svm-rbf/dtheta", "incipient"}) {
    EXPECT_NE(a.out.find(name), std::string::npos) << name;
  }
  // Every column but the two timing ones is identical between the two runs.
  const auto r1 = SplitLines(Slurp(P("b1/bench.csv"))), r2 = SplitLines(Slurp(P("b2/bench.csv")));
  ASSERT_EQ(r1.size(), 10u) << "header + 9 detectors";
  ASSERT_EQ(r1.size(), r2.size());
  auto strip_timing = [](const std::string& row) {
    std::vector<std::string> f;
    std::stringstream ss(row);
    std::string x;
    while (std::getline(ss, x, ',')) f.push_back(x);
    f.erase(f.begin() + 8, f.begin() + 10);  // us_per_frame_mean, us_per_frame_p99
    std::string out;
    for (const auto& y : f) out += y + ",";
    return out;
  };
  for (size_t i = 0; i < r1.size(); ++i) EXPECT_EQ(strip_timing(r1[i]), strip_timing(r2[i]));
  EXPECT_EQ(Slurp(P("b1/svm-rbf.model")), Slurp(P("b2/svm-rbf.model")));
  // The files the same-file check guards are exactly the ones written.
  BenchOptions o;
  o.dataset = P("d.h5");
  std::set<std::string> expected, written;
  for (const auto& f : BenchOutputFiles(o)) expected.insert(f);
  for (const auto& e : fs::directory_iterator(P("b1"))) written.insert(e.path().filename().string());
  EXPECT_EQ(written, expected);
  const std::string json = Slurp(P("b1/bench.json"));
  for (const char* key : {"\"dataset\"", "\"detectors\"", "\"f1\"", "\"precision\"", "\"recall\"", "\"accuracy\"",
                          "\"delay_ms\"", "\"fp_per_min\"", "\"us_per_frame_mean\"", "\"us_per_frame_p99\""}) {
    EXPECT_NE(json.find(key), std::string::npos) << key;
  }
}

// The onset column of `evaluate --per-run`'s run lines.
std::vector<int> OnsetFrames(const std::string& table) {
  std::vector<int> out;
  for (const std::string& line : SplitLines(table)) {
    std::stringstream ss(line);
    int run = 0, tp = 0, fp = 0, tn = 0, fn = 0, onset = 0;
    if (ss >> run >> tp >> fp >> tn >> fn >> onset) out.push_back(onset);
  }
  return out;
}

TEST_F(DetectCliTest, MarkerLabelsScoreWithTheMarkerCamerasLaterOnset) {
  const std::string model = P("thr_marker.model");
  ASSERT_EQ(Run("train threshold --data " + P("d.h5") + " --runs 0-3 --labels marker --out " + model).code, 0);
  const CliResult exact = Run("evaluate --model " + model + " --data " + P("d.h5") + " --runs 4-5 --per-run");
  const CliResult marker =
      Run("evaluate --model " + model + " --data " + P("d.h5") + " --runs 4-5 --per-run --labels marker");
  ASSERT_EQ(exact.code, 0) << exact.err;
  ASSERT_EQ(marker.code, 0) << marker.err;
  const std::vector<int> a = OnsetFrames(exact.out), b = OnsetFrames(marker.out);
  ASSERT_EQ(a.size(), 2u) << exact.out;
  ASSERT_EQ(b.size(), 2u) << marker.out;
  // The object has to drop 1 mm before the marker camera sees it: 2-8 frames at 100 fps.
  for (size_t i = 0; i < a.size(); ++i) {
    EXPECT_GE(b[i] - a[i], 2) << exact.out << marker.out;
    EXPECT_LE(b[i] - a[i], 8) << exact.out << marker.out;
  }
  const CliResult bad = Run("evaluate --model " + model + " --data " + P("d.h5") + " --labels camera");
  EXPECT_EQ(bad.code, 2);
  EXPECT_NE(bad.err.find("--labels"), std::string::npos) << bad.err;
}

TEST_F(DetectCliTest, TheMixedSetHasEveryStimulusAndDrawnSpeeds) {
  const CliResult r = Run("bench --standard-set mixed --runs 16 --labels marker --set rail.lift_mm=10 --set "
                          "rail.hold_s=0.1 --c-grid 1 --gamma-grid 0.25 --folds 2 --jobs 2 --out " + P("mixed"));
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("set mixed | labels marker"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("train: 8 runs"), std::string::npos) << r.out;
  std::vector<double> speeds;
  for (const std::string& stimulus : MixedSetStimuli()) {
    const DatasetReader reader(P("mixed/bench-mixed-" + stimulus + ".h5"));
    ASSERT_EQ(reader.run_indices().size(), 4u) << stimulus;
    for (int k : reader.run_indices()) {
      const RunRecord run = reader.ReadRunSummary(k);
      EXPECT_EQ(run.text_attrs.at("stimulus"), stimulus);
      speeds.push_back(run.attrs.at("retract_speed_mm_s"));
    }
  }
  for (double v : speeds) {
    EXPECT_GE(v, 0.1);
    EXPECT_LE(v, 5.0);
  }
  EXPECT_GT(*std::max_element(speeds.begin(), speeds.end()) - *std::min_element(speeds.begin(), speeds.end()), 1.0);
  BenchOptions o;
  o.standard_set = "mixed";
  std::set<std::string> expected, written;
  for (const auto& f : BenchOutputFiles(o)) expected.insert(f);
  for (const auto& e : fs::directory_iterator(P("mixed"))) written.insert(e.path().filename().string());
  EXPECT_EQ(written, expected);
  const CliResult speed = Run("bench --standard-set mixed --speed-mm-s 1 --out " + P("m2"));
  EXPECT_EQ(speed.code, 2);
  EXPECT_NE(speed.err.find("--speed-mm-s"), std::string::npos) << speed.err;
  EXPECT_FALSE(fs::exists(P("m2")));
}

}  // namespace
}  // namespace tactip
