#pragma once
// A user's pins of cluster styles (classify --overrides FILE): one wrong call of the
// classifier put right without rerunning the chain. The file is TOML, a [[pin]] table per
// cluster, naming the cluster by its id or by a point it contains:
//
//   [[pin]]
//   cluster = 3
//   style = "fixed"
//
//   [[pin]]
//   point_m = [0.012, 1.655, -0.094]   # metres, the hair mesh's frame (as extract.h5)
//   style = "normal"
//
// A point names the cluster of the grown point nearest to it, which must lie within
// kPinPointMaxDistanceH of it. Documented in docs/classify.md, "Unsure styles and pins".

#include <Eigen/Core>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "hair/core/strand_set.h"
#include "hair/style/cluster_styles.h"
#include "hair/style/hair_style.h"

namespace hair {

/// The farthest a pin's point may lie from the nearest grown point, in H.
inline constexpr double kPinPointMaxDistanceH = 0.1;

/// One [[pin]] of an overrides file: a cluster id or a point, and the style.
struct StylePin {
  std::optional<int32_t> cluster;
  std::optional<Eigen::Vector3d> point_m;
  HairStyle style = HairStyle::normal;
  int index = 0;  ///< its place among the file's pins, from 1 (for messages)
};

/// Reads an overrides file. Throws hair::Error (bad_input, naming the file) on one line
/// for a file that cannot be read or is not TOML (with its line), a key other than "pin"
/// at the top or other than cluster, point_m and style in a pin, a pin with neither or
/// both of cluster and point_m, a cluster id that is not a whole number >= 0, a point
/// that is not three finite numbers, or a style that is not one of normal, fixed, short,
/// braided. An empty file pins nothing.
std::vector<StylePin> read_style_pins(const std::string& path);

/// A pin resolved to its cluster.
struct ResolvedPin {
  int32_t cluster = 0;
  HairStyle style = HairStyle::normal;
  double distance_m = 0;  ///< from a pin's point to the nearest grown point (0 for an id)
};

/// Finds each pin's cluster: its id, which must be one of the `cluster_style.size()`
/// clusters and have a style (grown strands run through it); or the cluster of the grown
/// point of `strands` (point attribute "cluster") nearest its point, within
/// kPinPointMaxDistanceH x `head_height_m`. Two pins of one cluster must agree. Throws
/// hair::Error (bad_input, naming `path`) on one line otherwise.
std::vector<ResolvedPin> resolve_style_pins(const std::vector<StylePin>& pins,
                                            const std::vector<int8_t>& cluster_style,
                                            const StrandSet& strands, double head_height_m,
                                            const std::string& path);

/// Sets each pinned cluster's style in `styles` and marks it pinned; the classifiers' own
/// answers (svm_style, forest_style, confidence) stay as they were.
void apply_style_pins(const std::vector<ResolvedPin>& pins, ClusterStyles& styles);

}  // namespace hair
