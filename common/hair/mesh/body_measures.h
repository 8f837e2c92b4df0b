#pragma once

#include "hair/mesh/poly_mesh.h"

namespace hair {

/// Where the head is on a body mesh (+Y up).
struct HeadMeasures {
  double head_top_y = 0;   ///< highest body vertex (crown)
  double neck_y = 0;       ///< height of the narrowest horizontal slice of the neck
  double head_height = 0;  ///< H = head_top_y - neck_y, the normaliser of eq. (1)
  double head_width = 0;   ///< widest horizontal slice of the head
  double neck_width = 0;   ///< width at neck_y
};

/// Measures the head of an upright body mesh (+Y up).
///
/// The body is cut by 300 horizontal planes spread over its height; a slice's width is
/// the larger of the x and z extents of the surface's cross-section there (every edge
/// crossing the plane). Walking down from the
/// crown, the width grows to the head's widest, narrows at the neck (to at most 0.7
/// of the widest) and jumps at the shoulders (over 1.6 times the widest); the neck is
/// the narrowest slice between the two, or the narrowest below the head for a mesh
/// without shoulders. H is the height from the neck to the crown: it is the
/// "head height" of the paper's eq. (1), measured where a mesh defines it well (the
/// chin is hard to find on a mesh; the neck's waist is not). On the MakeHuman body
/// it is 0.242 m.
///
/// Throws hair::Error (bad_input) naming `file` for a mesh with no height.
HeadMeasures head_measures(const PolyMesh& body, const std::string& file);

}  // namespace hair
