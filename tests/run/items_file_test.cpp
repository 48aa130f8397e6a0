#include "run/items_file.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <functional>
#include <string>

#include "core/error.hpp"
#include "support/expect_bad_input.hpp"
#include "support/temp_dir.hpp"

namespace littermap::run {
namespace {

using test::ExpectBadInput;

void WriteFile(const std::filesystem::path& file, const std::string& text) {
  std::ofstream(file) << text;
}

TEST(ItemsFile, ReadsColumnsByName) {
  test::TempDir dir;
  WriteFile(dir / "items.csv",
            "y,class,extra,id,x,confidence\n1.5,can,?,a,2.5,0.9\n\n# comment\n2,leaf,,b,3,1\n");
  const auto items = ReadItemsCsv(dir / "items.csv");
  ASSERT_EQ(items.size(), 2u);
  EXPECT_EQ(items[0].id, "a");
  EXPECT_EQ(items[0].class_name, "can");
  EXPECT_DOUBLE_EQ(items[0].x_m, 2.5);
  EXPECT_DOUBLE_EQ(items[0].y_m, 1.5);
  EXPECT_DOUBLE_EQ(items[0].confidence, 0.9);
  EXPECT_FALSE(items[0].litter.has_value());  // no litter column: the reader leaves it open
  EXPECT_DOUBLE_EQ(items[1].confidence, 1.0);

  WriteFile(dir / "flagged.csv", "id,class,x,y,litter\na,leaf,0,0,1\nb,can,0,0,0\n");
  const auto flagged = ReadItemsCsv(dir / "flagged.csv");
  ASSERT_EQ(flagged.size(), 2u);
  EXPECT_EQ(flagged[0].litter, true);  // the column, whatever the class
  EXPECT_EQ(flagged[1].litter, false);

  WriteFile(dir / "litter.csv", "id,class,x,y,z,size_m\r\n7,can,1.0,2.0,0.05,0.12\r\n");
  const auto truth = ReadItemsCsv(dir / "litter.csv", {"z", "size_m"});
  ASSERT_EQ(truth.size(), 1u);
  EXPECT_DOUBLE_EQ(truth[0].z_m, 0.05);
  EXPECT_DOUBLE_EQ(truth[0].size_m, 0.12);
}

TEST(ItemsFile, ErrorsNameFileLineAndColumn) {
  test::TempDir dir;
  const std::string items = (dir / "items.csv").string();
  WriteFile(items, "id,class,x\n1,can,0\n");
  ExpectBadInput([&] { ReadItemsCsv(items); }, items + ":1: the header has no column 'y'");
  WriteFile(items, "id,class,x,y\n1,can,0,0\n2,can,abc,0\n");
  ExpectBadInput([&] { ReadItemsCsv(items); }, items + ":3: column 'x' is not a number");
  WriteFile(items, "id,class,x,y\n1,can,0\n");
  ExpectBadInput([&] { ReadItemsCsv(items); }, items + ":2: column 'y' is missing");
  WriteFile(items, "id,class,x,y,confidence\n1,can,0,0,1.5\n");
  ExpectBadInput([&] { ReadItemsCsv(items); }, items + ":2: column 'confidence'");
  WriteFile(items, "id,class,x,y,litter\n1,can,0,0,yes\n");
  ExpectBadInput([&] { ReadItemsCsv(items); }, items + ":2: column 'litter'");
  WriteFile(items, "id,class,x,y\n,can,0,0\n");
  ExpectBadInput([&] { ReadItemsCsv(items); }, items + ":2: column 'id' is empty");
  WriteFile(items, "id,class,x,y\n1,can,0,0\n");
  ExpectBadInput([&] { ReadItemsCsv(items, {"size_m"}); },
                 items + ":1: the header has no column 'size_m'");
}

TEST(ItemsFile, ReadsTheDetectStagesColumns) {
  test::TempDir dir;
  WriteFile(dir / "items.csv",
            "id,class,x,y,z,size_m,confidence,views,missed_views,litter,litter_probability,"
            "first_seen_ns,last_seen_ns\n3,can,1.250,-0.500,0.040,0.110,0.870,5,1,1,0.930,10,20\n"
            "4,leaf,2.000,3.000,0.010,0.080,0.600,3,0,0,0.100,30,40\n");
  const auto items = ReadItemsCsv(dir / "items.csv");
  ASSERT_EQ(items.size(), 2u);
  EXPECT_EQ(items[0].litter, true);
  EXPECT_EQ(items[1].litter, false);
  EXPECT_DOUBLE_EQ(items[0].confidence, 0.87);
  EXPECT_DOUBLE_EQ(items[1].size_m, 0.08);
}

}  // namespace
}  // namespace littermap::run
