#include "bag/bag_convert.hpp"

#include <algorithm>

#include "bag/bag_reader.hpp"
#include "bag/output_guard.hpp"

namespace littermap::bag {

ConvertResult ConvertBag(const std::filesystem::path& input, const std::filesystem::path& output,
                         const ConvertOptions& options, const ProgressCallback& progress) {
  BagReader reader(input);
  for (const std::string& topic : options.topics) reader.RequireTopic(topic, "requested");
  reader.SetTopicFilter(options.topics);

  OutputGuard guard;
  guard.Add(output);
  BagWriterOptions writer_options;
  writer_options.storage = options.storage;
  writer_options.mcap = options.mcap;
  if (!reader.info().ros_distro.empty()) writer_options.ros_distro = reader.info().ros_distro;
  BagWriter writer(output, writer_options);
  ConvertResult result;
  std::uint64_t total = 0;
  for (const TopicInfo& topic : reader.info().topics) {
    const auto& wanted = options.topics;
    if (!wanted.empty() && std::find(wanted.begin(), wanted.end(), topic.name) == wanted.end()) {
      continue;
    }
    writer.AddTopic(topic);
    ++result.topic_count;
    total += topic.message_count;
  }
  const std::string task = "converting " + input.filename().string();
  while (auto message = reader.Next()) {
    writer.Write(message->topic->name, message->timestamp_ns, message->data);
    if (++result.message_count % 1024 == 0) {
      ReportProgress(progress, {task, result.message_count, total});
    }
  }
  writer.Close();
  result.warnings = reader.warnings();
  std::error_code error;
  for (const auto& entry : std::filesystem::directory_iterator(output, error)) {
    if (entry.path().filename() != "metadata.yaml") result.output_bytes += entry.file_size(error);
  }
  guard.Commit();
  return result;
}

}  // namespace littermap::bag
