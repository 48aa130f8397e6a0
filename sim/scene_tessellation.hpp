#pragma once
// Turns the park into triangles for the z-buffer, every frame: the terrain patch in view as a
// polar grid around the camera (rings whose spacing grows with distance, so far ground gets
// coarse cells and near ground resolves roots), and each object primitive (box, cylinder,
// ellipsoid) as a small mesh, culled against the view frustum.

#include <cstdint>
#include <vector>

#include <Eigen/Geometry>

#include "sim/camera_model.hpp"
#include "sim/world.hpp"
#include "sim/zbuffer.hpp"

namespace littermap::sim {

struct TessellationOptions {
  double ring_spacing_m = 0.03;  // radial cell size at the camera ...
  double ring_growth = 0.03;     // ... plus this share of the distance
  int ground_columns = 128;      // angular cells across the field of view
  double fine_min_pixels = 24;   // objects larger on screen get 20 segments around, others 10
};

// The instance id an object is drawn with: its id + 1, because 0 is the ground (kGroundInstance)
// and object ids start at 0.
inline std::int32_t InstanceIdOf(const WorldObject& object) { return object.id + 1; }
// The index into World::objects of an instance id > 0.
inline int ObjectIdOfInstance(std::int32_t instance) { return instance - 1; }

// Draws the terrain around the camera pose out to the horizontal distance range_m.
void DrawTerrain(const Terrain& terrain, const Eigen::Isometry3d& T_world_camera,
                 const PinholeCamera& camera, const TessellationOptions& options, double range_m,
                 ZBuffer& zbuffer);

// Draws every object whose bounding sphere intersects the view frustum; returns how many.
int DrawObjects(const std::vector<WorldObject>& objects, const Eigen::Isometry3d& T_world_camera,
                const PinholeCamera& camera, const TessellationOptions& options, float far_m,
                ZBuffer& zbuffer);

}  // namespace littermap::sim
