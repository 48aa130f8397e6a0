// littermap heatmap SITE.gpkg -o DIR [--from DATE --to DATE --class C]: survey effort and
// effort-normalised litter density of a site as Cloud-Optimized GeoTIFFs and a PNG preview,
// hotspots, and the items as CSV and GeoJSON.

#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <utility>

#include "cli/cli_context.hpp"
#include "cli/date_argument.hpp"
#include "cli/run_stages.hpp"
#include "db/site_database.hpp"
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
  arguments.options.map.from_time_s = ParseDateArgument(arguments.from, "--from");
  arguments.options.map.to_time_s = ParseDateArgument(arguments.to, "--to");
  db::SiteDatabase site = db::SiteDatabase::Open(arguments.site);
  const heatmap::HeatmapFilesResult result =
      heatmap::WriteHeatmapFiles(site, arguments.output, arguments.options);
  for (const std::string& warning : result.warnings) context.Warn(warning);
  std::printf(
      "%zu runs, %zu items (%zu detections), %.0f m2 surveyed; peak density %.2f items per "
      "100 m2 per survey; %zu hotspots; written to %s\n",
      result.runs, result.items, result.detections, result.surveyed_area_m2,
      result.max_density_per_100m2, result.hotspots, arguments.output.c_str());
}

}  // namespace

void HeatmapStage(const std::filesystem::path& site, const std::filesystem::path& output_dir,
                  CliContext& context) {
  HeatmapArguments arguments;
  arguments.site = site.string();
  arguments.output = output_dir.string();
  RunHeatmap(std::move(arguments), context);
}

void RegisterHeatmapCommand(CLI::App& app, CliContext& context) {
  auto arguments = std::make_shared<HeatmapArguments>();
  CLI::App* command = context.AddCommand(app, "heatmap", "Litter density maps of a site");
  command->add_option("SITE", arguments->site, "Site database (SITE.gpkg)")->required();
  command->add_option("-o,--output", arguments->output, "Output directory")->required();
  command->add_option("--from", arguments->from, "Only runs starting on or after (YYYY-MM-DD)");
  command->add_option("--to", arguments->to, "Only runs starting before (YYYY-MM-DD)");
  auto& options = arguments->options.map;
  command->add_option("--class", options.class_name, "Only items of this class");
  command->add_option("--cell-size", options.cell_size_m, "Raster cell size (m)")
      ->capture_default_str();
  command
      ->add_option("--bandwidth", options.density.kernel.bandwidth_m, "Quartic kernel radius (m)")
      ->capture_default_str();
  command
      ->add_option("--min-effort", options.density.min_effort_surveys,
                   "Cells surveyed fewer times are nodata")
      ->capture_default_str();
  command
      ->add_option("--hotspots", arguments->options.hotspots.max_count, "Number of hotspots listed")
      ->capture_default_str();
  command->callback([arguments, &context] {
    context.run = [arguments, &context] { RunHeatmap(*arguments, context); };
  });
}

}  // namespace littermap::cli
