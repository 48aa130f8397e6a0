#include "bag/bag_writer.hpp"

#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <exception>
#include <map>
#include <mutex>
#include <optional>
#include <thread>

#include "bag/bag_schema.hpp"
#include "bag/storage_file.hpp"
#include "core/failure.hpp"
#include "core/utf8.hpp"

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

// The storage file of a new bag: BAG/BAG_0.db3 or BAG/BAG_0.mcap.
std::unique_ptr<StorageFileWriter> CreateStorage(const std::filesystem::path& directory,
                                                 const BagWriterOptions& options) {
  if (options.storage != "sqlite3" && options.storage != "mcap") {
    throw UsageError("bag storage '" + options.storage + "' is not supported (sqlite3 or mcap)");
  }
  std::error_code error;
  if (std::filesystem::exists(directory, error)) {
    if (!std::filesystem::is_directory(directory) || !std::filesystem::is_empty(directory, error)) {
      throw UsageError(directory.string() + ": output bag already exists (choose another path)");
    }
  } else if (!std::filesystem::create_directories(directory, error)) {
    throw FileFailure(directory, "cannot create directory", error.value());
  }
  std::string name = directory.filename().string();
  if (name.empty()) name = directory.parent_path().filename().string();
  if (options.storage == "mcap")
    return CreateMcapStorage(directory / (name + "_0.mcap"), options.mcap);
  return CreateSqliteStorage(directory / (name + "_0.db3"), options.ros_distro);
}

}  // namespace

struct BagWriter::Impl {
  Impl(const std::filesystem::path& dir, BagWriterOptions opts)
      : directory(dir), options(opts), storage(CreateStorage(dir, opts)) {}

  void CommitLocked() {
    if (!uncommitted) return;
    storage->Commit();
    uncommitted = false;
  }

  bool CommitDue() const {
    return uncommitted && Clock::now() - first_uncommitted >=
                              std::chrono::milliseconds(options.commit_interval_ms);
  }

  // Commits on a timer, so a writer that goes quiet still has everything on disk within
  // commit_interval_ms. A failed commit (the disk full) is kept for the writer's next call to
  // throw: an exception leaving this thread would abort the recording process.
  void CommitLoop() {
    std::unique_lock lock(mutex);
    const auto period =
        std::chrono::milliseconds(std::max<std::int64_t>(options.commit_interval_ms / 4, 1));
    while (!stopping) {
      wake.wait_for(lock, period);
      if (failure || !CommitDue()) continue;
      try {
        CommitLocked();
      } catch (...) {
        failure = std::current_exception();
      }
    }
  }

  void ThrowIfFailedLocked() const {
    if (failure) std::rethrow_exception(failure);
  }

  BagInfo Summary() const {
    BagInfo info;
    info.storage_identifier = options.storage;
    info.ros_distro = options.ros_distro;
    info.schema_version = options.storage == "sqlite3" ? bag_schema::kSchemaVersion : 0;
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
    // Saturated for stamps 292 years apart, which readers then refuse, naming the file.
    info.duration_ns = SaturatingDifference(last, first);
    info.files.push_back(
        {storage->file().filename().string(), first, info.duration_ns, message_count});
    return info;
  }

  std::filesystem::path directory;
  BagWriterOptions options;
  std::unique_ptr<StorageFileWriter> storage;
  std::map<std::string, TopicState> topics;
  std::uint64_t message_count = 0;
  std::uint64_t bytes = 0;
  bool uncommitted = false;
  bool closed = false;
  Clock::time_point first_uncommitted;
  std::mutex mutex;
  std::condition_variable wake;
  bool stopping = false;
  std::exception_ptr failure;  // the committer's failed commit, thrown by the next call
  std::thread committer;
};

BagWriter::BagWriter(const std::filesystem::path& directory, BagWriterOptions options) {
  if (options.commit_interval_ms <= 0) {
    throw UsageError("bag writer: commit_interval_ms must be positive");
  }
  // Its name goes into the storage files' names and metadata.yaml, which readers take as UTF-8.
  RequireUtf8(directory.string(), "the bag folder's name");
  impl_ = std::make_unique<Impl>(directory, options);
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
  TopicInfo topic;
  topic.name = name;
  topic.type = type;
  topic.offered_qos_profiles = QosFor(qos);
  topic.message_definition = message_definition;
  AddTopic(topic);
}

void BagWriter::AddTopic(const TopicInfo& topic) {
  std::lock_guard lock(impl_->mutex);
  if (auto it = impl_->topics.find(topic.name); it != impl_->topics.end()) {
    if (it->second.info.type != topic.type) {
      throw UsageError("bag " + impl_->directory.string() + ": topic '" + topic.name +
                       "' already has type " + it->second.info.type + ", not " + topic.type);
    }
    return;
  }
  TopicState state;
  state.info = topic;
  state.info.message_count = 0;
  state.id = impl_->storage->AddTopic(state.info);
  impl_->topics.emplace(topic.name, std::move(state));
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
  impl_->ThrowIfFailedLocked();
  TopicState& state = it->second;
  impl_->storage->Write(state.id, timestamp_ns, serialized);
  if (!impl_->uncommitted) {
    impl_->uncommitted = true;
    impl_->first_uncommitted = Clock::now();
  }

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
  impl_->ThrowIfFailedLocked();
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
  // A failed commit (the disk full, now or in the committer) loses what it held; the storage is
  // still closed over what was committed, so the bag opens and verifies, and the failure is
  // thrown after that.
  try {
    impl_->CommitLocked();
  } catch (...) {
    if (!impl_->failure) impl_->failure = std::current_exception();
  }
  const BagInfo info = impl_->Summary();
  impl_->storage->Close(info);
  WriteMetadataYaml(impl_->directory / "metadata.yaml", info);
  impl_->ThrowIfFailedLocked();
}

const std::filesystem::path& BagWriter::directory() const { return impl_->directory; }

std::uint64_t BagWriter::message_count() const { return impl_->message_count; }

std::uint64_t BagWriter::bytes_written() const { return impl_->bytes; }

}  // namespace littermap::bag
