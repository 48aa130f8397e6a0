#include "detect/colour_gmm.hpp"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <numbers>
#include <numeric>

#include <opencv2/ml.hpp>

#include "core/error.hpp"
#include "detect/seeded_the_rng.hpp"

namespace littermap::detect {
namespace {

const double kLog2Pi = std::log(2.0 * std::numbers::pi);

// Colours as a continuous N x 3 CV_32F matrix (layouts in the header).
cv::Mat ToSampleRows(const cv::Mat& samples, const char* what) {
  const int depth = samples.depth();
  const bool pixels = samples.channels() == 3;
  if (samples.empty() || (depth != CV_8U && depth != CV_32F) ||
      !(pixels || (samples.channels() == 1 && samples.cols == 3))) {
    throw UsageError(std::string(what) +
                     ": samples must be N x 3 (CV_8U or CV_32F) or CV_8UC3 / CV_32FC3 colours");
  }
  cv::Mat rows;
  samples.convertTo(rows, pixels ? CV_32FC3 : CV_32FC1);  // a continuous copy
  rows = rows.reshape(1, static_cast<int>(rows.total() * rows.channels() / 3));
  if (depth == CV_32F && !cv::checkRange(rows)) {
    throw UsageError(std::string(what) + ": samples must be finite");
  }
  return rows;
}

// max_samples rows chosen by a seeded partial Fisher-Yates shuffle, kept in input order.
cv::Mat Subsample(const cv::Mat& rows, int max_samples, std::uint64_t seed) {
  if (rows.rows <= max_samples) return rows;
  std::vector<int> index(std::size_t(rows.rows));
  std::iota(index.begin(), index.end(), 0);
  cv::RNG rng(seed);
  for (int i = 0; i < max_samples; ++i) {
    std::swap(index[std::size_t(i)], index[std::size_t(rng.uniform(i, rows.rows))]);
  }
  std::sort(index.begin(), index.begin() + max_samples);
  cv::Mat kept(max_samples, 3, CV_32F);
  for (int i = 0; i < max_samples; ++i) rows.row(index[std::size_t(i)]).copyTo(kept.row(i));
  return kept;
}

// Covariance with every eigenvalue raised to at least min_variance. A diagonal matrix has the
// axes as eigenvectors, so it stays diagonal.
cv::Matx33d FloorCovariance(const cv::Matx33d& covariance, double min_variance, int* floored) {
  cv::Matx31d values;
  cv::Matx33d vectors;  // rows are eigenvectors
  cv::eigen(0.5 * (covariance + covariance.t()), values, vectors);
  cv::Matx33d clamped = cv::Matx33d::zeros();
  for (int i = 0; i < 3; ++i) {
    *floored += values(i) < min_variance ? 1 : 0;
    clamped(i, i) = std::max(values(i), min_variance);
  }
  return vectors.t() * clamped * vectors;
}

// Initial mixture from K-means: cluster centres, shares and (floored) covariances. Diagonal EM
// gets spherical initial covariances: cv::ml::EM takes a given diagonal covariance's singular
// values in descending order, not per axis, until its first M-step.
struct InitialMixture {
  cv::Mat means;  // K x 3 CV_64F
  std::vector<cv::Mat> covariances;
  cv::Mat weights;  // 1 x K CV_64F
};

InitialMixture KMeansInit(const cv::Mat& rows, const ColourGmmOptions& options) {
  const int k = options.components;
  cv::Mat labels, centres;
  {
    const SeededTheRng seeded(options.seed);  // repeatable training
    cv::kmeans(rows, k, labels,
               cv::TermCriteria(cv::TermCriteria::COUNT | cv::TermCriteria::EPS, 20, 0.1), 3,
               cv::KMEANS_PP_CENTERS, centres);
  }
  std::vector<cv::Matx33d> scatter(std::size_t(k), cv::Matx33d::zeros());
  std::vector<double> count(std::size_t(k), 0.0);
  for (int i = 0; i < rows.rows; ++i) {
    const auto c = std::size_t(labels.at<int>(i));
    const cv::Vec3d d = cv::Vec3d(rows.at<cv::Vec3f>(i)) - cv::Vec3d(centres.at<cv::Vec3f>(int(c)));
    scatter[c] += d * d.t();
    count[c] += 1.0;
  }
  InitialMixture init;
  centres.convertTo(init.means, CV_64F);
  init.weights.create(1, k, CV_64F);
  int floored = 0;
  for (std::size_t c = 0; c < std::size_t(k); ++c) {
    cv::Matx33d covariance = scatter[c] * (1.0 / std::max(count[c], 1.0));
    if (options.covariance == GmmCovariance::kDiagonal) {
      covariance = cv::Matx33d::eye() * (cv::trace(covariance) / 3.0);
    }
    init.covariances.push_back(
        cv::Mat(FloorCovariance(covariance, options.min_variance, &floored)));
    init.weights.at<double>(int(c)) = count[c] / rows.rows;
  }
  return init;
}

void CheckImageAndMask(const cv::Mat& image_bgr, const cv::Mat& mask, const char* what) {
  if (image_bgr.empty() || image_bgr.type() != CV_8UC3) {
    throw UsageError(std::string("colour GMM ") + what + ": image must be non-empty CV_8UC3");
  }
  if (!mask.empty() && (mask.type() != CV_8UC1 || mask.size() != image_bgr.size())) {
    throw UsageError(std::string("colour GMM ") + what + ": mask must be CV_8UC1 of image size");
  }
}

std::string GmmField(const std::string& text) { return "colour GMM model: " + text; }

std::string ReadString(const cv::FileNode& node, const std::string& field) {
  if (!node.isString()) throw BadInputError(GmmField(field + " must be a string"));
  return static_cast<std::string>(node);
}

// rows: the required row count, or -1 for any (the component count K).
cv::Mat ReadMatrix(const cv::FileNode& node, const std::string& field, int rows, int cols) {
  cv::Mat m;
  try {
    node >> m;
  } catch (const cv::Exception&) {
    throw BadInputError(GmmField(field + " is not a matrix"));
  }
  if (m.empty() || m.channels() != 1 || (rows > 0 && m.rows != rows) || m.cols != cols) {
    throw BadInputError(GmmField(field + " must be a " +
                                 (rows > 0 ? std::to_string(rows) : std::string("K")) + " x " +
                                 std::to_string(cols) + " matrix"));
  }
  m.convertTo(m, CV_64F);
  if (!cv::checkRange(m)) throw BadInputError(GmmField(field + " has a value that is not finite"));
  return m;
}

}  // namespace

void ColourGmmOptions::Validate() const {
  constexpr const char* kStage = "colour GMM";
  RequireOption(components >= 1, kStage, "components", ">= 1");
  RequireOption(max_samples >= components, kStage, "max_samples", ">= components");
  RequireOption(max_em_iterations >= 1, kStage, "max_em_iterations", ">= 1");
  RequireOption(em_relative_tolerance > 0, kStage, "em_relative_tolerance", "> 0");
  RequireOption(min_variance > 0 && std::isfinite(min_variance), kStage, "min_variance",
                "> 0, finite");
}

ColourGmm::ColourGmm(const ColourGmmOptions& options) : options_(options) { options_.Validate(); }

ColourGmmTrainResult ColourGmm::Train(const cv::Mat& samples) {
  const cv::Mat all = ToSampleRows(samples, "colour GMM training");
  if (all.rows < options_.components) {
    throw UsageError("colour GMM: " + std::to_string(all.rows) + " training colours for " +
                     std::to_string(options_.components) + " components");
  }
  ColourGmmTrainResult result;
  result.samples_given = std::size_t(all.rows);
  const cv::Mat rows = Subsample(all, options_.max_samples, options_.seed);
  result.samples_used = std::size_t(rows.rows);
  const InitialMixture init = KMeansInit(rows, options_);

  cv::Ptr<cv::ml::EM> em = cv::ml::EM::create();
  em->setClustersNumber(options_.components);
  em->setCovarianceMatrixType(options_.covariance == GmmCovariance::kFull
                                  ? cv::ml::EM::COV_MAT_GENERIC
                                  : cv::ml::EM::COV_MAT_DIAGONAL);
  em->setTermCriteria(cv::TermCriteria(cv::TermCriteria::COUNT | cv::TermCriteria::EPS,
                                       options_.max_em_iterations, options_.em_relative_tolerance));
  if (!em->trainE(rows, init.means, init.covariances, init.weights)) {
    throw InternalError("colour GMM: cv::ml::EM training failed (log-likelihood diverged)");
  }
  // Fresh matrices, never written in place: copies of a ColourGmm share them. A component EM
  // starved keeps a tiny weight rather than log(0).
  cv::Mat weights, means, covariances(options_.components, 9, CV_64F);
  cv::max(em->getWeights().reshape(1, options_.components), DBL_MIN, weights);
  std::vector<cv::Mat> covs;
  em->getCovs(covs);
  for (int j = 0; j < options_.components; ++j) {
    const cv::Matx33d floored = FloorCovariance(cv::Matx33d(covs[std::size_t(j)]),
                                                options_.min_variance, &result.floored_eigenvalues);
    std::copy(floored.val, floored.val + 9, covariances.ptr<double>(j));
  }
  em->getMeans().convertTo(means, CV_64F);
  weights_ = weights / cv::sum(weights)[0];
  means_ = means;
  covariances_ = covariances;
  Prepare();
  result.mean_log_likelihood = cv::mean(LogLikelihoods(rows))[0];
  return result;
}

double ColourGmm::weight(int j) const { return weights_.at<double>(j); }
cv::Vec3d ColourGmm::mean(int j) const { return cv::Vec3d(means_.ptr<double>(j)); }
cv::Matx33d ColourGmm::covariance(int j) const { return cv::Matx33d(covariances_.ptr<double>(j)); }

void ColourGmm::Prepare() {
  evaluators_.clear();
  for (int j = 0; j < weights_.rows; ++j) {
    const cv::Matx33d c = covariance(j);
    cv::Matx31d values;
    cv::Matx33d vectors;
    cv::eigen(c, values, vectors);
    if (!(weight(j) > 0) || !(values(2) > 0) || cv::norm(c - c.t()) > 1e-9 * cv::norm(c)) {
      throw BadInputError("colour GMM model: component " + std::to_string(j) +
                          " needs a positive weight and a symmetric positive definite covariance");
    }
    const cv::Matx33d p =
        vectors.t() * cv::Matx33d::diag(cv::Vec3d(1 / values(0), 1 / values(1), 1 / values(2))) *
        vectors;
    const double log_det = std::log(values(0)) + std::log(values(1)) + std::log(values(2));
    Evaluator e{};
    for (int i = 0; i < 3; ++i) e.mean[i] = static_cast<float>(means_.at<double>(j, i));
    e.p00 = float(p(0, 0)), e.p11 = float(p(1, 1)), e.p22 = float(p(2, 2));
    e.p01 = float(2 * p(0, 1)), e.p02 = float(2 * p(0, 2));  // off-diagonal terms appear twice
    e.p12 = float(2 * p(1, 2));                              // in the quadratic form
    e.log_scale = static_cast<float>(std::log(weight(j)) - 0.5 * (3.0 * kLog2Pi + log_det));
    evaluators_.push_back(e);
  }
}

// Log-likelihoods of n interleaved BGR colours, in chunks: the exponent a_j of every component for
// every colour (loops the compiler vectorises), their maximum per colour, then
// log sum_j exp(a_j - max) + max with cv::exp / cv::log, which are SIMD. Scalar expf and logf per
// pixel and component cost four times as much.
void ColourGmm::EvaluateColours(const float* bgr, int n, float* out) const {
  constexpr int kChunk = 1024;
  const int k = components();
  std::vector<float> buffer(std::size_t(k + 4) * std::min(n, kChunk));
  for (int start = 0; start < n; start += kChunk) {
    const int m = std::min(kChunk, n - start);
    float* x0 = buffer.data();  // planar channels, the maximum, then the K x m exponents
    float *x1 = x0 + m, *x2 = x1 + m, *best = x2 + m, *a = best + m;
    for (int i = 0; i < m; ++i) {
      x0[i] = bgr[3 * (start + i)], x1[i] = bgr[3 * (start + i) + 1];
      x2[i] = bgr[3 * (start + i) + 2], best[i] = -FLT_MAX;
    }
    for (int j = 0; j < k; ++j) {
      const Evaluator& e = evaluators_[std::size_t(j)];
      float* aj = a + static_cast<std::ptrdiff_t>(j) * m;
      for (int i = 0; i < m; ++i) {
        const float d0 = x0[i] - e.mean[0], d1 = x1[i] - e.mean[1], d2 = x2[i] - e.mean[2];
        aj[i] = e.log_scale - 0.5f * (d0 * (e.p00 * d0 + e.p01 * d1 + e.p02 * d2) +
                                      d1 * (e.p11 * d1 + e.p12 * d2) + e.p22 * d2 * d2);
        best[i] = std::max(best[i], aj[i]);
      }
    }
    for (int j = 0; j < k; ++j) {
      for (int i = 0; i < m; ++i) a[j * m + i] -= best[i];
    }
    cv::Mat terms(k, m, CV_32F, a), sums(1, m, CV_32F, x0);
    cv::exp(terms, terms);
    cv::reduce(terms, sums, 0, cv::REDUCE_SUM);  // >= 1: the largest term is exp(0)
    cv::log(sums, sums);
    for (int i = 0; i < m; ++i) out[start + i] = best[i] + x0[i];
  }
}

void ColourGmm::RequireTrained(const char* what) const {
  if (!trained()) throw UsageError(std::string("colour GMM: ") + what + " of an untrained model");
}

double ColourGmm::LogLikelihood(const cv::Vec3f& bgr) const {
  RequireTrained("log-likelihood");
  float out = 0;
  EvaluateColours(bgr.val, 1, &out);
  return out;
}

cv::Mat ColourGmm::LogLikelihoods(const cv::Mat& samples) const {
  RequireTrained("log-likelihoods");
  const cv::Mat rows = ToSampleRows(samples, "colour GMM log-likelihoods");
  cv::Mat out(rows.rows, 1, CV_32F);
  EvaluateColours(rows.ptr<float>(), rows.rows, out.ptr<float>());
  return out;
}

cv::Mat ColourGmm::LogLikelihoodImage(const cv::Mat& image_bgr, const cv::Mat& mask) const {
  RequireTrained("log-likelihood image");
  CheckImageAndMask(image_bgr, mask, "log-likelihood image");
  cv::Mat out = cv::Mat::zeros(image_bgr.size(), CV_32F);
  std::vector<float> colours, values;  // the row's selected pixels
  std::vector<int> columns;
  for (int r = 0; r < image_bgr.rows; ++r) {
    const auto* pixels = image_bgr.ptr<cv::Vec3b>(r);
    const std::uint8_t* m = mask.empty() ? nullptr : mask.ptr<std::uint8_t>(r);
    colours.clear();
    columns.clear();
    for (int c = 0; c < image_bgr.cols; ++c) {
      if (m != nullptr && m[c] == 0) continue;
      columns.push_back(c);
      for (int i = 0; i < 3; ++i) colours.push_back(pixels[c][i]);
    }
    values.resize(columns.size());
    EvaluateColours(colours.data(), static_cast<int>(columns.size()), values.data());
    auto* row = out.ptr<float>(r);
    for (std::size_t i = 0; i < columns.size(); ++i) row[columns[i]] = values[i];
  }
  return out;
}

double ColourGmm::Energy(const cv::Mat& image_bgr, const cv::Mat& mask) const {
  const cv::Mat log_likelihood = LogLikelihoodImage(image_bgr, mask);
  if (!mask.empty() && cv::countNonZero(mask) == 0) {
    throw UsageError("colour GMM energy: the mask selects no pixel");
  }
  return -cv::mean(log_likelihood, mask)[0];  // cv::mean sums in double
}

void ColourGmm::Write(cv::FileStorage& fs, const std::string& key) const {
  RequireTrained("writing");
  if (!fs.isOpened()) throw UsageError("colour GMM: the file storage is not open");
  const bool full = options_.covariance == GmmCovariance::kFull;
  fs << key << "{"
     << "colour_space"
     << "bgr"
     << "covariance" << (full ? "full" : "diagonal") << "weights" << weights_ << "means" << means_
     << "covariances" << covariances_ << "}";
}

ColourGmm ColourGmm::Read(const cv::FileNode& node) {
  if (!node.isMap()) throw BadInputError(GmmField("expected a map"));
  if (ReadString(node["colour_space"], "colour_space") != "bgr") {
    throw BadInputError(GmmField("colour_space must be bgr"));
  }
  const std::string type = ReadString(node["covariance"], "covariance");
  if (type != "full" && type != "diagonal") {
    throw BadInputError(GmmField("covariance must be full or diagonal"));
  }
  ColourGmmOptions options;
  options.covariance = type == "full" ? GmmCovariance::kFull : GmmCovariance::kDiagonal;
  const cv::Mat weights = ReadMatrix(node["weights"], "weights", -1, 1);
  options.components = weights.rows;
  options.max_samples = std::max(options.max_samples, weights.rows);
  ColourGmm gmm(options);
  gmm.weights_ = weights;
  gmm.means_ = ReadMatrix(node["means"], "means", weights.rows, 3);
  gmm.covariances_ = ReadMatrix(node["covariances"], "covariances", weights.rows, 9);
  if (std::abs(cv::sum(weights)[0] - 1.0) > 1e-9) {
    throw BadInputError(GmmField("weights must sum to 1"));
  }
  gmm.Prepare();
  return gmm;
}

}  // namespace littermap::detect
