// Leave-one-model-out evaluations repeated with fresh seeds (hair-train-style
// --holdout-report --repeats): each repeat is the single evaluation with its seed, and the
// report gives the spread over the repeats and each held-out model's share right.
#include <gtest/gtest.h>

#include "../feature_blobs.h"
#include "hair/core/error.h"
#include "hair/style/repeated_model_holdout.h"

namespace hair {
namespace {

StyleClassifierParams quick_params(uint64_t seed) {
  StyleClassifierParams params;
  params.svm_grid = {{1, 4}, {1}, {1, 10}};
  params.forest.trees = 30;
  params.seed = seed;
  return params;
}

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

/// Four blobs over six synthetic models; real model "clear" drawn in class 2's blob and
/// labelled 2, real model "between" halfway between the blobs of classes 0 and 1 and
/// labelled 1, where the classifiers' draws decide.
using Corpus = test::ModelCorpus;

Corpus corpus_with_a_clear_and_an_unclear_model() {
  Corpus corpus = test::synthetic_model_corpus(20, 0.6, 7, 6);
  const test::LabelledRows drawn = test::four_blobs(6, 0.6, 8);
  Eigen::Index n = corpus.data.features.rows();
  for (Eigen::Index r = 0; r < drawn.features.rows(); ++r) {
    const int32_t label = drawn.labels[static_cast<size_t>(r)];
    if (label != 0 && label != 2) continue;
    corpus.data.features.conservativeResize(n + 1, Eigen::NoChange);
    corpus.data.features.row(n) = drawn.features.row(r);
    if (label == 0) {  // moved halfway towards class 1's centre (x = 4)
      corpus.data.features(n, 0) += 2.0;
      corpus.model.push_back("/runs/between");
      corpus.data.labels.push_back(1);
    } else {
      corpus.model.push_back("/runs/clear");
      corpus.data.labels.push_back(2);
    }
    corpus.real.push_back(true);
    corpus.strands.push_back(250);
    ++n;
  }
  return corpus;
}

TEST(RepeatedLeaveOneModelOut, EachRepeatIsTheSingleEvaluationWithItsSeed) {
  const Corpus corpus = corpus_with_a_clear_and_an_unclear_model();
  const RepeatedModelHoldout repeated =
      repeated_leave_one_model_out(corpus.data.features, corpus.data.labels, corpus.model,
                                   corpus.real, corpus.strands, quick_params(5), 3);
  ASSERT_EQ(repeated.seeds, (std::vector<uint64_t>{5, 6, 7}));
  ASSERT_EQ(repeated.repeats.size(), 3u);
  for (size_t r = 0; r < 3; ++r) {
    const ModelHoldout single =
        leave_one_model_out(corpus.data.features, corpus.data.labels, corpus.model, corpus.real,
                            corpus.strands, quick_params(5 + r));
    EXPECT_EQ(repeated.repeats[r].svm, single.svm) << "repeat " << r;
    EXPECT_EQ(repeated.repeats[r].forest, single.forest) << "repeat " << r;
    EXPECT_EQ(repeated.repeats[r].rows, single.rows);
  }
  const std::string markdown = repeated_model_holdout_markdown(repeated);
  EXPECT_TRUE(contains(markdown, "3 leave-one-model-out evaluations")) << markdown;
  EXPECT_TRUE(contains(markdown, "seeds 5 to 7")) << markdown;
  // The clear model is right whatever the draw; models are named by their folder.
  EXPECT_TRUE(contains(markdown, "| clear | 100.0% | 100.0% | 100.0% | 100.0% | 100.0% | 100.0% |"))
      << markdown;
  EXPECT_TRUE(contains(markdown, "| between | ")) << markdown;
  EXPECT_TRUE(repeated_model_holdout_markdown({}).empty());
}

TEST(RepeatedLeaveOneModelOut, RefusesNoRepeats) {
  const Corpus corpus = corpus_with_a_clear_and_an_unclear_model();
  EXPECT_THROW(repeated_leave_one_model_out(corpus.data.features, corpus.data.labels, corpus.model,
                                            corpus.real, corpus.strands, quick_params(1), 0),
               Error);
}

}  // namespace
}  // namespace hair
