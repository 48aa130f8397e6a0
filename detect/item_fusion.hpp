#pragma once
// Multi-view fusion: sightings of objects in many frames, placed in the world with the
// trajectory, become litter items. A sighting joins the nearest item within the association
// radius (else starts one); an item's position is the range-weighted mean of its sightings
// (depth noise grows with range), its class distribution the mean of its largest sightings' (a
// bottle at the far edge of the range is a dozen pixels, where a root top or a flower looks much
// like it). Items seen in too few frames are dropped: one frame's segmentation error does not
// become an item.
//
// Which candidate a sighting joins depends on the order of the sightings: a bag seen in fragments
// that scatter over 0.3 m becomes one candidate or two as the first two fragments happen to fall
// within the radius or just outside it. So at the end, candidates whose positions lie within the
// association radius of each other and whose likeliest classes agree are merged, the closest pair
// first, as an order of their sightings could have joined them. A cup 0.3 m from a plastic bag
// stays apart where the order kept it apart.

#include <functional>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "core/time.hpp"

namespace littermap::detect {

struct Sighting {
  std::size_t frame = 0;
  TimestampNs stamp_ns = 0;
  Eigen::Vector3d position_world_m = Eigen::Vector3d::Zero();
  double size_m = 0;
  double range_m = 1;
  int pixels = 0;                           // the object's pixels in the image
  std::vector<double> class_probabilities;  // indexed like the classifier's classes
};

struct LitterItem {
  int id = 0;
  Eigen::Vector3d position_world_m = Eigen::Vector3d::Zero();
  double size_m = 0;
  std::vector<double> class_probabilities;  // mean over the class views (FusionOptions)
  int views = 0;
  TimestampNs first_seen_ns = 0;
  TimestampNs last_seen_ns = 0;
  std::size_t best_class = 0;
  double confidence = 0;  // mean probability of the best class
  // Frames after its first sighting that could have seen it (Observe) but did not: litter in the
  // open is found in most frames that could see it, a bump of terrain or a look-alike that a few
  // views happened to cut out is missed in most.
  int missed_views = 0;
  double seen_share() const { return double(views) / double(views + missed_views); }
};

// What Fuse gives: the items, and for detections.csv the item each candidate became part of.
struct FusedItems {
  std::vector<LitterItem> items;
  // Indexed by candidate id - 1 (the ids Add returned): the id of the candidate it was merged
  // into, its own id when it was not merged. Ids of candidates left out of `items` stay.
  std::vector<int> item_of_candidate;
  std::size_t seldom_seen = 0;  // candidates with enough views left out for their seen share
  std::size_t merged = 0;       // candidates merged into a neighbour
};

struct FusionOptions {
  double association_radius_m = 0.25;
  int min_views = 3;
  // Items seen in a smaller share of the frames that could see them (Observe) are dropped: three
  // in four, chosen on six of the classifier's training parks (seeds 41-56, true trajectory),
  // where it dropped 9 of 15 false litter items and 1 of 86 true ones. Checked again by two-fold
  // cross-validation over all 24 training parks: shares 0.6, 0.75 and 0.85 give precision / recall
  // 0.946 / 0.929, 0.949 / 0.929 and 0.951 / 0.923 (argmax decision of kinds).
  double min_seen_share = 0.75;
  // An item's class distribution is the mean over this many of its sightings with the most pixels
  // (0: all of them), and it is litter when its litter classes together have at least
  // min_litter_probability (LitterClassifier::Decide). Chosen together by two-fold
  // cross-validation over 48 training parks (seeds 11-18 and 41-80, two models of 24 parks,
  // true trajectory; 680 visible litter items), precision / recall:
  //   all views,  0.5: 0.905 / 0.943;  0.6: 0.968 / 0.922;  0.65: 0.983 / 0.909
  //   10 largest, 0.5: 0.886 / 0.949;  0.6: 0.949 / 0.937;  0.65: 0.975 / 0.925
  // The far views of an item are a dozen pixels, where a root top or a flower looks much like a
  // bottle; and the forest learnt from more litter crops than natural ones (4,663 against 2,000
  // for the shipped model), so its vote shares lean towards litter.
  int class_views = 10;
  double min_litter_probability = 0.65;
  void Validate() const;
};

class ItemFusion {
 public:
  ItemFusion(FusionOptions options, std::size_t classes);
  // Returns the id of the candidate the sighting joined or started: ids count from 1 in order of
  // first sighting, and an item keeps the id of its first candidate in Fuse() (the ids of
  // candidates it leaves out or merges are unused there).
  int Add(const Sighting& sighting);
  // After a frame's sightings were added: every item the frame did not see although
  // `could_see(position_world_m, size_m)` says it could have counts a missed view.
  void Observe(std::size_t frame,
               const std::function<bool(const Eigen::Vector3d&, double)>& could_see);
  // Merges neighbouring candidates, then keeps those with at least min_views views and the seen
  // share, with the ids Add returned; their best_class is the likeliest class, to be decided
  // (LitterClassifier::Decide) by the caller.
  FusedItems Fuse() const;
  std::size_t candidates() const { return tracks_.size(); }

 private:
  struct Track {
    Eigen::Vector3d weighted_sum = Eigen::Vector3d::Zero();
    double weight = 0;
    double size_sum = 0;
    // The class_views largest sightings: pixels and class probabilities.
    std::vector<std::pair<int, std::vector<double>>> class_views;
    int views = 0;
    // Ascending frame indices: frames with a sighting, and frames that could see it without one.
    std::vector<std::size_t> seen_frames, missed_frames;
    TimestampNs first_seen_ns = 0, last_seen_ns = 0;
    Eigen::Vector3d mean() const { return weighted_sum / weight; }
  };
  bool SeldomSeen(const Track& track) const;
  void KeepIfAmongTheLargest(Track& track, int pixels, const std::vector<double>& classes) const;
  void Merge(Track& into, const Track& from) const;
  // The mean of the track's class views, and the index of the largest probability.
  std::vector<double> ClassProbabilities(const Track& track) const;
  static std::size_t Likeliest(const std::vector<double>& probabilities);
  LitterItem MakeItem(const Track& track, int id) const;
  FusionOptions options_;
  std::size_t classes_;
  std::vector<Track> tracks_;
};

}  // namespace littermap::detect
