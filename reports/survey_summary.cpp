#include "reports/survey_summary.hpp"

#include <algorithm>
#include <cstdio>

#include "reports/class_palette.hpp"
#include "reports/plain_words.hpp"

namespace littermap::reports {

std::string SurveySummary(const SiteReport& report, const std::string& run_name,
                          const std::filesystem::path& report_html) {
  std::string text;
  const auto print = [&text](const char* format, auto... values) {
    const int size = std::snprintf(nullptr, 0, format, values...);
    std::string line(static_cast<std::size_t>(std::max(size, 0)), '\0');
    std::snprintf(line.data(), line.size() + 1, format, values...);
    text += line;
  };
  const auto run = std::find_if(report.runs.begin(), report.runs.end(),
                                [&](const RunFigures& r) { return r.name == run_name; });
  print("\nSurvey '%s' done.\n", run_name.c_str());
  if (run != report.runs.end()) {
    print("  driven %.0f m, ground surveyed %.0f m2 (%.0f %% of the site's)\n", run->length_m,
          run->observed_area_m2, 100 * run->coverage_fraction);
    std::string classes;
    for (const auto& [class_name, count] : run->items_by_class) {
      classes +=
          (classes.empty() ? "" : ", ") + ClassCount(class_name, static_cast<std::size_t>(count));
    }
    print("  litter found: %zu items%s%s%s\n", run->items_found, classes.empty() ? "" : " (",
          classes.c_str(), classes.empty() ? "" : ")");
    print("  %zu new, %zu still there from earlier runs, %zu gone since\n", run->new_items,
          run->items_still_there, run->items_gone);
    for (const std::string& warning : run->warnings) print("  note: %s\n", warning.c_str());
  }
  print("  site '%s': %zu %s, %zu litter items\n", report.site_name.c_str(), report.runs.size(),
        report.runs.size() == 1 ? "run" : "runs", report.items);
  for (std::size_t i = 0; i < std::min<std::size_t>(3, report.hotspots.size()); ++i) {
    const HotspotFigures& h = report.hotspots[i];
    print("  hotspot %d: %s, %.1f items per 100 m2, mostly %s\n", h.rank,
          FromTheDock(h.site_xy.x, h.site_xy.y, 1).c_str(), h.density_per_100m2,
          StyleOf(h.dominant_class).many.c_str());
  }
  print("Report: %s\n", report_html.c_str());
  return text;
}

}  // namespace littermap::reports
