#include "bag/bag_writer.hpp"

#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <map>
#include <mutex>
#include <optional>
#include <thread>

#include "bag/bag_schema.hpp"
#include "core/sqlite_database.hpp"

namespace littermap::bag {
namespace {

using Clock = std::chrono::steady_clock;

struct TopicState {
  TopicInfo info;
  std::int64_t id = 0;
  TimestampNs first_ns = 0;
  TimestampNs last_ns = 0;
};

std::string QosFor(TopicQos qos) {
  switch (qos) {
    case TopicQos::kSensorData:
      return bag_schema::QosProfileYaml(2, 2);
    case TopicQos::kReliable:
      return bag_schema::QosProfileYaml(1, 2);
    case TopicQos::kLatched:
      return bag_schema::QosProfileYaml(1, 1);
  }
  return {};
}

std::filesystem::path PrepareDirectory(const std::filesystem::path& directory) {
  std::error_code error;
  if (std::filesystem::exists(directory, error)) {
    if (!std::filesystem::is_directory(directory) || !std::filesystem::is_empty(directory, error)) {
      throw UsageError(directory.string() + ": output bag already exists (choose another path)");
    }
  } else if (!std::filesystem::create_directories(directory, error)) {
    throw InternalError(directory.string() + ": cannot create directory: " + error.message());
  }
  std::string name = directory.filename().string();
  if (name.empty()) name = directory.parent_path().filename().string();
  return directory / (name + "_0.db3");
}

}  // namespace

struct BagWriter::Impl {
  Impl(const std::filesystem::path& dir, BagWriterOptions opts)
      : directory(dir),
        options(opts),
        database(PrepareDirectory(dir), SqliteDatabase::Mode::kCreate) {}

  void CreateSchema() {
    // WAL + synchronous=FULL: every commit is on disk when it returns, and a reader sees a
    // consistent database whatever moment the process dies.
    database.Execute("PRAGMA journal_mode=WAL; PRAGMA synchronous=FULL;");
    database.Execute(bag_schema::kCreateTables);
    auto schema = database.Prepare("INSERT INTO schema (schema_version, ros_distro) VALUES (?, ?)");
    schema.Bind(1, std::int64_t{bag_schema::kSchemaVersion});
    schema.Bind(2, options.ros_distro);
    schema.Run();
    insert.emplace(
        database.Prepare("INSERT INTO messages (timestamp, topic_id, data) VALUES (?, ?, ?)"));
  }

  void BeginIfNeeded() {
    if (in_transaction) return;
    database.Execute("BEGIN");
    in_transaction = true;
    transaction_start = Clock::now();
  }

  void CommitLocked() {
    if (!in_transaction) return;
    database.Execute("COMMIT");
    in_transaction = false;
  }

  bool CommitDue() const {
    return in_transaction && Clock::now() - transaction_start >=
                                 std::chrono::milliseconds(options.commit_interval_ms);
  }

  // Commits on a timer, so a writer that goes quiet still has everything on disk within
  // commit_interval_ms.
  void CommitLoop() {
    std::unique_lock lock(mutex);
    const auto period =
        std::chrono::milliseconds(std::max<std::int64_t>(options.commit_interval_ms / 4, 1));
    while (!stopping) {
      wake.wait_for(lock, period);
      if (CommitDue()) CommitLocked();
    }
  }

  BagInfo Summary() const {
    BagInfo info;
    info.ros_distro = options.ros_distro;
    info.schema_version = bag_schema::kSchemaVersion;
    info.message_count = message_count;
    TimestampNs first = 0, last = 0;
    bool any = false;
    for (const auto& [name, topic] : topics) {
      info.topics.push_back(topic.info);
      if (topic.info.message_count == 0) continue;
      first = any ? std::min(first, topic.first_ns) : topic.first_ns;
      last = any ? std::max(last, topic.last_ns) : topic.last_ns;
      any = true;
    }
    info.starting_time_ns = first;
    info.duration_ns = last - first;
    info.files.push_back({database.file().filename().string(), first, last - first, message_count});
    return info;
  }

  std::filesystem::path directory;
  BagWriterOptions options;
  SqliteDatabase database;
  std::optional<SqliteStatement> insert;
  std::map<std::string, TopicState> topics;
  std::uint64_t message_count = 0;
  std::uint64_t bytes = 0;
  bool in_transaction = false;
  bool closed = false;
  Clock::time_point transaction_start;
  std::mutex mutex;
  std::condition_variable wake;
  bool stopping = false;
  std::thread committer;
};

BagWriter::BagWriter(const std::filesystem::path& directory, BagWriterOptions options) {
  if (options.commit_interval_ms <= 0) {
    throw UsageError("bag writer: commit_interval_ms must be positive");
  }
  impl_ = std::make_unique<Impl>(directory, options);
  impl_->CreateSchema();
  impl_->committer = std::thread([impl = impl_.get()] { impl->CommitLoop(); });
}

BagWriter::~BagWriter() {
  try {
    Close();
  } catch (...) {
    // Destructors must not throw; Close() reports errors to callers who ask.
  }
}

void BagWriter::AddTopic(const std::string& name, const std::string& type, TopicQos qos,
                         std::string_view message_definition) {
  std::lock_guard lock(impl_->mutex);
  if (auto it = impl_->topics.find(name); it != impl_->topics.end()) {
    if (it->second.info.type != type) {
      throw UsageError("bag " + impl_->directory.string() + ": topic '" + name +
                       "' already has type " + it->second.info.type + ", not " + type);
    }
    return;
  }
  TopicState state;
  state.info.name = name;
  state.info.type = type;
  state.info.offered_qos_profiles = QosFor(qos);
  auto insert = impl_->database.Prepare(
      "INSERT INTO topics (name, type, serialization_format, offered_qos_profiles, "
      "type_description_hash) VALUES (?, ?, 'cdr', ?, '')");
  insert.Bind(1, name);
  insert.Bind(2, type);
  insert.Bind(3, state.info.offered_qos_profiles);
  insert.Run();
  state.id = impl_->database.LastInsertId();

  auto known = impl_->database.Prepare("SELECT 1 FROM message_definitions WHERE topic_type = ?");
  known.Bind(1, type);
  if (!message_definition.empty() && !known.Step()) {
    auto definition = impl_->database.Prepare(
        "INSERT INTO message_definitions (topic_type, encoding, encoded_message_definition, "
        "type_description_hash) VALUES (?, 'ros2msg', ?, '')");
    definition.Bind(1, type);
    definition.Bind(2, message_definition);
    definition.Run();
  }
  impl_->topics.emplace(name, std::move(state));
}

void BagWriter::Write(const std::string& topic, TimestampNs timestamp_ns,
                      std::span<const std::uint8_t> serialized) {
  std::lock_guard lock(impl_->mutex);
  if (impl_->closed)
    throw UsageError("bag " + impl_->directory.string() + ": written after Close()");
  auto it = impl_->topics.find(topic);
  if (it == impl_->topics.end()) {
    throw UsageError("bag " + impl_->directory.string() + ": topic '" + topic +
                     "' written before AddTopic()");
  }
  TopicState& state = it->second;
  impl_->BeginIfNeeded();
  impl_->insert->Bind(1, timestamp_ns);
  impl_->insert->Bind(2, state.id);
  impl_->insert->BindBlob(3, serialized);
  impl_->insert->Run();

  if (state.info.message_count == 0) state.first_ns = state.last_ns = timestamp_ns;
  state.first_ns = std::min(state.first_ns, timestamp_ns);
  state.last_ns = std::max(state.last_ns, timestamp_ns);
  ++state.info.message_count;
  ++impl_->message_count;
  impl_->bytes += serialized.size();
  if (impl_->CommitDue()) impl_->CommitLocked();
}

void BagWriter::Flush() {
  std::lock_guard lock(impl_->mutex);
  impl_->CommitLocked();
}

void BagWriter::Close() {
  if (!impl_) return;
  {
    std::lock_guard lock(impl_->mutex);
    if (impl_->closed) return;
    impl_->closed = true;
    impl_->stopping = true;
  }
  impl_->wake.notify_all();
  if (impl_->committer.joinable()) impl_->committer.join();

  std::lock_guard lock(impl_->mutex);
  impl_->CommitLocked();
  const BagInfo info = impl_->Summary();
  const std::string yaml = MetadataYamlText(info);
  auto metadata =
      impl_->database.Prepare("INSERT INTO metadata (metadata_version, metadata) VALUES (?, ?)");
  metadata.Bind(1, std::int64_t{info.version});
  metadata.Bind(2, yaml);
  metadata.Run();
  // A finished bag is one self-contained file: it then opens read-only from anywhere.
  impl_->database.Execute("PRAGMA journal_mode=DELETE");
  WriteMetadataYaml(impl_->directory / "metadata.yaml", info);
}

const std::filesystem::path& BagWriter::directory() const { return impl_->directory; }

std::uint64_t BagWriter::message_count() const { return impl_->message_count; }

std::uint64_t BagWriter::bytes_written() const { return impl_->bytes; }

}  // namespace littermap::bag
