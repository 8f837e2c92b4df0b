// grow's parameters are declared once (declare_grow_params) and held to their ranges for
// every caller: grow_strands() refuses what the command line would, by name.
#include <gtest/gtest.h>

#include <string>

#include "hair/core/error.h"
#include "hair/grow/grow_params.h"
#include "hair/grow/strand_growing.h"

namespace hair {
namespace {

std::string refusal(const GrowParams& params) {
  try {
    grow_strands(GrowInput{}, params);
  } catch (const Error& error) {
    if (error.kind() == ErrorKind::usage) return error.what();
    return "";  // past the check: the empty input's own error
  }
  return "";
}

TEST(GrowParams, GrowStrandsRefusesValuesOutOfTheirRanges) {
  EXPECT_NO_THROW(check_grow_params(GrowParams{}));
  GrowParams params;
  params.step_h = 0.5;
  EXPECT_EQ(refusal(params), "parameter step_h = 0.5 is out of range [0.001, 0.1]");
  params = {};
  params.max_turn_deg = 200;
  EXPECT_EQ(refusal(params), "parameter max_turn_deg = 200 is out of range [0, 180]");
  params = {};
  params.strand_count = 0;
  EXPECT_EQ(refusal(params), "parameter strand_count = 0 is out of range [1, 1000000]");
}

}  // namespace
}  // namespace hair
