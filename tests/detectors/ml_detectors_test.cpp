// Trained detectors (SVM, logistic regression) and their grouped cross-validation, on
// synthetic runs: static pins with pixel noise, then all pins jumping co-linearly at onset.

#include <gtest/gtest.h>

#include "scratch.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <atomic>
#include <mutex>
#include <thread>
#include <tuple>
#include <numbers>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "detectors/crossval.h"
#include "detectors/logreg.h"
#include "detectors/svm.h"
#include "detectors/text_io.h"

namespace tactip {
namespace {

using testing::TempPath;
using testing::WriteFile;

constexpr int kPins = 19;
constexpr int kFrames = 100;
constexpr int kFirstFrame = 5;
constexpr int kOnset = 60;
constexpr int kSlipFrames = 20;       // frames the pins keep moving after onset
constexpr double kNoisePx = 0.3;      // per-coordinate Gaussian pixel noise
constexpr double kSlipSpeedPx = 3.0;  // px/frame during slip
constexpr double kMinF1 = 0.95;
constexpr double kMomentTol = 1e-4;   // standardised mean / std tolerance

/// One synthetic run: fixed pin lattice plus noise; from kOnset all pins move co-linearly at
/// kSlipSpeedPx in a random direction for kSlipFrames frames.
LabeledRun MakeRun(int run, std::uint32_t seed) {
  std::mt19937 gen(seed);
  std::normal_distribution<float> noise(0.0f, static_cast<float>(kNoisePx));
  std::uniform_real_distribution<double> angle(0.0, 2.0 * std::numbers::pi);
  const double dir = angle(gen);
  LabeledRun r;
  r.run = run;
  r.first_frame = kFirstFrame;
  r.onset_frame = kOnset;
  for (int k = 0; k < kFrames; ++k) {
    const int moved = std::clamp(k - kOnset + 1, 0, kSlipFrames);
    const double off_x = kSlipSpeedPx * moved * std::cos(dir), off_y = kSlipSpeedPx * moved * std::sin(dir);
    PinFrame f;
    f.time_s = k * 0.01;
    f.pos_px.resize(kPins, 2);
    f.valid.assign(kPins, 1);
    for (int i = 0; i < kPins; ++i) {
      const double base_x = 200.0 + 12.0 * (i % 5), base_y = 150.0 + 12.0 * (i / 5);
      f.pos_px(i, 0) = static_cast<float>(base_x + off_x) + noise(gen);
      f.pos_px(i, 1) = static_cast<float>(base_y + off_y) + noise(gen);
    }
    r.frames.push_back(std::move(f));
  }
  return r;
}

/// `count` runs numbered from `first`, seeded from `seed`.
std::vector<LabeledRun> MakeRuns(int first, int count, std::uint32_t seed) {
  std::vector<LabeledRun> runs;
  for (int i = 0; i < count; ++i) runs.push_back(MakeRun(first + i, seed + 7919u * static_cast<std::uint32_t>(i)));
  return runs;
}

/// The default training options of these tests.
TrainOptions Options() {
  TrainOptions o;
  o.n_slip = 4;
  o.static_fraction = 0.4;
  o.seed = 3;
  return o;
}

/// Training runs 0-7 (shared by the tests; built once).
const std::vector<LabeledRun>& TrainRuns() {
  static const std::vector<LabeledRun> runs = MakeRuns(0, 8, 1234u);
  return runs;
}

/// Held-out runs 100-103 from another seed.
const std::vector<LabeledRun>& TestRuns() {
  static const std::vector<LabeledRun> runs = MakeRuns(100, 4, 98765u);
  return runs;
}

/// The training set of TrainRuns() with Options().
const TrainingSet& TrainSet() {
  static const TrainingSet ts = BuildTrainingSet(TrainRuns(), Options());
  return ts;
}

/// F1 of a detector streamed over whole runs, scored on the labelled window
/// [first_frame, onset + n_slip): static before the onset, slip from it.
double HeldOutF1(Detector& det, const std::vector<LabeledRun>& runs, int n_slip) {
  std::vector<int> truth, pred;
  for (const LabeledRun& run : runs) {
    det.Reset();
    for (int k = 0; k < static_cast<int>(run.frames.size()); ++k) {
      const Decision d = det.Update(run.frames[k]);
      if (k < run.first_frame || k >= run.onset_frame + n_slip) continue;
      truth.push_back(k >= run.onset_frame ? 1 : 0);
      pred.push_back(d.slip ? 1 : 0);
    }
  }
  return F1Score(truth, pred);
}

/// Every decision of a detector over one run.
std::vector<Decision> Stream(Detector& det, const LabeledRun& run) {
  det.Reset();
  std::vector<Decision> out;
  for (const PinFrame& f : run.frames) out.push_back(det.Update(f));
  return out;
}



/// Expects `fn` to throw InputError whose message contains every fragment.
template <typename Fn>
void ExpectInputError(Fn fn, const std::vector<std::string>& fragments) {
  try {
    fn();
    ADD_FAILURE() << "no InputError thrown; expected '" << fragments.front() << "'";
  } catch (const InputError& e) {
    for (const std::string& frag : fragments) {
      EXPECT_NE(std::string(e.what()).find(frag), std::string::npos) << "message: " << e.what() << "\nmissing: " << frag;
    }
  }
}

TEST(GroupFoldsTest, NeverSplitsAGroup) {
  std::mt19937 gen(5);
  std::uniform_int_distribution<int> pick(0, 12);
  std::vector<int> group(500);
  for (int& g : group) g = 3 * pick(gen) + 1;  // 13 distinct, non-contiguous ids
  const std::vector<int> fold = GroupFolds(group, 4);
  ASSERT_EQ(fold.size(), group.size());
  std::map<int, int> fold_of;
  for (size_t r = 0; r < group.size(); ++r) {
    EXPECT_GE(fold[r], 0);
    EXPECT_LT(fold[r], 4);
    const auto [it, inserted] = fold_of.emplace(group[r], fold[r]);
    EXPECT_EQ(it->second, fold[r]) << "group " << group[r] << " sits in two folds";
  }
  // Sorted groups go round-robin: 13 groups over 4 folds -> 4, 3, 3, 3.
  std::map<int, int> groups_per_fold;
  for (const auto& [g, f] : fold_of) ++groups_per_fold[f];
  EXPECT_EQ(groups_per_fold[0], 4);
  EXPECT_EQ(groups_per_fold[1], 3);
  EXPECT_EQ(groups_per_fold[3], 3);
}

TEST(GroupFoldsTest, IsDeterministicAndIndependentOfRowOrder) {
  const std::vector<int> a = {7, 7, 2, 9, 2, 5};
  const std::vector<int> b = {5, 9, 2, 7, 2, 7};
  const std::vector<int> fa = GroupFolds(a, 3), fb = GroupFolds(b, 3);
  EXPECT_EQ(fa, GroupFolds(a, 3));
  std::map<int, int> ma, mb;
  for (size_t i = 0; i < a.size(); ++i) ma[a[i]] = fa[i];
  for (size_t i = 0; i < b.size(); ++i) mb[b[i]] = fb[i];
  EXPECT_EQ(ma, mb);
  EXPECT_EQ(ma, (std::map<int, int>{{2, 0}, {5, 1}, {7, 2}, {9, 0}}));
  ExpectInputError([] { GroupFolds({1, 2}, 0); }, {"cv_folds = 0"});
}

TEST(F1ScoreTest, MatchesHandCountAndIsZeroWhenUndefined) {
  // tp = 2, fp = 1, fn = 1 -> F1 = 4 / 6.
  EXPECT_DOUBLE_EQ(F1Score({1, 1, 1, 0, 0, 0}, {1, 1, 0, 1, 0, 0}), 4.0 / 6.0);
  EXPECT_DOUBLE_EQ(F1Score({1, 0}, {1, 0}), 1.0);
  EXPECT_DOUBLE_EQ(F1Score({0, 0}, {0, 0}), 0.0);
  ExpectInputError([] { F1Score({1}, {1, 0}); }, {"1 labels but 2 predictions"});
}

TEST(StandardizerTest, GivesZeroMeanUnitVarianceAndLeavesConstantColumnsUnscaled) {
  std::mt19937 gen(11);
  std::normal_distribution<float> n(5.0f, 2.0f);
  Eigen::MatrixXf x(400, 3);
  for (int i = 0; i < 400; ++i) x.row(i) << n(gen), 0.5f * n(gen) - 3.0f, 7.25f;
  const Standardizer s = Standardizer::Fit(x);
  EXPECT_EQ(s.dim(), 3);
  EXPECT_EQ(s.inv_std[2], 1.0f);
  EXPECT_EQ(s.mean[2], 7.25f);
  Eigen::MatrixXf y = x;
  s.ApplyRows(y);
  for (int j = 0; j < 2; ++j) {
    EXPECT_NEAR(y.col(j).mean(), 0.0, kMomentTol);
    EXPECT_NEAR(std::sqrt(y.col(j).squaredNorm() / 400.0), 1.0, kMomentTol);
  }
  EXPECT_TRUE((y.col(2).array() == 0.0f).all());
  // Apply on one vector is the same arithmetic as ApplyRows.
  Eigen::VectorXf v = x.row(17).transpose();
  s.Apply(v);
  EXPECT_EQ(v, y.row(17).transpose());
  Eigen::VectorXf wrong(2);
  ExpectInputError([&] { s.Apply(wrong); }, {"2 values", "standardizer 3"});
  ExpectInputError([] { Standardizer::Fit(Eigen::MatrixXf(0, 3)); }, {"0 rows"});
}

TEST(GroupedGridSearchTest, StandardisesOnTrainingRowsAndPoolsOutOfFoldPredictions) {
  const TrainingSet& ts = TrainSet();
  int calls = 0;
  std::mutex mu;
  // Predict "slip" for every row: pooled F1 = 2P / (2P + N_static).
  const CvFitPredict fit = [&](const Eigen::MatrixXf& x_train, const std::vector<int>& y_train,
                               const Eigen::MatrixXf& x_test, const std::vector<CvCandidate>& grid) {
    const std::lock_guard<std::mutex> lock(mu);
    ++calls;
    EXPECT_EQ(static_cast<size_t>(x_train.rows()), y_train.size());
    EXPECT_EQ(x_train.rows() + x_test.rows(), ts.x.rows());
    for (Eigen::Index j = 0; j < x_train.cols(); ++j) EXPECT_NEAR(x_train.col(j).mean(), 0.0, kMomentTol);
    return std::vector<std::vector<int>>(grid.size(), std::vector<int>(x_test.rows(), 1));
  };
  const CvReport r = GroupedGridSearch(ts, 4, {{1.0, 0.0}, {2.0, 0.0}}, fit);
  EXPECT_EQ(calls, 4);
  EXPECT_EQ(r.folds, 4);
  EXPECT_EQ(r.n_rows, static_cast<int>(ts.y.size()));
  ASSERT_EQ(r.grid.size(), 2u);
  const double expect = 2.0 * r.n_slip / (2.0 * r.n_slip + (r.n_rows - r.n_slip));
  EXPECT_DOUBLE_EQ(std::get<2>(r.grid[0]), expect);
  EXPECT_EQ(r.best_c, 1.0);  // ties go to the first candidate
  ExpectInputError([&] { GroupedGridSearch(ts, 1, {{1.0, 0.0}}, fit); }, {"cv_folds = 1"});
}

TEST(GroupedGridSearchTest, ProgressHearsOfEveryFoldAndOfTheChoice) {
  const TrainingSet& ts = TrainSet();
  const CvFitPredict fit = [](const Eigen::MatrixXf&, const std::vector<int>&, const Eigen::MatrixXf& x_test,
                              const std::vector<CvCandidate>& grid) {
    return std::vector<std::vector<int>>(grid.size(), std::vector<int>(x_test.rows(), 1));
  };
  std::vector<std::string> lines;  // called one at a time (the search serialises it)
  GroupedGridSearch(ts, 3, {{1.0, 0.0}, {2.0, 0.5}}, fit, [&](const std::string& line) { lines.push_back(line); });
  ASSERT_EQ(lines.size(), 4u);
  for (int f = 0; f < 3; ++f) {
    EXPECT_NE(lines[f].find("/3 folds, 2 candidate(s) each"), std::string::npos) << lines[f];
  }
  EXPECT_NE(lines[3].find("best C 1, pooled F1"), std::string::npos) << lines[3];
  EXPECT_NE(lines[3].find("fitting it on all " + std::to_string(ts.y.size()) + " rows"), std::string::npos);
}

TEST(SvmDetectorTest, RbfReachesHighF1OnHeldOutRuns) {
  const auto det = SvmDetector::Train(TrainSet(), SvmDetector::Kernel::kRbf, Options());
  EXPECT_EQ(det->name(), "svm-rbf");
  EXPECT_GE(HeldOutF1(*det, TestRuns(), Options().n_slip), kMinF1);
  // The report covers the whole grid; gamma is scaled by 1/dim.
  const CvReport& cv = det->cv_report();
  EXPECT_EQ(cv.grid.size(), Options().c_grid.size() * Options().gamma_scale_grid.size());
  EXPECT_EQ(det->dim(), 2 * kPins);
  std::set<double> gammas, scaled;
  for (const auto& candidate : cv.grid) gammas.insert(std::get<1>(candidate));
  for (double g : Options().gamma_scale_grid) scaled.insert(g / det->dim());
  EXPECT_EQ(gammas, scaled);
  // The model is refitted with the first candidate of the highest out-of-fold F1.
  size_t best = 0;
  for (size_t i = 1; i < cv.grid.size(); ++i) {
    if (std::get<2>(cv.grid[i]) > std::get<2>(cv.grid[best])) best = i;
  }
  EXPECT_EQ(det->c(), std::get<0>(cv.grid[best]));
  EXPECT_EQ(det->gamma(), std::get<1>(cv.grid[best]));
  EXPECT_GE(std::get<2>(cv.grid[best]), kMinF1);
  EXPECT_GT(det->n_support_vectors(), 0);
}

TEST(SvmDetectorTest, LinearReachesHighF1OnHeldOutRuns) {
  const auto det = SvmDetector::Train(TrainSet(), SvmDetector::Kernel::kLinear, Options());
  EXPECT_EQ(det->name(), "svm-linear");
  EXPECT_GE(HeldOutF1(*det, TestRuns(), Options().n_slip), kMinF1);
  EXPECT_EQ(det->cv_report().grid.size(), Options().c_grid.size());
  EXPECT_EQ(det->gamma(), 0.0);
  // liblinear's weight vector, stored as libsvm's one support vector with coefficient 1.
  EXPECT_EQ(det->n_support_vectors(), 1);
}

TEST(LogRegDetectorTest, ReachesHighF1OnHeldOutRuns) {
  const auto det = LogRegDetector::Train(TrainSet(), Options());
  EXPECT_EQ(det->name(), "logreg");
  EXPECT_GE(HeldOutF1(*det, TestRuns(), Options().n_slip), kMinF1);
  EXPECT_GE(det->cv_report().best_f1, kMinF1);
}

TEST(SvmDetectorTest, ScoreIsPositiveExactlyWhenSlipAndFirstFrameIsStatic) {
  const auto det = SvmDetector::Train(TrainSet(), SvmDetector::Kernel::kRbf, Options());
  const std::vector<Decision> d = Stream(*det, TestRuns()[0]);
  EXPECT_FALSE(d[0].slip);
  EXPECT_EQ(d[0].score, 0.0);
  for (size_t k = 1; k < d.size(); ++k) EXPECT_EQ(d[k].slip, d[k].score > 0.0) << "frame " << k;
  EXPECT_TRUE(d[kOnset].slip);
  // After Reset the next frame has no velocity again, even mid-slip.
  det->Reset();
  EXPECT_FALSE(det->Update(TestRuns()[0].frames[kOnset + 1]).slip);
}

TEST(SvmDetectorTest, SaveLoadRoundTripGivesIdenticalDecisions) {
  for (const auto kernel : {SvmDetector::Kernel::kRbf, SvmDetector::Kernel::kLinear}) {
    const auto det = SvmDetector::Train(TrainSet(), kernel, Options());
    const std::string path = TempPath(det->name() + ".model");
    det->Save(path);
    const auto loaded = SvmDetector::Load(path);
    EXPECT_EQ(loaded->name(), det->name());
    EXPECT_EQ(loaded->c(), det->c());
    EXPECT_EQ(loaded->gamma(), det->gamma());
    EXPECT_EQ(loaded->standardizer().mean, det->standardizer().mean);
    EXPECT_EQ(loaded->standardizer().inv_std, det->standardizer().inv_std);
    EXPECT_TRUE(std::isnan(loaded->cv_report().best_f1));
    for (const LabeledRun& run : TestRuns()) {
      const std::vector<Decision> a = Stream(*det, run), b = Stream(*loaded, run);
      for (size_t k = 0; k < a.size(); ++k) {
        EXPECT_EQ(a[k].slip, b[k].slip);
        EXPECT_EQ(a[k].score, b[k].score);
      }
    }
    // Saving the loaded model reproduces the file byte for byte.
    const std::string again = TempPath(det->name() + ".again.model");
    loaded->Save(again);
    EXPECT_EQ(ReadText(path), ReadText(again));
    std::filesystem::remove(path);
    std::filesystem::remove(again);
  }
}

TEST(LogRegDetectorTest, SaveLoadRoundTripGivesIdenticalDecisions) {
  const auto det = LogRegDetector::Train(TrainSet(), Options());
  const std::string path = TempPath("logreg.model");
  det->Save(path);
  EXPECT_EQ(ReadText(path).rfind("tactip-detector logreg 1\n", 0), 0u);
  const auto loaded = LogRegDetector::Load(path);
  EXPECT_EQ(loaded->c(), det->c());
  for (const LabeledRun& run : TestRuns()) {
    const std::vector<Decision> a = Stream(*det, run), b = Stream(*loaded, run);
    for (size_t k = 0; k < a.size(); ++k) {
      EXPECT_EQ(a[k].slip, b[k].slip);
      EXPECT_EQ(a[k].score, b[k].score);
      EXPECT_EQ(a[k].slip, a[k].score > 0.0);
    }
  }
  std::filesystem::remove(path);
}

TEST(SvmDetectorTest, TrainingTwiceGivesByteIdenticalModelFiles) {
  const std::string a = TempPath("det_a.model"), b = TempPath("det_b.model");
  SvmDetector::Train(TrainSet(), SvmDetector::Kernel::kRbf, Options())->Save(a);
  SvmDetector::Train(BuildTrainingSet(TrainRuns(), Options()), SvmDetector::Kernel::kRbf, Options())->Save(b);
  EXPECT_EQ(ReadText(a), ReadText(b));
  LogRegDetector::Train(TrainSet(), Options())->Save(a);
  LogRegDetector::Train(TrainSet(), Options())->Save(b);
  EXPECT_EQ(ReadText(a), ReadText(b));
  std::filesystem::remove(a);
  std::filesystem::remove(b);
}

/// Replaces the first occurrence of `from` in `s` (which must occur).
std::string Replace(std::string s, const std::string& from, const std::string& to) {
  const size_t at = s.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) s.replace(at, from.size(), to);
  return s;
}

/// The line of `text` that starts with `prefix`, without its newline.
std::string LineStartingWith(const std::string& text, const std::string& prefix) {
  const size_t at = text.find("\n" + prefix);
  if (at == std::string::npos) return "";
  return text.substr(at + 1, text.find('\n', at + 1) - at - 1);
}

TEST(SvmDetectorTest, CorruptOrMissingModelFileThrowsNamingThePath) {
  const std::string good_path = TempPath("good_rbf.model");
  SvmDetector::Train(TrainSet(), SvmDetector::Kernel::kRbf, Options())->Save(good_path);
  const std::string good = ReadText(good_path);
  const std::string rho = LineStartingWith(good, "rho ");
  const std::string without_last_sv = good.substr(0, good.rfind('\n', good.size() - 2) + 1);
  struct Case {
    std::string name, text, fragment;
  };
  const std::vector<Case> cases = {
      {"empty", "", "file ends early"},
      {"kind", Replace(good, "svm-rbf 1", "logreg 1"), "kind 'logreg' is not svm-rbf or svm-linear"},
      {"version", Replace(good, "svm-rbf 1", "svm-rbf 2"), "unsupported model version '2'"},
      {"features", Replace(good, "features drdtheta", "features xyz"), "features 'xyz'"},
      {"c", Replace(good, "\nC ", "\nC -"), "C must be > 0"},
      {"dim", Replace(good, "dim 38", "dim 37"), "'mean' has 38 values, expected 37"},
      {"mean", Replace(good, "\nmean ", "\nmean abc"), "is not a finite number"},
      {"marker", Replace(good, "libsvm-model", "svm-model"), "expected 'libsvm-model'"},
      {"kernel", Replace(good, "kernel_type rbf", "kernel_type linear"), "expected 'kernel_type rbf'"},
      {"rho", Replace(good, rho, "rho nan"), "rho 'nan' is not a finite number"},
      {"truncated", without_last_sv, "file ends early"},
      {"index", Replace(good, " 38:", " 39:"), "outside 1..38"},
      {"trailing", good + "extra\n", "unexpected text after the last support vector"},
      // Cut inside the last line: every prefix still parses, with a shortened last value.
      {"cut in the last value", good.substr(0, good.size() - 3), "the last support vector has no end of line"},
      {"cut after an entry", good.substr(0, good.rfind(' ') + 1), "the last support vector has no end of line"},
      {"no final newline", good.substr(0, good.size() - 1), "the last support vector has no end of line"},
      // Counts whose int sum overflows (undefined behaviour), or that are negative.
      {"nr_sv overflow", Replace(good, LineStartingWith(good, "nr_sv "), "nr_sv 2147483647 2"),
       "nr_sv 2147483647 2 does not add up to " + LineStartingWith(good, "total_sv ")},
      {"nr_sv negative", Replace(good, LineStartingWith(good, "nr_sv "), "nr_sv -1 2"),
       "nr_sv -1 2 does not add up to " + LineStartingWith(good, "total_sv ")},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    const std::string path = TempPath("corrupt_" + c.name + ".model");
    WriteFile(path, c.text);
    ExpectInputError([&] { SvmDetector::Load(path); }, {"'" + path + "'", c.fragment});
    std::filesystem::remove(path);
  }
  const std::string missing = TempPath("does_not_exist.model");
  ExpectInputError([&] { SvmDetector::Load(missing); }, {"'" + missing + "'"});
  std::filesystem::remove(good_path);
}

TEST(LogRegDetectorTest, CorruptOrMissingModelFileThrowsNamingThePath) {
  const std::string good_path = TempPath("good_logreg.model");
  LogRegDetector::Train(TrainSet(), Options())->Save(good_path);
  const std::string good = ReadText(good_path);
  const std::string truncated = good.substr(0, good.rfind('\n', good.size() - 2) + 1);
  struct Case {
    std::string name, text, fragment;
  };
  const std::vector<Case> cases = {
      {"kind", Replace(good, "logreg 1", "svm-rbf 1"), "kind 'svm-rbf' is not logreg"},
      {"solver", Replace(good, "solver_type L2R_LR", "solver_type L1R_LR"), "expected 'solver_type L2R_LR'"},
      {"nr_feature", Replace(good, "nr_feature 38", "nr_feature 37"), "nr_feature 37 differs from dim 38"},
      {"truncated", truncated, "file ends early"},
      {"weight", Replace(good, "\nw\n", "\nw\nx"), "weight 'x"},
      // Cut inside the last weight: what is left still parses as a (different) number.
      {"cut in the last weight", good.substr(0, good.find_last_not_of(" \n") - 1), "the last weight has no end of line"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    const std::string path = TempPath("corrupt_logreg_" + c.name + ".model");
    WriteFile(path, c.text);
    ExpectInputError([&] { LogRegDetector::Load(path); }, {"'" + path + "'", c.fragment});
    std::filesystem::remove(path);
  }
  const std::string missing = TempPath("does_not_exist_logreg.model");
  ExpectInputError([&] { LogRegDetector::Load(missing); }, {"'" + missing + "'"});
  std::filesystem::remove(good_path);
}

TEST(SvmDetectorTest, TrainingSetWithoutSlipOrStaticRowsThrows) {
  std::vector<LabeledRun> no_onset = MakeRuns(0, 4, 77u);
  for (LabeledRun& r : no_onset) r.onset_frame = -1;
  const TrainingSet static_only = BuildTrainingSet(no_onset, Options());
  ExpectInputError([&] { SvmDetector::Train(static_only, SvmDetector::Kernel::kRbf, Options()); },
                   {"training set has no slip frames"});
  ExpectInputError([&] { LogRegDetector::Train(static_only, Options()); }, {"training set has no slip frames"});
  TrainingSet slip_only = TrainSet();
  for (int& y : slip_only.y) y = 1;
  ExpectInputError([&] { SvmDetector::Train(slip_only, SvmDetector::Kernel::kLinear, Options()); },
                   {"training set has no static frames"});
}

TEST(SvmDetectorTest, BadOptionsAndWrongPinCountThrow) {
  TrainOptions o = Options();
  o.c_grid = {1.0, -2.0};
  ExpectInputError([&] { SvmDetector::Train(TrainSet(), SvmDetector::Kernel::kRbf, o); }, {"c_grid value -2"});
  o = Options();
  o.gamma_scale_grid = {};
  ExpectInputError([&] { SvmDetector::Train(TrainSet(), SvmDetector::Kernel::kRbf, o); }, {"gamma_scale_grid is empty"});
  // A frame with another pin count than the model was trained on.
  const auto det = LogRegDetector::Train(TrainSet(), Options());
  PinFrame f;
  f.pos_px = Eigen::Matrix<float, Eigen::Dynamic, 2>::Zero(7, 2);
  det->Update(f);
  ExpectInputError([&] { det->Update(f); }, {"14 features", "expects 38"});
}

}  // namespace
}  // namespace tactip

namespace tactip {
namespace {

TEST(SvmDetectorTest, ModelsLoadAndSaveFromManyThreadsAtOnce) {
  // libsvm's model reader keeps process-wide state; closed-loop trials load one detector
  // per trial on every worker thread.
  const std::string path = TempPath("threads.model");
  SvmDetector::Train(TrainSet(), SvmDetector::Kernel::kRbf, Options())->Save(path);
  const std::string text = ReadText(path);
  std::vector<std::thread> threads;
  std::atomic<int> identical{0};
  constexpr int kThreads = 8, kLoads = 20;
  for (int t = 0; t < kThreads; ++t) {
    threads.emplace_back([&, t] {
      for (int k = 0; k < kLoads; ++k) {
        const auto det = SvmDetector::Load(path);
        const std::string again = TempPath("threads." + std::to_string(t) + ".model");
        det->Save(again);
        if (ReadText(again) == text) ++identical;
        std::filesystem::remove(again);
      }
    });
  }
  for (auto& th : threads) th.join();
  EXPECT_EQ(identical.load(), kThreads * kLoads);
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace tactip
