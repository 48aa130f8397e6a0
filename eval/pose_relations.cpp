#include "eval/pose_relations.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <numbers>
#include <numeric>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "bag/tum_trajectory.hpp"
#include "core/error.hpp"
#include "core/stamped_pose.hpp"
#include "eval/text_format.hpp"

namespace littermap::eval {
namespace {

// The whitespace-separated numbers of a line; false if a field is not a finite number.
bool ParseNumbers(std::string_view line, std::vector<double>* numbers) {
  numbers->clear();
  std::size_t at = 0;
  while (true) {
    at = line.find_first_not_of(" \t\r", at);
    if (at == std::string_view::npos) return true;
    const std::size_t end = std::min(line.find_first_of(" \t\r", at), line.size());
    double value = 0;
    const auto [stop, error] = std::from_chars(line.data() + at, line.data() + end, value);
    if (error != std::errc() || stop != line.data() + end || !std::isfinite(value)) return false;
    numbers->push_back(value);
    at = end;
  }
}

// Calls row(numbers, where) for every line that is neither blank nor a '#' comment.
template <typename Row>
void ForEachRow(const std::filesystem::path& path, Row row) {
  std::ifstream in(path);
  if (!in) throw BadInputError(path.string() + ": cannot open");
  std::string line;
  std::vector<double> numbers;
  for (std::size_t number = 1; std::getline(in, line); ++number) {
    const std::size_t first = line.find_first_not_of(" \t\r");
    if (first == std::string::npos || line[first] == '#') continue;
    const std::string where = path.string() + ":" + std::to_string(number);
    if (!ParseNumbers(line, &numbers)) throw BadInputError(where + ": a field is not a number");
    row(numbers, where);
  }
}

nlohmann::ordered_json StatisticsJson(const ErrorStatistics& s) {
  return {{"mean", s.mean}, {"stddev", s.stddev}, {"max", s.max}};
}

nlohmann::ordered_json ErrorsJson(const RelationErrors& e) {
  return {{"trans_m", StatisticsJson(e.translation_m)},
          {"trans_sq_m2", StatisticsJson(e.translation_sq_m2)},
          {"rot_deg", StatisticsJson(e.rotation_deg)},
          {"rot_sq_deg2", StatisticsJson(e.rotation_sq_deg2)},
          {"trans_median_m", e.translation_median_m},
          {"over_large_error", e.over_large_error}};
}

void AppendErrors(std::string& text, const char* name, const RelationErrors& e,
                  double large_error_m) {
  AppendFormat(text, "%s\n", name);
  AppendFormat(text,
               "  translation      %.4f +- %.4f m (median %.4f m, max %.3f m, %zu over %.2f m)\n",
               e.translation_m.mean, e.translation_m.stddev, e.translation_median_m,
               e.translation_m.max, e.over_large_error, large_error_m);
  AppendFormat(text, "  translation^2    %.5f +- %.5f m^2\n", e.translation_sq_m2.mean,
               e.translation_sq_m2.stddev);
  AppendFormat(text, "  rotation         %.3f +- %.3f deg (max %.2f deg)\n", e.rotation_deg.mean,
               e.rotation_deg.stddev, e.rotation_deg.max);
  AppendFormat(text, "  rotation^2       %.3f +- %.3f deg^2\n", e.rotation_sq_deg2.mean,
               e.rotation_sq_deg2.stddev);
}

ErrorStatistics Statistics(const std::vector<double>& values) {
  ErrorStatistics statistics;
  if (values.empty()) return statistics;
  const double n = static_cast<double>(values.size());
  statistics.mean = std::accumulate(values.begin(), values.end(), 0.0) / n;
  double sum_sq = 0;
  for (double v : values) sum_sq += (v - statistics.mean) * (v - statistics.mean);
  statistics.stddev = values.size() > 1 ? std::sqrt(sum_sq / (n - 1)) : 0;
  statistics.max = *std::max_element(values.begin(), values.end());
  return statistics;
}

struct ErrorSamples {
  std::vector<double> translation_m;
  std::vector<double> rotation_deg;

  void Add(double translation, double rotation_rad) {
    translation_m.push_back(translation);
    rotation_deg.push_back(std::abs(rotation_rad) * 180 / std::numbers::pi);
  }

  RelationErrors Summarise(double large_error_m) const {
    const auto squares = [](std::vector<double> values) {
      for (double& v : values) v *= v;
      return values;
    };
    RelationErrors errors;
    errors.translation_m = Statistics(translation_m);
    errors.translation_sq_m2 = Statistics(squares(translation_m));
    errors.rotation_deg = Statistics(rotation_deg);
    errors.rotation_sq_deg2 = Statistics(squares(rotation_deg));
    std::vector<double> sorted = translation_m;
    std::sort(sorted.begin(), sorted.end());
    const std::size_t n = sorted.size();
    errors.translation_median_m =
        n % 2 == 1 ? sorted[n / 2] : (sorted[n / 2 - 1] + sorted[n / 2]) / 2;
    errors.over_large_error = static_cast<std::size_t>(std::count_if(
        translation_m.begin(), translation_m.end(), [&](double e) { return e > large_error_m; }));
    return errors;
  }
};

}  // namespace

std::vector<PoseRelation> ReadPoseRelations(const std::filesystem::path& path) {
  std::vector<PoseRelation> relations;
  ForEachRow(path, [&](const std::vector<double>& v, const std::string& where) {
    if (v.size() != 8) {
      throw BadInputError(where + ": expected 8 fields (t1 t2 x y z roll pitch yaw), got " +
                          std::to_string(v.size()));
    }
    relations.push_back({v[0], v[1], {v[2], v[3], v[7]}});
  });
  if (relations.empty()) throw BadInputError(path.string() + ": holds no relation");
  return relations;
}

std::vector<double> ReadScanMapStamps(const std::filesystem::path& path) {
  std::vector<double> stamps;
  ForEachRow(path, [&](const std::vector<double>& v, const std::string& where) {
    if (v.size() != 4) {
      throw BadInputError(where + ": expected 4 fields (scan_index log_stamp raw_scan_index " +
                          "raw_stamp), got " + std::to_string(v.size()));
    }
    if (v[0] != static_cast<double>(stamps.size())) {
      throw BadInputError(where + ": scan_index " + std::to_string(v[0]) + " where " +
                          std::to_string(stamps.size()) + " was expected");
    }
    stamps.push_back(v[3]);
  });
  if (stamps.empty()) throw BadInputError(path.string() + ": holds no scan");
  return stamps;
}

void PoseRelationOptions::Validate() const {
  if (!(max_stamp_difference_s >= 0) || !(large_error_m > 0)) {
    throw UsageError("relations: max_stamp_difference_s must be >= 0 and large_error_m > 0");
  }
}

PoseRelationMetrics EvaluatePoseRelations(const std::vector<PlanarPose>& trajectory,
                                          const std::vector<double>& scan_stamps_s,
                                          const std::vector<PoseRelation>& relations,
                                          const PoseRelationOptions& options) {
  options.Validate();
  if (trajectory.size() != scan_stamps_s.size()) {
    throw BadInputError("the trajectory has " + std::to_string(trajectory.size()) + " poses for " +
                        std::to_string(scan_stamps_s.size()) +
                        " scans: relations need one pose per scan, in scan order");
  }
  std::vector<std::size_t> by_stamp(scan_stamps_s.size());
  std::iota(by_stamp.begin(), by_stamp.end(), 0);
  std::sort(by_stamp.begin(), by_stamp.end(),
            [&](std::size_t a, std::size_t b) { return scan_stamps_s[a] < scan_stamps_s[b]; });
  // The scan whose stamp is nearest to t, if close enough.
  const auto scan_at = [&](double t) -> std::ptrdiff_t {
    const auto at = std::lower_bound(by_stamp.begin(), by_stamp.end(), t,
                                     [&](std::size_t i, double v) { return scan_stamps_s[i] < v; });
    std::ptrdiff_t best = -1;
    double best_difference = options.max_stamp_difference_s;
    for (auto it = at == by_stamp.begin() ? at : at - 1; it != by_stamp.end() && it <= at; ++it) {
      const double difference = std::abs(scan_stamps_s[*it] - t);
      if (difference <= best_difference) {
        best_difference = difference;
        best = static_cast<std::ptrdiff_t>(*it);
      }
    }
    return best;
  };
  PoseRelationMetrics metrics;
  metrics.relations = relations.size();
  ErrorSamples component, cartographer;
  for (const PoseRelation& relation : relations) {
    const std::ptrdiff_t a = scan_at(relation.t1_s);
    const std::ptrdiff_t b = scan_at(relation.t2_s);
    if (a < 0 || b < 0) {
      ++metrics.unmatched;
      continue;
    }
    ++metrics.used;
    const PlanarPose estimate = Between(trajectory[a], trajectory[b]);
    const PlanarPose& truth = relation.T_1_2;
    component.Add(std::hypot(estimate.x_m - truth.x_m, estimate.y_m - truth.y_m),
                  WrapAngle(estimate.theta_rad - truth.theta_rad));
    const PlanarPose error = Compose(estimate, Inverse(truth));
    cartographer.Add(std::hypot(error.x_m, error.y_m), error.theta_rad);
  }
  if (metrics.used == 0) {
    throw BadInputError("none of the " + std::to_string(relations.size()) +
                        " relations has both ends at a scan's stamp");
  }
  metrics.component = component.Summarise(options.large_error_m);
  metrics.cartographer = cartographer.Summarise(options.large_error_m);
  return metrics;
}

PoseRelationMetrics EvaluatePoseRelations(const std::filesystem::path& trajectory,
                                          const std::vector<double>& scan_stamps_s,
                                          const std::vector<PoseRelation>& relations,
                                          const PoseRelationOptions& options) {
  std::vector<PlanarPose> poses;
  for (const StampedPose& pose : bag::ReadTumTrajectory(trajectory)) {
    poses.push_back(PlanarPoseOf(pose));
  }
  try {
    return EvaluatePoseRelations(poses, scan_stamps_s, relations, options);
  } catch (const BadInputError& error) {
    throw BadInputError(trajectory.string() + ": " + error.what());
  }
}

std::string ToJson(const PoseRelationMetrics& metrics) {
  nlohmann::ordered_json json;
  json["relations"] = metrics.relations;
  json["used"] = metrics.used;
  json["unmatched"] = metrics.unmatched;
  json["metric_evaluator"] = ErrorsJson(metrics.component);
  json["cartographer"] = ErrorsJson(metrics.cartographer);
  return json.dump(2, ' ', false, nlohmann::json::error_handler_t::replace);
}

std::string ToText(const PoseRelationMetrics& metrics, const PoseRelationOptions& options) {
  std::string text;
  AppendFormat(text, "relations          %zu used of %zu (%zu with an end at no scan)\n",
               metrics.used, metrics.relations, metrics.unmatched);
  AppendErrors(text, "metricEvaluator (component difference)", metrics.component,
               options.large_error_m);
  AppendErrors(text, "Cartographer (est * inv(relation))", metrics.cartographer,
               options.large_error_m);
  text.pop_back();  // the caller ends the last line, as after ToJson
  return text;
}

}  // namespace littermap::eval
