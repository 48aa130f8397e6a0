// TextLineReader: plain and gzip text alike, and damaged gzip data as an error.

#include "core/text_lines.hpp"

#include <gtest/gtest.h>
#include <zlib.h>

#include <fstream>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "support/temp_dir.hpp"

namespace littermap {
namespace {

void WritePlain(const std::filesystem::path& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

void WriteGzip(const std::filesystem::path& path, const std::string& text,
               const char* mode = "wb") {
  gzFile file = gzopen(path.c_str(), mode);
  ASSERT_NE(file, nullptr);
  ASSERT_EQ(gzwrite(file, text.data(), static_cast<unsigned>(text.size())),
            static_cast<int>(text.size()));
  ASSERT_EQ(gzclose(file), Z_OK);
}

std::string ReadBytes(const std::filesystem::path& path) {
  std::ifstream stream(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(stream), std::istreambuf_iterator<char>());
}

std::vector<std::string> ReadAll(const std::filesystem::path& path) {
  TextLineReader reader(path);
  std::vector<std::string> lines;
  std::string_view line;
  while (reader.Next(&line)) lines.emplace_back(line);
  EXPECT_EQ(reader.line_number(), lines.size());
  return lines;
}

// Text whose lines straddle the 64 KiB read chunks, including one line longer than a chunk.
std::string BigText() {
  std::string text;
  for (int i = 0; i < 20000; ++i) text += "line " + std::to_string(i) + "\n";
  text += std::string(200000, 'x') + "\n";
  text += "last line without newline";
  return text;
}

TEST(TextLines, PlainTextWithCrLfBlankAndUnterminatedLines) {
  test::TempDir dir;
  WritePlain(dir / "a.txt", "one\r\n\ntwo\nthree");
  EXPECT_EQ(ReadAll(dir / "a.txt"), (std::vector<std::string>{"one", "", "two", "three"}));
  WritePlain(dir / "empty.txt", "");
  EXPECT_TRUE(ReadAll(dir / "empty.txt").empty());
}

TEST(TextLines, GzipReadsLikeThePlainFile) {
  test::TempDir dir;
  const std::string text = BigText();
  WritePlain(dir / "big.txt", text);
  WriteGzip(dir / "big.gz", text);
  const auto plain = ReadAll(dir / "big.txt");
  ASSERT_EQ(plain.size(), 20002u);
  EXPECT_EQ(plain[19999], "line 19999");
  EXPECT_EQ(plain[20000].size(), 200000u);
  EXPECT_EQ(plain[20001], "last line without newline");
  EXPECT_EQ(ReadAll(dir / "big.gz"), plain);
  EXPECT_TRUE(TextLineReader(dir / "big.gz").compressed());
  EXPECT_FALSE(TextLineReader(dir / "big.txt").compressed());
}

TEST(TextLines, ConcatenatedGzipMembersAreOneFile) {
  test::TempDir dir;
  WriteGzip(dir / "two.gz", "first\nsecond\n");
  WriteGzip(dir / "two.gz", "third\n", "ab");  // appends a second gzip member
  EXPECT_EQ(ReadAll(dir / "two.gz"), (std::vector<std::string>{"first", "second", "third"}));
}

TEST(TextLines, TruncatedGzipIsBadInputNamingFileAndLine) {
  test::TempDir dir;
  WriteGzip(dir / "full.gz", BigText());
  const std::string bytes = ReadBytes(dir / "full.gz");
  WritePlain(dir / "cut.gz", bytes.substr(0, bytes.size() / 2));
  TextLineReader reader(dir / "cut.gz");
  std::string_view line;
  try {
    while (reader.Next(&line)) {
    }
    FAIL() << "a truncated gzip file must not read as a shorter file";
  } catch (const BadInputError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("cut.gz"), std::string::npos) << message;
    EXPECT_NE(message.find("truncated"), std::string::npos) << message;
    EXPECT_NE(message.find("after line " + std::to_string(reader.line_number())), std::string::npos)
        << message;
    EXPECT_GT(reader.line_number(), 0u);
  }
}

TEST(TextLines, TruncatedTrailerIsAlsoAnError) {
  test::TempDir dir;
  WriteGzip(dir / "full.gz", "a\nb\n");
  const std::string bytes = ReadBytes(dir / "full.gz");
  WritePlain(dir / "cut.gz", bytes.substr(0, bytes.size() - 4));  // ISIZE of the trailer gone
  EXPECT_THROW(ReadAll(dir / "cut.gz"), BadInputError);
}

TEST(TextLines, CorruptGzipIsBadInput) {
  test::TempDir dir;
  WriteGzip(dir / "full.gz", BigText());
  std::string bytes = ReadBytes(dir / "full.gz");
  for (std::size_t i = bytes.size() / 3; i < bytes.size() / 3 + 64; ++i) bytes[i] ^= 0x5a;
  WritePlain(dir / "bad.gz", bytes);
  EXPECT_THROW(ReadAll(dir / "bad.gz"), BadInputError);
}

TEST(TextLines, MissingFileAndOverlongLineAreBadInput) {
  test::TempDir dir;
  EXPECT_THROW(TextLineReader(dir / "nope.txt"), BadInputError);
  WritePlain(dir / "long.txt", "short\n" + std::string(5000, 'y') + "\n");
  TextLineReader reader(dir / "long.txt", {.max_line_bytes = 1000});
  std::string_view line;
  EXPECT_TRUE(reader.Next(&line));
  try {
    reader.Next(&line);
    FAIL() << "expected an overlong-line error";
  } catch (const BadInputError& error) {
    EXPECT_NE(std::string(error.what()).find("line 2"), std::string::npos) << error.what();
  }
}

}  // namespace
}  // namespace littermap
