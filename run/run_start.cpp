#include "run/run_start.hpp"

#include "bag/tum_trajectory.hpp"
#include "core/error.hpp"
#include "core/time.hpp"
#include "run/run_files.hpp"

namespace littermap::run {

double RunStartTimeS(const std::filesystem::path& run_dir) {
  const std::filesystem::path file = RunFiles(run_dir).trajectory();
  const auto poses = bag::ReadTumTrajectory(file);
  if (poses.empty()) throw BadInputError(file.string() + ": the trajectory has no pose");
  return ToSeconds(poses.front().stamp_ns);
}

}  // namespace littermap::run
