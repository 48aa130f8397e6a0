#pragma once
// Records live sensors into a run bag without losing what they sent.
//
// Each source runs in its own thread and hands readings to a bounded queue of its own, so a
// stalled sensor never holds up another; the calling thread encodes (JPEG, 16-bit PNG, CDR) and
// writes. When a queue is full the newest reading is dropped and counted. A source that goes
// away (SensorDisconnectedError) or stays silent longer than silence_timeout_s is disconnected
// and reconnected every reconnect_interval_s while the others keep recording; each gap goes into
// the bag as an event on /capture/events (std_msgs/String) and into the result.
//
// Stopping: when `stop_requested` becomes true (SIGINT/SIGTERM in the CLI), after
// max_duration_s, when the disk holding the bag has less than min_free_disk_bytes left, or when
// a write fails. Every queued reading is written, then metadata.yaml, so the bag is complete.
// A process killed outright keeps everything up to the bag's last commit (at most
// bag.commit_interval_ms old, bag/bag_writer.hpp).

#include <atomic>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "bag/bag_writer.hpp"
#include "bag/image_codec.hpp"
#include "capture/sensor_source.hpp"
#include "core/error.hpp"

namespace littermap::capture {

struct RecorderOptions {
  std::size_t queue_capacity = 64;  // readings per source waiting to be written
  double connect_timeout_s = 5.0;   // each source must connect once within this at the start
  double read_timeout_s = 0.2;      // longest a source thread waits before checking for stop
  double silence_timeout_s = 2.0;   // a streaming sensor silent this long is reconnected
                                    // (connect_timeout_s for the first reading after connecting)
  double reconnect_interval_s = 1.0;
  int max_consecutive_malformed = 10;  // then the sensor is reconnected (its stream is confused)
  double status_interval_s = 1.0;
  std::uint64_t min_free_disk_bytes = 256ull << 20;
  double max_duration_s = std::numeric_limits<double>::infinity();
  bag::ImageCodecOptions codec;
  bag::BagWriterOptions bag;

  void Validate() const;
};

struct SourceStatus {
  std::string name;  // SensorName(kind)
  std::string uri;
  bool connected = false;
  std::uint64_t received = 0;   // readings the sensor delivered
  std::uint64_t written = 0;    // of which in the bag
  std::uint64_t dropped = 0;    // of which lost to a full queue
  std::uint64_t malformed = 0;  // readings rejected as malformed (not in received)
  std::uint64_t disconnects = 0;
  double gap_s = 0;    // time spent disconnected or silent, in total
  double rate_hz = 0;  // received per second over the last status interval
  std::size_t queue_depth = 0;
  std::size_t max_queue_depth = 0;
};

struct RecorderStatus {
  double elapsed_s = 0;
  std::vector<SourceStatus> sources;
  std::uint64_t bag_bytes = 0;          // serialized payload written so far
  std::uint64_t disk_free_bytes = 0;    // available on the bag's file system
  std::vector<std::string> new_events;  // written to /capture/events since the last status
};

// One status line for people: elapsed time, each source's rate (or LOST), drops and queue, the
// bag's size and the disk's free space.
std::string FormatStatus(const RecorderStatus& status);
// A source's counts at the end of a recording, on one line for people.
std::string FormatSummary(const SourceStatus& source);

enum class RecordingStop { kRequested, kDuration, kDiskFull, kWriteFailed };

struct RecordingResult {
  RecordingStop stop = RecordingStop::kRequested;
  std::string stop_reason;  // for people
  // With kWriteFailed: what kind of failure it was (core/failure.hpp), environment for a full
  // disk or a device gone.
  ErrorKind failure_kind = ErrorKind::kEnvironment;
  double duration_s = 0;
  std::uint64_t messages = 0;
  std::vector<SourceStatus> sources;
  std::vector<std::string> events;  // as written to /capture/events
};

using RecorderStatusCallback = std::function<void(const RecorderStatus&)>;

// Records `sources` into a new bag directory until a stop condition (see above); writes
// `tf_static` on /tf_static first when it has transforms. Throws UsageError for a bag path that
// exists or bad options, SensorDisconnectedError naming the URI when a source cannot connect at
// the start (nothing is left behind then).
RecordingResult Record(const std::filesystem::path& bag_path,
                       std::vector<std::unique_ptr<SensorSource>> sources,
                       const msg::TFMessage& tf_static, const RecorderOptions& options,
                       const std::atomic<bool>& stop_requested,
                       const RecorderStatusCallback& status = {});

}  // namespace littermap::capture
