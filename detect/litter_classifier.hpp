#pragma once
// The litter classifier, the scheme the thesis proposes (3.2, "Proposed training"): per class, a
// 9-bin naive Bayes colour model, a colour GMM, and K cluster centroids of its colour histograms
// (clustered under the Earth Mover's Distance's ground metric) and of its Hu moments. An object's
// naive-Bayes score, GMM energy and minimum EMD and Hu distances to every class, together with
// its raw colour, shape and size features, go to a random forest (OpenCV ml) that gives the
// final class and the vote share as confidence. Classes: the litter classes, "natural" and
// "clutter" (segmentation leftovers); is_litter says which is which.

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "detect/object_sample.hpp"

namespace littermap::detect {

struct ClassifierOptions {
  int clusters_per_class = 3;  // K
  int trees = 100;
  int max_depth = 14;
  int min_samples_per_leaf = 2;
  int max_samples_per_class = 2000;  // balances classes and bounds training time
  int gmm_components = 3;
  std::uint64_t seed = 1;
  void Validate() const;
};

// The classifiers of the thesis alone, and combined, for comparing them.
enum class ClassifierMethod { kNaiveBayes, kGmmEnergy, kEmd, kHu, kCombined };
const char* ClassifierMethodName(ClassifierMethod method);

struct Classification {
  std::vector<double> probabilities;  // per class
  std::size_t best = 0;
  double litter_probability = 0;  // sum over the litter classes
};

struct TrainingSummary {
  std::vector<std::pair<std::string, std::size_t>> samples_per_class;  // after balancing
  double training_accuracy = 0;
};

class LitterClassifier {
 public:
  // Throws UsageError with fewer than two classes. A class with fewer than K samples gets one
  // cluster per sample.
  static LitterClassifier Train(const std::vector<ObjectSample>& samples,
                                const ClassifierOptions& options, TrainingSummary* summary);
  // Throws BadInputError naming the file and field for an unreadable or foreign model.
  static LitterClassifier Load(const std::filesystem::path& file);
  void Save(const std::filesystem::path& file) const;

  Classification Classify(const ObjectSample& object) const;
  // The class for a probability vector, decided in two steps as the thesis's insight suggests
  // (the real split is litter vs not): litter when the litter classes together are at least as
  // likely as the other classes together, then the likeliest class of that kind. Seven litter
  // classes sharing one object's votes must not lose to one natural class, and an object more
  // likely not litter than litter is not litter, however the rest split between natural and
  // clutter. An item fused from many views may ask for more: litter when the litter classes
  // together have at least `min_litter_probability` of the whole.
  std::size_t Decide(const std::vector<double>& probabilities,
                     double min_litter_probability = 0.5) const;
  // The class one method alone picks (kCombined: Classify's best).
  std::size_t Predict(const ObjectSample& object, ClassifierMethod method) const;

  const std::vector<std::string>& classes() const;
  bool is_litter(std::size_t k) const;
  std::size_t ClassIndex(const std::string& name) const;  // classes().size() if unknown

  LitterClassifier(LitterClassifier&&) noexcept;
  LitterClassifier& operator=(LitterClassifier&&) noexcept;
  ~LitterClassifier();

 private:
  struct Model;
  explicit LitterClassifier(std::unique_ptr<Model> model);
  std::unique_ptr<Model> model_;
};

}  // namespace littermap::detect
