#pragma once
// The run directory, by name: the files `reconstruct` and `detect` write and `ingest`, `eval`,
// `samples` and the report read. Every stage names them through RunFiles.
//
//   trajectory.tum      a pose for every scan, optimised (TUM format, bag/tum_trajectory.hpp)
//   odometry.tum        the wheel odometry at the scans' times
//   keyframes.tum       the key frames' poses
//   map.pgm, map.yaml   the occupancy map (ROS map_server); map.png a preview
//   routines.csv        per scan: time, routine, matching ratio, landmark sightings
//   quality.json        counts, loops, warnings and run time of the reconstruction
//   camera.tum          with the RGB-D routine: the camera's optical frame at every frame tracked
//   camera_sources.csv  and which routine placed it (laser, rgbd, odometry)
//   detections.csv      per frame: every object segmented, placed and classified
//   items.csv           the fused litter items and natural objects

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace littermap::run {

struct RunFiles {
  explicit RunFiles(std::filesystem::path run_dir) : dir(std::move(run_dir)) {}

  std::filesystem::path trajectory() const { return dir / "trajectory.tum"; }
  std::filesystem::path odometry() const { return dir / "odometry.tum"; }
  std::filesystem::path key_frames() const { return dir / "keyframes.tum"; }
  std::filesystem::path map_pgm() const { return dir / "map.pgm"; }
  std::filesystem::path map_yaml() const { return dir / "map.yaml"; }
  std::filesystem::path map_png() const { return dir / "map.png"; }
  std::filesystem::path routines() const { return dir / "routines.csv"; }
  std::filesystem::path loops() const { return dir / "loops.csv"; }
  std::filesystem::path quality() const { return dir / "quality.json"; }
  std::filesystem::path sensor_roles() const { return dir / "sensor_roles.json"; }
  std::filesystem::path camera() const { return dir / "camera.tum"; }
  std::filesystem::path camera_sources() const { return dir / "camera_sources.csv"; }
  std::filesystem::path detections() const { return dir / "detections.csv"; }
  std::filesystem::path items() const { return dir / "items.csv"; }

  // Every name above: what a run directory may hold (core/output_folder.hpp).
  static std::vector<std::string> Names() {
    const RunFiles files("");
    std::vector<std::string> names;
    for (const std::filesystem::path& file :
         {files.trajectory(), files.odometry(), files.key_frames(), files.map_pgm(),
          files.map_yaml(), files.map_png(), files.routines(), files.loops(), files.quality(),
          files.sensor_roles(), files.camera(), files.camera_sources(), files.detections(),
          files.items()}) {
      names.push_back(file.filename().string());
    }
    return names;
  }

  std::filesystem::path dir;
};

}  // namespace littermap::run
