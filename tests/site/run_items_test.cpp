#include "site/run_items.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "core/error.hpp"
#include "support/temp_dir.hpp"

namespace littermap::site {
namespace {

using littermap::test::TempDir;

TEST(RunItems, ReadsDetectStageAndTruthFiles) {
  TempDir dir;
  std::ofstream(dir / "items.csv") << "id,class,x,y,z,size_m,confidence\n"
                                      "a1,can,1.5,-2.25,0.05,0.12,0.8\n";
  std::ofstream(dir / "litter.csv") << "id,class,x,y,z,size_m\r\n3,cup,4,5,0,0.1\r\n";
  const auto items = ReadRunItems(dir / "items.csv");
  ASSERT_EQ(items.size(), 1u);
  EXPECT_EQ(items[0].id, "a1");
  EXPECT_EQ(items[0].class_name, "can");
  EXPECT_EQ(items[0].xy.y, -2.25);
  EXPECT_EQ(items[0].confidence, 0.8);
  const auto truth = ReadRunItems(dir / "litter.csv");
  ASSERT_EQ(truth.size(), 1u);
  EXPECT_EQ(truth[0].confidence, 1.0);
  EXPECT_EQ(truth[0].size_m, 0.1);
}

TEST(RunItems, ErrorsNameFileLineAndColumn) {
  TempDir dir;
  std::ofstream(dir / "bad.csv") << "id,class,x,y,z,size_m\n1,can,1,2,0,0.1\n2,can,oops,2,0,0.1\n";
  try {
    ReadRunItems(dir / "bad.csv");
    FAIL() << "read a bad number";
  } catch (const BadInputError& e) {
    EXPECT_NE(std::string(e.what()).find("bad.csv:3: column 'x'"), std::string::npos) << e.what();
  }
  std::ofstream(dir / "nox.csv") << "id,class,y,z,size_m\n";
  EXPECT_THROW(ReadRunItems(dir / "nox.csv"), BadInputError);
  EXPECT_THROW(ReadRunItems(dir / "missing.csv"), BadInputError);
}

}  // namespace
}  // namespace littermap::site
