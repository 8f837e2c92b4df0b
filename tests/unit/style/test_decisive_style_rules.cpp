// The paper's criteria where they are decisive (issue 26): hair lying on the scalp to its
// ends is short, a cap gathered into a band and going on past it is fixed; elsewhere
// the classifiers decide.
#include <gtest/gtest.h>

#include "hair/core/error.h"
#include "hair/style/decisive_style_rules.h"

namespace hair {
namespace {

/// Short hair combed flat on the head: on the scalp (0.02 H), ending in the cluster, its
/// ends as spread as the rest.
PaperFeatures lying_on_the_head() {
  PaperFeatures features;
  features.mean_length_h = 0.45;
  features.far_scalp_distance_h = 0.02;
  features.tip_share = 0.99;
  features.gathering_ratio = 0.55;
  features.root_share = 1.0;
  return features;
}

/// A ponytail's cap: from the roots, on the scalp, gathered into the band, and going on.
PaperFeatures cap_into_a_band() {
  PaperFeatures features;
  features.mean_length_h = 0.55;
  features.far_scalp_distance_h = 0.08;
  features.tip_share = 0.14;
  features.gathering_ratio = 0.24;
  features.root_share = 0.93;
  return features;
}

TEST(DecisiveStyleRules, HairLyingOnTheHeadToItsEndsIsShort) {
  DecisiveStyleRules rules;
  EXPECT_EQ(decisive_style(lying_on_the_head(), rules), HairStyle::short_hair);
  // Hair that leaves the scalp (a bob's hanging sides, 0.3 H off it) is not decided.
  PaperFeatures hanging = lying_on_the_head();
  hanging.far_scalp_distance_h = 0.3;
  EXPECT_FALSE(decisive_style(hanging, rules));
  // Nor the first piece of long hair lying on the scalp: it goes on into another cluster.
  PaperFeatures first_piece = lying_on_the_head();
  first_piece.tip_share = 0.2;
  EXPECT_FALSE(decisive_style(first_piece, rules));
  // Nor locks on the scalp whose ends gather (a face-framing lock, a cap into a band).
  PaperFeatures gathered = lying_on_the_head();
  gathered.gathering_ratio = 0.3;
  EXPECT_FALSE(decisive_style(gathered, rules));
}

TEST(DecisiveStyleRules, ACapGatheredIntoABandAndGoingOnIsFixed) {
  DecisiveStyleRules rules;
  EXPECT_EQ(decisive_style(cap_into_a_band(), rules), HairStyle::fixed);
  PaperFeatures ending_in_it = cap_into_a_band();  // a gathered lock that ends: not decided
  ending_in_it.tip_share = 0.9;
  EXPECT_FALSE(decisive_style(ending_in_it, rules));
  PaperFeatures off_the_scalp = cap_into_a_band();  // a tail, hanging off the head
  off_the_scalp.far_scalp_distance_h = 0.6;
  EXPECT_FALSE(decisive_style(off_the_scalp, rules));
  PaperFeatures not_from_roots = cap_into_a_band();  // a middle piece
  not_from_roots.root_share = 0.1;
  EXPECT_FALSE(decisive_style(not_from_roots, rules));
  PaperFeatures spread = cap_into_a_band();  // not gathered
  spread.gathering_ratio = 0.8;
  EXPECT_FALSE(decisive_style(spread, rules));
}

/// bob02's main cluster: from the roots, hanging to the jaw and ending
/// there, its ends as spread as the rest.
PaperFeatures hanging_from_the_roots() {
  PaperFeatures features;
  features.mean_length_h = 0.86;
  features.far_scalp_distance_h = 0.10;
  features.tip_share = 0.97;
  features.gathering_ratio = 0.76;
  features.root_share = 1.0;
  return features;
}

TEST(DecisiveStyleRules, StrandsFromTheRootsEndingUngatheredAreNotFixed) {
  DecisiveStyleRules rules;
  EXPECT_TRUE(fixed_ruled_out(hanging_from_the_roots(), rules));
  EXPECT_FALSE(decisive_style(hanging_from_the_roots(), rules));  // nothing decided
  EXPECT_TRUE(fixed_ruled_out(lying_on_the_head(), rules));       // short: not fixed either
  EXPECT_FALSE(fixed_ruled_out(cap_into_a_band(), rules));        // gathered, going on
  // A bun's cap ends in its coil, gathered or not, but its strands do not start at roots in
  // its cluster (hair-synth's buns: root share 0); a gathered lock ends gathered; a tail
  // hangs from the band, not the roots: none ruled out.
  PaperFeatures bun = hanging_from_the_roots();
  bun.root_share = 0.0;
  EXPECT_FALSE(fixed_ruled_out(bun, rules));
  PaperFeatures gathered = hanging_from_the_roots();
  gathered.gathering_ratio = 0.3;
  EXPECT_FALSE(fixed_ruled_out(gathered, rules));
  PaperFeatures going_on = hanging_from_the_roots();  // most strands go on past the cluster
  going_on.tip_share = 0.5;
  EXPECT_FALSE(fixed_ruled_out(going_on, rules));
}

TEST(DecisiveStyleRules, SwitchedOffTheyDecideNothing) {
  DecisiveStyleRules off;
  off.enabled = false;
  EXPECT_FALSE(decisive_style(lying_on_the_head(), off));
  EXPECT_FALSE(decisive_style(cap_into_a_band(), off));
  EXPECT_FALSE(fixed_ruled_out(hanging_from_the_roots(), off));
}

TEST(DecisiveStyleRules, RowsOfAFeatureTableByColumnName) {
  std::vector<std::string> names = {"mean_length_h", "root_share", "tip_share", "gathering_ratio",
                                    "far_scalp_distance_h"};
  Eigen::MatrixXd rows(3, 5);
  PaperFeatures a = lying_on_the_head(), b = cap_into_a_band();
  rows << a.mean_length_h, a.root_share, a.tip_share, a.gathering_ratio, a.far_scalp_distance_h,
      b.mean_length_h, b.root_share, b.tip_share, b.gathering_ratio, b.far_scalp_distance_h, 1.5,
      1.0, 1.0, 0.9, 0.7;  // long hair hanging: not decided
  EXPECT_TRUE(has_decisive_rule_features(names));
  EXPECT_EQ(decisive_styles_of_rows(rows, names, {}),
            (std::vector<int32_t>{static_cast<int32_t>(HairStyle::short_hair),
                                  static_cast<int32_t>(HairStyle::fixed), -1}));
  EXPECT_EQ(fixed_ruled_out_of_rows(rows, names, {}), (std::vector<uint8_t>{1, 0, 1}));
  std::vector<std::string> paper = {"mean_length_h", "root_share", "gathering_ratio",
                                    "far_scalp_distance_h", "twist_h"};
  EXPECT_FALSE(has_decisive_rule_features(paper));
  EXPECT_THROW(decisive_styles_of_rows(rows, paper, {}), Error);
  EXPECT_THROW(fixed_ruled_out_of_rows(rows, paper, {}), Error);
}

}  // namespace
}  // namespace hair

// The SVM's confidence as cluster_styles gives it (cluster_styles.h): its margin in the
// contests of the class it chose, on a hand-made three-class SVM; and the class each
// classifier gives when the rules rule one out.
#include "hair/style/cluster_styles.h"
#include "hair/style/puk_svm.h"
#include "hair/style/random_forest.h"

namespace hair {
namespace {

TEST(SvmMarginConfidence, TheSmallestMarginOfTheChosenClassesContests) {
  PukSvm svm;
  svm.class_labels = {0, 1, 2};
  for (auto [first, second] : {std::pair{0, 1}, std::pair{0, 2}, std::pair{1, 2}}) {
    SvmDecisionFunction function;
    function.first = first;
    function.second = second;
    svm.decision_functions.push_back(function);
  }
  // Class 0 beats 1 by 2.5 and 2 by 0.4: inside the margin of one contest.
  std::vector<double> values = {2.5, 0.4, -3.0};
  EXPECT_DOUBLE_EQ(svm_margin_confidence(svm, values, 0), 0.4);
  // Class 2 beats 1 by 3 but lost to 0: no confidence.
  EXPECT_DOUBLE_EQ(svm_margin_confidence(svm, values, 2), 0.0);
  // Beyond every margin: 1.
  std::vector<double> clear = {1.5, 2.0, 0.0};
  EXPECT_DOUBLE_EQ(svm_margin_confidence(svm, clear, 0), 1.0);
  EXPECT_THROW(svm_margin_confidence(svm, std::vector<double>{1.0}, 0), Error);
  // Class 0 ruled out: class 2's margin over the contests left, its win over 1 by 3.
  EXPECT_DOUBLE_EQ(svm_margin_confidence_without(svm, values, 2, 0), 1.0);
  EXPECT_DOUBLE_EQ(svm_margin_confidence_without(svm, std::vector<double>{2.5, 0.4, -0.3}, 2, 0),
                   0.3);
}

TEST(LabelWithout, TheVoteAmongTheClassesLeft) {
  PukSvm svm;
  svm.class_labels = {0, 1, 2, 3};  // normal, fixed, short, braided
  for (int first = 0; first < 4; ++first)
    for (int second = first + 1; second < 4; ++second) {
      SvmDecisionFunction function;
      function.first = first;
      function.second = second;
      svm.decision_functions.push_back(function);
    }
  // Pairs 01 02 03 12 13 23. Fixed (1) beats everything; short (2) beats normal and
  // braided; normal beats braided. Without fixed: short.
  std::vector<double> values = {-1.0, -0.5, 0.8, 2.0, 1.5, 0.7};
  EXPECT_EQ(svm_label_without(svm, values, 1), 2);
  // Excluding a class it does not know, or one that would not win: the SVM's own vote.
  EXPECT_EQ(svm_label_without(svm, values, 7), 1);
  EXPECT_EQ(svm_label_without(svm, values, 3), 1);
  EXPECT_THROW(svm_label_without(svm, std::vector<double>{1.0}, 1), Error);

  std::vector<int32_t> classes = {0, 1, 2, 3};
  std::vector<double> votes = {0.2, 0.5, 0.2, 0.1};
  EXPECT_EQ(forest_label_without(classes, votes, 1), 0);  // equals: the lower label
  EXPECT_EQ(forest_label_without(classes, votes, 2), 1);
  std::vector<int32_t> one = {1};
  std::vector<double> all = {1.0};
  EXPECT_EQ(forest_label_without(one, all, 1), 1);  // nothing else: its own
  EXPECT_THROW(forest_label_without(classes, all, 1), Error);
}

}  // namespace
}  // namespace hair
