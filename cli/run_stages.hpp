#pragma once
// The stages a run goes through, as the commands of the same name run them and print their
// summaries; `littermap survey` calls them one after the other.

#include <filesystem>
#include <string>

#include "cli/cli_context.hpp"
#include "reconstruct/reconstruction.hpp"
#include "run/detect_run.hpp"

namespace littermap::cli {

void ReconstructStage(const std::filesystem::path& bag, const std::filesystem::path& run_dir,
                      const reconstruct::ReconstructionOptions& options, CliContext& context);

// debug_frames: a folder for a segmentation picture of every processed frame, or empty.
void DetectStage(const std::filesystem::path& bag, const std::filesystem::path& run_dir,
                 const run::DetectRunOptions& options, CliContext& context,
                 const std::filesystem::path& debug_frames = {});

// Adds the run directory to the site under `name`, placed by matching its map (ingest's
// defaults).
void IngestStage(const std::filesystem::path& site, const std::filesystem::path& run_dir,
                 const std::string& name, CliContext& context);

// The site's density and effort rasters, hotspots and exports into output_dir (heatmap's
// defaults).
void HeatmapStage(const std::filesystem::path& site, const std::filesystem::path& output_dir,
                  CliContext& context);

}  // namespace littermap::cli
