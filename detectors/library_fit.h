#pragma once
// What training on libsvm and on liblinear share: dense rows as the libraries' sparse nodes,
// the grouped grid search's fit-and-predict over them, and the final refit on every row.
// Header-only: each library's node type stays in its own .cpp (svm.cpp, logreg.cpp).

#include <Eigen/Core>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "detectors/crossval.h"

namespace tactip {

/// Dense rows as a library's nodes ({index, value}): indices 1..d, then the bias node d+1
/// when `bias` is given, then the -1 terminator, row after row.
template <class Node>
struct NodeRows {
  std::vector<Node> nodes;
  std::vector<Node*> rows;

  explicit NodeRows(const Eigen::MatrixXf& x, std::optional<double> bias = std::nullopt) {
    const Eigen::Index n = x.rows(), d = x.cols(), width = d + (bias ? 2 : 1);
    nodes.resize(static_cast<size_t>(n * width));
    rows.resize(static_cast<size_t>(n));
    for (Eigen::Index i = 0; i < n; ++i) {
      Node* row = &nodes[static_cast<size_t>(i * width)];
      for (Eigen::Index j = 0; j < d; ++j) row[j] = Node{static_cast<int>(j + 1), static_cast<double>(x(i, j))};
      if (bias) row[d] = Node{static_cast<int>(d + 1), *bias};
      row[width - 1] = Node{-1, 0.0};
      rows[static_cast<size_t>(i)] = row;
    }
  }
};

/// GroupedGridSearch's fit: for every candidate, `train(rows, y, candidate)` fits a model (an
/// owning pointer) on the training rows and `predict(model, row)` labels each test row.
/// `Rows` is constructible from a matrix (NodeRows with the library's node and bias).
template <class Rows, class Train, class Predict>
CvFitPredict FitAndPredictEachCandidate(Train train, Predict predict) {
  return [train, predict](const Eigen::MatrixXf& x_train, const std::vector<int>& y_train,
                          const Eigen::MatrixXf& x_test, const std::vector<CvCandidate>& candidates) {
    Rows train_rows(x_train);
    const Rows test_rows(x_test);
    std::vector<double> y(y_train.begin(), y_train.end());
    std::vector<std::vector<int>> pred(candidates.size(), std::vector<int>(test_rows.rows.size()));
    for (size_t c = 0; c < candidates.size(); ++c) {
      const auto model = train(train_rows, y, candidates[c]);
      for (size_t i = 0; i < test_rows.rows.size(); ++i) {
        pred[c][i] = static_cast<int>(predict(model.get(), test_rows.rows[i]));
      }
    }
    return pred;
  };
}

/// The final model: a Standardizer fitted on every row of `ts`, and the library's text
/// (`text(model)`) of the model `train` fits with `best` on the standardised rows, which is
/// what the detector then loads (so a trained and a reloaded detector are the same).
template <class Rows, class Train, class Text>
std::pair<Standardizer, std::string> RefitOnEveryRow(const TrainingSet& ts, const CvCandidate& best, Train train,
                                                     Text text) {
  Standardizer standardizer = Standardizer::Fit(ts.x);
  Eigen::MatrixXf x = ts.x;
  standardizer.ApplyRows(x);
  Rows rows(x);
  std::vector<double> y(ts.y.begin(), ts.y.end());
  std::string model_text = text(train(rows, y, best).get());
  return {std::move(standardizer), std::move(model_text)};
}

}  // namespace tactip
