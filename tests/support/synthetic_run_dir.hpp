#pragma once
// A reconstructed run directory written by hand (trajectory.tum, items.csv), for the ingest,
// heatmap and report commands without a simulation.

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

namespace littermap::test {

// A run along y = y0 from x = 0 to x = 40, heading east, 10 Hz at 0.5 m/s, with items next to
// the path every 4 m.
inline void WriteSyntheticRun(const std::filesystem::path& dir, double y0, double t0,
                              const std::string& cls) {
  std::filesystem::create_directories(dir);
  std::ofstream tum(dir / "trajectory.tum");
  tum << "# timestamp tx ty tz qx qy qz qw\n";
  for (int i = 0; i <= 800; ++i) {
    char line[128];
    std::snprintf(line, sizeof(line), "%.3f %.3f %.3f 0 0 0 0 1\n", t0 + 0.1 * i, 0.05 * i, y0);
    tum << line;
  }
  std::ofstream items(dir / "items.csv");
  items << "id,class,x,y,z,size_m,confidence\n";
  for (int i = 1; i <= 9; ++i)
    items << i << ',' << cls << ',' << 4 * i << ',' << y0 + 1 << ",0,0.1,0.9\n";
}

}  // namespace littermap::test
