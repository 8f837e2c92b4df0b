#pragma once
// The flow an artist painted on a hair mesh (issue: real artist meshes). A hair card's
// texture shows the hair: its strokes run along the strands and its alpha fades out
// towards the tips. Per face, the orientation of the strokes under the face (the
// structure tensor of the texture's luminance) is carried into 3D through the face's
// texture map; the alpha's fall along it across the face says which way the tips lie.

#include <Eigen/Core>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "hair/mesh/poly_mesh.h"

namespace hair {

/// Parameters of painted_flow().
struct PaintedFlowParams {
  /// Texels with at least this alpha are painted hair; the others are left out.
  double min_alpha = 0.2;
  /// Gaussian window of the structure tensor and of the alpha's gradient, texels.
  double window_px = 3.0;
  /// Detail finer than this (Gaussian sigma, texels) are strokes: the structure tensor is
  /// taken of the luminance less its blur at this scale, so that broad shading and painted
  /// highlight bands across the hair do not read as strokes.
  double stroke_scale_px = 2.0;
  /// Samples per side of each of a face's triangles in texture space (n (n + 1) / 2 each).
  int samples_per_side = 3;
  /// A face is painted when at least this share of its samples falls on painted texels.
  double min_painted_share = 0.5;
};

/// Per face of the mesh: the painted flow axis in 3D, how clearly the strokes run one way,
/// and how much the alpha falls along it. A face without an image, texture coordinates,
/// painted texels or a texture map that spans 2D has direction zero and coherence zero.
struct PaintedFlow {
  std::vector<Eigen::Vector3f> direction;  ///< #faces: unit, or zero where not painted
  /// #faces, in [0, 1]: (l1 - l2) / (l1 + l2) of the structure tensor's eigenvalues (1:
  /// strokes all one way; 0: no way preferred).
  std::vector<float> coherence;
  /// #faces, >= 0: the fall of the alpha along `direction` across the face (alpha at the
  /// face's back end minus at its front end, along the strokes). `direction` points the way
  /// the alpha falls, towards the tips, wherever this is clearly above zero; where it is
  /// near zero, its sign is arbitrary.
  std::vector<float> alpha_fall;
  /// Images that could not be read, one message each (already logged as warnings).
  std::vector<std::string> unreadable_images;

  int64_t painted_face_count() const;
};

struct PaintedTexture;

/// The images of a mesh's materials, decoded and prepared for painted_flow() (the
/// structure tensor of the luminance, the alpha and its gradient), one per material.
struct PaintedTextures {
  /// Per material of the mesh: its prepared texture, or null (no image, or unreadable).
  std::vector<std::shared_ptr<const PaintedTexture>> by_material;
  /// Images that could not be read, one message each (already logged as warnings).
  std::vector<std::string> unreadable_images;

  bool empty() const;
};

/// Reads and prepares the images of `materials` (from disk or embedded). An image that is
/// missing, unreadable, empty or not an image gives one warning naming it and leaves its
/// material without texture; it never throws for that. `source` names the mesh in messages.
PaintedTextures load_painted_textures(const std::vector<MeshMaterial>& materials,
                                      const PaintedFlowParams& params, const std::string& source);

/// The painted flow of every face of `mesh` from its materials' prepared `textures`
/// (load_painted_textures() of the same material list). Pure: no file access.
PaintedFlow painted_flow(const PolyMesh& mesh, const PaintedTextures& textures,
                         const PaintedFlowParams& params);

/// Both steps: the painted flow of every face of `mesh`, its images read from disk or
/// embedded (see load_painted_textures()).
PaintedFlow painted_flow(const PolyMesh& mesh, const PaintedFlowParams& params,
                         const std::string& source);

/// A face's painted flow is clear from this coherence on (the measures count only those).
inline constexpr double kClearFlowCoherence = 0.3;
/// A strand segment runs along the painted flow when within this angle of its axis.
inline constexpr double kFlowAgreementAngleDeg = 30;

/// Per point of `strands`, how the segment that ends there (the root: the segment that
/// starts there) runs against the painted flow of its nearest face: 1 within
/// `max_angle_deg` of its axis (either sense), 0 not, -1 not judged (the nearest face
/// farther than `max_distance_m`, or its flow under `min_coherence`; a segment of no
/// length; a strand of one point).
std::vector<int8_t> segments_along_painted_flow(const PolyMesh& mesh, const PaintedFlow& flow,
                                                const StrandSet& strands, double min_coherence,
                                                double max_angle_deg, double max_distance_m);

/// The flow of every face as a user judges grown hair against: the painted flow where it
/// is clear (coherence >= kClearFlowCoherence), else the face's rails: the direction of the
/// segment nearest the face's centroid, within `max_distance_m`, of the input strands of
/// the face's own group (`face_group`, one per face; their "group" strand attribute),
/// with coherence 1. Where a face's group has no input strand, or without the groups, the
/// nearest segment of any input strand. Faces with neither keep no flow. `input_strands`
/// are extract's strands. (The nearest segment of any strand would often be another card's
/// where cards cross or stack, as short01's spikes on its cap.)
PaintedFlow flow_with_rails(const PolyMesh& mesh, const PaintedFlow& painted,
                            const StrandSet& input_strands, const std::vector<int32_t>& face_group,
                            double max_distance_m);

/// The share of the judged segments of `strands` that run along the painted flow
/// (segments_along_painted_flow()); `counted` receives how many were judged (0: the share
/// is 0).
double painted_flow_agreement(const PolyMesh& mesh, const PaintedFlow& flow,
                              const StrandSet& strands, double min_coherence,
                              double max_angle_deg, double max_distance_m, int64_t& counted);

}  // namespace hair
