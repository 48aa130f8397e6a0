#pragma once
// A Gaussian mixture over pixel colours (thesis 3.2 "GMM energy", and the colour models of the
// ground refinement, thesis 3.1): K-means (cv::kmeans, k-means++ seeding) gives the initial
// components, cv::ml::EM::trainE refines them, and the mixture is then evaluated by our own code
// from precomputed inverse covariances and log-determinants: cv::ml::EM::predict2 allocates
// several cv::Mat per call: called per pixel of a 640 x 480 frame it took 100-125 ms (diagonal)
// and 770-930 ms (full), this 3.6 ms (diagonal) and 4.3-5.5 ms (full); one thread, 5 components.
//
// Colour space: BGR as float, 0..255. The log-likelihood is then a density over the camera's
// colour cube, the same space as the frame, ColourTable's BGR grid and the uniform density
// -3 log 256 the ground refinement mixes in (a density in another space, e.g. Lab, would differ
// from those by the conversion's colour-dependent Jacobian), and evaluation needs no colour
// conversion per pixel.
//
// Covariances are diagonal by default, for training speed: cv::ml::EM spends most of an
// iteration in per-sample cv::Mat arithmetic, and with full covariances it multiplies every
// centred sample by a rotation too. Measured on 2000 samples of a shaded synthetic 640 x 480
// park frame (5 components, 2 shared cores): diagonal about 60 ms per training, full 210-300 ms,
// while the ground refinement trains two models per frame. Full covariances fit shaded surfaces
// better (BGR channels are correlated along the grey diagonal; GrabCut, Rother et al. 2004, uses
// them): 0.4 nats per pixel on that frame, so they are an option. Evaluation costs the same for
// both.
//
// Batch evaluation (LogLikelihoodImage, Energy, LogLikelihoods) computes the exponents of all
// components for a run of pixels and takes log-sum-exp with OpenCV's SIMD cv::exp / cv::log.
// Single colours go through the same code, so they agree with the batch exactly.

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

namespace littermap::detect {

enum class GmmCovariance { kFull, kDiagonal };

struct ColourGmmOptions {
  int components = 5;
  // Training samples kept, chosen by a seeded shuffle (deterministic for a seed): EM costs
  // O(samples x components x iterations) and 2000 colours describe a surface well.
  int max_samples = 2000;
  std::uint64_t seed = 1;  // subsampling and k-means++ seeding
  GmmCovariance covariance = GmmCovariance::kDiagonal;
  int max_em_iterations = 50;
  // EM stops when the total log-likelihood gains less than this share of itself; 1e-5 took twice
  // the time for 0.003 nats per sample more.
  double em_relative_tolerance = 1e-4;
  // Floor of every covariance eigenvalue, in (grey levels)^2: a component on a flat synthetic
  // colour or a saturated region would otherwise collapse to a spike of unbounded density. One
  // grey level of standard deviation is the quantisation and noise floor of an 8-bit camera.
  double min_variance = 1.0;
  void Validate() const;
};

struct ColourGmmTrainResult {
  std::size_t samples_given = 0;
  std::size_t samples_used = 0;    // after subsampling to max_samples
  double mean_log_likelihood = 0;  // of the used samples under the final mixture
  int floored_eigenvalues = 0;     // covariance eigenvalues raised to min_variance
};

class ColourGmm {
 public:
  explicit ColourGmm(const ColourGmmOptions& options = {});

  // samples: BGR colours, 0..255, as N x 3 single-channel (CV_8U or CV_32F) or as CV_8UC3 /
  // CV_32FC3 of any shape (every element one colour). Throws UsageError for another layout or
  // fewer samples than components, InternalError if EM fails.
  ColourGmmTrainResult Train(const cv::Mat& samples);

  bool trained() const { return !evaluators_.empty(); }
  int components() const { return static_cast<int>(evaluators_.size()); }
  const ColourGmmOptions& options() const { return options_; }
  double weight(int j) const;
  cv::Vec3d mean(int j) const;
  cv::Matx33d covariance(int j) const;

  // log sum_j w_j N(bgr | mean_j, cov_j), a log density per (grey level)^3. A cv::Vec3b
  // converts. Throws UsageError when untrained.
  double LogLikelihood(const cv::Vec3f& bgr) const;
  // The same for every colour of `samples` (layouts as for Train): N x 1 CV_32F.
  cv::Mat LogLikelihoods(const cv::Mat& samples) const;
  // Per pixel of a CV_8UC3 BGR image: CV_32F of its size. mask: CV_8U of the image's size,
  // non-zero = evaluate; an empty mask evaluates every pixel. Pixels outside the mask are 0.
  cv::Mat LogLikelihoodImage(const cv::Mat& image_bgr, const cv::Mat& mask = cv::Mat()) const;
  // GMM energy (thesis 3.2): mean over the mask's pixels of -log sum_j w_j N(x | j); lower is
  // more likely. The thesis sums over pixels; the mean compares objects of different sizes.
  // Throws UsageError when the mask selects no pixel.
  double Energy(const cv::Mat& image_bgr, const cv::Mat& mask = cv::Mat()) const;

  // Writes the mixture as map `key` of an open cv::FileStorage (YAML, JSON or XML).
  void Write(cv::FileStorage& fs, const std::string& key) const;
  // Reads a map written by Write. Throws BadInputError naming the field that is missing or wrong.
  static ColourGmm Read(const cv::FileNode& node);

 private:
  // Evaluation form of component j: log-density = log_scale - 0.5 (x - mean)^T P (x - mean).
  struct Evaluator {
    float mean[3];
    float p00, p01, p02, p11, p12, p22;  // P = covariance^-1; off-diagonal entries doubled
    float log_scale;                     // log w - 0.5 (3 log 2 pi + log det covariance)
  };

  // Fills evaluators_ from the model; BadInputError for a weight <= 0 or a covariance that is
  // not symmetric positive definite (possible only in a model file).
  void Prepare();
  void EvaluateColours(const float* bgr, int n, float* out) const;
  void RequireTrained(const char* what) const;

  ColourGmmOptions options_;
  cv::Mat weights_;      // K x 1 CV_64F, summing to 1
  cv::Mat means_;        // K x 3 CV_64F, BGR
  cv::Mat covariances_;  // K x 9 CV_64F, row-major 3 x 3 per component
  std::vector<Evaluator> evaluators_;
};

}  // namespace littermap::detect
