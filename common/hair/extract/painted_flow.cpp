#include "hair/extract/painted_flow.h"

#include <spdlog/spdlog.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <optional>

#include "hair/geom/point_index.h"
#include "hair/geom/triangle_mesh_distance.h"

namespace hair {

/// One material's painted image as the flow reads it: per texel the structure tensor of
/// the luminance (Jxx, Jxy, Jyy, averaged over the painted texels of a Gaussian window),
/// the alpha, and the alpha's gradient (per texel, x right and y down the image).
struct PaintedTexture {
  cv::Mat tensor;          ///< CV_32FC3: Jxx, Jxy, Jyy
  cv::Mat alpha;           ///< CV_32F in [0, 1]
  cv::Mat alpha_gradient;  ///< CV_32FC2
  int width() const { return alpha.cols; }
  int height() const { return alpha.rows; }
};

namespace {

/// The image, decoded with every channel, or an empty Mat with `problem` set.
cv::Mat decode(const MaterialImage& image, std::string& problem) {
  cv::Mat decoded;
  try {
    if (!image.encoded.empty()) {
      decoded = cv::imdecode(image.encoded, cv::IMREAD_UNCHANGED);
    } else {
      std::error_code error;
      if (!std::filesystem::is_regular_file(image.path, error)) {
        problem = std::filesystem::exists(image.path, error) ? "not a regular file" : "no such file";
        return {};
      }
      decoded = cv::imread(image.path.string(), cv::IMREAD_UNCHANGED);
    }
  } catch (const cv::Exception& error) {
    problem = error.what();
    return {};
  }
  if (decoded.empty() || decoded.cols < 2 || decoded.rows < 2) {
    problem = "not an image OpenCV can read, or empty";
    return {};
  }
  return decoded;
}

/// `decoded` (1-4 channels, 8 or 16 bits or float) as float luminance and alpha in [0, 1].
void luminance_and_alpha(const cv::Mat& decoded, cv::Mat& luminance, cv::Mat& alpha) {
  double scale = decoded.depth() == CV_8U ? 1.0 / 255 : decoded.depth() == CV_16U ? 1.0 / 65535 : 1.0;
  cv::Mat scaled;
  decoded.convertTo(scaled, CV_32F, scale);
  std::vector<cv::Mat> channels;
  cv::split(scaled, channels);
  alpha = cv::Mat(scaled.size(), CV_32F, cv::Scalar(1.0));
  if (channels.size() >= 3) {  // BGR(A)
    luminance = 0.114f * channels[0] + 0.587f * channels[1] + 0.299f * channels[2];
    if (channels.size() == 4) alpha = channels[3];
  } else {  // gray(, alpha)
    luminance = channels[0];
    if (channels.size() == 2) alpha = channels[1];
  }
}

std::optional<PaintedTexture> load_texture(const MeshMaterial& material,
                                           const PaintedFlowParams& params,
                                           const std::string& source,
                                           std::vector<std::string>& unreadable) {
  auto complain = [&](const MaterialImage& image, const std::string& problem) {
    std::string message = image.path.string() + ": " + problem;
    spdlog::warn("{}: material '{}': image {}: its faces get no painted flow", source,
                 material.name, message);
    unreadable.push_back(message);
  };
  cv::Mat luminance, alpha;
  if (material.diffuse.present()) {
    std::string problem;
    cv::Mat decoded = decode(material.diffuse, problem);
    if (decoded.empty()) {
      complain(material.diffuse, problem);
    } else {
      luminance_and_alpha(decoded, luminance, alpha);
    }
  }
  if (material.alpha.present() && !(material.alpha.path == material.diffuse.path &&
                                    material.alpha.encoded == material.diffuse.encoded)) {
    std::string problem;
    cv::Mat decoded = decode(material.alpha, problem);
    if (decoded.empty()) {
      complain(material.alpha, problem);
    } else {
      cv::Mat coverage, unused;
      luminance_and_alpha(decoded, coverage, unused);  // map_d is a scalar image
      if (luminance.empty()) luminance = coverage.clone();
      if (coverage.size() != luminance.size())
        cv::resize(coverage, coverage, luminance.size(), 0, 0, cv::INTER_LINEAR);
      alpha = coverage;
    }
  }
  if (luminance.empty()) return std::nullopt;

  // The structure tensor of the luminance over the painted texels (the silhouette of the
  // paint, two texels in, is left out: its edge runs along the outline, not the strokes).
  cv::Mat painted = alpha >= params.min_alpha;
  cv::erode(painted, painted, cv::getStructuringElement(cv::MORPH_ELLIPSE, cv::Size(5, 5)));
  cv::Mat weight;
  painted.convertTo(weight, CV_32F, 1.0 / 255);
  // The strokes are fine detail; shading and the highlight band an artist paints across
  // the hair are broad, and their edges would read as strokes across it. So the tensor is
  // taken of the luminance less its blur over `stroke_scale_px` (a high pass).
  cv::Mat detail;
  cv::GaussianBlur(luminance, detail, cv::Size(0, 0), params.stroke_scale_px);
  detail = luminance - detail;
  cv::Mat gx, gy;
  cv::Sobel(detail, gx, CV_32F, 1, 0, 3);
  cv::Sobel(detail, gy, CV_32F, 0, 1, 3);
  std::vector<cv::Mat> products = {weight.mul(gx.mul(gx)), weight.mul(gx.mul(gy)),
                                   weight.mul(gy.mul(gy))};
  const cv::Size kernel(0, 0);
  cv::Mat weight_sum;
  cv::GaussianBlur(weight, weight_sum, kernel, params.window_px);
  for (cv::Mat& product : products) {
    cv::GaussianBlur(product, product, kernel, params.window_px);
    product /= cv::max(weight_sum, 1e-6);
  }
  PaintedTexture texture;
  cv::merge(products, texture.tensor);
  texture.alpha = alpha;
  cv::Mat smooth_alpha, ax, ay;
  cv::GaussianBlur(alpha, smooth_alpha, kernel, params.window_px);
  cv::Sobel(smooth_alpha, ax, CV_32F, 1, 0, 3, 1.0 / 8);  // per texel
  cv::Sobel(smooth_alpha, ay, CV_32F, 0, 1, 3, 1.0 / 8);
  cv::merge(std::vector<cv::Mat>{ax, ay}, texture.alpha_gradient);
  return texture;
}

/// The texel under texture coordinates (u, v): OBJ convention (v up, row 0 at v = 1),
/// repeating outside [0, 1).
cv::Point texel_of(const PaintedTexture& texture, double u, double v) {
  double x = u - std::floor(u), y = 1 - (v - std::floor(v));
  int column = std::clamp(static_cast<int>(x * texture.width()), 0, texture.width() - 1);
  int row = std::clamp(static_cast<int>(y * texture.height()), 0, texture.height() - 1);
  return {column, row};
}

/// The face's texture map's linear part: T (3 x 2) with P - P_mean ~ T (uv - uv_mean),
/// least squares over its corners; nullopt when its texture coordinates span no area.
std::optional<Eigen::Matrix<double, 3, 2>> texture_jacobian(const PolyMesh& mesh, int64_t face) {
  const int64_t first = mesh.face_offsets[static_cast<size_t>(face)];
  const int corners = mesh.face_size(face);
  Eigen::MatrixXd uv(corners, 2), position(corners, 3);
  for (int c = 0; c < corners; ++c) {
    uv.row(c) = mesh.corner_uv.row(first + c).cast<double>();
    position.row(c) = mesh.vertices.row(mesh.face_vertices[static_cast<size_t>(first + c)]).cast<double>();
  }
  uv.rowwise() -= uv.colwise().mean();
  position.rowwise() -= position.colwise().mean();
  Eigen::Matrix2d normal = uv.transpose() * uv;
  if (!(std::abs(normal.determinant()) > 1e-6 * normal.squaredNorm())) return std::nullopt;
  Eigen::Matrix<double, 2, 3> solved = normal.inverse() * (uv.transpose() * position);
  return Eigen::Matrix<double, 3, 2>(solved.transpose());
}

}  // namespace

int64_t PaintedFlow::painted_face_count() const {
  return std::count_if(coherence.begin(), coherence.end(), [](float c) { return c > 0; });
}

bool PaintedTextures::empty() const {
  return std::none_of(by_material.begin(), by_material.end(),
                      [](const auto& texture) { return texture != nullptr; });
}

PaintedTextures load_painted_textures(const std::vector<MeshMaterial>& materials,
                                      const PaintedFlowParams& params, const std::string& source) {
  PaintedTextures textures;
  for (const MeshMaterial& material : materials) {
    std::optional<PaintedTexture> texture =
        load_texture(material, params, source, textures.unreadable_images);
    textures.by_material.push_back(
        texture ? std::make_shared<const PaintedTexture>(std::move(*texture)) : nullptr);
  }
  return textures;
}

PaintedFlow painted_flow(const PolyMesh& mesh, const PaintedFlowParams& params,
                         const std::string& source) {
  return painted_flow(mesh, load_painted_textures(mesh.materials, params, source), params);
}

PaintedFlow painted_flow(const PolyMesh& mesh, const PaintedTextures& textures,
                         const PaintedFlowParams& params) {
  const auto faces = static_cast<size_t>(mesh.face_count());
  PaintedFlow flow;
  flow.direction.assign(faces, Eigen::Vector3f::Zero());
  flow.coherence.assign(faces, 0.0f);
  flow.alpha_fall.assign(faces, 0.0f);
  flow.unreadable_images = textures.unreadable_images;
  if (!mesh.has_materials() || !mesh.has_uv()) return flow;

  const int n = std::max(1, params.samples_per_side);
#pragma omp parallel for schedule(dynamic, 64)
  for (int64_t face = 0; face < mesh.face_count(); ++face) {
    const int32_t material = mesh.face_material[static_cast<size_t>(face)];
    if (material < 0 || static_cast<size_t>(material) >= textures.by_material.size() ||
        !textures.by_material[static_cast<size_t>(material)])
      continue;
    const PaintedTexture& texture = *textures.by_material[static_cast<size_t>(material)];
    const std::optional<Eigen::Matrix<double, 3, 2>> jacobian = texture_jacobian(mesh, face);
    if (!jacobian) continue;

    // Samples over the face's fan of triangles in texture space, weighted by area.
    const int64_t first = mesh.face_offsets[static_cast<size_t>(face)];
    const int corners = mesh.face_size(face);
    Eigen::Vector3d tensor = Eigen::Vector3d::Zero();
    Eigen::Vector2d alpha_gradient = Eigen::Vector2d::Zero();
    double weight_sum = 0, painted_weight = 0;
    for (int c = 1; c + 1 < corners; ++c) {
      Eigen::Vector2d a = mesh.corner_uv.row(first).cast<double>();
      Eigen::Vector2d b = mesh.corner_uv.row(first + c).cast<double>();
      Eigen::Vector2d d = mesh.corner_uv.row(first + c + 1).cast<double>();
      double area = 0.5 * std::abs((b - a).x() * (d - a).y() - (b - a).y() * (d - a).x());
      for (int s = 0; s < n; ++s)
        for (int t = 0; s + t < n; ++t) {
          double wb = (s + 1.0 / 3) / n, wd = (t + 1.0 / 3) / n;
          Eigen::Vector2d uv = a + wb * (b - a) + wd * (d - a);
          cv::Point texel = texel_of(texture, uv.x(), uv.y());
          double weight = area;
          weight_sum += weight;
          if (texture.alpha.at<float>(texel) < params.min_alpha) continue;
          painted_weight += weight;
          const cv::Vec3f& j = texture.tensor.at<cv::Vec3f>(texel);
          tensor += weight * Eigen::Vector3d(j[0], j[1], j[2]);
          const cv::Vec2f& g = texture.alpha_gradient.at<cv::Vec2f>(texel);
          alpha_gradient += weight * Eigen::Vector2d(g[0], g[1]);
        }
    }
    if (!(weight_sum > 0) || painted_weight < params.min_painted_share * weight_sum) continue;
    tensor /= painted_weight;
    alpha_gradient /= painted_weight;

    // The strokes run across the dominant gradient: along the tensor's minor eigenvector.
    const double jxx = tensor[0], jxy = tensor[1], jyy = tensor[2];
    const double trace = jxx + jyy;
    if (!(trace > 1e-12)) continue;
    const double spread = std::sqrt(0.25 * (jxx - jyy) * (jxx - jyy) + jxy * jxy);
    const double gradient_angle = 0.5 * std::atan2(2 * jxy, jxx - jyy);
    Eigen::Vector2d stroke_px(-std::sin(gradient_angle), std::cos(gradient_angle));

    // The alpha's fall along the strokes across the face: its derivative along them times
    // the face's extent along them.
    double low = std::numeric_limits<double>::infinity(), high = -low;
    for (int c = 0; c < corners; ++c) {  // the corners in texels, x right, y down
      Eigen::Vector2d corner(mesh.corner_uv(first + c, 0) * texture.width(),
                             (1 - mesh.corner_uv(first + c, 1)) * texture.height());
      low = std::min(low, corner.dot(stroke_px));
      high = std::max(high, corner.dot(stroke_px));
    }
    double fall = -alpha_gradient.dot(stroke_px) * std::max(1.0, high - low);
    if (fall < 0) {
      stroke_px = -stroke_px;
      fall = -fall;
    }
    // Texels (x right, y down) to texture coordinates (v up), then into 3D.
    Eigen::Vector2d stroke_uv(stroke_px.x() / texture.width(), -stroke_px.y() / texture.height());
    Eigen::Vector3d direction = *jacobian * stroke_uv;
    if (!(direction.norm() > 1e-12)) continue;
    flow.direction[static_cast<size_t>(face)] = direction.normalized().cast<float>();
    flow.coherence[static_cast<size_t>(face)] =
        static_cast<float>(std::max(1e-6, std::min(1.0, 2 * spread / trace)));
    flow.alpha_fall[static_cast<size_t>(face)] = static_cast<float>(fall);
  }
  return flow;
}

std::vector<int8_t> segments_along_painted_flow(const PolyMesh& mesh, const PaintedFlow& flow,
                                                const StrandSet& strands, double min_coherence,
                                                double max_angle_deg, double max_distance_m) {
  std::vector<int8_t> along(static_cast<size_t>(strands.point_count()), -1);
  Triangles3i triangles = fan_triangulation(mesh.face_offsets, mesh.face_vertices);
  if (triangles.rows() == 0 || flow.coherence.size() != static_cast<size_t>(mesh.face_count()))
    return along;
  std::vector<int64_t> triangle_face;
  for (int64_t face = 0; face < mesh.face_count(); ++face)
    triangle_face.insert(triangle_face.end(), static_cast<size_t>(mesh.face_size(face) - 2), face);
  TriangleMeshDistance distance(mesh.vertices, triangles);
  const double min_cosine = std::cos(max_angle_deg * M_PI / 180);
#pragma omp parallel for schedule(dynamic, 256)
  for (int64_t s = 0; s < strands.strand_count(); ++s) {
    const int64_t begin = strands.offsets[static_cast<size_t>(s)];
    const int64_t end = strands.offsets[static_cast<size_t>(s) + 1];
    for (int64_t row = begin + 1; row < end; ++row) {
      Eigen::Vector3d a = point_of(strands.points, row - 1), b = point_of(strands.points, row);
      Eigen::Vector3d segment = b - a;
      if (!(segment.norm() > 1e-9)) continue;
      TriangleMeshDistance::Nearest nearest = distance.nearest(0.5 * (a + b));
      if (nearest.triangle < 0 || nearest.distance > max_distance_m) continue;
      auto face = static_cast<size_t>(triangle_face[static_cast<size_t>(nearest.triangle)]);
      if (!(flow.coherence[face] >= min_coherence)) continue;
      double cosine = std::abs(segment.normalized().dot(flow.direction[face].cast<double>()));
      along[static_cast<size_t>(row)] = cosine >= min_cosine ? 1 : 0;
    }
    if (end - begin > 1) along[static_cast<size_t>(begin)] = along[static_cast<size_t>(begin + 1)];
  }
  return along;
}

PaintedFlow flow_with_rails(const PolyMesh& mesh, const PaintedFlow& painted,
                            const StrandSet& input_strands, const std::vector<int32_t>& face_group,
                            double max_distance_m) {
  const auto faces = static_cast<size_t>(mesh.face_count());
  PaintedFlow flow = painted;
  flow.direction.resize(faces, Eigen::Vector3f::Zero());
  flow.coherence.resize(faces, 0.0f);
  flow.alpha_fall.resize(faces, 0.0f);
  // Segment midpoints of the input strands and their directions, all together and by the
  // group (patch) of their strand.
  const std::vector<int32_t>* strand_group = nullptr;
  if (auto it = input_strands.strand_attributes.find("group");
      it != input_strands.strand_attributes.end() && face_group.size() == faces)
    strand_group = std::get_if<std::vector<int32_t>>(&it->second);
  std::vector<Eigen::Vector3f> directions;
  std::vector<Eigen::Vector3f> midpoints;
  std::map<int32_t, std::vector<int32_t>> group_segments;
  for (int64_t s = 0; s < input_strands.strand_count(); ++s)
    for (int64_t row = input_strands.offsets[static_cast<size_t>(s)] + 1;
         row < input_strands.offsets[static_cast<size_t>(s) + 1]; ++row) {
      Eigen::Vector3f a = input_strands.points.row(row - 1).transpose();
      Eigen::Vector3f b = input_strands.points.row(row).transpose();
      if (!((b - a).norm() > 0)) continue;
      if (strand_group)
        group_segments[(*strand_group)[static_cast<size_t>(s)]].push_back(
            static_cast<int32_t>(midpoints.size()));
      midpoints.push_back(0.5f * (a + b));
      directions.push_back((b - a).normalized());
    }
  if (midpoints.empty()) return flow;
  auto index_of = [&](const std::vector<int32_t>& ids) {
    Points3f rows(static_cast<Eigen::Index>(ids.size()), 3);
    for (size_t i = 0; i < ids.size(); ++i)
      rows.row(static_cast<Eigen::Index>(i)) = midpoints[static_cast<size_t>(ids[i])].transpose();
    return std::make_unique<PointIndex>(rows);
  };
  std::vector<int32_t> all(midpoints.size());
  for (size_t i = 0; i < all.size(); ++i) all[i] = static_cast<int32_t>(i);
  const std::unique_ptr<PointIndex> all_index = index_of(all);
  std::map<int32_t, std::unique_ptr<PointIndex>> group_index;
  for (const auto& [group, ids] : group_segments) group_index[group] = index_of(ids);
  std::vector<int64_t> unclear;
  for (int64_t face = 0; face < mesh.face_count(); ++face)
    if (!(flow.coherence[static_cast<size_t>(face)] >= kClearFlowCoherence))
      unclear.push_back(face);
#pragma omp parallel for schedule(static)
  for (size_t i = 0; i < unclear.size(); ++i) {
    const int64_t face = unclear[i];
    const auto f = static_cast<size_t>(face);
    Eigen::Vector3f centroid = Eigen::Vector3f::Zero();
    const int64_t first = mesh.face_offsets[f];
    for (int c = 0; c < mesh.face_size(face); ++c)
      centroid += mesh.vertices.row(mesh.face_vertices[static_cast<size_t>(first + c)]).transpose();
    centroid /= static_cast<float>(mesh.face_size(face));
    flow.direction[f] = Eigen::Vector3f::Zero();
    flow.coherence[f] = 0;
    // The face's own rails: its group's strands; any strand's where its group has none.
    const std::vector<int32_t>* ids = &all;
    const PointIndex* index = all_index.get();
    if (strand_group)
      if (auto it = group_index.find(face_group[f]); it != group_index.end()) {
        ids = &group_segments.at(face_group[f]);
        index = it->second.get();
      }
    for (int32_t id : index->nearest(centroid, 1)) {
      const auto segment = static_cast<size_t>((*ids)[static_cast<size_t>(id)]);
      if ((midpoints[segment] - centroid).norm() <= max_distance_m) {
        flow.direction[f] = directions[segment];
        flow.coherence[f] = 1;
      }
    }
  }
  return flow;
}

double painted_flow_agreement(const PolyMesh& mesh, const PaintedFlow& flow,
                              const StrandSet& strands, double min_coherence,
                              double max_angle_deg, double max_distance_m, int64_t& counted) {
  std::vector<int8_t> along = segments_along_painted_flow(mesh, flow, strands, min_coherence,
                                                          max_angle_deg, max_distance_m);
  int64_t agreeing = 0;
  counted = 0;
  for (int64_t s = 0; s < strands.strand_count(); ++s)  // each segment once: not the roots
    for (int64_t row = strands.offsets[static_cast<size_t>(s)] + 1;
         row < strands.offsets[static_cast<size_t>(s) + 1]; ++row) {
      counted += along[static_cast<size_t>(row)] >= 0;
      agreeing += along[static_cast<size_t>(row)] == 1;
    }
  return counted ? static_cast<double>(agreeing) / static_cast<double>(counted) : 0.0;
}

}  // namespace hair
