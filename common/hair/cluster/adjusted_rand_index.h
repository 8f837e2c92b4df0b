#pragma once

#include <cstdint>
#include <vector>

namespace hair {

/// Adjusted Rand index (Hubert & Arabie 1985) of two labelings of the same items.
///
/// Labels are any int32 values; only which items share a label matters. The index is
/// 1 for identical partitions (up to renaming the clusters), about 0 for independent
/// random ones, and can be negative. Where it is 0/0 (both labelings one cluster, both
/// all singletons, or fewer than two items) it is 1: the partitions are identical.
/// Agrees with sklearn.metrics.adjusted_rand_score.
///
/// Throws hair::Error (usage) when the labelings differ in length.
double adjusted_rand_index(const std::vector<int32_t>& a, const std::vector<int32_t>& b);

}  // namespace hair
