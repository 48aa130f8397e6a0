// littermap site init SITE --name NAME [--crs EPSG:N --origin E N --rotation DEG]: creates a
// site database (a GeoPackage file, or a schema of a PostGIS database) in a local frame or placed
// in a projected CRS.
// littermap site export SITE -o FILE.gpkg, site import FILE.gpkg --site URI: moves a site from
// one engine to the other (db/site_copy.hpp).

#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "cli/cli_context.hpp"
#include "db/site_copy.hpp"
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

struct SiteCopyArguments {
  std::string from;
  std::string to;
};

void RunSiteCopy(const SiteCopyArguments& arguments, const char* verb, CliContext& context) {
  const db::SiteLocator from = db::ParseSiteLocator(arguments.from);
  const db::SiteLocator to = db::ParseSiteLocator(arguments.to);
  const db::SiteCopyResult result = db::CopySite(from, to, context.Progress());
  context.FinishProgress();
  std::printf("%s site '%s' from %s to %s: %zu runs, %zu items, %zu detections, %zu hotspots\n",
              verb, result.site_name.c_str(), from.display.c_str(), to.display.c_str(),
              result.Rows("runs"), result.Rows("litter_items"), result.Rows("detections"),
              result.Rows("hotspots"));
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

  auto exported = std::make_shared<SiteCopyArguments>();
  CLI::App* export_command = context.AddCommand(
      *site, "export", "Copy a site (from PostGIS) into a new GeoPackage, ids and all");
  export_command->add_option("SITE", exported->from, "Site to copy: postgresql://...?site=NAME")
      ->required();
  export_command->add_option("-o,--output", exported->to, "GeoPackage to create (FILE.gpkg)")
      ->required();
  export_command->callback([exported, &context] {
    context.run = [exported, &context] { RunSiteCopy(*exported, "Exported", context); };
  });

  auto imported = std::make_shared<SiteCopyArguments>();
  CLI::App* import_command = context.AddCommand(
      *site, "import", "Copy a site from a GeoPackage into a new PostGIS site, ids and all");
  import_command->add_option("FILE", imported->from, "GeoPackage site to copy (FILE.gpkg)")
      ->required();
  import_command
      ->add_option("--site", imported->to, "Site to create: postgresql://[USER@HOST]/DB?site=NAME")
      ->required();
  import_command->callback([imported, &context] {
    context.run = [imported, &context] { RunSiteCopy(*imported, "Imported", context); };
  });
}

}  // namespace littermap::cli
