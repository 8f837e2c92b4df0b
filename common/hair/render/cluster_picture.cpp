#include "hair/render/cluster_picture.h"

#include <algorithm>
#include <opencv2/imgproc.hpp>
#include <variant>
#include <vector>

#include "hair/cluster/clustering_io.h"
#include "hair/core/error.h"
#include "hair/extract/extract_io.h"
#include "hair/h5/attribute.h"
#include "hair/h5/dataset.h"
#include "hair/h5/schema_validation.h"
#include "hair/h5/strand_set_io.h"

namespace hair {
namespace {

/// What the pictures draw of extract.h5: its strands with their groups, and the body.
struct ExtractScene {
  StrandSet strands;
  std::vector<int32_t> strand_group;
  size_t group_count = 0;
  Points3f body_vertices;
  Triangles3i body_triangles;
};

ExtractScene read_extract_scene(const h5::File& extract) {
  h5::require_schema(extract, kExtractSchema);
  ExtractScene scene;
  scene.strands = h5::read_strand_set(extract, "/strands");
  scene.strand_group = std::get<std::vector<int32_t>>(scene.strands.strand_attributes.at("group"));
  // The schema binds n_groups here and checks that every strand's group is below it.
  scene.group_count =
      static_cast<size_t>(h5::dataset_info(extract, "/groups/face_count").shape.at(0));
  ExtractedBody body = read_extracted_body(extract);
  scene.body_vertices = std::move(body.vertices);
  scene.body_triangles = std::move(body.triangles);
  return scene;
}

/// Spreads a per-group id to the strands.
std::vector<int32_t> per_strand(const std::vector<int32_t>& per_group,
                                const std::vector<int32_t>& strand_group) {
  std::vector<int32_t> ids;
  ids.reserve(strand_group.size());
  for (int32_t group : strand_group) ids.push_back(per_group[static_cast<size_t>(group)]);
  return ids;
}

/// Colours by id with the palette of colours_by_id(); strands with a negative id grey.
PointColours colours_by_cluster(const StrandSet& strands, const std::vector<int32_t>& strand_ids) {
  PointColours colours = colours_by_id(strands, strand_ids);
  for (int64_t s = 0; s < strands.strand_count(); ++s)
    if (strand_ids[static_cast<size_t>(s)] < 0)
      std::fill(colours.begin() + strands.offsets[s], colours.begin() + strands.offsets[s + 1],
                kNonMiddleGrey);
  return colours;
}

cv::Mat render_scene(const ExtractScene& scene, const std::vector<int32_t>& group_ids,
                     const RenderOptions& options) {
  std::vector<int32_t> strand_ids = per_strand(group_ids, scene.strand_group);
  return render_strands(scene.strands, colours_by_cluster(scene.strands, strand_ids),
                        scene.body_vertices, scene.body_triangles, options);
}

/// Lines of text under the title, as the legends of extract_picture() are placed.
void draw_lines(cv::Mat& image, const std::vector<std::string>& lines) {
  int y = 44;
  for (const std::string& line : lines) {
    cv::putText(image, line, cv::Point(10, y), cv::FONT_HERSHEY_SIMPLEX, 0.45,
                cv::Scalar(40, 40, 40), 1, cv::LINE_AA);
    y += 18;
  }
}

std::string plural(int64_t count, const std::string& noun) {
  return std::to_string(count) + " " + noun + (count == 1 ? "" : "s");
}

}  // namespace

cv::Mat middle_picture(const h5::File& middle, const h5::File& extract,
                       const RenderOptions& options) {
  ExtractScene scene = read_extract_scene(extract);
  // Checks the schema of middle.h5 and that it has the groups of extract.h5.
  std::vector<int32_t> middle_cluster = read_middle_clusters(middle, scene.group_count);
  int64_t cluster_count = h5::read_int64_attribute(middle, "/", "cluster_count");
  std::string source = h5::read_string_attribute(middle, "/", "cluster_count_source");
  auto middle_groups = std::count_if(middle_cluster.begin(), middle_cluster.end(),
                                     [](int32_t cluster) { return cluster >= 0; });

  cv::Mat image = render_scene(scene, middle_cluster, options);
  draw_lines(image, {plural(cluster_count, "middle cluster") + " (count: " + source + "); " +
                     std::to_string(middle_groups) + " of " +
                     plural(static_cast<int64_t>(scene.group_count), "group") +
                     " middle-type, the others grey"});
  return image;
}

cv::Mat clusters_picture(const h5::File& clusters, const h5::File& extract,
                         const RenderOptions& options, bool before_split) {
  GroupClusters group_clusters = read_group_clusters(clusters);  // checks the schema
  ExtractScene scene = read_extract_scene(extract);
  if (group_clusters.cluster.size() != scene.group_count)
    throw Error::bad_dataset(clusters.name(), "/groups/cluster",
                             "has " + std::to_string(group_clusters.cluster.size()) + " groups, " +
                                 extract.name() + " " + std::to_string(scene.group_count) +
                                 ": made from another model");
  int64_t count_before_split = h5::read_int64_attribute(clusters, "/", "cluster_count");
  int64_t split_count = h5::read_int64_attribute(clusters, "/", "split_count");
  std::string source = h5::read_string_attribute(clusters, "/", "cluster_count_source");
  auto final_count = static_cast<int64_t>(group_clusters.starts_at_root.size());
  auto root_count = std::count(group_clusters.starts_at_root.begin(),
                               group_clusters.starts_at_root.end(), uint8_t{1});

  cv::Mat image = render_scene(
      scene, before_split ? group_clusters.cluster_before_split : group_clusters.cluster, options);
  std::string counts =
      before_split
          ? plural(count_before_split, "cluster") + " before the split (count: " + source + "); " +
                std::to_string(final_count) + " after " + plural(split_count, "split")
          : plural(final_count, "cluster") + " (" + std::to_string(count_before_split) +
                " before the split, count: " + source + "; " + plural(split_count, "split") +
                "); " + std::to_string(root_count) + " start at the root";
  draw_lines(image, {counts});
  return image;
}

bool parse_cluster_colouring(const std::string& word) {
  if (word == "cluster") return false;
  if (word == "before_split") return true;
  throw Error::usage("colouring '" + word +
                     "' of clusters.h5 is not one of: cluster, before_split");
}

}  // namespace hair
