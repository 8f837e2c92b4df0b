#include "hair/style/style_cross_validation_markdown.h"

#include <fmt/format.h>

#include <cstdint>

#include "hair/style/hair_style.h"

namespace hair {
namespace {

std::string percent(int part, int whole) {
  if (whole <= 0) return "–";
  return fmt::format("{:.1f}%", 100.0 * part / whole);
}

std::string accuracy_cell(int correct, int rows) {
  return fmt::format("{} ({} / {})", percent(correct, rows), correct, rows);
}

void append_confusion(std::string& text, const char* title, const StyleCrossValidation& result,
                      const ClassificationScores& scores) {
  text += fmt::format("{} (rows: truth, columns: predicted)\n\n| truth \\ predicted |", title);
  for (int32_t label : result.class_labels)
    text += fmt::format(" {} |", hair_style_label_text(label));
  text += "\n|---|";
  for (size_t c = 0; c < result.class_labels.size(); ++c) text += "---:|";
  text += "\n";
  for (size_t truth = 0; truth < result.class_labels.size(); ++truth) {
    text += fmt::format("| {} |", hair_style_label_text(result.class_labels[truth]));
    for (size_t predicted = 0; predicted < result.class_labels.size(); ++predicted)
      text += fmt::format(" {} |", scores.confusion(static_cast<Eigen::Index>(truth),
                                                    static_cast<Eigen::Index>(predicted)));
    text += "\n";
  }
  text += "\n";
}

}  // namespace

std::string style_cross_validation_markdown(const StyleCrossValidation& result,
                                            std::string_view subset_name) {
  bool with_subset = result.svm.subset_rows > 0;
  std::string text = fmt::format("{}-fold {} cross-validation, {} rows\n\n", result.folds,
                                 result.given_folds ? "grouped" : "stratified", result.svm.rows);
  text += "| classifier | accuracy |";
  text += with_subset ? fmt::format(" {} |\n|---|---:|---:|\n", subset_name) : "\n|---|---:|\n";
  auto accuracy_row = [&](const char* name, const ClassificationScores& scores) {
    text += fmt::format("| {} | {} |", name, accuracy_cell(scores.correct, scores.rows));
    if (with_subset)
      text += fmt::format(" {} |", accuracy_cell(scores.subset_correct, scores.subset_rows));
    text += "\n";
  };
  accuracy_row("SVM (PUK kernel)", result.svm);
  accuracy_row("random forest", result.forest);
  text += "\n";

  text +=
      "| class | rows | SVM precision | SVM recall | forest precision | forest recall |\n"
      "|---|---:|---:|---:|---:|---:|\n";
  for (size_t c = 0; c < result.class_labels.size(); ++c) {
    const ClassScore& svm = result.svm.classes[c];
    const ClassScore& forest = result.forest.classes[c];
    text += fmt::format("| {} | {} | {} | {} | {} | {} |\n", hair_style_label_text(svm.label),
                        svm.rows, percent(svm.correct, svm.predicted),
                        percent(svm.correct, svm.rows), percent(forest.correct, forest.predicted),
                        percent(forest.correct, forest.rows));
  }
  text += "\n";

  append_confusion(text, "SVM confusion", result, result.svm);
  append_confusion(text, "Random forest confusion", result, result.forest);

  text +=
      "SVM settings chosen by the grid search on each fold's training rows\n\n"
      "| fold | test rows | sigma | omega | C | inner accuracy |\n"
      "|---:|---:|---:|---:|---:|---:|\n";
  for (size_t fold = 0; fold < result.svm_choice.size(); ++fold) {
    const PukSvmSelection& choice = result.svm_choice[fold];
    text += fmt::format("| {} | {} | {:g} | {:g} | {:g} | {} |\n", fold, result.fold_rows[fold],
                        choice.params.sigma, choice.params.omega, choice.params.c,
                        accuracy_cell(choice.correct, choice.rows));
  }
  return text;
}

}  // namespace hair
