#include "run/detections_file.hpp"

#include <cstdio>
#include <utility>

namespace littermap::run {

DetectionsCsvWriter::DetectionsCsvWriter(std::filesystem::path file) : output_(std::move(file)) {
  output_.stream()
      << "frame,stamp_ns,u,v,width_px,height_px,x,y,z,size_m,height_m,range_m,class,confidence,"
         "litter_probability,item\n";
}

void DetectionsCsvWriter::Write(const detect::PlacedObject& placed, const std::string& class_name,
                                const detect::Classification& classification, int candidate) {
  const cv::Rect& box = placed.object->box;
  char line[400];
  std::snprintf(
      line, sizeof line, "%zu,%lld,%d,%d,%d,%d,%.3f,%.3f,%.3f,%.3f,%.3f,%.2f,%s,%.3f,%.3f,",
      placed.frame->index, static_cast<long long>(placed.frame->stamp_ns), box.x, box.y, box.width,
      box.height, placed.position_world_m.x(), placed.position_world_m.y(),
      placed.position_world_m.z(), placed.object->size_m, placed.object->height_m,
      placed.object->range_m, class_name.c_str(), classification.probabilities[classification.best],
      classification.litter_probability);
  rows_.emplace_back(line, candidate);
}

void DetectionsCsvWriter::Close(const std::vector<int>& item_of_candidate) {
  std::ostream& out = output_.stream();
  for (const auto& [row, candidate] : rows_) {
    const bool known =
        candidate >= 1 && static_cast<std::size_t>(candidate) <= item_of_candidate.size();
    out << row << (known ? item_of_candidate[static_cast<std::size_t>(candidate) - 1] : -1) << '\n';
  }
  output_.Commit();
}

}  // namespace littermap::run
