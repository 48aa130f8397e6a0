// rosbag2's sqlite3 storage: a .db3 written by littermap or by any ROS 2 release since Foxy
// (older schemas lack the schema/metadata/message_definitions tables and some topic columns).

#include <algorithm>
#include <map>

#include "bag/bag_schema.hpp"
#include "bag/storage_file.hpp"
#include "core/error.hpp"
#include "core/sqlite_database.hpp"

namespace littermap::bag {
namespace {

// Opens a .db3 and checks it is a rosbag2 database; errors are the user's file's fault.
std::unique_ptr<SqliteDatabase> OpenDatabase(const std::filesystem::path& file) {
  try {
    // Read-write when allowed, so a WAL left by a crashed recorder is recovered (checkpointed)
    // instead of failing; read-only media fall back to a read-only connection.
    std::unique_ptr<SqliteDatabase> database;
    try {
      database = std::make_unique<SqliteDatabase>(file, SqliteDatabase::Mode::kReadWrite);
      database->Execute("SELECT 1 FROM sqlite_master LIMIT 1");
    } catch (const SqliteError& e) {
      if (e.code() != 8 /* SQLITE_READONLY */ && e.code() != 14 /* SQLITE_CANTOPEN */) throw;
      database = std::make_unique<SqliteDatabase>(file, SqliteDatabase::Mode::kReadOnly);
    }
    if (!database->HasTable("messages") || !database->HasTable("topics")) {
      throw BadInputError(file.string() +
                          ": a SQLite database but not a ROS 2 bag (no 'topics'/'messages' table)");
    }
    return database;
  } catch (const SqliteError& e) {
    throw BadInputError(file.string() + ": not a readable ROS 2 bag database (" + e.what() + ")");
  }
}

class SqliteStorageReader : public StorageFileReader {
 public:
  explicit SqliteStorageReader(const std::filesystem::path& file) : database_(OpenDatabase(file)) {
    ReadTopics();
  }

  std::vector<StoredTopic> Topics() const override { return topics_; }

  std::vector<TopicCount> Counts() override {
    auto query = database_->Prepare(
        "SELECT topic_id, COUNT(*), MIN(timestamp), MAX(timestamp) FROM messages GROUP BY "
        "topic_id");
    std::vector<TopicCount> counts;
    while (query.Step()) {
      const std::int64_t id = query.ColumnInt64(0);
      if (std::none_of(topics_.begin(), topics_.end(),
                       [&](const StoredTopic& t) { return t.id == id; })) {
        throw BadInputError(database_->file().string() + ": messages refer to topic id " +
                            std::to_string(id) + ", which is not in 'topics'");
      }
      counts.push_back({id, static_cast<std::uint64_t>(query.ColumnInt64(1)), query.ColumnInt64(2),
                        query.ColumnInt64(3)});
    }
    return counts;
  }

  int SchemaVersion() const override {
    if (!database_->HasTable("schema")) return 0;
    auto query = database_->Prepare("SELECT MAX(schema_version) FROM schema");
    return query.Step() ? static_cast<int>(query.ColumnInt64(0)) : 0;
  }

  void Start(const std::vector<std::int64_t>& topic_ids) override {
    std::string sql = "SELECT topic_id, timestamp, data FROM messages";
    if (!topic_ids.empty()) {
      sql += " WHERE topic_id IN (";
      for (std::size_t i = 0; i < topic_ids.size(); ++i) {
        sql += (i ? ", " : "") + std::to_string(topic_ids[i]);
      }
      sql += ")";
    }
    sql += " ORDER BY timestamp, id";
    cursor_.reset();
    cursor_.emplace(database_->Prepare(sql));
    Advance();
  }

  std::optional<TimestampNs> PeekTime() override {
    if (!has_row_) return std::nullopt;
    return cursor_->ColumnInt64(1);
  }

  StoredMessage Take() override {
    StoredMessage message;
    message.topic_id = cursor_->ColumnInt64(0);
    message.timestamp_ns = cursor_->ColumnInt64(1);
    const auto blob = cursor_->ColumnBlob(2);
    message.data.assign(blob.begin(), blob.end());
    Advance();
    return message;
  }

 private:
  void ReadTopics() {
    const bool has_qos = database_->HasColumn("topics", "offered_qos_profiles");
    const bool has_hash = database_->HasColumn("topics", "type_description_hash");
    const bool has_definitions = database_->HasTable("message_definitions");
    auto query = database_->Prepare(
        std::string("SELECT id, name, type, serialization_format, ") +
        (has_qos ? "offered_qos_profiles" : "''") + ", " +
        (has_hash ? "type_description_hash" : "''") + ", " +
        (has_definitions ? "(SELECT encoded_message_definition FROM message_definitions d "
                           "WHERE d.topic_type = topics.type LIMIT 1)"
                         : "''") +
        " FROM topics ORDER BY id");
    while (query.Step()) {
      StoredTopic topic;
      topic.id = query.ColumnInt64(0);
      topic.info.name = query.ColumnText(1);
      topic.info.type = query.ColumnText(2);
      topic.info.serialization_format = query.ColumnText(3);
      topic.info.offered_qos_profiles = query.ColumnText(4);
      topic.info.type_description_hash = query.ColumnText(5);
      topic.info.message_definition = query.ColumnText(6);
      topics_.push_back(std::move(topic));
    }
  }

  void Advance() {
    try {
      has_row_ = cursor_->Step();
    } catch (const SqliteError& e) {
      throw BadInputError(database_->file().string() + ": database is damaged: " + e.what());
    }
  }

  std::unique_ptr<SqliteDatabase> database_;
  std::vector<StoredTopic> topics_;
  std::optional<SqliteStatement> cursor_;
  bool has_row_ = false;
};

class SqliteStorageWriter : public StorageFileWriter {
 public:
  SqliteStorageWriter(const std::filesystem::path& file, const std::string& ros_distro)
      : database_(file, SqliteDatabase::Mode::kCreate) {
    // WAL + synchronous=FULL: every commit is on disk when it returns, and a reader sees a
    // consistent database whatever moment the process dies.
    database_.Execute("PRAGMA journal_mode=WAL; PRAGMA synchronous=FULL;");
    database_.Execute(bag_schema::kCreateTables);
    auto schema =
        database_.Prepare("INSERT INTO schema (schema_version, ros_distro) VALUES (?, ?)");
    schema.Bind(1, std::int64_t{bag_schema::kSchemaVersion});
    schema.Bind(2, ros_distro);
    schema.Run();
    insert_.emplace(
        database_.Prepare("INSERT INTO messages (timestamp, topic_id, data) VALUES (?, ?, ?)"));
  }

  std::int64_t AddTopic(const TopicInfo& topic) override {
    auto insert = database_.Prepare(
        "INSERT INTO topics (name, type, serialization_format, offered_qos_profiles, "
        "type_description_hash) VALUES (?, ?, ?, ?, ?)");
    insert.Bind(1, topic.name);
    insert.Bind(2, topic.type);
    insert.Bind(3, topic.serialization_format);
    insert.Bind(4, topic.offered_qos_profiles);
    insert.Bind(5, topic.type_description_hash);
    insert.Run();
    const std::int64_t id = database_.LastInsertId();
    auto known = database_.Prepare("SELECT 1 FROM message_definitions WHERE topic_type = ?");
    known.Bind(1, topic.type);
    if (!topic.message_definition.empty() && !known.Step()) {
      auto definition = database_.Prepare(
          "INSERT INTO message_definitions (topic_type, encoding, encoded_message_definition, "
          "type_description_hash) VALUES (?, 'ros2msg', ?, ?)");
      definition.Bind(1, topic.type);
      definition.Bind(2, topic.message_definition);
      definition.Bind(3, topic.type_description_hash);
      definition.Run();
    }
    return id;
  }

  void Write(std::int64_t topic_id, TimestampNs timestamp_ns,
             std::span<const std::uint8_t> serialized) override {
    if (!in_transaction_) {
      database_.Execute("BEGIN");
      in_transaction_ = true;
    }
    insert_->Bind(1, timestamp_ns);
    insert_->Bind(2, topic_id);
    insert_->BindBlob(3, serialized);
    try {
      insert_->Run();
    } catch (...) {
      Abandon();
      throw;
    }
  }

  void Commit() override {
    if (!in_transaction_) return;
    try {
      database_.Execute("COMMIT");
    } catch (...) {
      Abandon();
      throw;
    }
    in_transaction_ = false;
  }

  void Close(const BagInfo& info) override {
    Commit();
    // The metadata row (metadata.yaml holds the same) and the single file (a WAL bag reads as
    // well) are conveniences: on a full disk they are left out, the messages committed stay.
    try {
      auto metadata =
          database_.Prepare("INSERT INTO metadata (metadata_version, metadata) VALUES (?, ?)");
      metadata.Bind(1, std::int64_t{info.version});
      metadata.Bind(2, MetadataYamlText(info));
      metadata.Run();
      // A finished bag is one self-contained file: it then opens read-only from anywhere.
      database_.Execute("PRAGMA journal_mode=DELETE");
    } catch (const Error& e) {
      if (e.kind() != ErrorKind::kEnvironment) throw;
    }
  }

  const std::filesystem::path& file() const override { return database_.file(); }

 private:
  // After a failed insert or commit (the disk full): the open transaction is given up, so the
  // database holds exactly what was committed and the writer can still close it.
  void Abandon() {
    try {
      database_.Execute("ROLLBACK");
    } catch (const Error&) {  // SQLite rolled it back already
    }
    in_transaction_ = false;
  }

  SqliteDatabase database_;
  std::optional<SqliteStatement> insert_;
  bool in_transaction_ = false;
};

}  // namespace

std::unique_ptr<StorageFileWriter> CreateSqliteStorage(const std::filesystem::path& file,
                                                       const std::string& ros_distro) {
  return std::make_unique<SqliteStorageWriter>(file, ros_distro);
}

std::unique_ptr<StorageFileReader> OpenSqliteStorage(const std::filesystem::path& file) {
  return std::make_unique<SqliteStorageReader>(file);
}

}  // namespace littermap::bag
