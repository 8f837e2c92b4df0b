#include "hair/style/style_training.h"

#include <algorithm>
#include <array>
#include <string>

#include "hair/core/error.h"

namespace hair {
namespace {

constexpr int kStyleCount = 4;

/// Weighted style votes per cluster.
std::vector<std::array<double, kStyleCount>> cluster_votes(
    const std::vector<int32_t>& group_cluster, const std::vector<int8_t>& group_style,
    const std::vector<double>& group_weight, int32_t cluster_count) {
  if (group_style.size() != group_cluster.size() || group_weight.size() != group_cluster.size())
    throw Error::usage(
        "cluster labels: group_cluster, group_style and group_weight differ in size");
  std::vector<std::array<double, kStyleCount>> votes(static_cast<size_t>(cluster_count),
                                                     std::array<double, kStyleCount>{});
  for (size_t g = 0; g < group_cluster.size(); ++g) {
    int32_t cluster = group_cluster[g];
    int8_t style = group_style[g];
    if (cluster < 0 || cluster >= cluster_count || style < 0 || style >= kStyleCount) continue;
    votes[static_cast<size_t>(cluster)][static_cast<size_t>(style)] +=
        std::max(0.0, group_weight[g]);
  }
  return votes;
}

}  // namespace

std::vector<int8_t> group_styles_from_truth(const std::vector<int64_t>& face_offsets,
                                            const std::vector<int32_t>& face_vertices,
                                            const std::vector<int32_t>& face_group,
                                            int32_t group_count,
                                            const std::vector<int64_t>& patch_first_vertex,
                                            const std::vector<int8_t>& patch_style) {
  if (face_offsets.size() != face_group.size() + 1)
    throw Error::usage("group styles: face_offsets must have one entry more than face_group");
  if (patch_first_vertex.size() != patch_style.size() + 1)
    throw Error::usage(
        "group styles: patch_first_vertex must have one entry more than patch_style");
  std::vector<std::array<int64_t, kStyleCount>> votes(static_cast<size_t>(group_count),
                                                      std::array<int64_t, kStyleCount>{});
  for (size_t f = 0; f < face_group.size(); ++f) {
    int32_t group = face_group[f];
    if (group < 0 || group >= group_count) continue;
    for (int64_t corner = face_offsets[f]; corner < face_offsets[f + 1]; ++corner) {
      int64_t vertex = face_vertices[static_cast<size_t>(corner)];
      auto after = std::upper_bound(patch_first_vertex.begin(), patch_first_vertex.end(), vertex);
      auto patch = (after - patch_first_vertex.begin()) - 1;
      if (patch < 0 || patch >= static_cast<int64_t>(patch_style.size())) continue;
      int8_t style = patch_style[static_cast<size_t>(patch)];
      if (style >= 0 && style < kStyleCount)
        ++votes[static_cast<size_t>(group)][static_cast<size_t>(style)];
    }
  }
  std::vector<int8_t> styles(static_cast<size_t>(group_count), -1);
  for (size_t g = 0; g < styles.size(); ++g) {
    auto best = std::max_element(votes[g].begin(), votes[g].end());  // first of the largest
    if (*best > 0) styles[g] = static_cast<int8_t>(best - votes[g].begin());
  }
  return styles;
}

std::vector<int8_t> cluster_styles_by_majority(const std::vector<int32_t>& group_cluster,
                                               const std::vector<int8_t>& group_style,
                                               const std::vector<double>& group_weight,
                                               int32_t cluster_count) {
  auto votes = cluster_votes(group_cluster, group_style, group_weight, cluster_count);
  std::vector<int8_t> styles(votes.size(), -1);
  for (size_t c = 0; c < votes.size(); ++c) {
    auto best = std::max_element(votes[c].begin(), votes[c].end());
    if (*best > 0) styles[c] = static_cast<int8_t>(best - votes[c].begin());
  }
  return styles;
}

std::vector<double> cluster_label_purity(const std::vector<int32_t>& group_cluster,
                                         const std::vector<int8_t>& group_style,
                                         const std::vector<double>& group_weight,
                                         int32_t cluster_count) {
  auto votes = cluster_votes(group_cluster, group_style, group_weight, cluster_count);
  std::vector<double> purity(votes.size(), 0.0);
  for (size_t c = 0; c < votes.size(); ++c) {
    double total = 0;
    for (double v : votes[c]) total += v;
    if (total > 0) purity[c] = *std::max_element(votes[c].begin(), votes[c].end()) / total;
  }
  return purity;
}

}  // namespace hair
