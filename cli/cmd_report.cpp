// littermap report SITE.gpkg -o DIR [--from DATE --to DATE]: the site's report for park staff,
// DIR/index.html (self-contained) and DIR/report.json.

#include <cstdio>
#include <memory>
#include <string>

#include "cli/cli_context.hpp"
#include "cli/option_checks.hpp"
#include "core/utc_date.hpp"
#include "db/site_locator.hpp"
#include "reports/report_files.hpp"

namespace littermap::cli {
namespace {

struct ReportArguments {
  std::string site;
  std::string output;
  std::string from;
  std::string to;
  reports::ReportFilesOptions options;
};

void RunReport(ReportArguments arguments) {
  reports::StampReportFilesOptions(arguments.options);
  arguments.options.figures.from_time_s = ParseUtcDate(arguments.from, "--from");
  arguments.options.figures.to_time_s = ParseUtcDate(arguments.to, "--to");
  const reports::SiteReport report = reports::WriteReportFiles(db::ParseSiteLocator(arguments.site),
                                                               arguments.output, arguments.options);
  std::printf("%s\n", reports::ReportSummary(report, arguments.output).c_str());
}

}  // namespace

void RegisterReportCommand(CLI::App& app, CliContext& context) {
  auto arguments = std::make_shared<ReportArguments>();
  CLI::App* command = context.AddCommand(
      app, "report", "HTML report of a site for park staff (index.html and report.json)");
  command
      ->add_option("SITE", arguments->site,
                   "Site database: SITE.gpkg, or postgresql://[USER@HOST]/DB?site=NAME")
      ->required();
  command->add_option("-o,--output", arguments->output, "Output directory")->required();
  command->add_flag("--force", arguments->options.force_output,
                    "Write into an output folder that holds files littermap does not write there");
  command->add_option("--from", arguments->from, "Only runs starting on or after (YYYY-MM-DD)");
  command->add_option("--to", arguments->to, "Only runs starting before (YYYY-MM-DD)");
  auto& figures = arguments->options.figures;
  command->option_defaults()->always_capture_default();  // shown in --help
  command->add_option("--hotspots", figures.max_hotspots, "Number of hotspots listed")
      ->check(CLI::Range(0, kMaxHotspots));
  command
      ->add_option("--hotspot-min-items", figures.hotspot_min_items,
                   "Distinct items a place needs to be called a hotspot")
      ->check(WholeNumber(1, kMaxHotspotMinItems));
  command
      ->add_option("--bandwidth", figures.heatmap.density.kernel.bandwidth_m,
                   "Density kernel radius (m), also the hotspot radius")
      ->check(FiniteRange(kMinBandwidthM, kMaxBandwidthM));
  command->add_option("--cell-size", figures.heatmap.cell_size_m, "Density cell size (m)")
      ->check(FiniteRange(kMinCellSizeM, kMaxCellSizeM));
  command
      ->add_option("--min-confidence", figures.heatmap.min_confidence,
                   "Only detections at least this sure (items.csv confidence, 0 to 1)")
      ->check(FiniteRange(0.0, 1.0));
  command->callback(
      [arguments, &context] { context.run = [arguments] { RunReport(*arguments); }; });
}

}  // namespace littermap::cli
