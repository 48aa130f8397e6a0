// littermap site init SITE --name NAME [--crs EPSG:N --origin E N --rotation DEG]: creates a
// site database (a GeoPackage file, or a schema of a PostGIS database) in a local frame or placed
// in a projected CRS.

#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "cli/cli_context.hpp"
#include "db/site_database.hpp"
#include "db/spatial_ref_sys.hpp"

namespace littermap::cli {
namespace {

struct SiteInitArguments {
  std::string file;
  std::string crs;
  std::vector<double> origin;
  db::SiteOptions options;
};

void RunSiteInit(SiteInitArguments arguments) {
  arguments.options.epsg_code = db::ParseEpsgCode(arguments.crs, "--crs");
  if (!arguments.origin.empty()) {
    arguments.options.origin_easting_m = arguments.origin[0];
    arguments.options.origin_northing_m = arguments.origin[1];
  }
  const db::SiteLocator where = db::ParseSiteLocator(arguments.file);
  const db::SiteDatabase site = db::SiteDatabase::Create(where, arguments.options);
  std::printf("Created site '%s' in %s: %s\n", site.site().name.c_str(), where.display.c_str(),
              db::Describe(site.site().frame).c_str());
}

}  // namespace

void RegisterSiteCommands(CLI::App& app, CliContext& context) {
  CLI::App* site = context.AddCommand(app, "site", "Create and manage site databases");
  site->require_subcommand(1);
  auto arguments = std::make_shared<SiteInitArguments>();
  CLI::App* init = context.AddCommand(*site, "init",
                                      "Create a site database (a GeoPackage or a PostGIS schema)");
  init->add_option("SITE", arguments->file,
                   "Site database to create: SITE.gpkg, or postgresql://[USER@HOST]/DB?site=NAME")
      ->required();
  init->add_option("--name", arguments->options.name, "Site name")->required();
  CLI::Option* crs = init->add_option("--crs", arguments->crs,
                                      "Projected CRS of the site, EPSG:N (default: local frame)");
  init->add_option("--origin", arguments->origin,
                   "Easting and northing (m) of the site frame's origin in the CRS")
      ->expected(2)
      ->needs(crs);
  init->add_option("--rotation", arguments->options.rotation_deg,
                   "Angle (deg, counter-clockwise) from the CRS easting axis to the site x axis")
      ->needs(crs);
  init->callback([arguments, &context] { context.run = [arguments] { RunSiteInit(*arguments); }; });
}

}  // namespace littermap::cli
