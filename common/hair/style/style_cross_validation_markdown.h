#pragma once

#include <string>
#include <string_view>

#include "hair/style/style_cross_validation.h"

namespace hair {

/// A cross-validation's report as Markdown tables: the accuracy of both classifiers (with
/// that on the subset, titled `subset_name`, when the subset has rows), precision and
/// recall per class, the two confusion matrices (rows truth, columns predicted), and the
/// SVM settings chosen in each fold. Classes are named by hair_style_name() (labels that
/// are no HairStyle by their number); a precision with no row predicted as the class is
/// "–".
std::string style_cross_validation_markdown(const StyleCrossValidation& result,
                                            std::string_view subset_name);

}  // namespace hair
