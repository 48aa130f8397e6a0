#include "reports/svg_charts.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>

#include "reports/html_text.hpp"

namespace littermap::reports {
namespace {

std::string Num(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f", v);
  return text;
}

// An axis maximum of 1, 2 or 5 times a power of ten at or above `value`, and its tick step.
std::pair<double, double> NiceAxis(double value) {
  if (!(value > 0)) return {1.0, 0.25};
  const double power = std::pow(10.0, std::floor(std::log10(value)));
  for (const double step : {1.0, 2.0, 5.0, 10.0}) {
    if (step * power >= value) return {step * power, step * power / (step == 5.0 ? 5 : 4)};
  }
  return {10 * power, 2.5 * power};
}

}  // namespace

std::string StackedBarChart(const std::vector<std::string>& labels,
                            const std::vector<ChartSeries>& series,
                            const BarChartOptions& options) {
  const double left = 46, right = 8, top = series.size() > 1 ? 34 : 22, bottom = 40;
  const double plot_w = options.width_px - left - right;
  const double plot_h = options.height_px - top - bottom;
  double peak = 0;
  for (std::size_t i = 0; i < labels.size(); ++i) {
    double total = 0;
    for (const ChartSeries& s : series) total += i < s.values.size() ? s.values[i] : 0;
    peak = std::max(peak, total);
  }
  const std::pair<double, double> axis = NiceAxis(peak);
  const double axis_max = axis.first, step = axis.second;
  const auto y_of = [&](double v) { return top + plot_h * (1 - v / axis_max); };

  std::string svg = "<svg class=\"chart\" viewBox=\"0 0 " + std::to_string(options.width_px) + " " +
                    std::to_string(options.height_px) +
                    "\" role=\"img\" xmlns=\"http://www.w3.org/2000/svg\"><title>" +
                    EscapeHtml(options.title) + "</title>";
  svg += "<text x=\"4\" y=\"12\" class=\"unit\">" + EscapeHtml(options.unit) + "</text>";
  for (double v = 0; v <= axis_max + step / 2; v += step) {
    char label[32];
    std::snprintf(label, sizeof label, "%.*f", options.decimals, v);
    svg += "<line x1=\"" + Num(left) + "\" x2=\"" + Num(left + plot_w) + "\" y1=\"" + Num(y_of(v)) +
           "\" y2=\"" + Num(y_of(v)) + "\" class=\"grid\"/>";
    svg += "<text x=\"" + Num(left - 4) + "\" y=\"" + Num(y_of(v) + 4) + "\" text-anchor=\"end\">" +
           label + "</text>";
  }
  const double slot = labels.empty() ? plot_w : plot_w / static_cast<double>(labels.size());
  const double bar = std::min(48.0, slot * 0.7);
  for (std::size_t i = 0; i < labels.size(); ++i) {
    const double x = left + slot * (static_cast<double>(i) + 0.5);
    double base = 0;
    for (const ChartSeries& s : series) {
      const double v = i < s.values.size() ? s.values[i] : 0;
      if (v > 0) {
        svg += "<rect x=\"" + Num(x - bar / 2) + "\" y=\"" + Num(y_of(base + v)) + "\" width=\"" +
               Num(bar) + "\" height=\"" + Num(y_of(base) - y_of(base + v)) + "\" fill=\"" +
               EscapeHtml(s.colour) + "\"><title>" + EscapeHtml(labels[i]) + ": " +
               EscapeHtml(s.name) + " " + Num(v) + "</title></rect>";
      }
      base += v;
    }
    svg += "<text x=\"" + Num(x) + "\" y=\"" + Num(top + plot_h + 16) +
           "\" text-anchor=\"middle\">" + EscapeHtml(labels[i]) + "</text>";
  }
  svg += "<line x1=\"" + Num(left) + "\" x2=\"" + Num(left + plot_w) + "\" y1=\"" +
         Num(top + plot_h) + "\" y2=\"" + Num(top + plot_h) + "\" class=\"axis\"/>";
  if (series.size() > 1) {
    double x = left;
    for (const ChartSeries& s : series) {
      svg += "<rect x=\"" + Num(x) + "\" y=\"18\" width=\"12\" height=\"12\" fill=\"" +
             EscapeHtml(s.colour) + "\"/><text x=\"" + Num(x + 16) + "\" y=\"28\">" +
             EscapeHtml(s.name) + "</text>";
      x += 26 + 7.0 * static_cast<double>(s.name.size());
    }
  }
  return svg + "</svg>";
}

std::string Sparkline(const std::vector<std::optional<double>>& values, double max_value,
                      int width_px, int height_px) {
  const double pad = 4;
  const double label_px = 11;  // below the baseline: the first and the last value
  const double bottom = height_px - label_px - 1;
  const double top = max_value > 0 ? max_value : 1;
  const double dx =
      values.size() > 1 ? (width_px - 2 * pad) / static_cast<double>(values.size() - 1) : 0;
  const auto point = [&](std::size_t i) {
    const double x = values.size() > 1 ? pad + dx * static_cast<double>(i) : width_px / 2.0;
    const double y = bottom - (bottom - pad) * std::min(1.0, *values[i] / top);
    return std::make_pair(x, y);
  };
  std::string svg = "<svg class=\"spark\" viewBox=\"0 0 " + std::to_string(width_px) + " " +
                    std::to_string(height_px) + "\" width=\"" + std::to_string(width_px) +
                    "\" height=\"" + std::to_string(height_px) +
                    "\" role=\"img\" xmlns=\"http://www.w3.org/2000/svg\"><title>density per "
                    "run, oldest first</title>";
  // The baseline is zero density: a line that lies on it is a place found clean.
  svg += "<line class=\"base\" x1=\"" + Num(pad) + "\" y1=\"" + Num(bottom) + "\" x2=\"" +
         Num(width_px - pad) + "\" y2=\"" + Num(bottom) + "\"/>";
  std::string path;
  bool pen_down = false;
  std::optional<std::size_t> first, last;
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (!values[i]) {
      pen_down = false;
      continue;
    }
    if (!first) first = i;
    last = i;
    const auto [x, y] = point(i);
    path += (pen_down ? "L" : "M") + Num(x) + " " + Num(y);
    pen_down = true;
    svg += "<circle cx=\"" + Num(x) + "\" cy=\"" + Num(y) + "\" r=\"2.5\"/>";
  }
  if (!path.empty()) svg += "<path d=\"" + path + "\"/>";
  const auto label = [&](std::size_t i, const char* anchor) {
    svg += "<text x=\"" + Num(point(i).first) + "\" y=\"" + Num(height_px - 1.0) +
           "\" font-size=\"10\" text-anchor=\"" + anchor + "\">" + Num(*values[i]) + "</text>";
  };
  if (first) label(*first, values.size() > 1 ? "start" : "middle");
  if (last && last != first) label(*last, "end");
  return svg + "</svg>";
}

}  // namespace littermap::reports
