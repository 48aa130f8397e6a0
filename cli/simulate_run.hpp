#pragma once
// The simulated run shared by `littermap simulate` and `littermap capture --camera sim:...`.

#include <cstdint>
#include <optional>
#include <string>

#include "cli/cli_context.hpp"

namespace littermap::cli {

struct SimulateRequest {
  std::string world;
  std::string bag;
  std::string truth;          // empty: no ground truth
  std::string contact_sheet;  // empty: none
  std::optional<std::uint64_t> seed;
  std::optional<std::uint64_t> run_seed;
  std::string route;  // empty: the world's `route`
  std::optional<double> duration_s;
  int litter_day = 0;
  std::string start_time;  // a date (cli/date_argument.hpp); empty: the world's start_time_s
};

// Records the run, prints what was written to stdout. Throws littermap errors.
void RunSimulate(const SimulateRequest& request, CliContext& context);

}  // namespace littermap::cli
