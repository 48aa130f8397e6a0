#pragma once
// `littermap ingest` as a library call: a run directory (trajectory.tum, items.csv and, when
// reconstructed, map.yaml and quality.json; or a simulator truth directory with litter.csv)
// placed in the site (site/run_placement.hpp) and added to it (site/run_ingest.hpp). If another
// process's run defined the site map in between, the run is placed again against that map.

#include <filesystem>
#include <string>
#include <vector>

#include "db/site_database.hpp"
#include "site/run_ingest.hpp"
#include "site/run_placement.hpp"

namespace littermap::site {

struct RunDirectoryIngestOptions {
  // The run's name in the site; empty: from the directory (run/run_name.hpp). A name the site
  // holds for a run made of other files is refused: the same survey reprocessed, whose litter
  // the site would count twice, or another run that the report could not tell apart.
  std::string name;
  PlacementOptions placement;
  IngestOptions ingest;
};

struct RunDirectoryIngestResult {
  std::string name;
  bool simulator_truth = false;       // litter.csv stood in for items.csv
  std::vector<std::string> warnings;  // for the user's attention
  std::vector<std::string> notes;     // what placing the run did
  IngestResult ingest;
};

// Throws BadInputError naming the file for a run directory, trajectory, items or quality file
// at fault, or when the run's map does not match the site map.
RunDirectoryIngestResult IngestRunDirectory(db::SiteDatabase& site,
                                            const std::filesystem::path& run_dir,
                                            RunDirectoryIngestOptions options);
// The same for the site `site_file` (a GeoPackage or a PostGIS site); throws BadInputError when it
// is not one.
RunDirectoryIngestResult IngestRunDirectory(const db::SiteLocator& site_file,
                                            const std::filesystem::path& run_dir,
                                            RunDirectoryIngestOptions options);

// What placing and adding the run did, a line each (the notes, then the counts of the run).
std::string IngestSummary(const RunDirectoryIngestResult& result, const std::string& site_name);

}  // namespace littermap::site
