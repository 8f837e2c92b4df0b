#include "hair/style/random_forest.h"

#include <algorithm>
#include <string>

#include "hair/core/error.h"

namespace hair {

void check_random_forest_params(const RandomForestParams& params) {
  auto outside = [](const char* name, int value, const char* range) {
    return Error::usage(std::string("random forest: ") + name + " = " + std::to_string(value) +
                        " is outside " + range);
  };
  if (params.trees < 1) throw outside("trees", params.trees, "[1, inf)");
  if (params.max_depth < 1 || params.max_depth > 20)
    throw outside("max_depth", params.max_depth, "[1, 20]");
  if (params.min_sample_count < 1)
    throw outside("min_sample_count", params.min_sample_count, "[1, inf)");
  if (params.active_var_count < 0)
    throw outside("active_var_count", params.active_var_count, "[0, inf)");
}

cv::Ptr<cv::ml::RTrees> trained_random_forest(const FloatRows& rows,
                                              std::span<const int32_t> labels,
                                              const RandomForestParams& params) {
  check_random_forest_params(params);
  if (static_cast<size_t>(rows.rows()) != labels.size() || labels.empty())
    throw Error::usage("random forest: " + std::to_string(rows.rows()) + " rows and " +
                       std::to_string(labels.size()) + " labels (need as many, at least one)");
  cv::Mat samples(static_cast<int>(rows.rows()), static_cast<int>(rows.cols()), CV_32F);
  std::copy(rows.data(), rows.data() + rows.size(), samples.ptr<float>());
  cv::Mat responses(static_cast<int>(labels.size()), 1, CV_32S);
  std::copy(labels.begin(), labels.end(), responses.ptr<int32_t>());

  cv::Ptr<cv::ml::RTrees> forest = cv::ml::RTrees::create();
  forest->setMaxDepth(params.max_depth);
  forest->setMinSampleCount(params.min_sample_count);
  forest->setActiveVarCount(params.active_var_count);
  forest->setRegressionAccuracy(0);
  forest->setUseSurrogates(false);
  forest->setCalculateVarImportance(false);
  forest->setCVFolds(0);
  forest->setPriors(cv::Mat());
  forest->setTermCriteria(cv::TermCriteria(cv::TermCriteria::COUNT, params.trees, 0));

  cv::RNG saved = cv::theRNG();
  cv::theRNG() = cv::RNG(params.seed);
  bool trained = false;
  try {
    trained = forest->train(cv::ml::TrainData::create(samples, cv::ml::ROW_SAMPLE, responses));
  } catch (const cv::Exception& error) {
    cv::theRNG() = saved;
    throw Error::runtime("",
                         std::string("random forest training failed in OpenCV: ") + error.what());
  }
  cv::theRNG() = saved;
  if (!trained) throw Error::runtime("", "random forest training failed in OpenCV");
  return forest;
}

ForestPrediction forest_prediction(const cv::ml::RTrees& forest,
                                   std::span<const int32_t> class_labels, const float* row,
                                   int feature_count) {
  cv::Mat sample(1, feature_count, CV_32F);
  std::copy(row, row + feature_count, sample.ptr<float>());
  cv::Mat votes;  // row 0: the forest's class labels; row 1: the votes for each
  forest.getVotes(sample, votes, 0);

  ForestPrediction prediction;
  prediction.votes.assign(class_labels.size(), 0);
  for (int column = 0; column < votes.cols; ++column) {
    auto found =
        std::lower_bound(class_labels.begin(), class_labels.end(), votes.at<int32_t>(0, column));
    if (found != class_labels.end() && *found == votes.at<int32_t>(0, column))
      prediction.votes[static_cast<size_t>(found - class_labels.begin())] =
          votes.at<int32_t>(1, column);
  }
  int32_t total = 0;
  size_t best = 0;
  for (size_t c = 0; c < prediction.votes.size(); ++c) {
    total += prediction.votes[c];
    if (prediction.votes[c] > prediction.votes[best]) best = c;
  }
  for (int32_t count : prediction.votes)
    prediction.vote_fraction.push_back(total > 0 ? static_cast<double>(count) / total : 0.0);
  prediction.label = class_labels.empty() ? 0 : class_labels[best];
  return prediction;
}

int32_t forest_label_without(std::span<const int32_t> class_labels, std::span<const double> votes,
                             int32_t excluded_label) {
  if (class_labels.size() != votes.size() || class_labels.empty())
    throw Error::usage("forest_label_without: " + std::to_string(votes.size()) + " votes for " +
                       std::to_string(class_labels.size()) + " classes");
  size_t best = class_labels.size();
  for (size_t c = 0; c < class_labels.size(); ++c)
    if (class_labels[c] != excluded_label &&
        (best == class_labels.size() || votes[c] > votes[best]))
      best = c;
  if (best == class_labels.size())
    best = static_cast<size_t>(std::max_element(votes.begin(), votes.end()) - votes.begin());
  return class_labels[best];
}

}  // namespace hair
