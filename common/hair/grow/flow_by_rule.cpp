#include "hair/grow/flow_by_rule.h"

#include <algorithm>

#include "hair/core/error.h"

namespace hair {

namespace {
constexpr int8_t kFieldRule = 1;  // GrowRule::field (grow/strand_growing.h)
}  // namespace

FlowByRule flow_agreement_by_rule(const StrandSet& strands,
                                  const std::vector<int8_t>& along_per_point,
                                  const std::vector<int8_t>& point_rule) {
  const auto point_count = static_cast<size_t>(strands.point_count());
  if (along_per_point.size() != point_count || point_rule.size() != point_count)
    throw Error::bad_input("flow by rule",
                           "the per-point answers or rules do not match the strands");
  FlowByRule tally;
  for (int64_t s = 0; s < strands.strand_count(); ++s)
    for (int64_t row = strands.offsets[s] + 1; row < strands.offsets[s + 1]; ++row) {
      const int8_t rule = point_rule[static_cast<size_t>(row)];
      if (rule < 0 || rule > 3)
        throw Error::bad_input("flow by rule", "a point's grow rule lies outside 0-3");
      const int8_t along = along_per_point[static_cast<size_t>(row)];
      if (along < 0) continue;
      FlowTally& by_rule = tally.by_rule[static_cast<size_t>(rule)];
      ++by_rule.judged;
      by_rule.along += along;
      if (rule != kFieldRule) continue;
      const auto step = static_cast<size_t>(std::min<int64_t>(row - strands.offsets[s] - 1, 3));
      ++tally.field_by_step[step].judged;
      tally.field_by_step[step].along += along;
    }
  return tally;
}

}  // namespace hair
