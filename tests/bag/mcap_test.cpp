// MCAP storage: round trips through every compression, the summary and the linear scan agree,
// cut-off and damaged files read up to the damage with a warning naming file and offset, and
// files laid out differently from littermap's own (messages outside chunks, overlapping chunks,
// channels inside chunks) read in log-time order.

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <limits>

#include "bag/bag_reader.hpp"
#include "bag/bag_writer.hpp"
#include "bag/mcap_compression.hpp"
#include "bag/mcap_records.hpp"
#include "support/expect_bad_input.hpp"
#include "support/file_size_limit.hpp"
#include "support/temp_dir.hpp"

namespace littermap::bag {
namespace {

using test::TempDir;

std::vector<std::uint8_t> RunsPayload(std::uint64_t seed, std::size_t size) {
  std::vector<std::uint8_t> bytes(size);
  for (std::size_t i = 0; i < size; ++i) bytes[i] = static_cast<std::uint8_t>(seed * 31 + i / 7);
  return bytes;
}

struct Written {
  std::string topic;
  TimestampNs time;
  std::vector<std::uint8_t> data;
};

// 300 messages on three topics, slightly out of order, in chunks of ~8 KiB.
std::vector<Written> WriteBag(const std::filesystem::path& bag, McapCompression compression,
                              std::uint64_t chunk_bytes = 8192) {
  BagWriterOptions options;
  options.storage = "mcap";
  options.mcap.compression = compression;
  options.mcap.chunk_size_bytes = chunk_bytes;
  BagWriter writer(bag, options);
  writer.AddTopic("/scan", "test_msgs/msg/Blob", TopicQos::kSensorData, "uint8[] data");
  writer.AddTopic("/odom", "test_msgs/msg/Pose", TopicQos::kReliable);
  writer.AddTopic("/scan2", "test_msgs/msg/Blob", TopicQos::kSensorData, "uint8[] data");
  std::vector<Written> written;
  for (std::uint64_t i = 0; i < 300; ++i) {
    const std::string topic = i % 3 == 0 ? "/scan" : i % 3 == 1 ? "/odom" : "/scan2";
    const TimestampNs time =
        1'000'000'000 + static_cast<TimestampNs>(i / 2 * 2) * 1000 + (i % 2 ? -500 : 0);
    written.push_back({topic, time, RunsPayload(i, 40 + i % 200)});
    writer.Write(topic, time, written.back().data);
  }
  writer.Close();
  std::stable_sort(written.begin(), written.end(),
                   [](const Written& a, const Written& b) { return a.time < b.time; });
  return written;
}

void ExpectSameMessages(BagReader& reader, const std::vector<Written>& expected) {
  std::size_t i = 0;
  while (auto message = reader.Next()) {
    ASSERT_LT(i, expected.size());
    EXPECT_EQ(message->topic->name, expected[i].topic) << i;
    EXPECT_EQ(message->timestamp_ns, expected[i].time) << i;
    EXPECT_EQ(message->data, expected[i].data) << i;
    ++i;
  }
  EXPECT_EQ(i, expected.size());
}

std::filesystem::path OnlyFile(const std::filesystem::path& bag) {
  return bag / (bag.filename().string() + "_0.mcap");
}

std::vector<std::uint8_t> ReadFile(const std::filesystem::path& file) {
  std::vector<std::uint8_t> bytes(std::filesystem::file_size(file));
  std::ifstream(file, std::ios::binary).read(reinterpret_cast<char*>(bytes.data()), bytes.size());
  return bytes;
}

void WriteFile(const std::filesystem::path& file, const std::vector<std::uint8_t>& bytes) {
  std::ofstream(file, std::ios::binary | std::ios::trunc)
      .write(reinterpret_cast<const char*>(bytes.data()),
             static_cast<std::streamsize>(bytes.size()));
}

// Offsets of the top-level records with this opcode, walking the file record by record.
std::vector<std::size_t> RecordOffsets(const std::vector<std::uint8_t>& bytes,
                                       mcap::Opcode opcode) {
  std::vector<std::size_t> offsets;
  for (std::size_t at = mcap::kMagic.size(); at + mcap::kRecordPrefixBytes <= bytes.size();) {
    std::uint64_t length = 0;
    for (int b = 7; b >= 0; --b) length = length << 8 | bytes[at + 1 + b];
    if (bytes[at] == static_cast<std::uint8_t>(opcode)) offsets.push_back(at);
    if (bytes[at] == static_cast<std::uint8_t>(mcap::Opcode::kFooter)) break;
    at += mcap::kRecordPrefixBytes + length;
  }
  return offsets;
}

class McapRoundTrip : public ::testing::TestWithParam<McapCompression> {};

TEST_P(McapRoundTrip, KeepsMessagesTopicsAndOrder) {
  TempDir dir;
  const auto expected = WriteBag(dir / "run", GetParam());
  BagReader reader(dir / "run");
  EXPECT_FALSE(reader.metadata_rebuilt());
  EXPECT_TRUE(reader.warnings().empty());
  EXPECT_EQ(reader.info().storage_identifier, "mcap");
  EXPECT_EQ(reader.info().message_count, 300u);
  EXPECT_EQ(reader.info().starting_time_ns, expected.front().time);
  EXPECT_EQ(reader.info().duration_ns, expected.back().time - expected.front().time);
  const TopicInfo* scan = reader.info().FindTopic("/scan");
  ASSERT_NE(scan, nullptr);
  EXPECT_EQ(scan->type, "test_msgs/msg/Blob");
  EXPECT_EQ(scan->message_count, 100u);
  EXPECT_EQ(scan->message_definition, "uint8[] data");
  EXPECT_NE(scan->offered_qos_profiles.find("reliability: 2"), std::string::npos);
  ExpectSameMessages(reader, expected);
  EXPECT_TRUE(reader.warnings().empty());

  reader.SetTopicFilter({"/odom"});
  std::vector<Written> odom;
  for (const auto& w : expected) {
    if (w.topic == "/odom") odom.push_back(w);
  }
  ExpectSameMessages(reader, odom);
}

INSTANTIATE_TEST_SUITE_P(Compressions, McapRoundTrip,
                         ::testing::Values(McapCompression::kNone, McapCompression::kZstd,
                                           McapCompression::kLz4));

TEST(Mcap, WithoutSummaryOrMetadataTheScanReadsTheSame) {
  TempDir dir;
  const auto expected = WriteBag(dir / "run", McapCompression::kZstd);
  std::filesystem::remove(dir / "run" / "metadata.yaml");
  // Cut the summary, summary offsets and footer: the file ends after the data section.
  const auto file = OnlyFile(dir / "run");
  const auto data_end = RecordOffsets(ReadFile(file), mcap::Opcode::kDataEnd);
  ASSERT_EQ(data_end.size(), 1u);
  std::filesystem::resize_file(file, data_end[0] + mcap::kRecordPrefixBytes + 4);

  BagReader reader(dir / "run");
  EXPECT_TRUE(reader.metadata_rebuilt());
  EXPECT_EQ(reader.info().storage_identifier, "mcap");
  EXPECT_EQ(reader.info().message_count, 300u);
  ASSERT_NE(reader.info().FindTopic("/odom"), nullptr);
  EXPECT_EQ(reader.info().FindTopic("/odom")->message_count, 100u);
  ExpectSameMessages(reader, expected);
}

// A recording split into two files, as rosbag2 splits one (bag_0.mcap, bag_1.mcap), with and
// without its metadata.yaml: read as one bag, in time order.
TEST(Mcap, SplitFilesReadAsOneBag) {
  TempDir dir;
  // The two files hold messages of the same times: the merge interleaves them.
  WriteBag(dir / "a", McapCompression::kZstd);
  WriteBag(dir / "b", McapCompression::kLz4);
  std::filesystem::create_directories(dir / "bag");
  std::filesystem::rename(OnlyFile(dir / "a"), dir / "bag" / "bag_0.mcap");
  std::filesystem::rename(OnlyFile(dir / "b"), dir / "bag" / "bag_1.mcap");
  {
    BagReader reader(dir / "bag");
    ASSERT_EQ(reader.info().files.size(), 2u);
    EXPECT_EQ(reader.info().message_count, 600u);
    EXPECT_TRUE(reader.metadata_rebuilt());
    std::uint64_t read = 0;
    TimestampNs last = 0;
    while (auto message = reader.Next()) {
      EXPECT_GE(message->timestamp_ns, last);
      last = message->timestamp_ns;
      ++read;
    }
    EXPECT_EQ(read, 600u);
  }
  BagReader reader(dir / "bag");
  WriteMetadataYaml(dir / "bag" / "metadata.yaml", reader.info());
  BagReader with_metadata(dir / "bag");
  EXPECT_FALSE(with_metadata.metadata_rebuilt());
  EXPECT_EQ(with_metadata.info().files.size(), 2u);
  EXPECT_EQ(with_metadata.info().message_count, 600u);
}

TEST(Mcap, CutOffFileReadsUpToTheCutWithAWarning) {
  TempDir dir;
  const auto expected = WriteBag(dir / "run", McapCompression::kLz4);
  std::filesystem::remove(dir / "run" / "metadata.yaml");
  const auto file = OnlyFile(dir / "run");
  std::filesystem::resize_file(file, std::filesystem::file_size(file) * 2 / 3);
  BagReader reader(dir / "run");
  ASSERT_FALSE(reader.warnings().empty());
  EXPECT_NE(reader.warnings()[0].find("run_0.mcap: offset "), std::string::npos)
      << reader.warnings()[0];
  EXPECT_NE(reader.warnings()[0].find("cut off"), std::string::npos) << reader.warnings()[0];
  const std::uint64_t kept = reader.info().message_count;
  EXPECT_GT(kept, 100u);
  EXPECT_LT(kept, 300u);
  std::uint64_t read = 0;
  while (auto message = reader.Next()) ++read;
  EXPECT_EQ(read, kept);
}

// Writes ten commits of 20 messages each, uncompressed (so every run lays the file out alike);
// returns the file's size after each commit.
std::vector<std::uintmax_t> WriteCommits(const std::filesystem::path& bag) {
  BagWriterOptions options;
  options.storage = "mcap";
  options.mcap.compression = McapCompression::kNone;
  BagWriter writer(bag, options);
  writer.AddTopic("/scan", "test_msgs/msg/Blob", TopicQos::kSensorData, "uint8[] data");
  std::vector<std::uintmax_t> sizes;
  for (std::uint64_t i = 0; i < 200; ++i) {
    writer.Write("/scan", 1'000'000'000 + static_cast<TimestampNs>(i) * 1000, RunsPayload(i, 300));
    if (i % 20 == 19) {
      writer.Flush();
      sizes.push_back(std::filesystem::file_size(OnlyFile(bag)));
    }
  }
  writer.Close();
  return sizes;
}

// The disk fills less than the ending's 50 bytes after a commit: the file ends at the commit
// before it and reads whole, with no damage.
TEST(Mcap, ADiskFullJustAfterACommitEndsTheFileAtTheCommitBefore) {
  TempDir dir;
  const std::vector<std::uintmax_t> sizes = WriteCommits(dir / "free");
  ASSERT_EQ(sizes.size(), 10u);
  // A file size limit 20 bytes past the 5th commit: the 6th commit fails.
  const int exit_code = test::RunWithFileSizeLimit(sizes[4] + 20, [&] {
    try {
      WriteCommits(dir / "full");
      return 10;
    } catch (const Error& error) {
      return error.kind() == ErrorKind::kEnvironment ? 0 : 11;
    } catch (...) {
      return 12;
    }
  });
  ASSERT_EQ(exit_code, 0) << "10: no error, 11: not an environment error, 12: another";
  BagReader reader(dir / "full");
  reader.SetVerifyChecksums(true);
  for (const std::string& warning : reader.warnings()) {
    EXPECT_EQ(warning.find("cut off"), std::string::npos) << warning;
  }
  std::uint64_t read = 0;
  while (auto message = reader.Next()) ++read;
  EXPECT_EQ(read, 80u);  // the 4th commit's messages: the 5th's ending did not fit
  EXPECT_EQ(std::filesystem::file_size(OnlyFile(dir / "full")), sizes[3] + 50);
  const std::vector<std::uint8_t> bytes = ReadFile(OnlyFile(dir / "full"));
  ASSERT_GE(bytes.size(), mcap::kMagic.size());
  EXPECT_TRUE(std::equal(mcap::kMagic.begin(), mcap::kMagic.end(),
                         bytes.end() - static_cast<std::ptrdiff_t>(mcap::kMagic.size())))
      << "the file does not end with MCAP's closing magic";
}

TEST(Mcap, DamagedChunkIsSkippedAndNamed) {
  TempDir dir;
  WriteBag(dir / "run", McapCompression::kZstd);
  const auto file = OnlyFile(dir / "run");
  // The second chunk record: flip bytes in the middle of its compressed records.
  auto bytes = ReadFile(file);
  const auto chunks = RecordOffsets(bytes, mcap::Opcode::kChunk);
  ASSERT_GE(chunks.size(), 3u);
  const std::size_t second = chunks[1];
  for (std::size_t i = 0; i < 16; ++i) bytes[second + 80 + i] ^= 0x5A;
  WriteFile(file, bytes);

  BagReader reader(dir / "run");
  std::uint64_t read = 0;
  while (auto message = reader.Next()) ++read;
  EXPECT_GT(read, 200u);
  EXPECT_LT(read, 300u);
  ASSERT_EQ(reader.warnings().size(), 1u);
  EXPECT_NE(reader.warnings()[0].find("run_0.mcap: offset " + std::to_string(second) +
                                      ": chunk is damaged"),
            std::string::npos)
      << reader.warnings()[0];
  EXPECT_EQ(reader.damage(), reader.warnings());

  // Reopened without metadata.yaml (the counts rebuilt from the file), it is still reported once.
  std::filesystem::remove(dir / "run" / "metadata.yaml");
  BagReader again(dir / "run");
  while (again.Next()) {
  }
  EXPECT_EQ(again.damage().size(), 1u);
}

TEST(Mcap, ChecksumsAreCheckedWhenVerifying) {
  TempDir dir;
  WriteBag(dir / "run", McapCompression::kNone);
  const auto file = OnlyFile(dir / "run");
  // Flip one byte of a message inside the first chunk: the records still parse.
  auto bytes = ReadFile(file);
  const auto chunks = RecordOffsets(bytes, mcap::Opcode::kChunk);
  ASSERT_FALSE(chunks.empty());
  // Chunk header: prefix 9 + times 16 + sizes 12 + compression "" 4 + records length 8 = 49;
  // then the first message record: prefix 9 + header 22, then its data.
  bytes[chunks[0] + 49 + 31 + 5] ^= 0x01;
  WriteFile(file, bytes);

  BagReader plain(dir / "run");
  std::uint64_t read = 0;
  while (plain.Next()) ++read;
  EXPECT_EQ(read, 300u) << "without verifying, the damage goes through";
  BagReader verifying(dir / "run");
  verifying.SetVerifyChecksums(true);
  read = 0;
  while (verifying.Next()) ++read;
  EXPECT_LT(read, 300u);
  ASSERT_EQ(verifying.warnings().size(), 1u);
  EXPECT_NE(verifying.warnings()[0].find("fail their CRC"), std::string::npos)
      << verifying.warnings()[0];
}

// A file as another writer may lay it out: a channel defined inside a chunk, two chunks whose
// times overlap, a message outside any chunk, a chunk compressed with an unknown codec, and no
// summary.
TEST(Mcap, ReadsOtherLayoutsInLogTimeOrder) {
  TempDir dir;
  std::filesystem::create_directories(dir / "other");
  std::vector<std::uint8_t> out(mcap::kMagic.begin(), mcap::kMagic.end());
  std::vector<std::uint8_t> header;
  mcap::FieldWriter(header).String("ros2");
  mcap::FieldWriter(header).String("test");
  mcap::AppendRecord(out, mcap::Opcode::kHeader, header);
  mcap::AppendRecord(out, mcap::Opcode::kSchema,
                     mcap::SchemaContent({1, "std_msgs/msg/String", "ros2msg", "string data"}));
  auto message = [](std::uint16_t channel, std::uint64_t time) {
    mcap::Message m;
    m.channel_id = channel;
    m.log_time = m.publish_time = time;
    auto content = mcap::MessageContentHead(m);
    content.push_back(static_cast<std::uint8_t>(time));
    return content;
  };
  auto chunk = [&](const std::vector<std::uint8_t>& records, const std::string& compression) {
    std::vector<std::uint8_t> content;
    mcap::FieldWriter writer(content);
    writer.U64(0);
    writer.U64(0);
    writer.U64(records.size());
    writer.U32(0);
    writer.String(compression);
    const auto packed = compression == "bogus"
                            ? records
                            : CompressChunk(records, ParseMcapCompression(compression));
    writer.U64(packed.size());
    writer.Bytes(packed);
    mcap::AppendRecord(out, mcap::Opcode::kChunk, content);
  };
  std::vector<std::uint8_t> first;
  mcap::AppendRecord(first, mcap::Opcode::kChannel,
                     mcap::ChannelContent({3, 1, "/chatter", "cdr", {}}));
  for (std::uint64_t t : {10, 30, 50})
    mcap::AppendRecord(first, mcap::Opcode::kMessage, message(3, t));
  chunk(first, "lz4");
  std::vector<std::uint8_t> second;
  for (std::uint64_t t : {20, 40, 60})
    mcap::AppendRecord(second, mcap::Opcode::kMessage, message(3, t));
  chunk(second, "zstd");
  mcap::AppendRecord(out, mcap::Opcode::kMessage, message(3, 35));
  std::vector<std::uint8_t> third;
  mcap::AppendRecord(third, mcap::Opcode::kMessage, message(3, 70));
  const std::size_t bogus_offset = out.size();
  chunk(third, "bogus");
  mcap::AppendRecord(out, mcap::Opcode::kDataEnd, std::vector<std::uint8_t>(4, 0));
  WriteFile(dir / "other" / "x.mcap", out);

  BagReader reader(dir / "other");
  ASSERT_EQ(reader.info().topics.size(), 1u);
  EXPECT_EQ(reader.info().topics[0].type, "std_msgs/msg/String");
  EXPECT_EQ(reader.info().message_count, 7u);
  std::vector<TimestampNs> times;
  while (auto m = reader.Next()) times.push_back(m->timestamp_ns);
  EXPECT_EQ(times, (std::vector<TimestampNs>{10, 20, 30, 35, 40, 50, 60}));
  ASSERT_FALSE(reader.warnings().empty());
  EXPECT_NE(reader.warnings()[0].find("offset " + std::to_string(bogus_offset)), std::string::npos)
      << reader.warnings()[0];
  EXPECT_NE(reader.warnings()[0].find("'bogus'"), std::string::npos) << reader.warnings()[0];
}

TEST(Mcap, ErrorsNameTheFile) {
  TempDir dir;
  std::filesystem::create_directories(dir / "bad");
  std::ofstream(dir / "bad" / "x.mcap") << "not an mcap file at all";
  test::ExpectBadInput([&] { BagReader reader(dir / "bad"); }, "x.mcap");

  WriteBag(dir / "odd", McapCompression::kNone);
  std::string yaml;
  {
    std::ifstream in(dir / "odd" / "metadata.yaml");
    yaml.assign(std::istreambuf_iterator<char>(in), {});
  }
  const auto at = yaml.find("storage_identifier: mcap");
  ASSERT_NE(at, std::string::npos) << yaml;
  yaml.replace(at, 24, "storage_identifier: rocksdb");
  std::ofstream(dir / "odd" / "metadata.yaml") << yaml;
  test::ExpectBadInput([&] { BagReader reader(dir / "odd"); }, "storage 'rocksdb'");

  BagWriterOptions options;
  options.storage = "parquet";
  EXPECT_THROW(BagWriter(dir / "new", options), UsageError);
}

// Found by fuzzing: stamps at both ends of the 64-bit range, whose span the reader computed
// with a signed overflow.
TEST(Mcap, StampsTooFarApartAreBadInput) {
  TempDir dir;
  for (const std::string storage : {"mcap", "sqlite3"}) {
    BagWriterOptions options;
    options.storage = storage;
    BagWriter writer(dir / storage, options);
    writer.AddTopic("/notes", "std_msgs/msg/String", TopicQos::kReliable);
    const std::vector<std::uint8_t> note = {0, 1, 0, 0, 1, 0, 0, 0, 0};
    writer.Write("/notes", std::numeric_limits<TimestampNs>::min() + 1000, note);
    writer.Write("/notes", 1040, note);
    writer.Close();
    test::ExpectBadInput([&] { BagReader reader(dir / storage); },
                         "lie further apart than 64-bit nanoseconds reach");
  }
}

TEST(McapCompression, RefusesHostileSizes) {
  const auto packed = CompressChunk(RunsPayload(1, 1000), McapCompression::kZstd);
  test::ExpectBadInput([&] { DecompressChunk(packed, "zstd", 1ull << 40); }, "512 MiB");
  // A size under the limit but far beyond the data costs nothing until the data is there.
  test::ExpectBadInput([&] { DecompressChunk(packed, "zstd", 400ull << 20); }, "cut short");
  test::ExpectBadInput([&] { DecompressChunk(packed, "zstd", 10); }, "more than the 10");
  const auto lz4 = CompressChunk(RunsPayload(1, 1000), McapCompression::kLz4);
  test::ExpectBadInput([&] { DecompressChunk(lz4, "lz4", 400ull << 20); }, "cut short");
  test::ExpectBadInput([&] { DecompressChunk(lz4, "brotli", 1000); }, "'brotli'");
  const ByteBuffer unpacked = DecompressChunk(lz4, "lz4", 1000);
  EXPECT_TRUE(std::ranges::equal(unpacked.span(), RunsPayload(1, 1000)));
}

}  // namespace
}  // namespace littermap::bag
