#include "hair/export/strand_export.h"

#include <charconv>

#include <array>
#include <cstring>
#include <fstream>
#include <limits>
#include <sstream>

#include "hair/core/error.h"

namespace hair {
namespace {

std::ofstream open_output(const std::filesystem::path& path, std::ios::openmode mode = {}) {
  std::ofstream out(path, std::ios::out | std::ios::trunc | mode);
  if (!out) throw Error::runtime(path.string(), "cannot open for writing");
  return out;
}

void finish(std::ofstream& out, const std::filesystem::path& path) {
  out.flush();
  if (!out) throw Error::runtime(path.string(), "cannot write");
}

/// A float as text that reads back as the same float.
std::string exact(float value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.9g", static_cast<double>(value));
  return text;
}

/// The cyHair header (128 bytes, little-endian as the format's reference code writes it).
struct CyHairHeader {
  char signature[4] = {'H', 'A', 'I', 'R'};
  uint32_t hair_count = 0;
  uint32_t point_count = 0;
  uint32_t arrays = 0;  ///< bit 0 segments, 1 points, 2 thickness, 3 transparency, 4 colours
  uint32_t default_segments = 0;
  float default_thickness = 0;
  float default_transparency = 0;
  float default_colour[3] = {0, 0, 0};
  char info[88] = {};
};
static_assert(sizeof(CyHairHeader) == 128, "cyHair's header is 128 bytes");

constexpr uint32_t kSegmentsArray = 1, kPointsArray = 2, kThicknessArray = 4,
                   kTransparencyArray = 8, kColourArray = 16;

}  // namespace

void write_obj_polylines(const std::filesystem::path& path, const StrandSet& strands,
                         const std::string& comment) {
  std::ofstream out = open_output(path);
  out << "# hairstyle strands as polylines: " << strands.strand_count() << " strands, "
      << strands.point_count() << " points, metres, +Y up\n";
  if (!comment.empty()) out << "# " << comment << "\n";
  for (Eigen::Index row = 0; row < strands.points.rows(); ++row)
    out << "v " << exact(strands.points(row, 0)) << ' ' << exact(strands.points(row, 1)) << ' '
        << exact(strands.points(row, 2)) << '\n';
  // Each strand as its consecutive two-point segments: Blender's OBJ importer (3.4) keeps
  // only the end points of an `l` line of more than two vertices, and every importer
  // reads two-point lines whole. A strand's segments share their vertices, so readers
  // that join lines (ours, Houdini's, Maya's) get the polyline back.
  for (int64_t s = 0; s < strands.strand_count(); ++s)
    for (int64_t row = strands.offsets[static_cast<size_t>(s)] + 1;
         row < strands.offsets[static_cast<size_t>(s) + 1]; ++row)
      out << "l " << row << ' ' << row + 1 << '\n';
  finish(out, path);
}

StrandSet read_obj_polylines(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) throw Error::bad_input(path.string(), "cannot open");
  std::vector<float> vertices;
  std::vector<std::vector<int64_t>> lines;
  std::string line;
  int64_t number = 0;
  auto fail = [&](const std::string& why) {
    return Error::bad_input(path.string(), "line " + std::to_string(number) + ": " + why);
  };
  while (std::getline(in, line)) {
    ++number;
    std::istringstream words(line);
    std::string tag;
    if (!(words >> tag) || tag[0] == '#') continue;
    if (tag == "v") {
      float x, y, z;
      if (!(words >> x >> y >> z)) throw fail("expected v x y z");
      vertices.insert(vertices.end(), {x, y, z});
    } else if (tag == "l") {
      std::vector<int64_t> indices;
      int64_t index;
      while (words >> index) {
        if (index < 1 || index > static_cast<int64_t>(vertices.size() / 3))
          throw fail("vertex " + std::to_string(index) + " is not defined");
        indices.push_back(index - 1);
      }
      if (indices.size() < 2) throw fail("a polyline needs at least 2 vertices");
      // A line that starts where the last one ended goes on with it (a strand written as
      // its two-point segments).
      if (!lines.empty() && lines.back().back() == indices.front())
        lines.back().insert(lines.back().end(), indices.begin() + 1, indices.end());
      else
        lines.push_back(std::move(indices));
    }
  }
  StrandSet strands;
  int64_t total = 0;
  for (const auto& indices : lines) total += static_cast<int64_t>(indices.size());
  strands.points.resize(total, 3);
  strands.offsets.reserve(lines.size() + 1);
  int64_t row = 0;
  for (const auto& indices : lines) {
    for (int64_t index : indices) {
      for (int axis = 0; axis < 3; ++axis)
        strands.points(row, axis) = vertices[static_cast<size_t>(3 * index + axis)];
      ++row;
    }
    strands.offsets.push_back(row);
  }
  return strands;
}

void write_cyhair(const std::filesystem::path& path, const StrandSet& strands,
                  const std::vector<float>& thickness_m, const std::string& info) {
  CyHairHeader header;
  header.hair_count = static_cast<uint32_t>(strands.strand_count());
  header.point_count = static_cast<uint32_t>(strands.point_count());
  header.arrays = kSegmentsArray | kPointsArray | (thickness_m.empty() ? 0 : kThicknessArray);
  header.default_thickness = 1e-4f;
  header.default_transparency = 0;
  header.default_colour[0] = header.default_colour[1] = header.default_colour[2] = 0.5f;
  std::strncpy(header.info, info.c_str(), sizeof header.info - 1);
  std::vector<uint16_t> segments;
  for (int64_t s = 0; s < strands.strand_count(); ++s) {
    int64_t size = strands.strand_size(s);
    if (size < 2 || size - 1 > std::numeric_limits<uint16_t>::max())
      throw Error::usage("cyHair: strand " + std::to_string(s) + " has " + std::to_string(size) +
                         " points; the format holds 2 to 65,536");
    segments.push_back(static_cast<uint16_t>(size - 1));
  }
  if (!thickness_m.empty() && static_cast<int64_t>(thickness_m.size()) != strands.point_count())
    throw Error::usage("cyHair: " + std::to_string(thickness_m.size()) + " thickness values for " +
                       std::to_string(strands.point_count()) + " points");
  std::ofstream out = open_output(path, std::ios::binary);
  out.write(reinterpret_cast<const char*>(&header), sizeof header);
  out.write(reinterpret_cast<const char*>(segments.data()),
            static_cast<std::streamsize>(segments.size() * sizeof(uint16_t)));
  out.write(reinterpret_cast<const char*>(strands.points.data()),
            static_cast<std::streamsize>(strands.points.size() * sizeof(float)));
  if (!thickness_m.empty())
    out.write(reinterpret_cast<const char*>(thickness_m.data()),
              static_cast<std::streamsize>(thickness_m.size() * sizeof(float)));
  finish(out, path);
}

StrandSet read_cyhair(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error::bad_input(path.string(), "cannot open");
  CyHairHeader header;
  if (!in.read(reinterpret_cast<char*>(&header), sizeof header) ||
      std::memcmp(header.signature, "HAIR", 4) != 0)
    throw Error::bad_input(path.string(), "not a cyHair file (no HAIR signature)");
  if (!(header.arrays & kPointsArray)) throw Error::bad_input(path.string(), "has no points array");
  std::vector<uint16_t> segments(header.hair_count, static_cast<uint16_t>(header.default_segments));
  if (header.arrays & kSegmentsArray)
    in.read(reinterpret_cast<char*>(segments.data()),
            static_cast<std::streamsize>(segments.size() * sizeof(uint16_t)));
  StrandSet strands;
  strands.points.resize(header.point_count, 3);
  in.read(reinterpret_cast<char*>(strands.points.data()),
          static_cast<std::streamsize>(strands.points.size() * sizeof(float)));
  if (!in) throw Error::bad_input(path.string(), "ends before its points do");
  int64_t total = 0;
  for (uint16_t count : segments) {
    total += count + 1;
    strands.offsets.push_back(total);
  }
  if (total != header.point_count)
    throw Error::bad_input(path.string(), "its segments cover " + std::to_string(total) +
                                              " points, its header says " +
                                              std::to_string(header.point_count));
  (void)kTransparencyArray;
  (void)kColourArray;
  return strands;
}

namespace {

/// The shortest decimal text that reads back as the same float (std::to_chars).
std::string shortest(float value) {
  char text[32];
  const auto result = std::to_chars(text, text + sizeof text, value);
  return std::string(text, result.ptr);
}

/// Writes points as a USD point3f list, each coordinate in its shortest exact text and no
/// spaces (USD's text format needs none; a tenth of the size).
void write_points(std::ostream& out, const Points3f& points) {
  out << '[';
  for (Eigen::Index row = 0; row < points.rows(); ++row)
    out << (row ? ",(" : "(") << shortest(points(row, 0)) << ',' << shortest(points(row, 1))
        << ',' << shortest(points(row, 2)) << ')';
  out << ']';
}

/// The layer's metadata: metres, +Y up, the time codes of `frames` (none: no range).
void write_layer_header(std::ostream& out, const std::string& comment, double fps,
                        const std::vector<int64_t>& frames, const std::string& sublayer) {
  out << "#usda 1.0\n(\n    defaultPrim = \"Groom\"\n    doc = \"hairstyle interpolate: " << comment
      << "\"\n    metersPerUnit = 1\n    upAxis = \"Y\"\n";
  if (!sublayer.empty()) out << "    subLayers = [\n        @" << sublayer << "@\n    ]\n";
  if (!frames.empty())
    out << "    startTimeCode = " << frames.front() << "\n    endTimeCode = " << frames.back()
        << "\n";
  out << "    timeCodesPerSecond = " << fps << "\n    framesPerSecond = " << fps << "\n)\n\n";
}

}  // namespace

void write_usda_groom(const std::filesystem::path& path, const UsdaCurves& curves,
                      const Points3f& rest_points) {
  const auto strand_count = static_cast<int64_t>(curves.offsets.size()) - 1;
  std::ofstream out = open_output(path);
  auto ints = [&](const auto& values) {
    out << '[';
    for (size_t i = 0; i < values.size(); ++i) out << (i ? ", " : "") << values[i];
    out << ']';
  };
  write_layer_header(out, curves.comment, curves.fps, {}, "");
  out << "def Xform \"Groom\" (\n    kind = \"component\"\n)\n{\n";
  out << "    def BasisCurves \"Strands\"\n    {\n        uniform token type = \"linear\"\n";
  out << "        uniform token wrap = \"nonperiodic\"\n";
  std::vector<int64_t> counts;
  for (int64_t s = 0; s < strand_count; ++s)
    counts.push_back(curves.offsets[static_cast<size_t>(s) + 1] -
                     curves.offsets[static_cast<size_t>(s)]);
  out << "        int[] curveVertexCounts = ";
  ints(counts);
  out << "\n        point3f[] points = ";
  write_points(out, rest_points);
  // Widths to three digits: a render hint, half the size of exact floats.
  out << "\n        float[] widths = [";
  char width[32];
  for (size_t i = 0; i < curves.width_m.size(); ++i) {
    std::snprintf(width, sizeof width, "%.3g", static_cast<double>(curves.width_m[i]));
    out << (i ? "," : "") << width;
  }
  out << "] (\n            interpolation = \"vertex\"\n        )\n";
  out << "        int[] primvars:groom_id = ";
  ints(curves.groom_id);
  out << " (\n            interpolation = \"uniform\"\n        )\n";
  out << "        int[] primvars:groom_guide = ";
  ints(curves.groom_guide);
  out << " (\n            interpolation = \"uniform\"\n        )\n";
  out << "        texCoord2f[] primvars:groom_root_uv = [";
  for (size_t i = 0; i < curves.root_uv.size(); ++i)
    out << (i ? ", " : "") << '(' << shortest(curves.root_uv[i].x()) << ", "
        << shortest(curves.root_uv[i].y()) << ')';
  out << "] (\n            interpolation = \"uniform\"\n        )\n";
  out << "        int[] primvars:cluster = ";
  ints(curves.cluster);
  out << " (\n            interpolation = \"uniform\"\n        )\n";
  out << "        int[] primvars:style = ";
  ints(curves.style);
  out << " (\n            interpolation = \"uniform\"\n        )\n";
  out << "    }\n}\n";
  finish(out, path);
}

void write_usda_animation(const std::filesystem::path& path, const std::string& groom_layer,
                          double fps, const std::string& comment,
                          const std::vector<int64_t>& frames,
                          const std::function<Points3f(size_t)>& frame_points) {
  std::ofstream out = open_output(path);
  write_layer_header(out, comment, fps, frames, groom_layer);
  out << "over \"Groom\"\n{\n    over \"Strands\"\n    {\n";
  out << "        point3f[] points.timeSamples = {\n";
  for (size_t k = 0; k < frames.size(); ++k) {
    out << "            " << frames[k] << ": ";
    write_points(out, frame_points(k));
    out << ",\n";
  }
  out << "        }\n    }\n}\n";
  finish(out, path);
}

}  // namespace hair
