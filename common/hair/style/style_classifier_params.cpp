#include "hair/style/style_classifier_params.h"

#include <string>

#include "hair/core/error.h"
#include "hair/style/feature_standardization.h"

namespace hair {

const char* style_classifier_name(StyleClassifierKind kind) {
  switch (kind) {
    case StyleClassifierKind::svm:
      return "svm";
    case StyleClassifierKind::random_forest:
      return "random_forest";
  }
  return "unknown";
}

std::optional<StyleClassifierKind> style_classifier_from_name(std::string_view name) {
  for (StyleClassifierKind kind : {StyleClassifierKind::svm, StyleClassifierKind::random_forest})
    if (name == style_classifier_name(kind)) return kind;
  return std::nullopt;
}

void StyleClassifierParams::check() const {
  if (folds < 2)
    throw Error::usage("style classifier: folds = " + std::to_string(folds) +
                       " (the cross-validation needs at least 2)");
  if (inner_folds < 2)
    throw Error::usage("style classifier: inner_folds = " + std::to_string(inner_folds) +
                       " (the grid search needs at least 2)");
  check_puk_svm_grid(svm_grid);
  check_log_offsets(feature_log_offsets, "style classifier: feature_log_offsets");
  check_random_forest_params(forest);
  if (default_classifier != StyleClassifierKind::svm &&
      default_classifier != StyleClassifierKind::random_forest)
    throw Error::usage("style classifier: default_classifier is neither svm nor random_forest");
}

}  // namespace hair
