#pragma once
// RUN_DIR/detections.csv, every object of every processed frame, one row each:
//   frame,stamp_ns,u,v,width_px,height_px,x,y,z,size_m,height_m,range_m,class,confidence,
//   litter_probability,item
// the box in pixels, the position in the run's map frame (m), the classifier's best class for
// this one view and the fused item it became part of (-1: none, e.g. clutter).

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "core/output_file.hpp"
#include "detect/litter_classifier.hpp"
#include "detect/run_objects.hpp"

namespace littermap::run {

class DetectionsCsvWriter {
 public:
  // Writes FILE.tmp; throws the FileFailure naming FILE if it cannot be created.
  explicit DetectionsCsvWriter(std::filesystem::path file);

  // `candidate` is the id ItemFusion::Add returned (-1: none); rows are kept until Close names
  // the item each candidate became part of.
  void Write(const detect::PlacedObject& placed, const std::string& class_name,
             const detect::Classification& classification, int candidate);
  // Writes the rows with `item_of_candidate` (FusedItems) and renames FILE.tmp to FILE; throws the
  // FileFailure naming FILE if writing failed.
  void Close(const std::vector<int>& item_of_candidate);

 private:
  OutputFile output_;
  std::vector<std::pair<std::string, int>> rows_;  // a row up to its item, and its candidate
};

}  // namespace littermap::run
