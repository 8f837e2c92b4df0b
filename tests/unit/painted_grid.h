#pragma once
// A flat quad grid with a painted flow set by hand, for the tests of what extract reads
// from the paint (rail_paint, painted_streamlines).

#include <numeric>
#include <vector>

#include "hair/extract/painted_flow.h"
#include "hair/mesh/poly_mesh.h"

namespace hair::test {

/// A flat grid of `columns` x `rows` quads in the x-y plane from the origin, `width` by
/// `height` metres; vertex (i, j) is j * (columns + 1) + i.
inline PolyMesh flat_grid(int columns, int rows, float width, float height) {
  PolyMesh mesh;
  mesh.vertices.resize((columns + 1) * (rows + 1), 3);
  for (int j = 0; j <= rows; ++j)
    for (int i = 0; i <= columns; ++i)
      mesh.vertices.row(j * (columns + 1) + i) << width * static_cast<float>(i) / static_cast<float>(columns),
          height * static_cast<float>(j) / static_cast<float>(rows), 0.0f;
  for (int j = 0; j < rows; ++j)
    for (int i = 0; i < columns; ++i) {
      const int32_t a = j * (columns + 1) + i;
      const int32_t corners[4] = {a, a + 1, a + columns + 2, a + columns + 1};
      mesh.append_face(corners);
    }
  return mesh;
}

/// Every face's flow along `direction`, clear (coherence 0.9), the alpha falling by
/// `fall` along it.
inline PaintedFlow uniform_flow(const PolyMesh& mesh, const Eigen::Vector3f& direction, float fall) {
  PaintedFlow flow;
  const auto faces = static_cast<size_t>(mesh.face_count());
  flow.direction.assign(faces, direction.normalized());
  flow.coherence.assign(faces, 0.9f);
  flow.alpha_fall.assign(faces, fall);
  return flow;
}

/// The ids of every face of `mesh`.
inline std::vector<int64_t> all_faces(const PolyMesh& mesh) {
  std::vector<int64_t> faces(static_cast<size_t>(mesh.face_count()));
  std::iota(faces.begin(), faces.end(), 0);
  return faces;
}

}  // namespace hair::test
