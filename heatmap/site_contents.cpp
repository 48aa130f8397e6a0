#include "heatmap/site_contents.hpp"

#include <vector>

namespace littermap::heatmap {

SiteContents ReadSiteContents(db::SiteDatabase& site, double min_confidence) {
  SiteContents contents;
  contents.site_name = site.name();
  contents.frame = site.site().frame;
  contents.runs = site.Runs();
  contents.coverages = site.Coverages();
  contents.items = site.Items();
  contents.detections = site.AllDetections();
  if (min_confidence > 0.0) {
    std::erase_if(contents.detections,
                  [&](const db::DetectionRecord& d) { return d.confidence < min_confidence; });
  }
  for (std::size_t i = 0; i < contents.items.size(); ++i) {
    contents.item_index[contents.items[i].fid] = i;
  }
  for (std::size_t i = 0; i < contents.detections.size(); ++i) {
    auto [range, added] =
        contents.detections_of_run.try_emplace(contents.detections[i].run_id, i, i + 1);
    if (!added) range->second.second = i + 1;
  }
  return contents;
}

}  // namespace littermap::heatmap
