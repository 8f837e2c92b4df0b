#include "hair/style/puk_svm.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "hair/core/error.h"
#include "hair/style/puk_kernel.h"

namespace hair {
namespace {

std::vector<int32_t> distinct_labels(std::span<const int32_t> labels) {
  std::vector<int32_t> classes(labels.begin(), labels.end());
  std::sort(classes.begin(), classes.end());
  classes.erase(std::unique(classes.begin(), classes.end()), classes.end());
  return classes;
}

void check_params(const PukSvmParams& params) {
  if (!(std::isfinite(params.c) && params.c > 0))
    throw Error::usage("SVM: C (" + std::to_string(params.c) + ") must be finite and positive");
  PukKernel check(params.sigma, params.omega);  // throws for a bad sigma or omega
}

}  // namespace

cv::Ptr<cv::ml::SVM> trained_opencv_puk_svm(const FloatRows& rows, std::span<const int32_t> labels,
                                            const PukSvmParams& params) {
  check_params(params);
  if (static_cast<size_t>(rows.rows()) != labels.size())
    throw Error::usage("SVM: " + std::to_string(rows.rows()) + " rows but " +
                       std::to_string(labels.size()) + " labels");
  if (distinct_labels(labels).size() < 2)
    throw Error::usage("SVM: training needs rows of at least two classes");

  cv::Mat samples(static_cast<int>(rows.rows()), static_cast<int>(rows.cols()), CV_32F);
  std::copy(rows.data(), rows.data() + rows.size(), samples.ptr<float>());
  cv::Mat responses(static_cast<int>(labels.size()), 1, CV_32S);
  std::copy(labels.begin(), labels.end(), responses.ptr<int32_t>());

  cv::Ptr<cv::ml::SVM> svm = cv::ml::SVM::create();
  svm->setType(cv::ml::SVM::C_SVC);
  svm->setCustomKernel(cv::makePtr<PukKernel>(params.sigma, params.omega));
  svm->setC(params.c);
  svm->setTermCriteria(cv::TermCriteria(cv::TermCriteria::COUNT + cv::TermCriteria::EPS,
                                        kSvmMaxIterations, kSvmTolerance));
  bool trained = false;
  try {
    trained = svm->train(cv::ml::TrainData::create(samples, cv::ml::ROW_SAMPLE, responses));
  } catch (const cv::Exception& error) {
    throw Error::runtime("", std::string("SVM training failed in OpenCV: ") + error.what());
  }
  if (!trained || svm->getSupportVectors().empty())
    throw Error::runtime("", "SVM training failed in OpenCV (no support vectors)");
  return svm;
}

PukSvm puk_svm_from_opencv(const cv::ml::SVM& svm, std::vector<int32_t> class_labels,
                           const PukSvmParams& params) {
  PukSvm result;
  result.params = params;
  result.class_labels = std::move(class_labels);
  cv::Mat vectors = svm.getSupportVectors();
  result.feature_count = svm.getVarCount();
  result.support_vectors.resize(vectors.rows, vectors.cols);
  for (int row = 0; row < vectors.rows; ++row)
    for (int column = 0; column < vectors.cols; ++column)
      result.support_vectors(row, column) = vectors.at<float>(row, column);
  auto k = static_cast<int32_t>(result.class_labels.size());
  int index = 0;
  for (int32_t first = 0; first < k; ++first)
    for (int32_t second = first + 1; second < k; ++second, ++index) {
      cv::Mat alpha, sv_index;
      SvmDecisionFunction function;
      function.first = first;
      function.second = second;
      function.rho = svm.getDecisionFunction(index, alpha, sv_index);
      function.alpha.assign(alpha.ptr<double>(), alpha.ptr<double>() + alpha.total());
      function.sv_index.assign(sv_index.ptr<int32_t>(), sv_index.ptr<int32_t>() + sv_index.total());
      result.decision_functions.push_back(std::move(function));
    }
  return result;
}

PukSvm trained_puk_svm(const FloatRows& rows, std::span<const int32_t> labels,
                       const PukSvmParams& params) {
  std::vector<int32_t> classes = distinct_labels(labels);
  if (classes.size() == 1) {
    check_params(params);
    PukSvm single;
    single.params = params;
    single.class_labels = std::move(classes);
    single.support_vectors.resize(0, rows.cols());
    single.feature_count = static_cast<int>(rows.cols());
    return single;
  }
  return puk_svm_from_opencv(*trained_opencv_puk_svm(rows, labels, params), std::move(classes),
                             params);
}

SvmPrediction svm_prediction(const PukSvm& svm, const float* row) {
  auto sv_count = static_cast<int>(svm.support_vectors.rows());
  std::vector<float> kernel(static_cast<size_t>(sv_count));
  for (int sv = 0; sv < sv_count; ++sv)
    kernel[static_cast<size_t>(sv)] =
        puk_kernel_float(svm.support_vectors.row(sv).data(), row, svm.feature_count,
                         svm.params.sigma, svm.params.omega);

  SvmPrediction prediction;
  prediction.votes.assign(svm.class_labels.size(), 0);
  prediction.decision_values.reserve(svm.decision_functions.size());
  for (const SvmDecisionFunction& function : svm.decision_functions) {
    double sum = -function.rho;
    for (size_t k = 0; k < function.alpha.size(); ++k)
      sum += function.alpha[k] * kernel[static_cast<size_t>(function.sv_index[k])];
    prediction.decision_values.push_back(sum);
    ++prediction.votes[static_cast<size_t>(sum > 0 ? function.first : function.second)];
  }
  size_t best = 0;
  for (size_t c = 1; c < prediction.votes.size(); ++c)
    if (prediction.votes[c] > prediction.votes[best]) best = c;
  prediction.label = svm.class_labels[best];
  return prediction;
}

int32_t svm_label_without(const PukSvm& svm, std::span<const double> decision_values,
                          int32_t excluded_label) {
  if (decision_values.size() != svm.decision_functions.size())
    throw Error::usage("svm_label_without: " + std::to_string(decision_values.size()) +
                       " decision values for " + std::to_string(svm.decision_functions.size()) +
                       " decision functions");
  const size_t classes = svm.class_labels.size();
  const auto excluded = static_cast<size_t>(
      std::find(svm.class_labels.begin(), svm.class_labels.end(), excluded_label) -
      svm.class_labels.begin());
  const bool excluding = excluded < classes && classes > 1;
  auto out = [&](int32_t index) { return excluding && static_cast<size_t>(index) == excluded; };
  std::vector<int32_t> votes(classes, 0);
  for (size_t p = 0; p < svm.decision_functions.size(); ++p) {
    const SvmDecisionFunction& function = svm.decision_functions[p];
    if (out(function.first) || out(function.second)) continue;
    ++votes[static_cast<size_t>(decision_values[p] > 0 ? function.first : function.second)];
  }
  size_t best = classes;
  for (size_t c = 0; c < classes; ++c)
    if (!out(static_cast<int32_t>(c)) && (best == classes || votes[c] > votes[best])) best = c;
  return svm.class_labels[best];
}

}  // namespace hair
