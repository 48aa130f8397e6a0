#pragma once
// The simulated run shared by `littermap simulate` and `littermap capture --camera sim:...`.

#include <string>

#include "cli/cli_context.hpp"
#include "sim/simulate_run.hpp"

namespace littermap::cli {

struct SimulateRequest {
  std::string world;
  std::string bag;
  std::string start_time;  // a date (core/utc_date.hpp); empty: the world's start_time_s
  sim::SimulateRunOptions options;
};

// Records the run, prints what was written to stdout. Throws littermap errors.
void RunSimulate(SimulateRequest request, CliContext& context);

}  // namespace littermap::cli
