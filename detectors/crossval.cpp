// Grouped cross-validation, F1 and standardisation of the trained detectors.

#include "detectors/crossval.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <exception>
#include <functional>
#include <limits>
#include <mutex>
#include <set>
#include <stdexcept>
#include <thread>

#include "sim/base/number_text.h"

namespace tactip {

std::vector<int> GroupFolds(const std::vector<int>& group, int k) {
  if (k < 1) throw InputError("cv_folds = " + std::to_string(k) + ": must be >= 1");
  // Sorted distinct groups go round-robin to the folds.
  const std::vector<int> distinct = [&] {
    std::vector<int> g(group);
    std::sort(g.begin(), g.end());
    g.erase(std::unique(g.begin(), g.end()), g.end());
    return g;
  }();
  std::vector<int> fold(group.size());
  for (size_t r = 0; r < group.size(); ++r) {
    const auto it = std::lower_bound(distinct.begin(), distinct.end(), group[r]);
    fold[r] = static_cast<int>(it - distinct.begin()) % k;
  }
  return fold;
}

double F1Score(const std::vector<int>& truth, const std::vector<int>& pred) {
  if (truth.size() != pred.size()) {
    throw InputError("F1: " + std::to_string(truth.size()) + " labels but " + std::to_string(pred.size()) +
                     " predictions");
  }
  long tp = 0, fp = 0, fn = 0;
  for (size_t i = 0; i < truth.size(); ++i) {
    const bool t = truth[i] == 1, p = pred[i] == 1;
    tp += t && p;
    fp += !t && p;
    fn += t && !p;
  }
  const long den = 2 * tp + fp + fn;
  return den > 0 ? 2.0 * static_cast<double>(tp) / static_cast<double>(den) : 0.0;
}

Standardizer Standardizer::Fit(const Eigen::MatrixXf& x) {
  if (x.rows() == 0) throw InputError("cannot fit a standardizer on 0 rows");
  const Eigen::Index n = x.rows(), d = x.cols();
  Standardizer s;
  s.mean.resize(d);
  s.inv_std.resize(d);
  for (Eigen::Index j = 0; j < d; ++j) {
    // Two-pass mean and population variance in double.
    const auto col = x.col(j);
    double sum = 0.0;
    for (Eigen::Index i = 0; i < n; ++i) sum += col[i];
    const double mean = sum / static_cast<double>(n);
    double ss = 0.0;
    for (Eigen::Index i = 0; i < n; ++i) ss += (col[i] - mean) * (col[i] - mean);
    const double sd = std::sqrt(ss / static_cast<double>(n));
    // Exactly constant columns (and ones too narrow for a float scale) are left unscaled.
    const bool constant = col.minCoeff() == col.maxCoeff();
    s.mean[j] = static_cast<float>(mean);
    const float inv = static_cast<float>(1.0 / sd);
    s.inv_std[j] = constant || !(sd > 0.0) || !std::isfinite(inv) ? 1.0f : inv;
  }
  return s;
}

void Standardizer::Apply(Eigen::VectorXf& x) const {
  if (x.size() != mean.size()) {
    throw InputError("feature vector has " + std::to_string(x.size()) + " values, the standardizer " +
                     std::to_string(mean.size()));
  }
  x.array() = (x.array() - mean.array()) * inv_std.array();
}

void Standardizer::ApplyRows(Eigen::MatrixXf& x) const {
  if (x.cols() != mean.size()) {
    throw InputError("feature rows have " + std::to_string(x.cols()) + " columns, the standardizer " +
                     std::to_string(mean.size()));
  }
  for (Eigen::Index i = 0; i < x.rows(); ++i) {
    x.row(i).array() = (x.row(i).array() - mean.transpose().array()) * inv_std.transpose().array();
  }
}

namespace {

// Fold f's out-of-fold predictions for every candidate: fit on the other folds' rows
// (standardised with their statistics only), predict this fold's rows into `oof` (each
// fold writes only its own rows). A one-class training side predicts its class.
void PredictFold(const TrainingSet& ts, const std::vector<int>& fold, int f, const std::vector<CvCandidate>& grid,
                 const CvFitPredict& fit, std::vector<std::vector<int>>& oof) {
  const int n = static_cast<int>(ts.y.size());
  const Eigen::Index d = ts.x.cols();
  std::vector<int> train_rows, test_rows;
  for (int r = 0; r < n; ++r) (fold[r] == f ? test_rows : train_rows).push_back(r);
  Eigen::MatrixXf x_train(static_cast<Eigen::Index>(train_rows.size()), d);
  Eigen::MatrixXf x_test(static_cast<Eigen::Index>(test_rows.size()), d);
  std::vector<int> y_train(train_rows.size());
  for (size_t i = 0; i < train_rows.size(); ++i) {
    x_train.row(static_cast<Eigen::Index>(i)) = ts.x.row(train_rows[i]);
    y_train[i] = ts.y[train_rows[i]];
  }
  for (size_t i = 0; i < test_rows.size(); ++i) x_test.row(static_cast<Eigen::Index>(i)) = ts.x.row(test_rows[i]);
  const Standardizer s = Standardizer::Fit(x_train);
  s.ApplyRows(x_train);
  s.ApplyRows(x_test);
  const bool has_slip = std::find(y_train.begin(), y_train.end(), 1) != y_train.end();
  const bool has_static = std::find(y_train.begin(), y_train.end(), 0) != y_train.end();
  std::vector<std::vector<int>> pred;
  if (has_slip && has_static) {
    pred = fit(x_train, y_train, x_test, grid);
  } else {
    pred.assign(grid.size(), std::vector<int>(test_rows.size(), has_slip ? 1 : 0));
  }
  if (pred.size() != grid.size()) throw std::logic_error("CV fit returned the wrong number of candidates");
  for (size_t c = 0; c < grid.size(); ++c) {
    if (pred[c].size() != test_rows.size()) throw std::logic_error("CV fit returned the wrong number of rows");
    for (size_t i = 0; i < test_rows.size(); ++i) oof[c][test_rows[i]] = pred[c][i];
  }
}

// Runs run_fold(0 .. folds-1) on up to `folds` threads; errors are rethrown in fold order.
void ForEachFold(int folds, const std::function<void(int)>& run_fold) {
  const int n_threads = std::max(1, std::min<int>(folds, static_cast<int>(std::thread::hardware_concurrency())));
  std::atomic<int> next{0};
  std::vector<std::exception_ptr> errors(folds);
  auto worker = [&] {
    for (int f = next.fetch_add(1); f < folds; f = next.fetch_add(1)) {
      try {
        run_fold(f);
      } catch (...) {
        errors[f] = std::current_exception();
      }
    }
  };
  {
    std::vector<std::jthread> threads;
    for (int t = 1; t < n_threads; ++t) threads.emplace_back(worker);
    worker();
  }
  for (const auto& e : errors) {
    if (e) std::rethrow_exception(e);
  }
}

}  // namespace

CvReport GroupedGridSearch(const TrainingSet& ts, int k, const std::vector<CvCandidate>& grid,
                           const CvFitPredict& fit, const std::function<void(const std::string&)>& progress) {
  if (grid.empty()) throw InputError("hyperparameter grid is empty");
  if (k < 2) throw InputError("cv_folds = " + std::to_string(k) + ": must be >= 2");
  const int n = static_cast<int>(ts.y.size());
  CvReport report;
  report.n_rows = n;
  for (int y : ts.y) report.n_slip += y == 1;
  const double nan = std::numeric_limits<double>::quiet_NaN();

  // Too few runs: skip CV when there is nothing to choose, refuse otherwise.
  const int n_groups = static_cast<int>(std::set<int>(ts.group.begin(), ts.group.end()).size());
  if (n_groups < 2) {
    if (grid.size() == 1) {
      report.best_c = grid[0].c;
      report.best_gamma = grid[0].gamma;
      report.best_f1 = nan;
      report.grid.emplace_back(grid[0].c, grid[0].gamma, nan);
      return report;
    }
    throw InputError("grouped cross-validation needs at least 2 runs; the training set has " +
                     std::to_string(n_groups));
  }
  const int folds = std::min(k, n_groups);
  report.folds = folds;
  const std::vector<int> fold = GroupFolds(ts.group, folds);

  // Out-of-fold predictions per candidate, each fold announced as it finishes.
  std::vector<std::vector<int>> oof(grid.size(), std::vector<int>(n, 0));
  std::mutex progress_mu;
  int folds_done = 0;
  ForEachFold(folds, [&](int f) {
    PredictFold(ts, fold, f, grid, fit, oof);
    if (!progress) return;
    std::lock_guard lock(progress_mu);
    progress("cross-validation: fold " + std::to_string(f + 1) + " done (" + std::to_string(++folds_done) + "/" +
             std::to_string(folds) + " folds, " + std::to_string(grid.size()) + " candidate(s) each)");
  });

  // Score every candidate on the pooled out-of-fold predictions; first best wins.
  report.best_f1 = -1.0;
  for (size_t c = 0; c < grid.size(); ++c) {
    const double f1 = F1Score(ts.y, oof[c]);
    report.grid.emplace_back(grid[c].c, grid[c].gamma, f1);
    if (f1 > report.best_f1) {
      report.best_f1 = f1;
      report.best_c = grid[c].c;
      report.best_gamma = grid[c].gamma;
    }
  }
  if (progress) {
    char gamma[48] = "", line[160];
    if (report.best_gamma > 0.0) std::snprintf(gamma, sizeof gamma, ", gamma %.4g", report.best_gamma);
    std::snprintf(line, sizeof line, "cross-validation: best C %g%s, pooled F1 %.3f; fitting it on all %d rows",
                  report.best_c, gamma, report.best_f1, n);
    progress(line);
  }
  return report;
}

void CheckTrainingSet(const TrainingSet& ts) {
  const size_t n = ts.y.size();
  if (static_cast<size_t>(ts.x.rows()) != n || ts.group.size() != n) {
    throw InputError("training set has " + std::to_string(ts.x.rows()) + " feature rows, " +
                     std::to_string(n) + " labels and " + std::to_string(ts.group.size()) + " groups");
  }
  if (n == 0) throw InputError("training set is empty: no frames were selected");
  if (ts.x.cols() == 0) throw InputError("training set has no feature columns");
  if (!ts.x.allFinite()) throw InputError("training set has non-finite feature values");
  long slip = 0;
  for (size_t i = 0; i < n; ++i) {
    if (ts.y[i] != 0 && ts.y[i] != 1) {
      throw InputError("training set label " + std::to_string(ts.y[i]) + " in row " + std::to_string(i) +
                       ": must be 0 (static) or 1 (slip)");
    }
    slip += ts.y[i];
  }
  const size_t runs = std::set<int>(ts.group.begin(), ts.group.end()).size();
  const std::string where = std::to_string(n) + " rows from " + std::to_string(runs) + " runs";
  if (slip == 0) throw InputError("training set has no slip frames: " + where + " (do the runs have an onset?)");
  if (slip == static_cast<long>(n)) throw InputError("training set has no static frames: " + where);
}

void CheckPositiveGrid(const std::vector<double>& values, std::string_view what) {
  if (values.empty()) throw InputError(std::string(what) + " is empty: needs at least one value");
  for (double v : values) {
    if (!std::isfinite(v) || v <= 0.0) {
      throw InputError(std::string(what) + " value " + RoundTripText(v) + ": must be finite and > 0");
    }
  }
}

}  // namespace tactip
