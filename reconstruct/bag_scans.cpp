#include "reconstruct/bag_scans.hpp"

#include "reconstruct/reconstruction.hpp"

namespace littermap::reconstruct {

BagScans ReadBagScans(const std::filesystem::path& bag, const std::string& scan_topic,
                      const ProgressCallback& progress, const WarningCallback& warn) {
  ReconstructionOptions options;
  options.topics.scan = scan_topic;
  std::vector<std::string> warnings;
  BagScans read;
  read.T_base_laser = ReadLaserExtrinsic(bag, options, &warnings);
  if (warn) {
    for (const std::string& warning : warnings) warn(warning);
  }
  const std::string task = "reading the scans of " + bag.string();
  ReportProgress(progress, {task});
  read.scans = ReadScans(bag, scan_topic);
  return read;
}

}  // namespace littermap::reconstruct
