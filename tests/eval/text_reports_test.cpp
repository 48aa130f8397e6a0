// The text reports of the metrics (ToText) and the relations' JSON: the figures with their
// widths and decimals, the lines without a newline after the last, and printf-style appending.

#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "eval/map_sharpness.hpp"
#include "eval/pose_relations.hpp"
#include "eval/text_format.hpp"
#include "eval/trajectory_metrics.hpp"

namespace littermap::eval {
namespace {

TEST(TextFormat, AppendsFormattedText) {
  std::string text = "a";
  AppendFormat(text, "%s %05.1f|%-4s|%zu", "b", 3.14159, "c", std::size_t{7});
  EXPECT_EQ(text, "ab 003.1|c   |7");
  AppendFormat(text, "%s", "");
  EXPECT_EQ(text, "ab 003.1|c   |7");
  // Longer than any fixed buffer a formatter might use.
  const std::string long_word(5000, 'x');
  AppendFormat(text, "[%s]", long_word.c_str());
  EXPECT_EQ(text.size(), 15u + 5002u);
  EXPECT_EQ(text.back(), ']');
}

TEST(TextReports, TrajectoryMetrics) {
  TrajectoryMetrics m;
  m.associated_poses = 910;
  m.ate_rmse_m = 0.06106, m.ate_mean_m = 0.05285, m.ate_max_m = 0.14968;
  m.rpe_pairs = 905, m.rpe_trans_mean_m = 0.03391, m.rpe_trans_rmse_m = 0.04101;
  m.rpe_rot_mean_deg = 0.4992;
  EXPECT_EQ(ToText(m, {}),
            "associated poses   910\n"
            "ATE RMSE           0.0611 m (mean 0.0529 m, max 0.1497 m)\n"
            "RPE translation    0.0339 m mean, 0.0410 m RMSE over 905 pairs 1.00 m apart\n"
            "RPE rotation       0.499 deg mean");
}

TEST(TextReports, MapSharpnessComparesWithTheFirst) {
  std::vector<MapSharpness> maps(2);
  maps[0] = {406, 406, 142305, 27981};
  maps[1] = {406, 202, 70228, 30450};
  EXPECT_EQ(ToText({"ours.tum", "ref.tum"}, maps, {}),
            "occupied 5 cm cells of the echoes within 20.0 m (fewer: sharper map)\n"
            "       cells  vs first       echoes        scans  trajectory\n"
            "       27981    100.0%       142305   406/406     ours.tum\n"
            "       30450    108.8%        70228   202/406     ref.tum");
}

PoseRelationMetrics Relations() {
  PoseRelationMetrics m;
  m.relations = 2984, m.used = 90, m.unmatched = 2894;
  m.component.translation_m = {0.01718, 0.01851, 0.14944};
  m.component.translation_sq_m2 = {0.00064, 0.00243, 0.0223};
  m.component.rotation_deg = {0.2541, 0.2062, 1.0931};
  m.component.rotation_sq_deg2 = {0.1072, 0.1831, 1.19};
  m.component.translation_median_m = 0.01234;
  m.cartographer = m.component;
  m.cartographer.over_large_error = 2;
  return m;
}

TEST(TextReports, PoseRelationsGiveABlockPerDefinition) {
  PoseRelationOptions options;
  options.large_error_m = 0.1;
  const std::string text = ToText(Relations(), options);
  EXPECT_EQ(text.substr(0, text.find('\n')),
            "relations          90 used of 2984 (2894 with an end at no scan)");
  EXPECT_NE(text.find("metricEvaluator (component difference)\n"
                      "  translation      0.0172 +- 0.0185 m (median 0.0123 m, max 0.149 m, 0 "
                      "over 0.10 m)\n"
                      "  translation^2    0.00064 +- 0.00243 m^2\n"
                      "  rotation         0.254 +- 0.206 deg (max 1.09 deg)\n"
                      "  rotation^2       0.107 +- 0.183 deg^2\n"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("Cartographer (est * inv(relation))\n"), std::string::npos);
  EXPECT_NE(text.find("2 over 0.10 m"), std::string::npos);
  EXPECT_NE(text.back(), '\n');
}

TEST(TextReports, PoseRelationsJsonKeys) {
  const auto json = nlohmann::ordered_json::parse(ToJson(Relations()));
  std::vector<std::string> keys;
  for (const auto& [key, value] : json.items()) keys.push_back(key);
  EXPECT_EQ(keys, (std::vector<std::string>{"relations", "used", "unmatched", "metric_evaluator",
                                            "cartographer"}));
  EXPECT_EQ(json["used"], 90);
  EXPECT_DOUBLE_EQ(json["metric_evaluator"]["trans_m"]["mean"].get<double>(), 0.01718);
  EXPECT_DOUBLE_EQ(json["cartographer"]["rot_deg"]["max"].get<double>(), 1.0931);
  EXPECT_EQ(json["cartographer"]["over_large_error"], 2);
  EXPECT_DOUBLE_EQ(json["metric_evaluator"]["trans_median_m"].get<double>(), 0.01234);
  EXPECT_TRUE(json["metric_evaluator"].contains("rot_sq_deg2"));
}

}  // namespace
}  // namespace littermap::eval
