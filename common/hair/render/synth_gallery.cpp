#include "hair/render/synth_gallery.h"

#include "hair/geom/triangle_mesh_distance.h"
#include "hair/render/style_picture.h"

namespace hair {

PointColours colours_by_style(const synth::SynthModel& model) {
  // BGR, indexed by synth::HairStyle.
  PointColours result;
  result.reserve(model.strand_point_style.size());
  for (synth::HairStyle style : model.strand_point_style)
    result.push_back(style_colour(static_cast<int8_t>(style)));
  return result;
}

cv::Mat synth_gallery(const std::vector<synth::SynthModel>& models, const PolyMesh& body_m,
                      int view_size_px) {
  Triangles3i triangles = fan_triangulation(body_m.face_offsets, body_m.face_vertices);
  std::vector<cv::Mat> rows, tiles;
  for (const synth::SynthModel& model : models) {
    const auto& stream_of_strand =
        std::get<std::vector<int32_t>>(model.strands.strand_attributes.at("stream"));
    RenderOptions options;
    options.views = {ViewDirection::side, ViewDirection::back};
    options.view_size_px = view_size_px;
    options.title = model.name + ": streams";
    cv::Mat by_stream =
        render_strands(model.strands, colours_by_id(model.strands, stream_of_strand),
                       body_m.vertices, triangles, options);
    options.title = model.name + ": styles";
    cv::Mat by_style =
        render_strands(model.strands, colours_by_style(model), body_m.vertices, triangles, options);
    cv::Mat tile;
    cv::hconcat(by_stream, by_style, tile);
    tiles.push_back(tile);
    if (tiles.size() == 2) {
      cv::Mat row;
      cv::hconcat(tiles, row);
      rows.push_back(row);
      tiles.clear();
    }
  }
  if (!tiles.empty()) {
    tiles.push_back(cv::Mat(tiles[0].size(), tiles[0].type(), cv::Scalar(255, 255, 255)));
    cv::Mat row;
    cv::hconcat(tiles, row);
    rows.push_back(row);
  }
  cv::Mat gallery;
  cv::vconcat(rows, gallery);
  return gallery;
}

}  // namespace hair
