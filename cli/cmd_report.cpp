// littermap report SITE.gpkg -o DIR [--from DATE --to DATE]: the site's report for park staff,
// DIR/index.html (self-contained) and DIR/report.json.

#include <cstdio>
#include <ctime>
#include <memory>
#include <string>

#include "cli/cli_context.hpp"
#include "cli/date_argument.hpp"
#include "cli/report_command.hpp"
#include "core/time.hpp"
#include "littermap_version.hpp"
#include "reports/report_files.hpp"

namespace littermap::cli {

reports::ReportFilesOptions DefaultReportOptions() {
  reports::ReportFilesOptions options;
  options.html.generated_utc = FormatUtc(static_cast<double>(std::time(nullptr)));
  options.html.version = LITTERMAP_VERSION;
  return options;
}

namespace {

struct ReportArguments {
  std::string site;
  std::string output;
  std::string from;
  std::string to;
  reports::ReportFilesOptions options = DefaultReportOptions();
};

void RunReport(ReportArguments arguments) {
  arguments.options.figures.from_time_s = ParseDateArgument(arguments.from, "--from");
  arguments.options.figures.to_time_s = ParseDateArgument(arguments.to, "--to");
  db::SiteDatabase site = db::SiteDatabase::Open(arguments.site);
  const std::filesystem::path dir = arguments.output;
  const reports::SiteReport report = reports::WriteReportFiles(site, dir, arguments.options);
  std::printf("Report of %s: %zu %s, %zu litter items, %zu hotspots\n%s\n",
              report.site_name.c_str(), report.runs.size(),
              report.runs.size() == 1 ? "run" : "runs", report.items, report.hotspots.size(),
              (dir / "index.html").c_str());
}

}  // namespace

void RegisterReportCommand(CLI::App& app, CliContext& context) {
  auto arguments = std::make_shared<ReportArguments>();
  CLI::App* command = context.AddCommand(
      app, "report", "HTML report of a site for park staff (index.html and report.json)");
  command->add_option("SITE", arguments->site, "Site database (SITE.gpkg)")->required();
  command->add_option("-o,--output", arguments->output, "Output directory")->required();
  command->add_option("--from", arguments->from, "Only runs starting on or after (YYYY-MM-DD)");
  command->add_option("--to", arguments->to, "Only runs starting before (YYYY-MM-DD)");
  auto& figures = arguments->options.figures;
  command->add_option("--hotspots", figures.max_hotspots, "Number of hotspots listed")
      ->capture_default_str();
  command
      ->add_option("--bandwidth", figures.heatmap.density.kernel.bandwidth_m,
                   "Density kernel radius (m), also the hotspot radius")
      ->capture_default_str();
  command->add_option("--cell-size", figures.heatmap.cell_size_m, "Density cell size (m)")
      ->capture_default_str();
  command->callback(
      [arguments, &context] { context.run = [arguments] { RunReport(*arguments); }; });
}

}  // namespace littermap::cli
