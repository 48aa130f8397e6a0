// littermap heatmap SITE.gpkg -o DIR [--from DATE --to DATE --class C]: survey effort and
// effort-normalised litter density of a site as Cloud-Optimized GeoTIFFs and a PNG preview,
// hotspots, and the items as CSV and GeoJSON.

#include <cstdio>
#include <memory>
#include <string>

#include "cli/cli_context.hpp"
#include "cli/option_checks.hpp"
#include "core/utc_date.hpp"
#include "db/site_locator.hpp"
#include "heatmap/heatmap_files.hpp"

namespace littermap::cli {
namespace {

struct HeatmapArguments {
  std::string site;
  std::string output;
  std::string from;
  std::string to;
  heatmap::HeatmapFilesOptions options;
};

void RunHeatmap(HeatmapArguments arguments, CliContext& context) {
  arguments.options.map.from_time_s = ParseUtcDate(arguments.from, "--from");
  arguments.options.map.to_time_s = ParseUtcDate(arguments.to, "--to");
  const heatmap::HeatmapFilesResult result = heatmap::WriteHeatmapFiles(
      db::ParseSiteLocator(arguments.site), arguments.output, arguments.options);
  for (const std::string& warning : result.warnings) context.Warn(warning);
  std::printf("%s\n", heatmap::HeatmapSummary(result, arguments.output).c_str());
}

}  // namespace

void RegisterHeatmapCommand(CLI::App& app, CliContext& context) {
  auto arguments = std::make_shared<HeatmapArguments>();
  CLI::App* command = context.AddCommand(app, "heatmap", "Litter density maps of a site");
  command
      ->add_option("SITE", arguments->site,
                   "Site database: SITE.gpkg, or postgresql://[USER@HOST]/DB?site=NAME")
      ->required();
  command->add_option("-o,--output", arguments->output, "Output directory")->required();
  command->add_flag("--force", arguments->options.force_output,
                    "Write into an output folder that holds files littermap does not write there");
  command->add_option("--from", arguments->from, "Only runs starting on or after (YYYY-MM-DD)");
  command->add_option("--to", arguments->to, "Only runs starting before (YYYY-MM-DD)");
  auto& options = arguments->options.map;
  command->add_option("--class", options.class_name, "Only items of this class");
  command->option_defaults()->always_capture_default();  // shown in --help
  command->add_option("--cell-size", options.cell_size_m, "Raster cell size (m)")
      ->check(FiniteRange(kMinCellSizeM, kMaxCellSizeM));
  command
      ->add_option("--bandwidth", options.density.kernel.bandwidth_m, "Quartic kernel radius (m)")
      ->check(FiniteRange(kMinBandwidthM, kMaxBandwidthM));
  command
      ->add_option("--min-effort", options.density.min_effort_surveys,
                   "Cells surveyed fewer times are nodata")
      ->check(FiniteRange(0.001, 1e6));
  command
      ->add_option("--min-confidence", options.min_confidence,
                   "Only detections at least this sure (items.csv confidence, 0 to 1)")
      ->check(FiniteRange(0.0, 1.0));
  command
      ->add_option("--hotspot-min-items", arguments->options.hotspots.min_items,
                   "Distinct items a place needs to be called a hotspot")
      ->check(WholeNumber(1, kMaxHotspotMinItems));
  command
      ->add_option("--hotspots", arguments->options.hotspots.max_count, "Number of hotspots listed")
      ->check(CLI::Range(0, kMaxHotspots));
  command->callback([arguments, &context] {
    context.run = [arguments, &context] { RunHeatmap(*arguments, context); };
  });
}

}  // namespace littermap::cli
