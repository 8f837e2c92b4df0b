#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace hair {

/// Style codes of hand labels (paper section 5.1): the values of
/// hair::synth::HairStyle, kept here as plain codes so that the labels depend on
/// nothing else.
inline constexpr int8_t kStyleNormal = 0;
inline constexpr int8_t kStyleFixed = 1;
inline constexpr int8_t kStyleShort = 2;
inline constexpr int8_t kStyleBraided = 3;

/// The style words, indexed by code.
inline constexpr std::array<std::string_view, 4> kStyleWords = {"normal", "fixed", "short",
                                                                "braided"};

/// The code of a style word ("normal", "fixed", "short", "braided"); none otherwise.
std::optional<int8_t> style_code(std::string_view word);

/// The hand label of one patch of a hair mesh (data/labels/makehuman_styles.tsv).
/// A patch (a connected set of faces, one extract group) is named by its first face,
/// which does not depend on how extract numbers its groups.
struct PatchStyleLabel {
  std::string model;            ///< the mesh's file name without extension, e.g. "braid01"
  int64_t first_face = 0;       ///< smallest face index of the patch, 0-based, in the file's order
  int8_t style = kStyleNormal;  ///< style code (kStyleWords)
  int64_t line = 0;             ///< line of the label in its file, 1-based (for messages)
};

/// Reads a table of patch labels: lines starting with '#' and blank lines are
/// comments; the first other line is the header `model<TAB>first_face<TAB>style`;
/// then one row per patch with those three tab-separated fields.
///
/// Throws hair::Error (bad_input) with one line naming the file and line number for
/// an unreadable file, a missing or wrong header, a row without three fields, an
/// empty model, a first face that is not a non-negative integer, a style that is not
/// one of kStyleWords, and a (model, first_face) given twice.
std::vector<PatchStyleLabel> read_patch_style_labels(const std::filesystem::path& tsv);

/// The style of every extract group of one model from its patch labels: the label
/// whose first face is the group's smallest face.
///
/// @param face_group   #faces group of every face (extract.h5 /mesh/face_group)
/// @param group_count  number of groups
/// @param labels       labels of any models; only those of `model` are used
/// @param model        the model the groups belong to
/// @return #group_count style codes; -1 for a group without a label (or without a face)
///
/// Throws hair::Error (bad_input) naming the model, the first face and the label's
/// line when a label of `model` names no group's smallest face (the mesh changed), and
/// when face_group holds a group outside [0, group_count).
std::vector<int8_t> group_styles_from_patch_labels(const std::vector<int32_t>& face_group,
                                                   int32_t group_count,
                                                   const std::vector<PatchStyleLabel>& labels,
                                                   std::string_view model);

}  // namespace hair
