#include "run/run_digest.hpp"

#include <gtest/gtest.h>

#include <fstream>

#include "core/error.hpp"
#include "support/temp_dir.hpp"

namespace littermap::run {
namespace {

using littermap::test::TempDir;

TEST(DigestFiles, ChangesWithContentAndOrder) {
  TempDir dir;
  std::ofstream(dir / "a") << "alpha";
  std::ofstream(dir / "b") << "beta";
  const std::filesystem::path ab[] = {dir / "a", dir / "b"};
  const std::filesystem::path ba[] = {dir / "b", dir / "a"};
  EXPECT_EQ(DigestFiles(ab), DigestFiles(ab));
  EXPECT_NE(DigestFiles(ab), DigestFiles(ba));
  EXPECT_EQ(DigestFiles(ab).size(), 16u);
  const std::filesystem::path missing[] = {dir / "c"};
  EXPECT_THROW(DigestFiles(missing), BadInputError);
}

TEST(RunDigest, NamesTheItemsOfARunOrOfASimulatorTruth) {
  TempDir dir;
  EXPECT_THROW(FindRunDirectoryFiles(dir.path()), BadInputError);
  std::ofstream(dir / "trajectory.tum") << "# timestamp tx ty tz qx qy qz qw\n";
  std::ofstream(dir / "litter.csv") << "id,class,x,y,z,size_m\n";
  const RunDirectoryFiles truth = FindRunDirectoryFiles(dir.path());
  EXPECT_TRUE(truth.simulator_truth);
  EXPECT_EQ(truth.items, dir / "litter.csv");
  std::ofstream(dir / "items.csv") << "id,class,x,y,z,size_m,confidence\n";
  const RunDirectoryFiles detected = FindRunDirectoryFiles(dir.path());
  EXPECT_FALSE(detected.simulator_truth);
  EXPECT_EQ(detected.items, dir / "items.csv");
  EXPECT_NE(RunDigest(truth), RunDigest(detected));
}

}  // namespace
}  // namespace littermap::run
