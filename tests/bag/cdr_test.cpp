// The CDR primitives on their own: alignment relative to the byte after the encapsulation header,
// string and sequence framing, and the Reader's refusal of malformed input (XTypes 1.3, 7.4.3.5).

#include "bag/cdr.hpp"

#include <array>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace littermap::cdr {
namespace {

using Bytes = std::vector<std::uint8_t>;

TEST(CdrWriter, StartsWithLittleEndianEncapsulationHeader) {
  Writer writer;
  EXPECT_EQ(writer.Take(), (Bytes{0x00, 0x01, 0x00, 0x00}));
}

TEST(CdrWriter, AlignsEachPrimitiveToItsSizeAfterTheHeader) {
  Writer writer;
  writer.Write<std::uint8_t>(0xAA);         // offset 0
  writer.Write<std::uint16_t>(0x0102);      // pad 1, offset 2..3
  writer.Write<std::uint8_t>(0xBB);         // offset 4
  writer.Write<std::uint32_t>(0x03040506);  // pad 3, offset 8..11
  writer.Write<std::uint8_t>(0xCC);         // offset 12
  writer.Write<double>(1.0);                // pad 3, offset 16..23
  const Bytes expected = {
      0x00, 0x01, 0x00, 0x00,                          // encapsulation
      0xAA, 0x00, 0x02, 0x01,                          // u8, pad, u16
      0xBB, 0x00, 0x00, 0x00, 0x06, 0x05, 0x04, 0x03,  // u8, pad 3, u32
      0xCC, 0x00, 0x00, 0x00,                          // u8 at 12, pad 3
      0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0xF0, 0x3F,  // 1.0 = 0x3FF0000000000000
  };
  EXPECT_EQ(writer.Take(), expected);
}

TEST(CdrWriter, StringCountsTheTerminatingNul) {
  Writer writer;
  writer.WriteString("ab");
  writer.WriteString("");
  const Bytes expected = {0x00, 0x01, 0x00, 0x00,  // encapsulation
                          0x03, 0x00, 0x00, 0x00,  // length 3 = "ab" + NUL
                          'a',  'b',  0x00, 0x00,  // "ab\0", pad 1
                          0x01, 0x00, 0x00, 0x00,  // length 1: the empty string is just a NUL
                          0x00};
  EXPECT_EQ(writer.Take(), expected);
}

TEST(CdrWriter, SequenceHasCountArrayHasNot) {
  Writer writer;
  const std::array<std::uint16_t, 2> values = {7, 8};
  writer.WriteSequence(std::span<const std::uint16_t>(values));
  writer.WriteArray(std::span<const std::uint16_t>(values));
  const Bytes expected = {0x00, 0x01, 0x00, 0x00, 0x02, 0x00, 0x00, 0x00,
                          0x07, 0x00, 0x08, 0x00, 0x07, 0x00, 0x08, 0x00};
  EXPECT_EQ(writer.Take(), expected);
}

TEST(CdrReader, ReadsWhatTheWriterWrote) {
  Writer writer;
  writer.Write<std::int8_t>(-3);
  writer.Write<std::int64_t>(-1234567890123);
  writer.WriteBool(true);
  writer.WriteString("frame");
  writer.Write<float>(2.5F);
  const std::vector<double> values = {1.5, -2.5};
  writer.WriteSequence(std::span<const double>(values));
  const Bytes bytes = writer.Take();

  Reader reader(bytes);
  EXPECT_EQ(reader.Read<std::int8_t>("a"), -3);
  EXPECT_EQ(reader.Read<std::int64_t>("b"), -1234567890123);
  EXPECT_TRUE(reader.ReadBool("c"));
  EXPECT_EQ(reader.ReadString("d"), "frame");
  EXPECT_EQ(reader.Read<float>("e"), 2.5F);
  EXPECT_EQ(reader.ReadSequence<double>("f"), values);
  EXPECT_EQ(reader.remaining(), 0U);
}

TEST(CdrReader, RejectsMissingOrForeignEncapsulation) {
  EXPECT_THROW(Reader(Bytes{}), CdrError);
  EXPECT_THROW(Reader(Bytes{0x00, 0x01, 0x00}), CdrError);
  EXPECT_THROW(Reader(Bytes{0x00, 0x00, 0x00, 0x00}), CdrError);  // CDR_BE
  EXPECT_THROW(Reader(Bytes{0x00, 0x03, 0x00, 0x00}), CdrError);  // PL_CDR_LE
  EXPECT_THROW(Reader(Bytes{0x00, 0x07, 0x00, 0x00}), CdrError);  // CDR2_LE (XCDR2)
  EXPECT_THROW(Reader(Bytes{0x01, 0x01, 0x00, 0x00}), CdrError);
  EXPECT_NO_THROW(Reader(Bytes{0x00, 0x01, 0x00, 0x00}));
}

TEST(CdrReader, EncapsulationErrorShowsTheBytesInHex) {
  try {
    Reader reader(Bytes{0x00, 0x1F, 0x00, 0x00});
    FAIL() << "no exception";
  } catch (const CdrError& error) {
    EXPECT_NE(std::string(error.what()).find("0x00 0x1f"), std::string::npos) << error.what();
  }
}

TEST(CdrReader, TruncationNamesTheField) {
  const Bytes bytes = {0x00, 0x01, 0x00, 0x00, 0x01, 0x02};
  Reader reader(bytes);
  try {
    reader.Read<std::uint32_t>("Thing.count");
    FAIL() << "no exception";
  } catch (const CdrError& error) {
    EXPECT_NE(std::string(error.what()).find("Thing.count"), std::string::npos) << error.what();
  }
}

TEST(CdrReader, PaddingPastTheEndIsTruncation) {
  // A u8 then a u32: the u32 needs 3 bytes of padding that are not there.
  const Bytes bytes = {0x00, 0x01, 0x00, 0x00, 0x05, 0x00};
  Reader reader(bytes);
  EXPECT_EQ(reader.Read<std::uint8_t>("a"), 5);
  EXPECT_THROW(reader.Read<std::uint32_t>("b"), CdrError);
}

TEST(CdrReader, RejectsStringWithoutNul) {
  const Bytes bytes = {0x00, 0x01, 0x00, 0x00, 0x02, 0x00, 0x00, 0x00, 'o', 'k'};
  Reader reader(bytes);
  EXPECT_THROW(reader.ReadString("s"), CdrError);
}

TEST(CdrReader, RejectsStringLongerThanTheMessage) {
  const Bytes bytes = {0x00, 0x01, 0x00, 0x00, 0xFF, 0xFF, 0xFF, 0xFF, 'o', 'k', 0x00};
  Reader reader(bytes);
  EXPECT_THROW(reader.ReadString("s"), CdrError);
}

TEST(CdrReader, AcceptsZeroLengthAsEmptyString) {
  // Not what a conforming writer emits (length 1, a NUL), but seen in the wild.
  const Bytes bytes = {0x00, 0x01, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00};
  Reader reader(bytes);
  EXPECT_EQ(reader.ReadString("s"), "");
}

TEST(CdrReader, RejectsBooleanOtherThanZeroOrOne) {
  const Bytes bytes = {0x00, 0x01, 0x00, 0x00, 0x02};
  Reader reader(bytes);
  EXPECT_THROW(reader.ReadBool("flag"), CdrError);
}

TEST(CdrReader, HugeSequenceCountThrowsBeforeAllocating) {
  // 0xFFFFFFFF doubles would be 32 GiB; the count is checked against the 8 bytes left.
  const Bytes bytes = {0x00, 0x01, 0x00, 0x00, 0xFF, 0xFF, 0xFF, 0xFF,
                       0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0xF0, 0x3F};
  Reader reader(bytes);
  EXPECT_THROW(reader.ReadSequence<double>("d"), CdrError);
}

TEST(CdrReader, SequenceCountIsCheckedAgainstElementSize) {
  // 2 floats claimed, 4 bytes present: enough bytes for the count as bytes, not as floats.
  const Bytes bytes = {0x00, 0x01, 0x00, 0x00, 0x02, 0x00, 0x00, 0x00, 0x00, 0x00, 0x80, 0x3F};
  Reader reader(bytes);
  EXPECT_THROW(reader.ReadSequence<float>("r"), CdrError);
}

TEST(CdrReader, ReadCountUsesTheGivenMinimumElementSize) {
  const Bytes bytes = {0x00, 0x01, 0x00, 0x00, 0x03, 0x00, 0x00, 0x00,
                       0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00};
  EXPECT_EQ(Reader(bytes).ReadCount(1, "n"), 3U);
  EXPECT_THROW(Reader(bytes).ReadCount(4, "n"), CdrError);  // 12 > 8 bytes left
  EXPECT_EQ(Reader(bytes).ReadCount(0, "n"), 3U);           // no bound, no division by zero
}

TEST(CdrReader, ReadCountOfMaxUint32DoesNotOverflow) {
  Bytes bytes = {0x00, 0x01, 0x00, 0x00, 0xFF, 0xFF, 0xFF, 0xFF};
  bytes.resize(64, 0);
  EXPECT_THROW(Reader(bytes).ReadCount(std::numeric_limits<std::size_t>::max() / 2, "n"), CdrError);
}

}  // namespace
}  // namespace littermap::cdr
