#include "detect/object_sample.hpp"

#include <algorithm>
#include <cstdio>
#include <fstream>

#include <opencv2/imgcodecs.hpp>

#include "bag/image_codec.hpp"
#include "core/csv_table.hpp"
#include "core/error.hpp"
#include "core/failure.hpp"
#include "core/output_file.hpp"

namespace littermap::detect {

std::vector<ObjectSample> ReadSamples(const std::filesystem::path& directory) {
  std::vector<ObjectSample> samples;
  const auto labels = directory / "labels.csv";
  ReadCsv(labels, {"crop", "mask", "label", "size_m", "width_m", "height_m", "range_m"},
          [&](const CsvRow& row) {
            ObjectSample sample;
            const auto crop = directory / row.Text("crop");
            const auto mask = directory / row.Text("mask");
            sample.colour_bgr = cv::imread(crop.string(), cv::IMREAD_COLOR);
            if (sample.colour_bgr.empty()) {
              throw BadInputError(row.where() + ": column 'crop': cannot read " + crop.string());
            }
            sample.mask = cv::imread(mask.string(), cv::IMREAD_GRAYSCALE);
            if (sample.mask.size() != sample.colour_bgr.size()) {
              throw BadInputError(row.where() + ": column 'mask': " + mask.string() +
                                  " is missing or not the crop's size");
            }
            if (cv::countNonZero(sample.mask) == 0) {
              throw BadInputError(row.where() + ": column 'mask': " + mask.string() +
                                  " has no object pixel");
            }
            sample.label = row.Text("label");
            if (sample.label.empty())
              throw BadInputError(row.where() + ": column 'label' is empty");
            sample.size_m = row.Number("size_m");
            sample.width_m = row.Number("width_m");
            sample.height_m = row.Number("height_m");
            sample.range_m = row.Number("range_m");
            if (row.Has("source")) sample.source = row.Text("source");
            samples.push_back(std::move(sample));
          });
  return samples;
}

void WriteSamples(const std::filesystem::path& directory,
                  const std::vector<ObjectSample>& samples) {
  std::error_code error;
  std::filesystem::create_directories(directory, error);
  if (error) throw FileFailure(directory, "cannot create the folder", error.value());
  OutputFile labels_file(directory / "labels.csv");
  std::ostream& labels = labels_file.stream();
  labels << "crop,mask,label,size_m,width_m,height_m,range_m,source\n";
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const ObjectSample& s = samples[i];
    char crop[32], mask[32];
    std::snprintf(crop, sizeof crop, "crop_%06zu.png", i);
    std::snprintf(mask, sizeof mask, "mask_%06zu.png", i);
    bag::WriteImageFile(directory / crop, s.colour_bgr);
    bag::WriteImageFile(directory / mask, s.mask);
    char line[256];
    std::snprintf(line, sizeof line, "%s,%s,%s,%.4f,%.4f,%.4f,%.3f,%s\n", crop, mask,
                  s.label.c_str(), s.size_m, s.width_m, s.height_m, s.range_m, s.source.c_str());
    labels << line;
  }
  labels_file.Commit();
}

}  // namespace littermap::detect
