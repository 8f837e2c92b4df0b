#pragma once
// Labels for training the hairstyle classifiers (issue 6): the style of every strand
// group from a synthetic model's truth or from hand labels, and the style of every
// cluster by majority of its groups.

#include <cstdint>
#include <vector>

namespace hair {

/// Per group, the truth style of a synthetic model: the style of the patch that most of
/// the group's face corners lie in (patches are runs of vertex ids; extract keeps vertex
/// ids), -1 for a group without faces.
///   @param face_offsets        #faces + 1 CSR offsets into face_vertices (extract.h5 /mesh)
///   @param face_vertices       vertex of every face corner
///   @param face_group          #faces group ids
///   @param patch_first_vertex  #patches + 1: patch p owns vertices [first[p], first[p+1])
///   @param patch_style         #patches style codes (normal 0, fixed 1, short 2, braided 3)
std::vector<int8_t> group_styles_from_truth(const std::vector<int64_t>& face_offsets,
                                            const std::vector<int32_t>& face_vertices,
                                            const std::vector<int32_t>& face_group,
                                            int32_t group_count,
                                            const std::vector<int64_t>& patch_first_vertex,
                                            const std::vector<int8_t>& patch_style);

/// Per cluster, the style most of its labelled groups have, each group weighted by
/// `group_weight` (its face count: the hair it stands for); a tie goes to the lower
/// style code; -1 for a cluster without a labelled group.
///   @param group_cluster  #groups final cluster ids
///   @param group_style    #groups style codes, -1 unlabelled
///   @param group_weight   #groups non-negative weights
std::vector<int8_t> cluster_styles_by_majority(const std::vector<int32_t>& group_cluster,
                                               const std::vector<int8_t>& group_style,
                                               const std::vector<double>& group_weight,
                                               int32_t cluster_count);

/// The share of a cluster's labelled weight that its majority style has (1: every group
/// agrees), per cluster; 0 for a cluster without a labelled group.
std::vector<double> cluster_label_purity(const std::vector<int32_t>& group_cluster,
                                         const std::vector<int8_t>& group_style,
                                         const std::vector<double>& group_weight,
                                         int32_t cluster_count);

}  // namespace hair
