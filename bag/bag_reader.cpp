#include "bag/bag_reader.hpp"

#include <algorithm>
#include <fstream>
#include <map>
#include <optional>

#include "bag/mcap_records.hpp"
#include "bag/storage_file.hpp"

namespace littermap::bag {
namespace {

bool IsStorageFile(const std::filesystem::path& file) {
  return file.extension() == ".db3" || file.extension() == ".mcap";
}

std::vector<std::filesystem::path> FindStorageFiles(const std::filesystem::path& directory) {
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::directory_iterator(directory)) {
    if (IsStorageFile(entry.path())) files.push_back(entry.path());
  }
  // Split bags are NAME_0.db3, NAME_1.db3, ...: order by the number, not the text.
  std::sort(files.begin(), files.end(), [](const auto& a, const auto& b) {
    const auto a_name = a.stem().string(), b_name = b.stem().string();
    return a_name.size() != b_name.size() ? a_name.size() < b_name.size() : a_name < b_name;
  });
  return files;
}

// MCAP files by their magic, whatever their name; anything else must be a rosbag2 database.
std::unique_ptr<StorageFileReader> OpenStorageFile(const std::filesystem::path& file) {
  std::array<char, mcap::kMagic.size()> magic{};
  std::ifstream(file, std::ios::binary).read(magic.data(), magic.size());
  const bool is_mcap = std::equal(magic.begin(), magic.end(), mcap::kMagic.begin(),
                                  [](char a, std::uint8_t b) { return std::uint8_t(a) == b; });
  return is_mcap ? OpenMcapStorage(file) : OpenSqliteStorage(file);
}

// One storage file of the bag, with its topic ids mapped to indices into BagInfo::topics.
struct StorageFile {
  std::unique_ptr<StorageFileReader> reader;
  std::map<std::int64_t, std::size_t> topic_index_by_id;
  std::optional<TimestampNs> next_time;
};

}  // namespace

struct BagReader::Impl {
  std::filesystem::path directory;
  BagInfo info;
  bool rebuilt = false;
  std::vector<StorageFile> files;
  std::vector<std::string> filter;
  std::vector<std::uint64_t> next_index;  // per topic
  std::vector<std::string> warnings;
  std::vector<std::string> damage;  // also in warnings
  StampSource stamp_source = StampSource::kHeader;
  StampAgreement stamp_agreement;

  void LocateFiles(const std::filesystem::path& path);
  void ReadTopics(StorageFile& file);
  void CountMessages();
  void StartCursors();
  void CollectWarnings();
};

void BagReader::Impl::LocateFiles(const std::filesystem::path& path) {
  std::error_code error;
  if (std::filesystem::is_regular_file(path, error)) {
    // One file of a bag whose metadata.yaml lists it: the bag is its folder (read alone, its
    // figures would look rebuilt, as after a crash).
    // When the folder's metadata.yaml is unreadable or names a file that is missing, the file
    // is read alone, as before.
    const std::filesystem::path folder = path.has_parent_path() ? path.parent_path() : ".";
    if (std::filesystem::is_regular_file(folder / "metadata.yaml", error)) {
      std::optional<BagInfo> listed;
      try {
        listed = ReadMetadataYaml(folder / "metadata.yaml");
      } catch (const Error&) {
      }
      const auto lists = [&](const std::string& name) {
        return listed &&
               std::any_of(listed->files.begin(), listed->files.end(),
                           [&](const BagFileInfo& file) { return file.relative_path == name; });
      };
      const bool complete =
          listed &&
          std::all_of(listed->files.begin(), listed->files.end(), [&](const BagFileInfo& file) {
            return std::filesystem::exists(folder / file.relative_path, error);
          });
      if (lists(path.filename().string()) && complete) {
        LocateFiles(folder);
        return;
      }
    }
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
    if (recorded.storage_identifier != "sqlite3" && recorded.storage_identifier != "mcap") {
      throw BadInputError(metadata_path.string() + ": storage '" + recorded.storage_identifier +
                          "' is not supported (sqlite3 or mcap)");
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
    throw BadInputError(path.string() +
                        ": no .db3 or .mcap file (not a ROS 2 bag with sqlite3 or MCAP storage)");
  }
}

void BagReader::Impl::ReadTopics(StorageFile& file) {
  for (StoredTopic& stored : file.reader->Topics()) {
    TopicInfo& topic = stored.info;
    auto known = std::find_if(info.topics.begin(), info.topics.end(),
                              [&](const TopicInfo& t) { return t.name == topic.name; });
    if (known == info.topics.end()) {
      info.topics.push_back(topic);
      known = info.topics.end() - 1;
    } else if (known->type != topic.type) {
      throw BadInputError((directory / info.files[files.size()].relative_path).string() +
                          ": topic '" + topic.name + "' has type " + topic.type + " here but " +
                          known->type + " elsewhere in the bag");
    }
    file.topic_index_by_id[stored.id] = static_cast<std::size_t>(known - info.topics.begin());
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
  // last - first of the messages in `where`; stamps too far apart for that are refused.
  const auto span = [](TimestampNs first_ns, TimestampNs last_ns,
                       const std::filesystem::path& where) {
    const auto duration = CheckedDifference(last_ns, first_ns);
    if (!duration) {
      throw BadInputError(where.string() + ": message stamps from " + std::to_string(first_ns) +
                          " to " + std::to_string(last_ns) +
                          " ns lie further apart than 64-bit nanoseconds reach");
    }
    return *duration;
  };
  for (std::size_t i = 0; i < files.size(); ++i) {
    BagFileInfo& file_info = info.files[i];
    file_info.message_count = 0;
    TimestampNs file_first = 0, file_last = 0;
    for (const TopicCount& count : files[i].reader->Counts()) {
      auto topic = files[i].topic_index_by_id.find(count.id);
      if (topic == files[i].topic_index_by_id.end()) {
        throw BadInputError((directory / file_info.relative_path).string() +
                            ": messages refer to topic id " + std::to_string(count.id) +
                            ", which is not in 'topics'");
      }
      info.topics[topic->second].message_count += count.count;
      file_first = file_info.message_count ? std::min(file_first, count.first_ns) : count.first_ns;
      file_last = file_info.message_count ? std::max(file_last, count.last_ns) : count.last_ns;
      file_info.message_count += count.count;
    }
    file_info.starting_time_ns = file_first;
    file_info.duration_ns = span(file_first, file_last, directory / file_info.relative_path);
    if (file_info.message_count == 0) continue;
    first = any ? std::min(first, file_first) : file_first;
    last = any ? std::max(last, file_last) : file_last;
    any = true;
    info.message_count += file_info.message_count;
  }
  info.starting_time_ns = first;
  info.duration_ns = span(first, last, directory);
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
    std::vector<std::int64_t> ids;
    for (const auto& [id, index] : file.topic_index_by_id) {
      if (std::find(filter.begin(), filter.end(), info.topics[index].name) != filter.end()) {
        ids.push_back(id);
      }
    }
    // A filter none of whose topics is in this file: nothing to read here.
    if (!filter.empty() && ids.empty()) {
      file.next_time.reset();
      continue;
    }
    file.reader->Start(ids);
    file.next_time = file.reader->PeekTime();
  }
  CollectWarnings();
}

void BagReader::Impl::CollectWarnings() {
  for (auto& file : files) {
    // A damaged chunk is seen when the file is indexed and again when it is read: once is enough.
    for (std::string& warning : file.reader->TakeWarnings()) {
      if (std::find(damage.begin(), damage.end(), warning) != damage.end()) continue;
      damage.push_back(warning);
      warnings.push_back(std::move(warning));
    }
  }
}

BagReader::BagReader(const std::filesystem::path& path) : impl_(std::make_unique<Impl>()) {
  impl_->LocateFiles(path);
  // Topics and counts always come from the storage files; metadata.yaml only names the files.
  std::vector<TopicInfo> recorded = std::move(impl_->info.topics);
  impl_->info.topics.clear();
  int schema = -1;
  bool all_mcap = true;
  for (const auto& file_info : impl_->info.files) {
    StorageFile file;
    file.reader = OpenStorageFile(impl_->directory / file_info.relative_path);
    schema = std::max(schema, file.reader->SchemaVersion());
    all_mcap = all_mcap && std::filesystem::path(file_info.relative_path).extension() == ".mcap";
    impl_->ReadTopics(file);
    impl_->files.push_back(std::move(file));
  }
  impl_->info.schema_version = schema;
  if (impl_->rebuilt) impl_->info.storage_identifier = all_mcap ? "mcap" : "sqlite3";
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

const std::vector<std::string>& BagReader::warnings() const { return impl_->warnings; }

const std::vector<std::string>& BagReader::damage() const { return impl_->damage; }

const TopicInfo& BagReader::RequireTopic(const std::string& name, const std::string& role) const {
  const TopicInfo* topic = impl_->info.FindTopic(name);
  if (topic == nullptr) {
    throw BadInputError(impl_->directory.string() + ": no " + role + " topic " + name);
  }
  return *topic;
}

void BagReader::SetStampSource(StampSource source) { impl_->stamp_source = source; }

void BagReader::SetVerifyChecksums(bool verify) {
  for (auto& file : impl_->files) file.reader->SetVerifyChecksums(verify);
  impl_->StartCursors();
}

void BagReader::SetTopicFilter(const std::vector<std::string>& topics) {
  impl_->filter = topics;
  impl_->StartCursors();
}

std::optional<BagMessage> BagReader::Next() {
  StorageFile* best = nullptr;
  for (auto& file : impl_->files) {
    if (file.next_time && (best == nullptr || *file.next_time < *best->next_time)) best = &file;
  }
  if (best == nullptr) return std::nullopt;
  StoredMessage stored = best->reader->Take();
  BagMessage message;
  const std::size_t topic = best->topic_index_by_id.at(stored.topic_id);
  message.topic = &impl_->info.topics[topic];
  message.timestamp_ns = stored.timestamp_ns;
  message.index = impl_->next_index[topic]++;
  message.data = std::move(stored.data);
  if (const auto header_ns = HeaderStamp(message.topic->type, message.data)) {
    std::string warning = impl_->stamp_agreement.Observe(message.topic->name, *header_ns,
                                                         message.timestamp_ns, impl_->stamp_source);
    if (!warning.empty()) impl_->warnings.push_back(std::move(warning));
    if (impl_->stamp_source == StampSource::kRecorded) {
      SetHeaderStamp(message.topic->type, message.data, message.timestamp_ns);
    }
  }
  best->next_time = best->reader->PeekTime();
  impl_->CollectWarnings();
  return message;
}

}  // namespace littermap::bag
