// The run bag: write/read round trips, rosbag2 schemas of older ROS 2 releases, split files,
// missing metadata, and the errors a user gets for things that are not bags.

#include <gtest/gtest.h>

#include <fstream>

#include "bag/bag_reader.hpp"
#include "bag/bag_writer.hpp"
#include "core/sqlite_database.hpp"
#include "support/temp_dir.hpp"

namespace littermap::bag {
namespace {

using test::TempDir;

std::vector<std::uint8_t> Payload(std::uint64_t seed, std::size_t size) {
  std::vector<std::uint8_t> bytes(size);
  for (std::size_t i = 0; i < size; ++i) bytes[i] = static_cast<std::uint8_t>(seed * 31 + i);
  return bytes;
}

std::vector<BagMessage> ReadAll(BagReader& reader) {
  std::vector<BagMessage> messages;
  while (auto message = reader.Next()) messages.push_back(std::move(*message));
  return messages;
}

TEST(Bag, RoundTripKeepsBytesAndReadsInTimeOrder) {
  TempDir dir;
  const auto bag = dir / "run";
  {
    BagWriter writer(bag);
    writer.AddTopic("/a", "std_msgs/msg/String", TopicQos::kReliable);
    writer.AddTopic("/b", "sensor_msgs/msg/LaserScan", TopicQos::kSensorData);
    // Written out of time order on purpose: readers must sort by receive time.
    writer.Write("/a", 300, Payload(1, 10));
    writer.Write("/b", 100, Payload(2, 0));
    writer.Write("/a", 200, Payload(3, 5000));
    writer.Write("/b", 200, Payload(4, 7));
    writer.Close();
    EXPECT_EQ(writer.message_count(), 4u);
  }
  EXPECT_TRUE(std::filesystem::exists(bag / "metadata.yaml"));
  EXPECT_TRUE(std::filesystem::exists(bag / "run_0.db3"));
  EXPECT_FALSE(std::filesystem::exists(bag / "run_0.db3-wal")) << "a closed bag is one file";

  BagReader reader(bag);
  EXPECT_FALSE(reader.metadata_rebuilt());
  EXPECT_EQ(reader.info().message_count, 4u);
  EXPECT_EQ(reader.info().starting_time_ns, 100);
  EXPECT_EQ(reader.info().duration_ns, 200);
  EXPECT_EQ(reader.info().schema_version, 4);
  ASSERT_NE(reader.info().FindTopic("/a"), nullptr);
  EXPECT_EQ(reader.info().FindTopic("/a")->message_count, 2u);

  const auto messages = ReadAll(reader);
  ASSERT_EQ(messages.size(), 4u);
  const std::vector<TimestampNs> times = {100, 200, 200, 300};
  for (std::size_t i = 0; i < times.size(); ++i) EXPECT_EQ(messages[i].timestamp_ns, times[i]);
  // Equal stamps keep write order: /a@200 was written before /b@200.
  EXPECT_EQ(messages[1].topic->name, "/a");
  EXPECT_EQ(messages[1].data, Payload(3, 5000));
  EXPECT_EQ(messages[1].index, 0u);
  EXPECT_EQ(messages[3].index, 1u);
  EXPECT_TRUE(messages[0].data.empty());
}

TEST(Bag, MetadataYamlIsRosbag2Layout) {
  TempDir dir;
  {
    BagWriter writer(dir / "bag");
    writer.AddTopic("/tf_static", "tf2_msgs/msg/TFMessage", TopicQos::kLatched);
    writer.Write("/tf_static", 5'000'000'000, Payload(0, 3));
  }
  const BagInfo info = ReadMetadataYaml(dir / "bag" / "metadata.yaml");
  EXPECT_EQ(info.version, 8);
  EXPECT_EQ(info.storage_identifier, "sqlite3");
  EXPECT_EQ(info.starting_time_ns, 5'000'000'000);
  EXPECT_EQ(info.message_count, 1u);
  ASSERT_EQ(info.topics.size(), 1u);
  EXPECT_EQ(info.topics[0].type, "tf2_msgs/msg/TFMessage");
  EXPECT_NE(info.topics[0].offered_qos_profiles.find("durability: 1"), std::string::npos)
      << "/tf_static must be offered transient-local so players latch it";
  ASSERT_EQ(info.files.size(), 1u);
  EXPECT_EQ(info.files[0].relative_path, "bag_0.db3");
}

TEST(Bag, TopicFilterRestartsAndSelects) {
  TempDir dir;
  {
    BagWriter writer(dir / "bag");
    writer.AddTopic("/a", "x/msg/A", TopicQos::kReliable);
    writer.AddTopic("/b", "x/msg/B", TopicQos::kReliable);
    for (int i = 0; i < 10; ++i) writer.Write(i % 2 ? "/a" : "/b", i, Payload(i, 4));
  }
  BagReader reader(dir / "bag");
  ASSERT_TRUE(reader.Next().has_value());
  reader.SetTopicFilter({"/a"});
  const auto messages = ReadAll(reader);
  ASSERT_EQ(messages.size(), 5u);
  for (const auto& message : messages) EXPECT_EQ(message.topic->name, "/a");
  EXPECT_EQ(messages.front().timestamp_ns, 1);
}

TEST(Bag, MissingMetadataIsRebuiltFromTheDatabase) {
  TempDir dir;
  {
    BagWriter writer(dir / "bag");
    writer.AddTopic("/a", "x/msg/A", TopicQos::kReliable);
    for (int i = 0; i < 7; ++i) writer.Write("/a", 1000 + i, Payload(i, 4));
  }
  std::filesystem::remove(dir / "bag" / "metadata.yaml");
  BagReader reader(dir / "bag");
  EXPECT_TRUE(reader.metadata_rebuilt());
  EXPECT_EQ(reader.info().message_count, 7u);
  EXPECT_EQ(reader.info().duration_ns, 6);
  EXPECT_EQ(ReadAll(reader).size(), 7u);
  // A .db3 given directly opens too.
  BagReader direct(dir / "bag" / "bag_0.db3");
  EXPECT_EQ(direct.info().message_count, 7u);
}

// Hand-made databases with the table layouts earlier ROS 2 releases wrote.
void MakeLegacyBag(const std::filesystem::path& file, const std::string& schema_sql,
                   const std::string& topic_insert) {
  SqliteDatabase db(file, SqliteDatabase::Mode::kCreate);
  db.Execute(schema_sql);
  db.Execute(topic_insert);
  auto insert = db.Prepare("INSERT INTO messages (topic_id, timestamp, data) VALUES (1, ?, ?)");
  for (int i = 0; i < 3; ++i) {
    insert.Bind(1, std::int64_t{10 + i});
    const auto payload = Payload(i, 8);
    insert.BindBlob(2, payload);
    insert.Run();
  }
}

constexpr const char* kMessagesTable =
    "CREATE TABLE messages(id INTEGER PRIMARY KEY, topic_id INTEGER NOT NULL, "
    "timestamp INTEGER NOT NULL, data BLOB NOT NULL);";

TEST(Bag, ReadsDashingEloquentSchema) {
  TempDir dir;
  std::filesystem::create_directories(dir / "bag");
  MakeLegacyBag(dir / "bag" / "bag_0.db3",
                std::string("CREATE TABLE topics(id INTEGER PRIMARY KEY, name TEXT NOT NULL, "
                            "type TEXT NOT NULL, serialization_format TEXT NOT NULL);") +
                    kMessagesTable,
                "INSERT INTO topics VALUES (1, '/chatter', 'std_msgs/msg/String', 'cdr')");
  BagReader reader(dir / "bag");
  EXPECT_EQ(reader.info().schema_version, 0);
  EXPECT_EQ(reader.info().message_count, 3u);
  EXPECT_EQ(ReadAll(reader).back().data, Payload(2, 8));
}

TEST(Bag, ReadsFoxyGalacticSchema) {
  TempDir dir;
  std::filesystem::create_directories(dir / "bag");
  MakeLegacyBag(dir / "bag" / "bag_0.db3",
                std::string("CREATE TABLE topics(id INTEGER PRIMARY KEY, name TEXT NOT NULL, "
                            "type TEXT NOT NULL, serialization_format TEXT NOT NULL, "
                            "offered_qos_profiles TEXT NOT NULL);") +
                    kMessagesTable,
                "INSERT INTO topics VALUES (1, '/chatter', 'std_msgs/msg/String', 'cdr', '')");
  BagReader reader(dir / "bag");
  EXPECT_EQ(reader.info().topics.at(0).name, "/chatter");
  EXPECT_EQ(ReadAll(reader).size(), 3u);
}

TEST(Bag, ReadsHumbleSchema) {
  TempDir dir;
  std::filesystem::create_directories(dir / "bag");
  MakeLegacyBag(dir / "bag" / "bag_0.db3",
                std::string("CREATE TABLE schema(schema_version INTEGER PRIMARY KEY, "
                            "ros_distro TEXT NOT NULL); INSERT INTO schema VALUES (3, 'humble');"
                            "CREATE TABLE metadata(id INTEGER PRIMARY KEY, metadata_version "
                            "INTEGER NOT NULL, metadata TEXT NOT NULL);"
                            "CREATE TABLE topics(id INTEGER PRIMARY KEY, name TEXT NOT NULL, "
                            "type TEXT NOT NULL, serialization_format TEXT NOT NULL, "
                            "offered_qos_profiles TEXT NOT NULL);") +
                    kMessagesTable,
                "INSERT INTO topics VALUES (1, '/chatter', 'std_msgs/msg/String', 'cdr', '')");
  BagReader reader(dir / "bag");
  EXPECT_EQ(reader.info().schema_version, 3);
  EXPECT_EQ(ReadAll(reader).size(), 3u);
}

TEST(Bag, MergesSplitFilesInTimeOrder) {
  TempDir dir;
  std::filesystem::create_directories(dir / "bag");
  for (int part = 0; part < 2; ++part) {
    SqliteDatabase db(dir / "bag" / ("bag_" + std::to_string(part) + ".db3"),
                      SqliteDatabase::Mode::kCreate);
    db.Execute(std::string("CREATE TABLE topics(id INTEGER PRIMARY KEY, name TEXT NOT NULL, "
                           "type TEXT NOT NULL, serialization_format TEXT NOT NULL);") +
               kMessagesTable);
    // The same topic under different ids in the two files.
    db.Execute("INSERT INTO topics VALUES (" + std::to_string(part + 5) +
               ", '/a', 'x/msg/A', 'cdr')");
    for (int i = 0; i < 4; ++i) {
      db.Execute("INSERT INTO messages (topic_id, timestamp, data) VALUES (" +
                 std::to_string(part + 5) + ", " + std::to_string(2 * i + part) + ", x'00')");
    }
  }
  BagReader reader(dir / "bag");
  EXPECT_EQ(reader.info().files.size(), 2u);
  const auto messages = ReadAll(reader);
  ASSERT_EQ(messages.size(), 8u);
  for (std::size_t i = 0; i < messages.size(); ++i) {
    EXPECT_EQ(messages[i].timestamp_ns, static_cast<TimestampNs>(i));
    EXPECT_EQ(messages[i].index, i);
  }
}

void ExpectBadInput(const std::filesystem::path& path, const std::string& fragment) {
  try {
    BagReader reader(path);
    FAIL() << "opened " << path;
  } catch (const BadInputError& e) {
    EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
  }
}

TEST(Bag, ErrorsNameTheFileAndTheProblem) {
  TempDir dir;
  ExpectBadInput(dir / "nothing-here", "no such bag directory");

  std::filesystem::create_directories(dir / "empty");
  ExpectBadInput(dir / "empty", "no .db3 or .mcap file");

  std::filesystem::create_directories(dir / "garbage");
  std::ofstream(dir / "garbage" / "x.db3") << std::string(5000, 'x');
  ExpectBadInput(dir / "garbage", "x.db3");

  std::filesystem::create_directories(dir / "other");
  {
    SqliteDatabase db(dir / "other" / "y.db3", SqliteDatabase::Mode::kCreate);
    db.Execute("CREATE TABLE t(a)");
  }
  ExpectBadInput(dir / "other", "not a ROS 2 bag");

  std::filesystem::create_directories(dir / "yaml");
  std::ofstream(dir / "yaml" / "metadata.yaml") << "rosbag2_bagfile_information: [oops";
  ExpectBadInput(dir / "yaml", "metadata.yaml");
}

TEST(Bag, WriterRefusesMisuse) {
  TempDir dir;
  std::filesystem::create_directories(dir / "used");
  std::ofstream(dir / "used" / "file") << "keep me";
  EXPECT_THROW(BagWriter(dir / "used"), UsageError);
  EXPECT_TRUE(std::filesystem::exists(dir / "used" / "file"));

  BagWriter writer(dir / "bag");
  EXPECT_THROW(writer.Write("/nope", 0, Payload(0, 1)), UsageError);
  writer.AddTopic("/a", "x/msg/A", TopicQos::kReliable);
  writer.AddTopic("/a", "x/msg/A", TopicQos::kReliable);  // idempotent
  EXPECT_THROW(writer.AddTopic("/a", "x/msg/B", TopicQos::kReliable), UsageError);
}

}  // namespace
}  // namespace littermap::bag
