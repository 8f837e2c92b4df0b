#pragma once
// The paper's style criteria where they are decisive (issue 26): a cluster whose every
// part lies on the scalp and whose strands end in it, not gathered, is short; one whose
// strands start at the roots, stay on the scalp and gather at their end into what follows
// is fixed; one whose strands start at the roots and end in it without gathering is not
// fixed. Learnt classifiers trained on synthetic hair miss these on artists' meshes
// (docs/classify.md, "Decisive criteria"); where a rule holds it decides.

#include <Eigen/Core>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "hair/style/hair_style.h"
#include "hair/style/style_features.h"

namespace hair {

/// Thresholds of the two rules, on the features of style_features.h. Set so that on the
/// synthetic training corpus each rule's clusters carry its style on at least 90% of
/// their strands (bench/train_style_models.sh; docs/classify.md).
struct DecisiveStyleRules {
  bool enabled = true;
  // Short: lies on the head to its ends.
  double short_far_scalp_distance_h = 0.05;  ///< at most: all parts close to the scalp
  double short_tip_share = 0.9;              ///< at least: the strands end in the cluster
  double short_gathering_ratio = 0.5;        ///< at least: their ends do not gather
  // Fixed: a cap gathered into a band (the paper's three conditions, and the strands go on
  // past the band into another cluster).
  double fixed_root_share = 0.9;            ///< at least: the strands start at roots
  double fixed_gathering_ratio = 0.3;       ///< at most: they gather at the end
  double fixed_far_scalp_distance_h = 0.1;  ///< at most: all parts close to the scalp
  double fixed_tip_share = 0.3;             ///< at most: they go on into another cluster
  // Not fixed: strands that start at the roots and end in their cluster without gathering
  // are gathered into nothing (no band, bun or braid takes them), so the paper's fixed,
  // "gather at the end", cannot hold. The classifiers then choose among the other styles.
  double ungathered_root_share = 0.9;       ///< at least: the strands start at roots
  double ungathered_tip_share = 0.9;        ///< at least: they end in the cluster
  double ungathered_gathering_ratio = 0.5;  ///< at least: their ends do not gather
};

/// The style the rules decide for a cluster with these features, or none.
std::optional<HairStyle> decisive_style(const PaperFeatures& features,
                                        const DecisiveStyleRules& rules);

/// The same on rows of a feature table whose columns are `names` (they must include
/// far_scalp_distance_h, tip_share, gathering_ratio and root_share: the extended set):
/// per row the decided style, or -1. Throws hair::Error (usage) naming a missing column.
std::vector<int32_t> decisive_styles_of_rows(const Eigen::MatrixXd& rows,
                                             const std::vector<std::string>& names,
                                             const DecisiveStyleRules& rules);

/// Whether the rules rule fixed out for a cluster with these features (its strands start
/// at the roots and end in it without gathering); false with the rules off.
bool fixed_ruled_out(const PaperFeatures& features, const DecisiveStyleRules& rules);

/// fixed_ruled_out() on rows of a feature table whose columns are `names` (as
/// decisive_styles_of_rows): per row 1 where fixed is ruled out, else 0.
std::vector<uint8_t> fixed_ruled_out_of_rows(const Eigen::MatrixXd& rows,
                                             const std::vector<std::string>& names,
                                             const DecisiveStyleRules& rules);

/// Whether `names` has every column the rules read.
bool has_decisive_rule_features(const std::vector<std::string>& names);

}  // namespace hair
