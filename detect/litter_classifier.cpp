#include "detect/litter_classifier.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <map>

#include <opencv2/ml.hpp>

#include "core/error.hpp"
#include "core/failure.hpp"
#include "detect/colour_emd.hpp"
#include "detect/colour_gmm.hpp"
#include "detect/hu_shape.hpp"
#include "detect/object_features.hpp"

namespace littermap::detect {

struct LitterClassifier::Model {
  std::vector<std::string> classes;
  std::vector<unsigned char> litter;
  ColourNaiveBayes naive_bayes;
  std::vector<ColourGmm> gmms;
  std::vector<std::vector<ColourHistogram>> emd_centroids;  // shares
  std::vector<std::vector<HuShape>> hu_medoids;
  cv::Ptr<cv::ml::RTrees> forest;

  // Per class: naive Bayes score per pixel, GMM energy, min EMD, log(1 + min Hu distance).
  std::vector<float> Distances(const ObjectDescription& d, const ObjectSample& object) const {
    std::vector<float> out;
    const std::vector<double> scores = naive_bayes.Scores(d.histogram);
    const double pixels = d.histogram.Total();
    const ColourHistogram shares = d.histogram.Normalised();
    for (std::size_t k = 0; k < classes.size(); ++k) {
      out.push_back(static_cast<float>(scores[k] / pixels));
      out.push_back(static_cast<float>(gmms[k].Energy(object.colour_bgr, object.mask)));
      double emd = 1e9, hu = 1e30;
      for (const auto& centroid : emd_centroids[k])
        emd = std::min(emd, ColourEmd(shares, centroid));
      for (const auto& medoid : hu_medoids[k]) hu = std::min(hu, HuInverseDistance(d.hu, medoid));
      out.push_back(static_cast<float>(emd));
      out.push_back(static_cast<float>(std::log1p(std::min(hu, 1e30))));
    }
    return out;
  }

  cv::Mat FeatureRow(const ObjectSample& object, ObjectDescription* description) const {
    *description = DescribeObject(object);
    std::vector<float> row = description->raw;
    const std::vector<float> distances = Distances(*description, object);
    row.insert(row.end(), distances.begin(), distances.end());
    return cv::Mat(row, true).reshape(1, 1);
  }
};

namespace {

std::map<std::string, std::vector<const ObjectSample*>> Balanced(
    const std::vector<ObjectSample>& samples, const ClassifierOptions& options) {
  std::map<std::string, std::vector<const ObjectSample*>> by_class;
  for (const auto& s : samples) by_class[s.label].push_back(&s);
  for (auto& [label, members] : by_class) {
    const std::size_t cap = static_cast<std::size_t>(options.max_samples_per_class);
    if (members.size() <= cap) continue;
    std::vector<const ObjectSample*> kept;
    for (std::size_t i = 0; i < cap; ++i) kept.push_back(members[i * members.size() / cap]);
    members = std::move(kept);
  }
  return by_class;
}

ColourGmm TrainClassGmm(const std::vector<const ObjectSample*>& members,
                        const ClassifierOptions& options) {
  std::vector<float> colours;
  const std::size_t step = std::max<std::size_t>(1, members.size() / 400);
  for (std::size_t i = 0; i < members.size(); i += step) {
    const ObjectSample& s = *members[i];
    for (int v = 0; v < s.mask.rows; v += 2) {
      for (int u = 0; u < s.mask.cols; u += 2) {
        if (!s.mask.at<std::uint8_t>(v, u)) continue;
        const cv::Vec3b c = s.colour_bgr.at<cv::Vec3b>(v, u);
        colours.insert(colours.end(), {float(c[0]), float(c[1]), float(c[2])});
      }
    }
  }
  const cv::Mat pixels(static_cast<int>(colours.size() / 3), 3, CV_32F, colours.data());
  ColourGmmOptions gmm_options;
  gmm_options.components = std::min(options.gmm_components, std::max(1, pixels.rows / 20));
  gmm_options.max_samples = 4000;
  gmm_options.seed = options.seed;
  ColourGmm gmm(gmm_options);
  gmm.Train(pixels);
  return gmm;
}

// K-means over the members' histogram shares (EMD centroids) and Hu medoids.
void ClusterClass(const std::vector<ObjectDescription>& descriptions, int k_wanted,
                  std::vector<ColourHistogram>* centroids, std::vector<HuShape>* medoids) {
  const int n = static_cast<int>(descriptions.size());
  const int k = std::min(k_wanted, n);
  cv::Mat shares(n, kColourBinCount, CV_32F), hu(n, 6, CV_32F);
  for (int i = 0; i < n; ++i) {
    const auto& d = descriptions[static_cast<std::size_t>(i)];
    for (int b = 0; b < kColourBinCount; ++b)
      shares.at<float>(i, b) = d.raw[static_cast<std::size_t>(b)];
    for (int m = 0; m < 6; ++m)
      hu.at<float>(i, m) = d.raw[kRawFeatureCount - 6 + static_cast<std::size_t>(m)];
  }
  const cv::TermCriteria stop(cv::TermCriteria::COUNT + cv::TermCriteria::EPS, 50, 1e-4);
  cv::Mat labels, centres;
  cv::setRNGSeed(1);
  cv::kmeans(shares, k, labels, stop, 3, cv::KMEANS_PP_CENTERS, centres);
  for (int c = 0; c < k; ++c) {
    ColourHistogram h;
    for (int b = 0; b < kColourBinCount; ++b) {
      h.counts[static_cast<std::size_t>(b)] = std::max(0.0f, centres.at<float>(c, b)) + 1e-6;
    }
    centroids->push_back(h.Normalised());
  }
  cv::kmeans(hu, k, labels, stop, 3, cv::KMEANS_PP_CENTERS, centres);
  for (int c = 0; c < k; ++c) {
    int best = 0;
    double best_distance = 1e300;
    for (int i = 0; i < n; ++i) {
      const double distance = cv::norm(hu.row(i), centres.row(c));
      if (distance < best_distance) best_distance = distance, best = i;
    }
    medoids->push_back(descriptions[static_cast<std::size_t>(best)].hu);
  }
}

}  // namespace

void ClassifierOptions::Validate() const {
  if (clusters_per_class < 1 || trees < 1 || max_depth < 1 || min_samples_per_leaf < 1 ||
      max_samples_per_class < clusters_per_class || gmm_components < 1) {
    throw UsageError("train: classifier options out of range");
  }
}

const char* ClassifierMethodName(ClassifierMethod method) {
  switch (method) {
    case ClassifierMethod::kNaiveBayes:
      return "naive Bayes (9 colour bins)";
    case ClassifierMethod::kGmmEnergy:
      return "GMM energy";
    case ClassifierMethod::kEmd:
      return "EMD to class centroids";
    case ClassifierMethod::kHu:
      return "Hu moment distance";
    case ClassifierMethod::kCombined:
      return "combined (random forest)";
  }
  return "?";
}

LitterClassifier::LitterClassifier(std::unique_ptr<Model> model) : model_(std::move(model)) {}
LitterClassifier::LitterClassifier(LitterClassifier&&) noexcept = default;
LitterClassifier& LitterClassifier::operator=(LitterClassifier&&) noexcept = default;
LitterClassifier::~LitterClassifier() = default;

const std::vector<std::string>& LitterClassifier::classes() const { return model_->classes; }
bool LitterClassifier::is_litter(std::size_t k) const { return model_->litter.at(k) != 0; }
std::size_t LitterClassifier::ClassIndex(const std::string& name) const {
  const auto& c = model_->classes;
  return static_cast<std::size_t>(std::find(c.begin(), c.end(), name) - c.begin());
}

LitterClassifier LitterClassifier::Train(const std::vector<ObjectSample>& samples,
                                         const ClassifierOptions& options,
                                         TrainingSummary* summary) {
  options.Validate();
  const auto by_class = Balanced(samples, options);
  if (by_class.size() < 2) throw UsageError("train: the samples name fewer than two classes");
  auto model = std::make_unique<Model>();
  std::vector<std::vector<ObjectDescription>> descriptions;
  for (const auto& [label, members] : by_class) {
    model->classes.push_back(label);
    model->litter.push_back(IsLitterClass(label));
    descriptions.emplace_back();
    for (const ObjectSample* s : members) {
      descriptions.back().push_back(DescribeObject(*s));
      model->naive_bayes.Train(label, descriptions.back().back().histogram);
    }
    model->gmms.push_back(TrainClassGmm(members, options));
    model->emd_centroids.emplace_back();
    model->hu_medoids.emplace_back();
    ClusterClass(descriptions.back(), options.clusters_per_class, &model->emd_centroids.back(),
                 &model->hu_medoids.back());
    if (summary) summary->samples_per_class.emplace_back(label, members.size());
  }
  cv::Mat features, responses;
  std::size_t k = 0;
  for (const auto& [label, members] : by_class) {
    for (std::size_t i = 0; i < members.size(); ++i) {
      ObjectDescription unused;
      features.push_back(model->FeatureRow(*members[i], &unused));
      responses.push_back(static_cast<int>(k));
    }
    ++k;
  }
  model->forest = cv::ml::RTrees::create();
  model->forest->setMaxDepth(options.max_depth);
  model->forest->setMinSampleCount(options.min_samples_per_leaf);
  model->forest->setTermCriteria({cv::TermCriteria::MAX_ITER, options.trees, 0});
  // Equal prior weight per class: the simulator (and a park) shows far more natural objects and
  // clutter than bottles, and the forest must not learn that rarity as "not litter".
  cv::Mat priors(1, static_cast<int>(by_class.size()), CV_32F);
  {
    int c = 0;
    for (const auto& [label, members] : by_class)
      priors.at<float>(c++) = 1.0f / static_cast<float>(members.size());
  }
  model->forest->setPriors(priors / cv::sum(priors)[0]);
  cv::setRNGSeed(static_cast<int>(options.seed));
  model->forest->train(cv::ml::TrainData::create(features, cv::ml::ROW_SAMPLE, responses));
  LitterClassifier classifier(std::move(model));
  if (summary) {
    cv::Mat predicted;
    classifier.model_->forest->predict(features, predicted);
    int correct = 0;
    for (int i = 0; i < features.rows; ++i) {
      correct += static_cast<int>(std::lround(predicted.at<float>(i))) == responses.at<int>(i);
    }
    summary->training_accuracy = double(correct) / features.rows;
  }
  return classifier;
}

Classification LitterClassifier::Classify(const ObjectSample& object) const {
  ObjectDescription description;
  const cv::Mat row = model_->FeatureRow(object, &description);
  cv::Mat votes;
  model_->forest->getVotes(row, votes, 0);
  // Row 0 holds the class responses, row 1 the votes for each.
  Classification out;
  out.probabilities.assign(model_->classes.size(), 0.0);
  double total = 0;
  for (int c = 0; c < votes.cols; ++c) total += votes.at<int>(1, c);
  for (int c = 0; c < votes.cols; ++c) {
    const auto k = static_cast<std::size_t>(votes.at<int>(0, c));
    if (k < out.probabilities.size() && total > 0)
      out.probabilities[k] = votes.at<int>(1, c) / total;
  }
  out.best = Decide(out.probabilities);
  for (std::size_t k = 0; k < out.probabilities.size(); ++k) {
    if (model_->litter[k]) out.litter_probability += out.probabilities[k];
  }
  return out;
}

std::size_t LitterClassifier::Decide(const std::vector<double>& probabilities,
                                     double min_litter_probability) const {
  // Litter or not first: the litter classes together against the whole, so by default an object
  // is litter when that is more likely than not. Then the most likely class of that kind.
  const std::size_t n = probabilities.size();
  double litter = 0, other = 0;
  for (std::size_t k = 0; k < n; ++k) (model_->litter[k] ? litter : other) += probabilities[k];
  const bool choose_litter = litter >= min_litter_probability * (litter + other);
  std::size_t best = n;
  for (std::size_t k = 0; k < n; ++k) {
    if ((model_->litter[k] != 0) != choose_litter) continue;
    if (best == n || probabilities[k] > probabilities[best]) best = k;
  }
  return best;
}

std::size_t LitterClassifier::Predict(const ObjectSample& object, ClassifierMethod method) const {
  if (method == ClassifierMethod::kCombined) return Classify(object).best;
  const ObjectDescription d = DescribeObject(object);
  const std::vector<float> distances = model_->Distances(d, object);
  const std::size_t field = static_cast<std::size_t>(method);  // 0 NB, 1 GMM, 2 EMD, 3 Hu
  std::size_t best = 0;
  for (std::size_t k = 1; k < model_->classes.size(); ++k) {
    const float a = distances[4 * k + field], b = distances[4 * best + field];
    // Naive Bayes: the largest score wins; the others are distances or energies.
    if (method == ClassifierMethod::kNaiveBayes ? a > b : a < b) best = k;
  }
  return best;
}

void LitterClassifier::Save(const std::filesystem::path& file) const {
  cv::FileStorage fs(file.string(), cv::FileStorage::WRITE);
  if (!fs.isOpened()) throw FileFailure(file, "cannot write the model", errno);
  fs << "format"
     << "littermap litter classifier"
     << "version" << 1;
  fs << "classes" << model_->classes;
  std::vector<int> litter(model_->litter.begin(), model_->litter.end());
  fs << "litter" << litter;
  model_->naive_bayes.Write(fs, "naive_bayes");
  for (std::size_t k = 0; k < model_->classes.size(); ++k) {
    const std::string key = "class_" + std::to_string(k);
    model_->gmms[k].Write(fs, key + "_gmm");
    cv::Mat centroids(0, kColourBinCount, CV_64F), medoids(0, 6, CV_64F);
    for (const auto& h : model_->emd_centroids[k])
      centroids.push_back(
          cv::Mat(1, kColourBinCount, CV_64F, const_cast<double*>(h.counts.data())));
    for (const auto& m : model_->hu_medoids[k])
      medoids.push_back(cv::Mat(1, 6, CV_64F, const_cast<double*>(m.values.data())));
    fs << key + "_emd_centroids" << centroids << key + "_hu_medoids" << medoids;
  }
  fs << "forest"
     << "{";
  model_->forest->write(fs);
  fs << "}";
  fs.release();
}

LitterClassifier LitterClassifier::Load(const std::filesystem::path& file) {
  cv::FileStorage fs;
  try {
    fs.open(file.string(), cv::FileStorage::READ);
  } catch (const cv::Exception& e) {
    throw BadInputError(file.string() + ": not a model file (" + e.msg + ")");
  }
  if (!fs.isOpened()) throw BadInputError(file.string() + ": cannot open the model");
  if (static_cast<std::string>(fs["format"]) != "littermap litter classifier") {
    throw BadInputError(file.string() + ": field 'format' is not 'littermap litter classifier'");
  }
  auto model = std::make_unique<Model>();
  fs["classes"] >> model->classes;
  std::vector<int> litter;
  fs["litter"] >> litter;
  if (model->classes.size() < 2 || litter.size() != model->classes.size()) {
    throw BadInputError(file.string() + ": fields 'classes' and 'litter' disagree");
  }
  model->litter.assign(litter.begin(), litter.end());
  try {
    model->naive_bayes = ColourNaiveBayes::Read(fs["naive_bayes"]);
    for (std::size_t k = 0; k < model->classes.size(); ++k) {
      const std::string key = "class_" + std::to_string(k);
      model->gmms.push_back(ColourGmm::Read(fs[key + "_gmm"]));
      cv::Mat centroids, medoids;
      fs[key + "_emd_centroids"] >> centroids;
      fs[key + "_hu_medoids"] >> medoids;
      if (centroids.empty() || centroids.cols != kColourBinCount || medoids.empty() ||
          medoids.cols != 6) {
        throw BadInputError(file.string() + ": field '" + key + "_emd_centroids' or '" + key +
                            "_hu_medoids' is missing or malformed");
      }
      model->emd_centroids.emplace_back();
      model->hu_medoids.emplace_back();
      for (int r = 0; r < centroids.rows; ++r) {
        ColourHistogram h;
        for (int b = 0; b < kColourBinCount; ++b)
          h.counts[static_cast<std::size_t>(b)] = centroids.at<double>(r, b);
        model->emd_centroids.back().push_back(h);
      }
      for (int r = 0; r < medoids.rows; ++r) {
        HuShape m;
        for (int b = 0; b < 6; ++b)
          m.values[static_cast<std::size_t>(b)] = medoids.at<double>(r, b);
        model->hu_medoids.back().push_back(m);
      }
    }
    model->forest = cv::ml::RTrees::create();
    model->forest->read(fs["forest"]);
  } catch (const cv::Exception& e) {
    throw BadInputError(file.string() + ": malformed model (" + e.msg + ")");
  }
  if (model->forest->getVarCount() <= 0)
    throw BadInputError(file.string() + ": field 'forest' is empty");
  return LitterClassifier(std::move(model));
}

}  // namespace littermap::detect
