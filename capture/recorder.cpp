#include "capture/recorder.hpp"

#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <deque>
#include <mutex>
#include <thread>
#include <utility>

#include "bag/message_header.hpp"
#include "bag/output_guard.hpp"
#include "bag/topics.hpp"
#include "capture/byte_stream.hpp"
#include "core/error.hpp"
#include "core/failure.hpp"

namespace littermap::capture {
namespace {

using Clock = std::chrono::steady_clock;

constexpr const char* kEventsTopic = "/capture/events";
constexpr std::uint64_t kMalformedEventsShown = 10;  // then one event per 100 malformed readings

double SecondsSince(Clock::time_point t) {
  return std::chrono::duration<double>(Clock::now() - t).count();
}

std::chrono::nanoseconds Seconds(double s) {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::duration<double>(s));
}

std::string FormatSeconds(double s) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f s", s);
  return text;
}

// What the source threads and the writer share.
struct Shared {
  explicit Shared(const RecorderOptions& o) : options(o) {}

  const RecorderOptions& options;
  std::mutex mutex;              // guards every Channel's queue and status, and `events`
  std::condition_variable wake;  // a reading or event arrived, or stopping
  bool stopping = false;
  std::vector<std::pair<TimestampNs, std::string>> events;  // not yet written

  void AddEvent(std::string text) {
    std::lock_guard lock(mutex);
    events.emplace_back(HostNowNs(), std::move(text));
    wake.notify_all();
  }
  // Sleeps up to `s` seconds; false when stopping.
  bool SleepUnlessStopping(double s) {
    std::unique_lock lock(mutex);
    return !wake.wait_for(lock, Seconds(s), [&] { return stopping; });
  }
  bool IsStopping() {
    std::lock_guard lock(mutex);
    return stopping;
  }
};

// One source with its thread and queue.
class Channel {
 public:
  Channel(std::unique_ptr<SensorSource> source, Shared& shared)
      : source_(std::move(source)), shared_(shared) {
    status_.name = SensorName(source_->kind());
    status_.uri = source_->uri();
  }

  SensorSource& source() { return *source_; }
  SourceStatus& status() { return status_; }            // under shared.mutex
  std::deque<SensorSample>& queue() { return queue_; }  // under shared.mutex

  void MarkConnected() {
    status_.connected = true;
    ForwardNotes();
  }
  void Start() {
    thread_ = std::thread([this] { Run(); });
  }
  void Join() {
    if (thread_.joinable()) thread_.join();
  }

 private:
  void Run() {
    const RecorderOptions& options = shared_.options;
    bool connected = true;
    Clock::time_point last_reading = Clock::now(), lost_at{};
    int malformed_in_a_row = 0;
    bool any_since_connect = false;
    while (!shared_.IsStopping()) {
      if (!connected) {
        try {
          source_->Connect();
        } catch (const std::exception&) {
          shared_.SleepUnlessStopping(options.reconnect_interval_s);
          continue;
        }
        connected = true;
        ForwardNotes();
        const double gap_s = SecondsSince(lost_at);
        {
          std::lock_guard lock(shared_.mutex);
          status_.connected = true;
          status_.gap_s += gap_s;
        }
        shared_.AddEvent(status_.name + ": reconnected after " + FormatSeconds(gap_s));
        last_reading = Clock::now();
        malformed_in_a_row = 0;
        any_since_connect = false;
      }
      std::string lost_because;
      bool silent = false;
      try {
        std::optional<SensorSample> sample = source_->Read(options.read_timeout_s);
        // A sensor just (re)connected may take a while for its first reading (a camera's
        // auto exposure, a laser's motor): it has connect_timeout_s for that.
        const double silence_limit_s =
            any_since_connect ? options.silence_timeout_s
                              : std::max(options.silence_timeout_s, options.connect_timeout_s);
        if (sample) {
          any_since_connect = true;
          last_reading = Clock::now();
          malformed_in_a_row = 0;
          Push(std::move(*sample));
        } else if (SecondsSince(last_reading) > silence_limit_s) {
          silent = true;
          lost_because = "silent for " + FormatSeconds(SecondsSince(last_reading));
        }
      } catch (const BadInputError& error) {
        std::uint64_t count = 0;
        {
          std::lock_guard lock(shared_.mutex);
          count = ++status_.malformed;
        }
        if (count <= kMalformedEventsShown || count % 100 == 0) {
          shared_.AddEvent(status_.name + ": malformed reading #" + std::to_string(count) + ": " +
                           error.what());
        }
        if (++malformed_in_a_row >= options.max_consecutive_malformed) {
          lost_because = std::to_string(malformed_in_a_row) + " malformed readings in a row";
        }
      } catch (const std::exception& error) {  // gone, or failing in a way a reconnect may cure
        lost_because = error.what();
      }
      if (!lost_because.empty()) {
        source_->Disconnect();
        connected = false;
        // A silent sensor was gone from its last reading on.
        lost_at = silent ? last_reading : Clock::now();
        {
          std::lock_guard lock(shared_.mutex);
          status_.connected = false;
          ++status_.disconnects;
        }
        shared_.AddEvent(status_.name + ": lost (" + lost_because + "); reconnecting");
      }
    }
    if (connected) {
      source_->Disconnect();
    } else {
      std::lock_guard lock(shared_.mutex);
      status_.gap_s += SecondsSince(lost_at);
    }
  }

  void ForwardNotes() {
    for (const std::string& note : source_->TakeNotes())
      shared_.AddEvent(status_.name + ": " + note);
  }

  void Push(SensorSample sample) {
    std::lock_guard lock(shared_.mutex);
    ++status_.received;
    if (queue_.size() >= shared_.options.queue_capacity) {
      ++status_.dropped;
      return;
    }
    queue_.push_back(std::move(sample));
    status_.max_queue_depth = std::max(status_.max_queue_depth, queue_.size());
    shared_.wake.notify_all();
  }

  std::unique_ptr<SensorSource> source_;
  Shared& shared_;
  SourceStatus status_;
  std::deque<SensorSample> queue_;
  std::thread thread_;
};

// Connects every source within options.connect_timeout_s, or disconnects them all and throws.
void ConnectAll(std::vector<std::unique_ptr<Channel>>& channels, const RecorderOptions& options) {
  const Clock::time_point start = Clock::now();
  for (std::size_t i = 0; i < channels.size(); ++i) {
    SensorSource& source = channels[i]->source();
    for (;;) {
      try {
        source.Connect();
        channels[i]->MarkConnected();
        break;
      } catch (const SensorDisconnectedError& error) {
        if (SecondsSince(start) < options.connect_timeout_s) {
          std::this_thread::sleep_for(std::chrono::milliseconds(200));
          continue;
        }
        for (std::size_t j = 0; j <= i; ++j) channels[j]->source().Disconnect();
        throw SensorDisconnectedError(std::string(SensorName(source.kind())) + " " + source.uri() +
                                      ": cannot connect within " +
                                      FormatSeconds(options.connect_timeout_s) + ": " +
                                      error.what());
      } catch (...) {
        for (std::size_t j = 0; j <= i; ++j) channels[j]->source().Disconnect();
        throw;
      }
    }
  }
}

void AddTopics(bag::BagWriter& writer, SensorKind kind) {
  switch (kind) {
    case SensorKind::kLaser:
      writer.AddTopic<msg::LaserScan>(topics::kScan, bag::TopicQos::kSensorData);
      break;
    case SensorKind::kOdometry:
      writer.AddTopic<msg::Odometry>(topics::kOdometry, bag::TopicQos::kReliable);
      break;
    case SensorKind::kCamera:
      writer.AddTopic<msg::CameraInfo>(topics::kCameraInfo, bag::TopicQos::kSensorData);
      writer.AddTopic<msg::CompressedImage>(topics::kColor, bag::TopicQos::kSensorData);
      writer.AddTopic<msg::CameraInfo>(topics::kDepthCameraInfo, bag::TopicQos::kSensorData);
      writer.AddTopic<msg::CompressedImage>(topics::kDepth, bag::TopicQos::kSensorData);
      break;
  }
}

// Encodes and writes one reading.
class SampleWriter {
 public:
  SampleWriter(bag::BagWriter& writer, const bag::ImageCodecOptions& codec)
      : writer_(writer), codec_(codec) {}

  void operator()(const msg::LaserScan& scan) {
    writer_.WriteMessage(topics::kScan, bag::StampOf(scan.header), scan);
  }
  void operator()(const msg::Odometry& odometry) {
    writer_.WriteMessage(topics::kOdometry, bag::StampOf(odometry.header), odometry);
  }
  void operator()(const RgbdFrame& frame) {
    const msg::Header header = bag::MakeHeader(frame.stamp_ns, frames::kCamera);
    msg::CameraInfo info = frame.camera_info;
    info.header = header;
    writer_.WriteMessage(topics::kCameraInfo, frame.stamp_ns, info);
    writer_.WriteMessage(topics::kColor, frame.stamp_ns,
                         bag::EncodeColorJpeg(frame.colour_bgr, header, codec_));
    writer_.WriteMessage(topics::kDepthCameraInfo, frame.stamp_ns, info);
    writer_.WriteMessage(topics::kDepth, frame.stamp_ns,
                         bag::EncodeDepthPng(frame.depth_mm, header, codec_));
  }

 private:
  bag::BagWriter& writer_;
  const bag::ImageCodecOptions& codec_;
};

std::uint64_t DiskFreeBytes(const std::filesystem::path& path) {
  std::error_code error;
  const std::filesystem::space_info space = std::filesystem::space(path, error);
  return error ? std::numeric_limits<std::uint64_t>::max() : space.available;
}

}  // namespace

const char* SensorName(SensorKind kind) {
  switch (kind) {
    case SensorKind::kLaser:
      return "laser";
    case SensorKind::kCamera:
      return "camera";
    case SensorKind::kOdometry:
      return "odometry";
  }
  return "sensor";
}

void RecorderOptions::Validate() const {
  if (queue_capacity < 1) throw UsageError("recorder queue_capacity must be at least 1");
  if (!(read_timeout_s > 0) || !(silence_timeout_s > read_timeout_s)) {
    throw UsageError("recorder silence_timeout_s must exceed read_timeout_s > 0");
  }
  if (!(reconnect_interval_s > 0) || !(status_interval_s > 0) || !(connect_timeout_s >= 0)) {
    throw UsageError("recorder reconnect, status and connect intervals must be positive");
  }
  if (max_consecutive_malformed < 1) {
    throw UsageError("recorder max_consecutive_malformed must be at least 1");
  }
  if (!(max_duration_s > 0)) throw UsageError("recording duration must be positive");
}

RecordingResult Record(const std::filesystem::path& bag_path,
                       std::vector<std::unique_ptr<SensorSource>> sources,
                       const msg::TFMessage& tf_static, const RecorderOptions& options,
                       const std::atomic<bool>& stop_requested,
                       const RecorderStatusCallback& status) {
  options.Validate();
  if (sources.empty()) throw UsageError("nothing to record: no sensor source given");
  Shared shared(options);
  std::vector<std::unique_ptr<Channel>> channels;
  for (auto& source : sources) {
    if (!source) throw UsageError("recorder given an empty source");
    for (const auto& other : channels) {
      if (other->source().kind() == source->kind()) {
        throw UsageError(std::string("two ") + SensorName(source->kind()) + " sources given");
      }
    }
    channels.push_back(std::make_unique<Channel>(std::move(source), shared));
  }
  // The bag before the sensors: a bad output path fails at once, not after a camera took its
  // seconds to start; and a sensor that does not connect leaves no empty bag behind (the writer
  // is closed before the guard removes it).
  bag::OutputGuard guard;
  guard.Add(bag_path);
  bag::BagWriter writer(bag_path, options.bag);
  ConnectAll(channels, options);
  guard.Commit();
  RecordingResult result;
  const Clock::time_point start = Clock::now();
  try {
    for (const auto& channel : channels) AddTopics(writer, channel->source().kind());
    writer.AddTopic<msg::String>(kEventsTopic, bag::TopicQos::kReliable);
    if (!tf_static.transforms.empty()) {
      writer.AddTopic<msg::TFMessage>(topics::kTfStatic, bag::TopicQos::kLatched);
      writer.WriteMessage(topics::kTfStatic, HostNowNs(), tf_static);
    }
  } catch (...) {
    for (const auto& channel : channels) channel->source().Disconnect();
    throw;
  }
  for (const auto& channel : channels) channel->Start();

  SampleWriter write_sample(writer, options.codec);
  std::vector<std::uint64_t> received_at_status(channels.size(), 0);
  Clock::time_point last_status = start;
  std::size_t events_reported = 0;
  bool stop = false;

  // Writes every queued reading and event; false when a write failed.
  const auto drain = [&]() -> bool {
    try {
      for (;;) {
        std::vector<std::pair<TimestampNs, std::string>> events;
        bool any = false;
        for (const auto& channel : channels) {
          std::optional<SensorSample> sample;
          {
            std::lock_guard lock(shared.mutex);
            if (!channel->queue().empty()) {
              sample = std::move(channel->queue().front());
              channel->queue().pop_front();
            }
          }
          if (!sample) continue;
          std::visit(write_sample, *sample);
          any = true;
          std::lock_guard lock(shared.mutex);
          ++channel->status().written;
        }
        {
          std::lock_guard lock(shared.mutex);
          events.swap(shared.events);
        }
        for (const auto& [stamp_ns, text] : events) {
          writer.WriteMessage(kEventsTopic, stamp_ns, msg::String{text});
          result.events.push_back(text);
        }
        if (!any && events.empty()) return true;
      }
    } catch (const std::exception& error) {
      result.stop = RecordingStop::kWriteFailed;
      result.stop_reason = std::string("writing the bag failed: ") + error.what();
      result.failure_kind = KindOf(error);
      return false;
    }
  };

  const auto snapshot = [&]() {
    std::lock_guard lock(shared.mutex);
    std::vector<SourceStatus> out;
    for (const auto& channel : channels) {
      SourceStatus s = channel->status();
      s.queue_depth = channel->queue().size();
      out.push_back(std::move(s));
    }
    return out;
  };

  while (!stop) {
    {
      std::unique_lock lock(shared.mutex);
      shared.wake.wait_for(lock, std::chrono::milliseconds(50), [&] {
        if (!shared.events.empty()) return true;
        for (const auto& channel : channels) {
          if (!channel->queue().empty()) return true;
        }
        return false;
      });
    }
    if (!drain()) break;
    const double elapsed_s = SecondsSince(start);
    if (stop_requested.load()) {
      result.stop = RecordingStop::kRequested;
      result.stop_reason = "stopped on request";
      stop = true;
    } else if (elapsed_s >= options.max_duration_s) {
      result.stop = RecordingStop::kDuration;
      result.stop_reason = "recorded the requested " + FormatSeconds(options.max_duration_s);
      stop = true;
    }
    if (stop || SecondsSince(last_status) >= options.status_interval_s) {
      const double interval_s = SecondsSince(last_status);
      last_status = Clock::now();
      RecorderStatus now;
      now.elapsed_s = elapsed_s;
      now.sources = snapshot();
      for (std::size_t i = 0; i < channels.size(); ++i) {
        now.sources[i].rate_hz =
            static_cast<double>(now.sources[i].received - received_at_status[i]) / interval_s;
        received_at_status[i] = now.sources[i].received;
      }
      now.new_events.assign(result.events.begin() + static_cast<std::ptrdiff_t>(events_reported),
                            result.events.end());
      events_reported = result.events.size();
      now.bag_bytes = writer.bytes_written();
      now.disk_free_bytes = DiskFreeBytes(bag_path);
      if (!stop && now.disk_free_bytes < options.min_free_disk_bytes) {
        result.stop = RecordingStop::kDiskFull;
        result.stop_reason = "disk nearly full: " + std::to_string(now.disk_free_bytes >> 20) +
                             " MiB left, below the " +
                             std::to_string(options.min_free_disk_bytes >> 20) + " MiB reserve";
        stop = true;
      }
      if (status) status(now);
    }
  }

  {
    std::lock_guard lock(shared.mutex);
    shared.stopping = true;
    shared.wake.notify_all();
  }
  for (const auto& channel : channels) channel->Join();
  if (result.stop != RecordingStop::kWriteFailed) {
    shared.AddEvent("stopped: " + result.stop_reason);
    drain();
  }
  result.duration_s = SecondsSince(start);
  result.sources = snapshot();
  result.messages = writer.message_count();
  if (result.stop == RecordingStop::kWriteFailed) {
    try {
      writer.Close();
    } catch (const std::exception&) {  // the bag keeps what was committed
    }
  } else {
    writer.Close();
  }
  return result;
}

std::string FormatStatus(const RecorderStatus& status) {
  std::string line;
  char text[160];
  std::snprintf(text, sizeof text, "recording %4.0f s", status.elapsed_s);
  line += text;
  for (const SourceStatus& source : status.sources) {
    if (source.connected) {
      std::snprintf(text, sizeof text, " | %s %.1f Hz", source.name.c_str(), source.rate_hz);
    } else {
      std::snprintf(text, sizeof text, " | %s LOST", source.name.c_str());
    }
    line += text;
    if (source.dropped > 0) line += " " + std::to_string(source.dropped) + " dropped";
    if (source.queue_depth > 1) line += " q" + std::to_string(source.queue_depth);
  }
  std::snprintf(text, sizeof text, " | bag %.0f MB, disk %.1f GB free",
                static_cast<double>(status.bag_bytes) / 1e6,
                static_cast<double>(status.disk_free_bytes) / 1e9);
  return line + text;
}

std::string FormatSummary(const SourceStatus& source) {
  char counts[320];
  std::snprintf(counts, sizeof counts,
                ": %llu received, %llu written, %llu dropped, %llu malformed, %llu disconnects, "
                "%.1f s without data, queue max %zu",
                static_cast<unsigned long long>(source.received),
                static_cast<unsigned long long>(source.written),
                static_cast<unsigned long long>(source.dropped),
                static_cast<unsigned long long>(source.malformed),
                static_cast<unsigned long long>(source.disconnects), source.gap_s,
                source.max_queue_depth);
  char name[64];
  std::snprintf(name, sizeof name, "%-8s ", source.name.c_str());
  return name + source.uri + counts;
}

}  // namespace littermap::capture
