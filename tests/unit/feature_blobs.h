#pragma once
// Labelled feature rows drawn around class centres, for the classifier tests.

#include <Eigen/Core>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>
#include <string>
#include <vector>

namespace hair::test {

/// Normal draws from a fixed generator (Box-Muller on its top 53 bits), the same on every
/// platform.
class NormalDraws {
 public:
  explicit NormalDraws(uint64_t seed) : random_(seed) {}
  double operator()() {
    double u = static_cast<double>(random_() >> 11) * 0x1.0p-53;
    double v = static_cast<double>(random_() >> 11) * 0x1.0p-53;
    return std::sqrt(-2 * std::log(1 - u)) * std::cos(2 * std::numbers::pi * v);
  }

 private:
  std::mt19937_64 random_;
};

struct LabelledRows {
  Eigen::MatrixXd features;     ///< n x d
  std::vector<int32_t> labels;  ///< n
};

/// `per_class` rows around each centre (row c of `centres`, label `labels[c]`), isotropic
/// with standard deviation `spread`, then column j multiplied by `column_scale[j]` (features
/// of different units). The classes are interleaved, not blocks of rows.
inline LabelledRows gaussian_blobs(const Eigen::MatrixXd& centres,
                                   const std::vector<int32_t>& labels, int per_class, double spread,
                                   const Eigen::RowVectorXd& column_scale, uint64_t seed) {
  NormalDraws normal(seed);
  auto k = static_cast<int>(centres.rows());
  LabelledRows rows;
  rows.features.resize(k * per_class, centres.cols());
  for (int i = 0; i < k * per_class; ++i) {
    int c = (i * 3 + 1) % k;
    for (Eigen::Index j = 0; j < centres.cols(); ++j)
      rows.features(i, j) = (centres(c, j) + spread * normal()) * column_scale[j];
    rows.labels.push_back(labels[static_cast<size_t>(c)]);
  }
  return rows;
}

/// Four classes (labels 0..3) at the corners of a tetrahedron-like set in 3-D, `distance`
/// apart along the axes, with columns in metres, thousands and thousandths.
inline LabelledRows four_blobs(int per_class, double spread, uint64_t seed, double distance = 4.0) {
  Eigen::MatrixXd centres(4, 3);
  centres << 0, 0, 0, distance, 0, 0, 0, distance, 0, 0, 0, distance;
  Eigen::RowVectorXd scale(3);
  scale << 1.0, 1000.0, 0.001;
  return gaussian_blobs(centres, {0, 1, 2, 3}, per_class, spread, scale, seed);
}

/// Rows of several models for the leave-one-model-out tests: features and labels, each
/// row's model, whether that model is a real mesh (held out) and its strands (weight).
struct ModelCorpus {
  LabelledRows data;
  std::vector<std::string> model;
  std::vector<bool> real;
  std::vector<double> strands;
};

/// four_blobs(per_class, spread, seed) as the synthetic rows of `models` models
/// ("synth_0", ...; row r in model r % models), 100 strands each; add the real models'
/// rows after.
inline ModelCorpus synthetic_model_corpus(int per_class, double spread, uint64_t seed, int models) {
  ModelCorpus corpus;
  corpus.data = four_blobs(per_class, spread, seed);
  for (size_t row = 0; row < corpus.data.labels.size(); ++row) {
    corpus.model.push_back("synth_" + std::to_string(row % static_cast<size_t>(models)));
    corpus.real.push_back(false);
    corpus.strands.push_back(100);
  }
  return corpus;
}

}  // namespace hair::test
