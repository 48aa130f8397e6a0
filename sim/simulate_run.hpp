#pragma once
// A simulated survey run with everything that goes with it: the run bag and its ground truth
// (sim/recorder.hpp), the ground-truth occupancy map (sim/truth_map.hpp) and a contact sheet of
// the bag (bag/contact_sheet.hpp), each reported in one line for people as soon as it is written.

#include <filesystem>
#include <functional>
#include <optional>
#include <string>

#include "bag/contact_sheet.hpp"
#include "core/progress.hpp"
#include "sim/recorder.hpp"
#include "sim/world_spec.hpp"

namespace littermap::sim {

struct SimulateRunOptions {
  SimRecordOptions record;                  // max_duration_s is set from duration_s
  std::optional<double> duration_s;         // of the route to drive; none: all of it
  std::filesystem::path truth_dir;          // empty: no ground truth
  std::filesystem::path contact_sheet_png;  // empty: no contact sheet
};

struct SimulateRunResult {
  SimRecordResult record;
  std::optional<bag::ContactSheetResult> contact_sheet;
};

// Called once per output, when it is complete, with a line saying what was written ("wrote
// BAG: 201 scans (urg-04lx), ...").
using OutputCallback = std::function<void(const std::string& line)>;

// Writes the bag, then the ground truth with its map.pgm, then the contact sheet. Throws
// UsageError "--duration: must be positive" for a duration that is not, and what the recorder,
// the map and the contact sheet throw; the outputs reported before an error stay written.
SimulateRunResult SimulateRun(const WorldSpec& spec, const std::filesystem::path& bag,
                              const SimulateRunOptions& options,
                              const ProgressCallback& progress = {},
                              const OutputCallback& output = {});

}  // namespace littermap::sim
