#include "hair/style/style_overrides.h"

#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <map>
#include <toml++/toml.h>

#include "hair/core/error.h"

namespace hair {
namespace {

/// A number of a TOML node (integer or float), or nullopt.
std::optional<double> number_of(const toml::node& node) {
  if (const auto* integer = node.as_integer()) return static_cast<double>(integer->get());
  if (const auto* floating = node.as_floating_point()) return floating->get();
  return std::nullopt;
}

StylePin read_pin(const toml::node& node, int index, const std::string& path) {
  const std::string where = fmt::format("pin {}", index);
  const toml::table* table = node.as_table();
  if (!table) throw Error::bad_input(path, where + ": expected a table ([[pin]])");
  StylePin pin;
  pin.index = index;
  bool has_style = false;
  for (auto&& [key, value] : *table) {
    const std::string name(key.str());
    if (name == "cluster") {
      const auto* integer = value.as_integer();
      if (!integer || integer->get() < 0 ||
          integer->get() > std::numeric_limits<int32_t>::max())
        throw Error::bad_input(path, where + ": cluster must be a whole number >= 0");
      pin.cluster = static_cast<int32_t>(integer->get());
    } else if (name == "point_m") {
      const toml::array* array = value.as_array();
      Eigen::Vector3d point;
      bool ok = array && array->size() == 3;
      for (size_t i = 0; ok && i < 3; ++i) {
        const std::optional<double> x = number_of(*array->get(i));
        ok = x && std::isfinite(*x);
        if (ok) point[static_cast<Eigen::Index>(i)] = *x;
      }
      if (!ok) throw Error::bad_input(path, where + ": point_m must be three finite numbers (metres)");
      pin.point_m = point;
    } else if (name == "style") {
      const std::optional<std::string> text = value.value<std::string>();
      const std::optional<HairStyle> style = text ? hair_style_from_name(*text) : std::nullopt;
      if (!style)
        throw Error::bad_input(path, where + ": style must be one of normal, fixed, short, braided");
      pin.style = *style;
      has_style = true;
    } else {
      throw Error::bad_input(path, where + ": unknown key '" + name +
                                       "' (a pin has cluster or point_m, and style)");
    }
  }
  if (!has_style) throw Error::bad_input(path, where + ": no style");
  if (pin.cluster.has_value() == pin.point_m.has_value())
    throw Error::bad_input(path, where + ": give either cluster or point_m");
  return pin;
}

}  // namespace

std::vector<StylePin> read_style_pins(const std::string& path) {
  toml::table root;
  try {
    root = toml::parse_file(path);
  } catch (const toml::parse_error& error) {
    const auto line = error.source().begin.line;
    std::string reason(error.description());
    if (line == 0) throw Error::bad_input(path, "cannot read the overrides: " + reason);
    throw Error::bad_input(path, fmt::format("line {}: not TOML: {}", line, reason));
  }
  std::vector<StylePin> pins;
  for (auto&& [key, value] : root) {
    if (key.str() != "pin")
      throw Error::bad_input(path, "unknown key '" + std::string(key.str()) +
                                       "' (an overrides file holds [[pin]] tables)");
    const toml::array* array = value.as_array();
    if (!array) throw Error::bad_input(path, "pin: expected [[pin]] tables");
    for (size_t i = 0; i < array->size(); ++i)
      pins.push_back(read_pin(*array->get(i), static_cast<int>(i) + 1, path));
  }
  return pins;
}

std::vector<ResolvedPin> resolve_style_pins(const std::vector<StylePin>& pins,
                                            const std::vector<int8_t>& cluster_style,
                                            const StrandSet& strands, double head_height_m,
                                            const std::string& path) {
  const auto cluster_count = static_cast<int32_t>(cluster_style.size());
  const std::vector<int32_t>* point_cluster = nullptr;
  if (auto found = strands.point_attributes.find("cluster"); found != strands.point_attributes.end())
    point_cluster = std::get_if<std::vector<int32_t>>(&found->second);
  std::vector<ResolvedPin> resolved;
  std::map<int32_t, HairStyle> seen;
  for (const StylePin& pin : pins) {
    const std::string where = fmt::format("pin {}", pin.index);
    ResolvedPin out;
    out.style = pin.style;
    if (pin.cluster) {
      out.cluster = *pin.cluster;
      if (out.cluster >= cluster_count)
        throw Error::bad_input(path, fmt::format("{}: no cluster {} (the model has {}: 0 to {})",
                                                 where, out.cluster, cluster_count,
                                                 cluster_count - 1));
    } else {
      if (!point_cluster || point_cluster->size() != static_cast<size_t>(strands.point_count()))
        throw Error::bad_input(path, where + ": the grown strands carry no cluster per point");
      double nearest = std::numeric_limits<double>::infinity();
      int64_t best = -1;
      for (int64_t p = 0; p < strands.point_count(); ++p) {
        const double d =
            (strands.points.row(p).cast<double>().transpose() - *pin.point_m).squaredNorm();
        if (d < nearest) nearest = d, best = p;
      }
      const double limit_m = kPinPointMaxDistanceH * head_height_m;
      if (best < 0 || std::sqrt(nearest) > limit_m)
        throw Error::bad_input(
            path, fmt::format("{}: no grown strand within {:.3f} m ({} H) of point_m ({:.4f}, "
                              "{:.4f}, {:.4f})",
                              where, limit_m, kPinPointMaxDistanceH, pin.point_m->x(),
                              pin.point_m->y(), pin.point_m->z()));
      out.cluster = (*point_cluster)[static_cast<size_t>(best)];
      out.distance_m = std::sqrt(nearest);
    }
    if (cluster_style[static_cast<size_t>(out.cluster)] < 0)
      throw Error::bad_input(path, fmt::format("{}: cluster {} has no grown strands, so no style to pin",
                                               where, out.cluster));
    if (auto [it, fresh] = seen.emplace(out.cluster, out.style); !fresh && it->second != out.style)
      throw Error::bad_input(path, fmt::format("{}: cluster {} is pinned already as {}", where,
                                               out.cluster, hair_style_name(it->second)));
    resolved.push_back(out);
  }
  return resolved;
}

void apply_style_pins(const std::vector<ResolvedPin>& pins, ClusterStyles& styles) {
  for (const ResolvedPin& pin : pins) {
    const auto c = static_cast<size_t>(pin.cluster);
    styles.style[c] = static_cast<int8_t>(pin.style);
    if (styles.pinned.size() < styles.style.size()) styles.pinned.resize(styles.style.size(), 0);
    styles.pinned[c] = 1;
  }
}

}  // namespace hair
