#include "bag/bag_reader.hpp"

#include <algorithm>
#include <map>

#include "core/sqlite_database.hpp"

namespace littermap::bag {
namespace {

// One .db3 file of the bag, with its topic ids mapped to indices into BagInfo::topics.
struct StorageFile {
  std::unique_ptr<SqliteDatabase> database;
  std::map<std::int64_t, std::size_t> topic_index_by_id;
  std::optional<SqliteStatement> cursor;
  bool has_row = false;
};

// Opens a .db3 and checks it is a rosbag2 database; errors are the user's file's fault.
std::unique_ptr<SqliteDatabase> OpenStorage(const std::filesystem::path& file) {
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

std::vector<std::filesystem::path> FindStorageFiles(const std::filesystem::path& directory) {
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::directory_iterator(directory)) {
    if (entry.path().extension() == ".db3") files.push_back(entry.path());
  }
  // Split bags are NAME_0.db3, NAME_1.db3, ...: order by the number, not the text.
  std::sort(files.begin(), files.end(), [](const auto& a, const auto& b) {
    const auto a_name = a.stem().string(), b_name = b.stem().string();
    return a_name.size() != b_name.size() ? a_name.size() < b_name.size() : a_name < b_name;
  });
  return files;
}

int SchemaVersion(const SqliteDatabase& database) {
  if (!database.HasTable("schema")) return 0;
  auto query = database.Prepare("SELECT MAX(schema_version) FROM schema");
  return query.Step() ? static_cast<int>(query.ColumnInt64(0)) : 0;
}

}  // namespace

struct BagReader::Impl {
  std::filesystem::path directory;
  BagInfo info;
  bool rebuilt = false;
  std::vector<StorageFile> files;
  std::vector<std::string> filter;
  std::vector<std::uint64_t> next_index;  // per topic

  void LocateFiles(const std::filesystem::path& path);
  void ReadTopics(StorageFile& file);
  void CountMessages();
  void StartCursors();
  void Advance(StorageFile& file);
};

void BagReader::Impl::LocateFiles(const std::filesystem::path& path) {
  std::error_code error;
  if (std::filesystem::is_regular_file(path, error)) {
    directory = path.parent_path();
    info.files.push_back({path.filename().string(), 0, 0, 0});
    rebuilt = true;
    return;
  }
  if (!std::filesystem::is_directory(path, error)) {
    throw BadInputError(path.string() + ": no such bag directory");
  }
  directory = path;
  const auto metadata_path = path / "metadata.yaml";
  if (std::filesystem::exists(metadata_path)) {
    const BagInfo recorded = ReadMetadataYaml(metadata_path);
    if (recorded.storage_identifier != "sqlite3") {
      throw BadInputError(metadata_path.string() + ": storage '" + recorded.storage_identifier +
                          "' is not supported (only sqlite3)");
    }
    info = recorded;
    for (const auto& file : info.files) {
      if (!std::filesystem::exists(directory / file.relative_path)) {
        throw BadInputError(metadata_path.string() + ": lists '" + file.relative_path +
                            "', which does not exist");
      }
    }
  }
  if (info.files.empty()) {
    rebuilt = true;
    for (const auto& file : FindStorageFiles(path)) {
      info.files.push_back({file.filename().string(), 0, 0, 0});
    }
  }
  if (info.files.empty()) {
    throw BadInputError(path.string() + ": no .db3 file (not a ROS 2 bag with sqlite3 storage)");
  }
}

void BagReader::Impl::ReadTopics(StorageFile& file) {
  SqliteDatabase& database = *file.database;
  const bool has_qos = database.HasColumn("topics", "offered_qos_profiles");
  const bool has_hash = database.HasColumn("topics", "type_description_hash");
  auto query =
      database.Prepare(std::string("SELECT id, name, type, serialization_format, ") +
                       (has_qos ? "offered_qos_profiles" : "''") + ", " +
                       (has_hash ? "type_description_hash" : "''") + " FROM topics ORDER BY id");
  while (query.Step()) {
    TopicInfo topic;
    topic.name = query.ColumnText(1);
    topic.type = query.ColumnText(2);
    topic.serialization_format = query.ColumnText(3);
    topic.offered_qos_profiles = query.ColumnText(4);
    topic.type_description_hash = query.ColumnText(5);
    auto known = std::find_if(info.topics.begin(), info.topics.end(),
                              [&](const TopicInfo& t) { return t.name == topic.name; });
    if (known == info.topics.end()) {
      info.topics.push_back(topic);
      known = info.topics.end() - 1;
    } else if (known->type != topic.type) {
      throw BadInputError(database.file().string() + ": topic '" + topic.name + "' has type " +
                          topic.type + " here but " + known->type + " elsewhere in the bag");
    }
    file.topic_index_by_id[query.ColumnInt64(0)] =
        static_cast<std::size_t>(known - info.topics.begin());
  }
}

void BagReader::Impl::CountMessages() {
  std::vector<std::uint64_t> recorded_counts;
  for (auto& topic : info.topics) {
    recorded_counts.push_back(topic.message_count);
    topic.message_count = 0;
  }
  const std::uint64_t recorded_total = info.message_count;
  info.message_count = 0;
  bool any = false;
  TimestampNs first = 0, last = 0;
  for (std::size_t i = 0; i < files.size(); ++i) {
    auto query = files[i].database->Prepare(
        "SELECT topic_id, COUNT(*), MIN(timestamp), MAX(timestamp) FROM messages GROUP BY "
        "topic_id");
    BagFileInfo& file_info = info.files[i];
    file_info.message_count = 0;
    TimestampNs file_first = 0, file_last = 0;
    while (query.Step()) {
      auto topic = files[i].topic_index_by_id.find(query.ColumnInt64(0));
      if (topic == files[i].topic_index_by_id.end()) {
        throw BadInputError(files[i].database->file().string() + ": messages refer to topic id " +
                            std::to_string(query.ColumnInt64(0)) + ", which is not in 'topics'");
      }
      const auto count = static_cast<std::uint64_t>(query.ColumnInt64(1));
      const TimestampNs lo = query.ColumnInt64(2), hi = query.ColumnInt64(3);
      info.topics[topic->second].message_count += count;
      file_first = file_info.message_count ? std::min(file_first, lo) : lo;
      file_last = file_info.message_count ? std::max(file_last, hi) : hi;
      file_info.message_count += count;
    }
    file_info.starting_time_ns = file_first;
    file_info.duration_ns = file_last - file_first;
    if (file_info.message_count == 0) continue;
    first = any ? std::min(first, file_first) : file_first;
    last = any ? std::max(last, file_last) : file_last;
    any = true;
    info.message_count += file_info.message_count;
  }
  info.starting_time_ns = first;
  info.duration_ns = last - first;
  for (std::size_t i = 0; i < info.topics.size(); ++i) {
    if (i >= recorded_counts.size() || recorded_counts[i] != info.topics[i].message_count) {
      rebuilt = true;
    }
  }
  if (recorded_total != info.message_count) rebuilt = true;
}

void BagReader::Impl::StartCursors() {
  next_index.assign(info.topics.size(), 0);
  for (auto& file : files) {
    std::string sql = "SELECT topic_id, timestamp, data FROM messages";
    std::vector<std::int64_t> ids;
    for (const auto& [id, index] : file.topic_index_by_id) {
      if (std::find(filter.begin(), filter.end(), info.topics[index].name) != filter.end()) {
        ids.push_back(id);
      }
    }
    if (!filter.empty()) {
      sql += " WHERE topic_id IN (";
      for (std::size_t i = 0; i < ids.size(); ++i) sql += (i ? ", " : "") + std::to_string(ids[i]);
      sql += ")";
    }
    sql += " ORDER BY timestamp, id";
    file.cursor.reset();
    file.cursor.emplace(file.database->Prepare(sql));
    Advance(file);
  }
}

void BagReader::Impl::Advance(StorageFile& file) {
  try {
    file.has_row = file.cursor->Step();
  } catch (const SqliteError& e) {
    throw BadInputError(file.database->file().string() + ": database is damaged: " + e.what());
  }
}

BagReader::BagReader(const std::filesystem::path& path) : impl_(std::make_unique<Impl>()) {
  impl_->LocateFiles(path);
  // Topics and counts always come from the databases; metadata.yaml only names the files.
  std::vector<TopicInfo> recorded = std::move(impl_->info.topics);
  impl_->info.topics.clear();
  int schema = -1;
  for (const auto& file_info : impl_->info.files) {
    StorageFile file;
    file.database = OpenStorage(impl_->directory / file_info.relative_path);
    schema = std::max(schema, SchemaVersion(*file.database));
    impl_->ReadTopics(file);
    impl_->files.push_back(std::move(file));
  }
  impl_->info.schema_version = schema;
  for (auto& topic : impl_->info.topics) {
    auto it = std::find_if(recorded.begin(), recorded.end(),
                           [&](const TopicInfo& t) { return t.name == topic.name; });
    topic.message_count = it == recorded.end() ? 0 : it->message_count;
  }
  if (recorded.size() != impl_->info.topics.size()) impl_->rebuilt = true;
  impl_->CountMessages();
  impl_->StartCursors();
}

BagReader::~BagReader() = default;

const BagInfo& BagReader::info() const { return impl_->info; }

bool BagReader::metadata_rebuilt() const { return impl_->rebuilt; }

const std::filesystem::path& BagReader::directory() const { return impl_->directory; }

const TopicInfo& BagReader::RequireTopic(const std::string& name, const std::string& role) const {
  const TopicInfo* topic = impl_->info.FindTopic(name);
  if (topic == nullptr) {
    throw BadInputError(impl_->directory.string() + ": no " + role + " topic " + name);
  }
  return *topic;
}

void BagReader::SetTopicFilter(const std::vector<std::string>& topics) {
  impl_->filter = topics;
  impl_->StartCursors();
}

std::optional<BagMessage> BagReader::Next() {
  StorageFile* best = nullptr;
  TimestampNs best_time = 0;
  for (auto& file : impl_->files) {
    if (!file.has_row) continue;
    const TimestampNs time = file.cursor->ColumnInt64(1);
    if (best == nullptr || time < best_time) {
      best = &file;
      best_time = time;
    }
  }
  if (best == nullptr) return std::nullopt;
  BagMessage message;
  const std::size_t topic = best->topic_index_by_id.at(best->cursor->ColumnInt64(0));
  message.topic = &impl_->info.topics[topic];
  message.timestamp_ns = best_time;
  message.index = impl_->next_index[topic]++;
  const auto blob = best->cursor->ColumnBlob(2);
  message.data.assign(blob.begin(), blob.end());
  impl_->Advance(*best);
  return message;
}

}  // namespace littermap::bag
