#include "importers/carmen_log.hpp"

#include <charconv>
#include <cmath>
#include <limits>
#include <system_error>

#include "core/error.hpp"
#include "core/text_lines.hpp"

namespace littermap::importers {
namespace {

bool IsSpace(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

// Walks the whitespace-separated tokens of one line; every accessor names the field it wants,
// so that a malformed line is reported by field.
class FieldCursor {
 public:
  FieldCursor(std::string_view type, std::string_view rest) : type_(type), rest_(rest) {}

  bool AtEnd() {
    SkipSpace();
    return rest_.empty();
  }

  std::string_view Token(std::string_view field, std::size_t index = kNoIndex) {
    SkipSpace();
    if (rest_.empty()) Fail(field, index, "is missing");
    std::size_t end = 0;
    while (end < rest_.size() && !IsSpace(rest_[end])) ++end;
    const std::string_view token = rest_.substr(0, end);
    rest_.remove_prefix(end);
    return token;
  }

  double Double(std::string_view field, std::size_t index = kNoIndex) {
    std::string_view token = Token(field, index);
    if (token.size() > 1 && token[0] == '+') token.remove_prefix(1);  // from_chars rejects '+'
    double value = 0;
    const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), value);
    if (error != std::errc() || end != token.data() + token.size() || !std::isfinite(value)) {
      Fail(field, index, "'" + std::string(token) + "' is not a finite number");
    }
    return value;
  }

  float Range(std::string_view field, std::size_t index) {
    const double value = Double(field, index);
    if (value < 0 || value > std::numeric_limits<float>::max()) {
      Fail(field, index, "'" + std::to_string(value) + "' is not a range in metres");
    }
    return static_cast<float>(value);
  }

  // A count of following tokens; it cannot exceed what the line still holds (so a corrupt
  // count never allocates much).
  std::size_t Count(std::string_view field) {
    const std::string_view token = Token(field);
    std::size_t value = 0;
    const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), value);
    if (error != std::errc() || end != token.data() + token.size()) {
      Fail(field, kNoIndex, "'" + std::string(token) + "' is not a count");
    }
    if (value > rest_.size() / 2 + 1) {
      Fail(field, kNoIndex, std::to_string(value) + " exceeds the values on the line");
    }
    return value;
  }

  PlanarPose Pose(std::string_view x, std::string_view y, std::string_view theta) {
    PlanarPose pose;
    pose.x_m = Double(x);
    pose.y_m = Double(y);
    pose.theta_rad = Double(theta);
    return pose;
  }

  // timestamp [hostname [logger_timestamp]], then nothing more.
  double Trailer() {
    const double timestamp = Double("timestamp");
    if (!AtEnd()) Token("hostname");
    if (!AtEnd()) Double("logger_timestamp");
    if (!AtEnd()) Fail("logger_timestamp", kNoIndex, "is followed by unexpected fields");
    return timestamp;
  }

  [[noreturn]] void Fail(std::string_view field, std::size_t index, const std::string& what) {
    std::string name(field);
    if (index != kNoIndex) name += "[" + std::to_string(index) + "]";
    throw BadInputError(std::string(type_) + " field '" + name + "': " + what);
  }

  static constexpr std::size_t kNoIndex = std::numeric_limits<std::size_t>::max();

 private:
  void SkipSpace() {
    while (!rest_.empty() && IsSpace(rest_.front())) rest_.remove_prefix(1);
  }

  std::string_view type_;
  std::string_view rest_;
};

CarmenOdomRecord ParseOdom(FieldCursor& cursor) {
  CarmenOdomRecord record;
  record.pose = cursor.Pose("x", "y", "theta");
  record.tv_mps = cursor.Double("tv");
  record.rv_radps = cursor.Double("rv");
  record.accel_mps2 = cursor.Double("accel");
  record.timestamp_s = cursor.Trailer();
  return record;
}

void ParseRanges(FieldCursor& cursor, CarmenLaserRecord& record) {
  const std::size_t count = cursor.Count("num_readings");
  if (count == 0) cursor.Fail("num_readings", FieldCursor::kNoIndex, "is 0");
  record.ranges_m.resize(count);
  for (std::size_t i = 0; i < count; ++i) record.ranges_m[i] = cursor.Range("range", i);
}

CarmenLaserRecord ParseFlaser(FieldCursor& cursor) {
  CarmenLaserRecord record;
  record.kind = CarmenLaserRecord::Kind::kFlaser;
  ParseRanges(cursor, record);
  record.laser_pose = cursor.Pose("x", "y", "theta");
  record.robot_pose = cursor.Pose("odom_x", "odom_y", "odom_theta");
  record.timestamp_s = cursor.Trailer();
  return record;
}

CarmenLaserRecord ParseRobotLaser1(FieldCursor& cursor) {
  CarmenLaserRecord record;
  record.kind = CarmenLaserRecord::Kind::kRobotLaser1;
  record.has_geometry = true;
  cursor.Token("laser_type");
  record.start_angle_rad = cursor.Double("start_angle");
  cursor.Double("field_of_view");
  record.angular_resolution_rad = cursor.Double("angular_resolution");
  record.max_range_m = cursor.Double("maximum_range");
  cursor.Double("accuracy");
  cursor.Token("remission_mode");
  ParseRanges(cursor, record);
  const std::size_t remissions = cursor.Count("num_remissions");
  for (std::size_t i = 0; i < remissions; ++i) cursor.Double("remission", i);
  record.laser_pose = cursor.Pose("laser_pose_x", "laser_pose_y", "laser_pose_theta");
  record.robot_pose = cursor.Pose("robot_pose_x", "robot_pose_y", "robot_pose_theta");
  for (const char* field :
       {"laser_tv", "laser_rv", "forward_safety_dist", "side_safety_dist", "turn_axis"}) {
    cursor.Double(field);
  }
  record.timestamp_s = cursor.Trailer();
  return record;
}

CarmenParamRecord ParseParam(FieldCursor& cursor) {
  CarmenParamRecord record;
  record.name = cursor.Token("param_name");
  record.value = cursor.Token("param_value");
  return record;  // hostname and time stamp, if any, are of no use
}

}  // namespace

CarmenRecord ParseCarmenLine(std::string_view line) {
  std::size_t begin = 0;
  while (begin < line.size() && IsSpace(line[begin])) ++begin;
  if (begin == line.size() || line[begin] == '#') return CarmenCommentRecord{};
  std::size_t end = begin;
  while (end < line.size() && !IsSpace(line[end])) ++end;
  const std::string_view type = line.substr(begin, end - begin);
  FieldCursor cursor(type, line.substr(end));
  if (type == "FLASER") return ParseFlaser(cursor);
  if (type == "ROBOTLASER1") return ParseRobotLaser1(cursor);
  if (type == "ODOM") return ParseOdom(cursor);
  if (type == "PARAM") return ParseParam(cursor);
  return CarmenOtherRecord{std::string(type)};
}

namespace {

void AddRecord(CarmenRecord&& record, std::uint64_t line_number, CarmenLog& log) {
  if (auto* laser = std::get_if<CarmenLaserRecord>(&record)) {
    log.scans.push_back(std::move(*laser));
    log.scan_line_numbers.push_back(line_number);
  } else if (auto* odom = std::get_if<CarmenOdomRecord>(&record)) {
    log.odometry.push_back(*odom);
  } else if (auto* param = std::get_if<CarmenParamRecord>(&record)) {
    log.params[param->name] = param->value;
  } else if (auto* other = std::get_if<CarmenOtherRecord>(&record)) {
    ++log.skipped_types[other->type];
  } else {
    ++log.comment_line_count;
  }
}

}  // namespace

CarmenLog ReadCarmenLog(const std::filesystem::path& path, const ProgressCallback& progress) {
  TextLineReader reader(path);
  const std::string task = "reading " + path.filename().string();
  CarmenLog log;
  std::string_view line;
  while (reader.Next(&line)) {
    try {
      AddRecord(ParseCarmenLine(line), reader.line_number(), log);
    } catch (const BadInputError& error) {
      throw BadInputError(path.string() + ":" + std::to_string(reader.line_number()) + ": " +
                          error.what());
    }
    if (reader.line_number() % 4096 == 0) {
      ReportProgress(progress, {task, reader.bytes_consumed(), reader.file_size()});
    }
  }
  log.line_count = reader.line_number();
  ReportProgress(progress, {task, reader.file_size(), reader.file_size()});
  return log;
}

}  // namespace littermap::importers
