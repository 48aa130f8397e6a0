#pragma once
// Small inline SVG charts for the report: they scale with the page, print sharply and need no
// script. All text put into them is escaped.

#include <optional>
#include <string>
#include <vector>

namespace littermap::reports {

struct ChartSeries {
  std::string name;
  std::string colour;          // CSS colour, e.g. "#0072B2"
  std::vector<double> values;  // one per bar
};

struct BarChartOptions {
  std::string title;  // read by screen readers
  std::string unit;   // shown above the y axis
  int width_px = 560;
  int height_px = 220;
  int decimals = 0;  // of the axis labels
};

// One bar per label, the series stacked bottom to top, a legend when there is more than one.
std::string StackedBarChart(const std::vector<std::string>& labels,
                            const std::vector<ChartSeries>& series, const BarChartOptions& options);

// A line over the values (gaps where a value is missing) from 0 to max_value, a dot each.
std::string Sparkline(const std::vector<std::optional<double>>& values, double max_value,
                      int width_px, int height_px);

}  // namespace littermap::reports
