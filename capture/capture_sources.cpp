#include "capture/capture_sources.hpp"

#include <filesystem>
#include <string_view>
#include <utility>

#include "capture/odometry_source.hpp"
#include "capture/scip_laser_source.hpp"
#include "core/error.hpp"

namespace littermap::capture {
namespace {

constexpr std::string_view kSimScheme = "sim:";

bool IsSim(const std::string& uri) { return uri.starts_with(kSimScheme); }
bool IsNone(const std::string& uri) { return uri.empty() || uri == "none"; }

bool SameFile(const std::filesystem::path& a, const std::filesystem::path& b) {
  std::error_code error;
  return std::filesystem::weakly_canonical(a, error) == std::filesystem::weakly_canonical(b, error);
}

}  // namespace

std::optional<std::string> SimulatedWorld(const CaptureSources& sources) {
  const std::string& camera = sources.camera_uri;
  if (!IsSim(camera) && !IsSim(sources.laser_uri) && !IsSim(sources.odometry_uri)) {
    return std::nullopt;
  }
  if (!IsSim(camera)) {
    throw UsageError("--camera '" + camera +
                     "': a simulated capture needs --camera sim:WORLD.yaml as well");
  }
  const std::string world = camera.substr(kSimScheme.size());
  if (world.empty()) throw UsageError("--camera '" + camera + "' names no world file");
  const std::pair<const char*, const std::string*> others[] = {
      {"--laser", &sources.laser_uri}, {"--odometry", &sources.odometry_uri}};
  for (const auto& [option, uri] : others) {
    if (IsNone(*uri) && std::string(option) == "--odometry") continue;
    if (!IsSim(*uri) || !SameFile(uri->substr(kSimScheme.size()), world)) {
      throw UsageError(std::string(option) + " '" + *uri + "' and --camera '" + camera +
                       "' must simulate the same world (a simulated and a real sensor do not "
                       "record together)");
    }
  }
  return world;
}

std::vector<std::unique_ptr<SensorSource>> MakeSources(const CaptureSources& sources,
                                                       const Openni2CameraOptions& camera) {
  std::vector<std::unique_ptr<SensorSource>> made;
  if (!IsNone(sources.camera_uri)) {
    made.push_back(std::make_unique<Openni2Camera>(sources.camera_uri, camera));
  }
  if (!IsNone(sources.laser_uri)) {
    made.push_back(std::make_unique<ScipLaserSource>(sources.laser_uri));
  }
  if (!IsNone(sources.odometry_uri)) {
    made.push_back(std::make_unique<OdometrySource>(sources.odometry_uri));
  }
  if (made.empty()) throw UsageError("nothing to record: give --camera, --laser or --odometry");
  return made;
}

}  // namespace littermap::capture
