#pragma once
// What an import wrote, for people: the lines `littermap import` prints when it is done.

#include <filesystem>
#include <string>

#include "importers/carmen_importer.hpp"
#include "importers/tum_importer.hpp"

namespace littermap::importers {

// "wrote BAG: N scans (B beams), N odometry [(noisy, seed S)], D s [(not imported: ...)]" and,
// with a reference path, "wrote REF: N reference poses"; every line ends in "\n".
std::string ImportSummary(const std::filesystem::path& bag, const CarmenImportOptions& options,
                          const CarmenImportResult& result);

// "wrote BAG: N colour, N depth, N camera_info (CAMERA[, from the directory name]), D s" and,
// with a reference path, "wrote REF: N reference poses"; every line ends in "\n".
std::string ImportSummary(const std::filesystem::path& bag, const TumImportOptions& options,
                          const TumImportResult& result);

}  // namespace littermap::importers
