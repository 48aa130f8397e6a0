#include "sim/simulate_run.hpp"

#include <cstdarg>
#include <cstdio>

#include "core/error.hpp"
#include "sim/simulation.hpp"
#include "sim/truth_map.hpp"

namespace littermap::sim {
namespace {

__attribute__((format(printf, 1, 2))) std::string Format(const char* format, ...) {
  va_list arguments;
  va_start(arguments, format);
  va_list copy;
  va_copy(copy, arguments);
  const int size = std::vsnprintf(nullptr, 0, format, copy);
  va_end(copy);
  std::string text(static_cast<std::size_t>(size > 0 ? size : 0), '\0');
  std::vsnprintf(text.data(), text.size() + 1, format, arguments);
  va_end(arguments);
  return text;
}

using ull = unsigned long long;

std::string BagLine(const std::filesystem::path& bag, const std::string& route,
                    const SimRecordResult& result) {
  return Format(
      "wrote %s: %llu scans (%s), %llu odometry, %llu imu, %llu rgb-d frames, %.1f s, %.1f m%s "
      "(seed %llu, run seed %llu%s%s, %.1f frames/s)",
      bag.c_str(), ull{result.scans}, result.laser.c_str(), ull{result.odometry}, ull{result.imu},
      ull{result.frames}, result.duration_s, result.distance_m,
      result.route_completed ? "" : " (route cut short)", ull{result.seed}, ull{result.run_seed},
      route.empty() ? "" : ", route ", route.c_str(),
      result.simulate_s > 0 ? static_cast<double>(result.frames) / result.simulate_s : 0.0);
}

std::string TruthLine(const std::filesystem::path& truth_dir, const SimRecordResult& result) {
  return Format(
      "wrote %s: %llu litter, %llu natural look-alikes, %llu primitives, %llu masks, "
      "map.pgm",
      truth_dir.c_str(), ull{result.litter}, ull{result.natural}, ull{result.objects},
      ull{result.masks});
}

void Report(const OutputCallback& output, const std::string& line) {
  if (output) output(line);
}

}  // namespace

SimulateRunResult SimulateRun(const WorldSpec& spec, const std::filesystem::path& bag,
                              const SimulateRunOptions& options, const ProgressCallback& progress,
                              const OutputCallback& output) {
  SimRecordOptions record = options.record;
  if (options.duration_s) {
    if (!(*options.duration_s > 0)) throw UsageError("--duration: must be positive");
    record.max_duration_s = *options.duration_s;
  }
  SimulateRunResult result;
  result.record = RecordSimulation(spec, bag, options.truth_dir, record, progress);
  Report(output, BagLine(bag, record.route, result.record));
  if (!options.truth_dir.empty()) {
    WriteTruthMap(Simulation(RunSpec(spec, record), {record.max_duration_s}), options.truth_dir);
    Report(output, TruthLine(options.truth_dir, result.record));
  }
  if (!options.contact_sheet_png.empty()) {
    result.contact_sheet = bag::WriteContactSheet(bag, options.contact_sheet_png);
    Report(output, Format("wrote %s: %d frames (colour | depth | laser), %dx%d px",
                          options.contact_sheet_png.c_str(), result.contact_sheet->rows,
                          result.contact_sheet->width_px, result.contact_sheet->height_px));
  }
  return result;
}

}  // namespace littermap::sim
