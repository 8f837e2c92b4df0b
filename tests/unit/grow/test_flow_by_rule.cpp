// flow_agreement_by_rule(): the segments of grown strands judged against the flow, tallied
// by how each was grown.
#include <gtest/gtest.h>

#include "hair/core/error.h"
#include "hair/grow/flow_by_rule.h"

namespace hair {
namespace {

/// Two strands: one of 6 points (root, four field segments, one along an input strand),
/// one of 4 (root, a field segment, a bridge, an input strand segment).
StrandSet two_strands() {
  Points3f first(6, 3), second(4, 3);
  for (int i = 0; i < 6; ++i) first.row(i) << 0.01f * static_cast<float>(i), 0.0f, 0.0f;
  for (int i = 0; i < 4; ++i) second.row(i) << 0.0f, 0.01f * static_cast<float>(i), 0.0f;
  return strand_set_from_polylines({first, second});
}

TEST(FlowByRule, TalliesEachSegmentOnceByItsRuleAndTheFieldByItsStep) {
  const StrandSet strands = two_strands();
  //                                  root field field field field input | root field bridge input
  const std::vector<int8_t> rule{0, 1, 1, 1, 1, 2, 0, 1, 3, 2};
  // The roots' answers (the first segment again) must not count: 0 and 1 there.
  const std::vector<int8_t> along{0, 1, 0, 1, 1, -1, 1, 0, 0, 1};
  const FlowByRule tally = flow_agreement_by_rule(strands, along, rule);
  EXPECT_EQ(tally.by_rule[0].judged, 0);
  EXPECT_EQ(tally.by_rule[1].judged, 5);  // 4 + 1 field segments
  EXPECT_EQ(tally.by_rule[1].along, 3);
  EXPECT_EQ(tally.by_rule[2].judged, 1);  // the first strand's input segment is not judged
  EXPECT_EQ(tally.by_rule[2].along, 1);
  EXPECT_EQ(tally.by_rule[3].judged, 1);
  EXPECT_EQ(tally.by_rule[3].along, 0);
  // Field segments by their place from the root: the first of each strand, then one each.
  EXPECT_EQ(tally.field_by_step[0].judged, 2);
  EXPECT_EQ(tally.field_by_step[0].along, 1);
  EXPECT_EQ(tally.field_by_step[1].judged, 1);
  EXPECT_EQ(tally.field_by_step[1].along, 0);
  EXPECT_EQ(tally.field_by_step[2].judged, 1);
  EXPECT_EQ(tally.field_by_step[3].judged, 1);
  EXPECT_EQ(tally.field_by_step[3].along, 1);
}

TEST(FlowByRule, RefusesArraysThatDoNotMatchTheStrands) {
  const StrandSet strands = two_strands();
  const std::vector<int8_t> rule(10, 1), along(10, 1);
  EXPECT_THROW(flow_agreement_by_rule(strands, std::vector<int8_t>(9, 1), rule), Error);
  EXPECT_THROW(flow_agreement_by_rule(strands, along, std::vector<int8_t>(11, 1)), Error);
  std::vector<int8_t> bad_rule = rule;
  bad_rule[3] = 4;
  EXPECT_THROW(flow_agreement_by_rule(strands, along, bad_rule), Error);
}

}  // namespace
}  // namespace hair
