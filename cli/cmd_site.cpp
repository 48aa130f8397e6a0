// littermap site init SITE.gpkg --name NAME [--crs EPSG:N --origin E N --rotation DEG]:
// creates a site database (a GeoPackage) in a local frame or placed in a projected CRS.

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "cli/cli_context.hpp"
#include "core/error.hpp"
#include "db/site_database.hpp"

namespace littermap::cli {
namespace {

struct SiteInitArguments {
  std::string file;
  std::string name;
  std::string crs;
  std::vector<double> origin;
  double rotation_deg = 0.0;
};

// "EPSG:32633", "epsg:32633" or "32633".
int ParseEpsg(const std::string& text) {
  std::string digits = text;
  std::string upper = text;
  std::transform(upper.begin(), upper.end(), upper.begin(),
                 [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
  if (upper.rfind("EPSG:", 0) == 0) digits = text.substr(5);
  const bool numeric = !digits.empty() && digits.size() < 10 &&
                       std::all_of(digits.begin(), digits.end(),
                                   [](unsigned char c) { return std::isdigit(c) != 0; });
  if (!numeric) throw UsageError("--crs " + text + ": expected EPSG:N, e.g. EPSG:32633");
  return std::stoi(digits);
}

void RunSiteInit(const SiteInitArguments& arguments) {
  db::SiteOptions options;
  options.name = arguments.name;
  if (!arguments.crs.empty()) options.epsg_code = ParseEpsg(arguments.crs);
  if (!arguments.origin.empty()) {
    options.origin_easting_m = arguments.origin[0];
    options.origin_northing_m = arguments.origin[1];
  }
  options.rotation_deg = arguments.rotation_deg;
  const db::SiteDatabase site = db::SiteDatabase::Create(arguments.file, options);
  const db::SiteFrame& frame = site.site().frame;
  if (frame.georeferenced()) {
    std::printf("Created site '%s' in %s: EPSG:%d, origin E %.3f N %.3f, rotation %.3f deg\n",
                site.site().name.c_str(), arguments.file.c_str(), frame.epsg_code,
                frame.origin_easting_m, frame.origin_northing_m, frame.rotation_deg);
  } else {
    std::printf("Created site '%s' in %s: local frame (not georeferenced)\n",
                site.site().name.c_str(), arguments.file.c_str());
  }
}

}  // namespace

void RegisterSiteCommands(CLI::App& app, CliContext& context) {
  CLI::App* site = context.AddCommand(app, "site", "Create and manage site databases");
  site->require_subcommand(1);
  auto arguments = std::make_shared<SiteInitArguments>();
  CLI::App* init = context.AddCommand(*site, "init", "Create a site database (a GeoPackage)");
  init->add_option("SITE", arguments->file, "Site database to create (SITE.gpkg)")->required();
  init->add_option("--name", arguments->name, "Site name")->required();
  CLI::Option* crs = init->add_option("--crs", arguments->crs,
                                      "Projected CRS of the site, EPSG:N (default: local frame)");
  init->add_option("--origin", arguments->origin,
                   "Easting and northing (m) of the site frame's origin in the CRS")
      ->expected(2)
      ->needs(crs);
  init->add_option("--rotation", arguments->rotation_deg,
                   "Angle (deg, counter-clockwise) from the CRS easting axis to the site x axis")
      ->needs(crs);
  init->callback([arguments, &context] { context.run = [arguments] { RunSiteInit(*arguments); }; });
}

}  // namespace littermap::cli
