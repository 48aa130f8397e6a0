#include "heatmap/site_contents.hpp"

namespace littermap::heatmap {

SiteContents ReadSiteContents(db::SiteDatabase& site) {
  SiteContents contents;
  contents.site_name = site.name();
  contents.frame = site.site().frame;
  contents.runs = site.Runs();
  contents.coverages = site.Coverages();
  contents.items = site.Items();
  contents.detections = site.AllDetections();
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
