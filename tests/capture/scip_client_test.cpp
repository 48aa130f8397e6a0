// SCIP 2.0 protocol functions (worked examples of the specification, round trips) and the client
// against the emulator over loopback TCP and a pseudo-terminal.

#include <arpa/inet.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "capture/scip_client.hpp"
#include "capture/scip_protocol.hpp"
#include "core/error.hpp"
#include "support/scip_emulator.hpp"

namespace littermap::capture {
namespace {

using test::ScipEmulator;
using test::ScipEmulatorOptions;
using test::ScipEmulatorRangeMm;

constexpr double kStepRad = 2 * std::numbers::pi / 1440;

// The message of the BadInputError `f` throws ("" and a test failure when it throws none).
template <typename F>
std::string BadInputMessage(F&& f) {
  try {
    f();
  } catch (const SensorDisconnectedError& e) {
    ADD_FAILURE() << "disconnect instead of bad input: " << e.what();
    return "";
  } catch (const BadInputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no BadInputError";
  return "";
}

ScipSensorParameters Utm30lx() {
  ScipSensorParameters p;
  p.model = "UTM-30LX";
  p.min_distance_mm = 23;
  p.max_distance_mm = 60000;
  p.steps_per_revolution = 1440;
  p.first_step = 0;
  p.last_step = 1080;
  p.front_step = 540;
  p.motor_speed_rpm = 2400;
  return p;
}

// ---------------------------------------------------------------- protocol

TEST(ScipProtocol, DecodesTheSpecificationExamples) {
  EXPECT_EQ(ScipDecode("CB"), 1234u);        // §6.1, 2-character encoding
  EXPECT_EQ(ScipDecode("1Dh"), 5432u);       // §6.2, 3-character encoding
  EXPECT_EQ(ScipDecode("m2@0"), 16000000u);  // §6.3, 4-character encoding
  EXPECT_EQ(ScipEncode(1234, 2), "CB");
  EXPECT_EQ(ScipEncode(5432, 3), "1Dh");
  EXPECT_EQ(ScipEncode(16000000, 4), "m2@0");
}

TEST(ScipProtocol, EncodingRoundTripsAtTheLimits) {
  for (const std::uint32_t v : {0u, 1u, 63u, 64u, 4095u})
    EXPECT_EQ(ScipDecode(ScipEncode(v, 2)), v);
  for (const std::uint32_t v : {0u, 4096u, 65533u, 262143u}) {
    EXPECT_EQ(ScipDecode(ScipEncode(v, 3)), v);
  }
  EXPECT_EQ(ScipDecode(ScipEncode(0xFFFFFF, 4)), 0xFFFFFFu);
  EXPECT_THROW(ScipEncode(4096, 2), UsageError);
  EXPECT_THROW(ScipDecode("0p"), BadInputError);  // 0x70 is above 0x6F
  EXPECT_THROW(ScipDecode("/0"), BadInputError);
}

TEST(ScipProtocol, ChecksumsOfKnownLines) {
  EXPECT_EQ(ScipChecksum("00"), 'P');       // "00P": success
  EXPECT_EQ(ScipChecksum("99"), 'b');       // "99b": scan frame
  EXPECT_EQ(ScipChecksum("0E"), 'e');       // "0Ee": undefined command
  EXPECT_EQ(ScipChecksum("DMIN:23"), '7');  // UTM-30LX PP line "DMIN:23;7"
  EXPECT_EQ(WithScipChecksum("1Dh"), std::string("1Dh") + ScipChecksum("1Dh"));
}

TEST(ScipProtocol, StatusLineVariants) {
  EXPECT_EQ(ParseScipStatus("0", "t").code, "0");
  EXPECT_FALSE(ParseScipStatus("0", "t").has_checksum);
  EXPECT_EQ(ParseScipStatus("00", "t").code, "00");
  EXPECT_EQ(ParseScipStatus("00P", "t").code, "00");
  EXPECT_TRUE(ParseScipStatus("00P", "t").has_checksum);
  EXPECT_EQ(ParseScipStatus("0Ee", "t").code, "0E");
  EXPECT_EQ(ParseScipStatus("99b", "t").code, "99");
  EXPECT_NE(BadInputMessage([] { ParseScipStatus("00Q", "ctx"); }).find("\"00Q\""),
            std::string::npos);
  EXPECT_THROW(ParseScipStatus("0E", "t"), BadInputError);  // an error code needs its sum
  EXPECT_THROW(ParseScipStatus("00P1", "t"), BadInputError);
  EXPECT_THROW(ParseScipStatus("", "t"), BadInputError);
}

TEST(ScipProtocol, WhichStatusesMeanSuccessForWhichCommand) {
  for (const char* ok : {"0", "00", "0E"}) EXPECT_TRUE(ScipStatusAccepted("SCIP2.0", ok)) << ok;
  EXPECT_FALSE(ScipStatusAccepted("SCIP2.0", "01"));
  EXPECT_TRUE(ScipStatusAccepted("MD", "00"));
  EXPECT_TRUE(ScipStatusAccepted("MD", "99"));
  EXPECT_FALSE(ScipStatusAccepted("MD", "0E"));
  EXPECT_FALSE(ScipStatusAccepted("MD", "50"));
  EXPECT_TRUE(ScipStatusAccepted("PP", "00"));
  EXPECT_FALSE(ScipStatusAccepted("PP", "0E"));
  EXPECT_FALSE(ScipStatusAccepted("PP", "0"));
  EXPECT_FALSE(ScipStatusAccepted("QT", "99"));
  EXPECT_TRUE(ScipStatusAccepted("BM", "02"));  // laser already on
}

TEST(ScipProtocol, SplitsAndParsesAReply) {
  const auto lines = SplitScipReply("VV\n00P\nPROT:SCIP 2.0;N\n\n", "t");
  ASSERT_EQ(lines.size(), 3u);
  EXPECT_EQ(lines[2], "PROT:SCIP 2.0;N");
  const ScipReply reply = ParseScipReply(lines, "VV", "t");
  EXPECT_EQ(reply.status.code, "00");
  ASSERT_EQ(reply.body.size(), 1u);
  EXPECT_THROW(SplitScipReply("VV\n00P\n", "t"), BadInputError);
  EXPECT_NE(BadInputMessage([&] { ParseScipReply(lines, "PP", "ctx"); }).find("\"VV\""),
            std::string::npos);
}

TEST(ScipProtocol, ASumThatIsItselfASemicolonParses) {
  // The sums of "DMIN:27" and "SERI:H1000005" are both ';' (sum & 0x3F = 11).
  ASSERT_EQ(ScipChecksum("DMIN:27"), ';');
  const std::vector<std::string> version = {"SERI:H1000005;;"};
  EXPECT_EQ(ParseScipInfo(version, "t").at("SERI"), "H1000005");
  EXPECT_THROW(ParseScipInfo(std::vector<std::string>{"SERI:H1000005;"}, "t"), BadInputError);
}

TEST(ScipProtocol, ParsesParametersWithEitherSumConvention) {
  auto line = [](const std::string& text, bool with_semicolon) {
    return text + ";" + ScipChecksum(with_semicolon ? text + ";" : text);
  };
  std::vector<std::string> body = {line("MODL:UTM-30LX", false), line("DMIN:23", false),
                                   line("DMAX:60000", true),     line("ARES:1440", true),
                                   line("AMIN:0", false),        line("AMAX:1080", false),
                                   line("AFRT:540", true),       line("SCAN:2400", false)};
  const ScipSensorParameters p = ParseScipParameters(body, "t");
  EXPECT_EQ(p.model, "UTM-30LX");
  EXPECT_EQ(p.min_distance_mm, 23);
  EXPECT_EQ(p.max_distance_mm, 60000);
  EXPECT_EQ(p.steps_per_revolution, 1440);
  EXPECT_EQ(p.first_step, 0);
  EXPECT_EQ(p.last_step, 1080);
  EXPECT_EQ(p.front_step, 540);
  EXPECT_EQ(p.motor_speed_rpm, 2400);
  EXPECT_DOUBLE_EQ(p.scan_period_s(), 0.025);

  std::vector<std::string> corrupt = body;
  corrupt[2].back() = corrupt[2].back() == '0' ? '1' : '0';
  const std::string message = BadInputMessage([&] { ParseScipParameters(corrupt, "ctx"); });
  EXPECT_NE(message.find("checksum"), std::string::npos) << message;
  EXPECT_NE(message.find(corrupt[2]), std::string::npos) << message;

  std::vector<std::string> missing(body.begin(), body.end() - 1);
  EXPECT_NE(BadInputMessage([&] { ParseScipParameters(missing, "ctx"); }).find("SCAN"),
            std::string::npos);
}

TEST(ScipProtocol, DecodesAFrameWhoseReadingsStraddleLines) {
  std::vector<std::uint32_t> ranges;
  std::string data;
  for (std::uint32_t i = 0; i < 30; ++i) {  // 90 characters: 64 + 26, reading 21 split
    ranges.push_back(i * 8000 + 17);
    data += ScipEncode(ranges.back(), 3);
  }
  const std::vector<std::string> body = {WithScipChecksum(ScipEncode(123456, 4)),
                                         WithScipChecksum(data.substr(0, 64)),
                                         WithScipChecksum(data.substr(64))};
  const ScipScanData scan = DecodeScipScanData(body, 3, "t");
  EXPECT_EQ(scan.timestamp_ms, 123456u);
  EXPECT_EQ(scan.ranges_mm, ranges);

  const std::vector<std::string> too_long = {body[0], WithScipChecksum(data.substr(0, 66))};
  EXPECT_NE(BadInputMessage([&] { DecodeScipScanData(too_long, 3, "ctx"); }).find("longer"),
            std::string::npos);
  // MS/GS frames: 2 characters a reading.
  const std::vector<std::string> two = {body[0], WithScipChecksum("CB1D")};
  EXPECT_EQ(DecodeScipScanData(two, 2, "t").ranges_mm, (std::vector<std::uint32_t>{1234, 84}));
}

TEST(ScipProtocol, LaserScanAnglesAndNoEcho) {
  const ScipSensorParameters utm = Utm30lx();
  const std::vector<std::uint32_t> mm = {1, 22, 23, 1234, 60000};
  const LaserScan scan = ScipToLaserScan(utm, {0, 4, 1}, mm, 42);
  EXPECT_EQ(scan.stamp_ns, 42);
  EXPECT_DOUBLE_EQ(scan.angle_min_rad, -0.75 * std::numbers::pi);  // step 0: 135° right
  EXPECT_DOUBLE_EQ(scan.angle_increment_rad, kStepRad);
  EXPECT_DOUBLE_EQ(scan.range_min_m, 0.023);
  EXPECT_DOUBLE_EQ(scan.range_max_m, 60.0);
  EXPECT_DOUBLE_EQ(scan.scan_time_s, 0.025);
  ASSERT_EQ(scan.ranges_m.size(), 5u);
  EXPECT_EQ(scan.ranges_m[0], std::numeric_limits<float>::infinity());  // error code 1
  EXPECT_EQ(scan.ranges_m[1], std::numeric_limits<float>::infinity());  // below DMIN
  EXPECT_FLOAT_EQ(scan.ranges_m[2], 0.023f);
  EXPECT_FLOAT_EQ(scan.ranges_m[3], 1.234f);
  EXPECT_FALSE(scan.IsValid(0));
  EXPECT_TRUE(scan.IsValid(2));

  const LaserScan full =
      ScipToLaserScan(utm, {0, 1080, 1}, std::vector<std::uint32_t>(1081, 500), 0);
  EXPECT_NEAR(full.AngleOf(540), 0.0, 1e-12);  // AFRT is straight ahead
  EXPECT_NEAR(full.angle_max_rad(), 0.75 * std::numbers::pi, 1e-12);

  // Clusters of 3 steps sit at their middle step.
  const LaserScan clustered =
      ScipToLaserScan(utm, {0, 1080, 3}, std::vector<std::uint32_t>(361, 500), 0);
  EXPECT_DOUBLE_EQ(clustered.angle_min_rad, (1 - 540) * kStepRad);
  EXPECT_DOUBLE_EQ(clustered.angle_increment_rad, 3 * kStepRad);
  EXPECT_EQ((ScipRangeRequest{0, 1080, 3}.reading_count()), 361u);
}

TEST(ScipProtocol, MdCommandText) {
  EXPECT_EQ(ScipMdCommand({0, 1080, 1}, 0, 0), "MD0000108001000");
  EXPECT_EQ(ScipMdCommand({44, 725, 2}, 1, 5), "MD0044072502105");
  EXPECT_THROW(ScipMdCommand({10, 5, 1}, 0, 0), UsageError);
}

// ---------------------------------------------------------------- client against the emulator

ScipClientOptions FastOptions() {
  ScipClientOptions options;
  options.reply_timeout_s = 1.0;
  options.scan_timeout_s = 1.0;
  return options;
}

// Checks every reading and angle of `scan` against the emulator's known ranges.
void ExpectEmulatorScan(const ScipScan& s, const ScipEmulatorOptions& emulator) {
  const int frame = static_cast<int>((s.sensor_time_unwrapped_ms - emulator.first_timestamp_ms) /
                                     emulator.scan_period_ms);
  ASSERT_EQ(s.scan.ranges_m.size(), 1081u);
  EXPECT_DOUBLE_EQ(s.scan.angle_min_rad, -540 * kStepRad);
  EXPECT_DOUBLE_EQ(s.scan.angle_increment_rad, kStepRad);
  int mismatches = 0;
  for (int step = 0; step <= 1080; ++step) {
    const std::uint32_t mm = ScipEmulatorRangeMm(step, frame);
    const float expected =
        mm < 23 ? std::numeric_limits<float>::infinity() : static_cast<float>(mm / 1000.0);
    if (s.scan.ranges_m[step] != expected) ++mismatches;
  }
  EXPECT_EQ(mismatches, 0) << "frame " << frame;
}

class ScipClientLink : public ::testing::TestWithParam<ScipEmulator::Link> {};

TEST_P(ScipClientLink, HandshakeAcceptsEveryStatusVariant) {
  const std::vector<std::pair<std::string, std::string>> variants = {
      {"0", "0"}, {"00", "00"}, {"00P", "00"}, {"0Ee", "0E"}};
  for (const auto& [line, code] : variants) {
    ScipEmulatorOptions options;
    options.scip2_status_line = line;
    ScipEmulator emulator(GetParam(), options);
    ScipClient client(emulator.uri(), FastOptions());
    EXPECT_EQ(client.handshake().scip2_status, code) << line;
    EXPECT_EQ(client.handshake().version.at("PROT"), "SCIP 2.0");
    EXPECT_EQ(client.handshake().version.at("SERI"), "H0000001");
    const ScipSensorParameters& p = client.handshake().sensor;
    EXPECT_EQ(p.model, "UTM-30LX(Hokuyo Automatic Co.,Ltd.)");
    EXPECT_EQ(p.steps_per_revolution, 1440);
    EXPECT_EQ(p.first_step, 0);
    EXPECT_EQ(p.last_step, 1080);
    EXPECT_EQ(p.front_step, 540);
    EXPECT_EQ(p.min_distance_mm, 23);
    EXPECT_EQ(p.max_distance_mm, 60000);
    EXPECT_EQ(p.motor_speed_rpm, 2400);
    EXPECT_EQ(emulator.commands(), (std::vector<std::string>{"QT", "SCIP2.0", "VV", "PP"}));
  }
}

TEST_P(ScipClientLink, StreamsScansWithExactRangesAnglesAndTimes) {
  ScipEmulatorOptions options;
  ScipEmulator emulator(GetParam(), options);
  ScipClient client(emulator.uri(), FastOptions());
  client.StartMeasurement();
  std::vector<ScipScan> scans;
  for (int i = 0; i < 6; ++i) scans.push_back(client.ReadScan());
  client.Stop();
  for (std::size_t i = 0; i < scans.size(); ++i) {
    const ScipScan& s = scans[i];
    ExpectEmulatorScan(s, options);
    EXPECT_EQ(s.sensor_time_ms, options.first_timestamp_ms + 10 * i);
    // The offset is the least delay seen so far: a stamp never follows its own arrival, and the
    // emulator sends on time, so it precedes it by little.
    EXPECT_LE(s.scan.stamp_ns, s.arrival_ns);
    EXPECT_LT(s.arrival_ns - s.scan.stamp_ns, 250'000'000);
    if (i > 0) {
      EXPECT_GT(s.scan.stamp_ns, scans[i - 1].scan.stamp_ns);
      EXPECT_EQ(s.sensor_time_unwrapped_ms - scans[i - 1].sensor_time_unwrapped_ms, 10);
    }
  }
  const auto commands = emulator.commands();
  ASSERT_GE(commands.size(), 6u);
  EXPECT_EQ(commands[4], "MD0000108001000");
  EXPECT_EQ(commands.back(), "QT");
}

TEST_P(ScipClientLink, DisconnectMidRunIsReportedAsADisconnect) {
  ScipEmulatorOptions options;
  options.disconnect_after_frames = 3;
  ScipEmulator emulator(GetParam(), options);
  ScipClient client(emulator.uri(), FastOptions());
  client.StartMeasurement();
  for (int i = 0; i < 3; ++i) ExpectEmulatorScan(client.ReadScan(), options);
  try {
    client.ReadScan();
    ADD_FAILURE() << "no error after the disconnect";
  } catch (const SensorDisconnectedError& e) {
    EXPECT_NE(std::string(e.what()).find(emulator.uri()), std::string::npos) << e.what();
  }
}

INSTANTIATE_TEST_SUITE_P(ScipLinks, ScipClientLink,
                         ::testing::Values(ScipEmulator::Link::kTcp,
                                           ScipEmulator::Link::kPseudoTerminal),
                         [](const auto& link) {
                           return link.param == ScipEmulator::Link::kTcp ? "Tcp" : "PseudoTerminal";
                         });

TEST(ScipClient, ReconnectsAfterADisconnect) {
  ScipEmulatorOptions options;
  options.disconnect_after_frames = 2;
  ScipEmulator emulator(ScipEmulator::Link::kTcp, options);
  {
    ScipClient client(emulator.uri(), FastOptions());
    client.StartMeasurement();
    client.ReadScan();
    client.ReadScan();
    EXPECT_THROW(client.ReadScan(), SensorDisconnectedError);
  }  // the destructor's QT meets a closed connection and stays quiet
  ScipClient again(emulator.uri(), FastOptions());
  again.StartMeasurement();
  ExpectEmulatorScan(again.ReadScan(), options);
}

TEST(ScipClient, StopsASensorLeftStreaming) {
  // An earlier process started MD on the serial line and died: frames are still coming when the
  // next client opens the device; its handshake must stop them and skip what is in flight.
  ScipEmulatorOptions options;
  ScipEmulator emulator(ScipEmulator::Link::kPseudoTerminal, options);
  const std::string device = emulator.uri().substr(5);
  const int fd = ::open(device.c_str(), O_RDWR | O_NOCTTY);
  ASSERT_GE(fd, 0);
  const std::string md = "MD0000108001000\n";
  ASSERT_EQ(::write(fd, md.data(), md.size()), static_cast<ssize_t>(md.size()));
  ::close(fd);
  for (int i = 0; i < 200 && emulator.frames_sent() < 3; ++i) ::usleep(5000);
  ASSERT_GE(emulator.frames_sent(), 3);
  ScipClient client(emulator.uri(), FastOptions());
  EXPECT_EQ(client.handshake().sensor.last_step, 1080);
  client.StartMeasurement();
  ExpectEmulatorScan(client.ReadScan(), options);
}

TEST(ScipClient, ASensorThatIgnoresQtIsADisconnectNotAHang) {
  ScipEmulatorOptions options;
  options.ignores_qt = true;
  options.scan_period_ms = 1;
  ScipEmulator emulator(ScipEmulator::Link::kTcp, options);
  ScipClient client(emulator.uri(), FastOptions());
  client.StartMeasurement();
  client.ReadScan();
  try {
    client.Stop();
    FAIL() << "Stop returned although the sensor never answered QT";
  } catch (const SensorDisconnectedError& e) {
    EXPECT_NE(std::string(e.what()).find("does not answer QT"), std::string::npos) << e.what();
  }
}

TEST(ScipClient, UnwrapsTheSensorClock) {
  ScipEmulatorOptions options;
  options.first_timestamp_ms = (1u << 24) - 25;  // wraps between the 3rd and 4th frame
  ScipEmulator emulator(ScipEmulator::Link::kTcp, options);
  ScipClientOptions client_options = FastOptions();
  client_options.clock_offset_scans = 1;  // hold the first offset: stamps follow the sensor
  ScipClient client(emulator.uri(), client_options);
  client.StartMeasurement();
  std::vector<ScipScan> scans;
  for (int i = 0; i < 6; ++i) scans.push_back(client.ReadScan());
  EXPECT_EQ(scans[2].sensor_time_ms, (1u << 24) - 5);
  EXPECT_EQ(scans[3].sensor_time_ms, 5u);
  for (std::size_t i = 1; i < scans.size(); ++i) {
    EXPECT_EQ(scans[i].sensor_time_unwrapped_ms, scans[0].sensor_time_unwrapped_ms + 10 * i);
    EXPECT_EQ(scans[i].scan.stamp_ns - scans[0].scan.stamp_ns,
              static_cast<TimestampNs>(i) * 10'000'000);
  }
  EXPECT_EQ(scans[0].scan.stamp_ns, scans[0].arrival_ns);
  // Host time within a tolerance: the emulator keeps its 10 ms period in real time.
  EXPECT_LT(std::llabs(scans[5].arrival_ns - scans[5].scan.stamp_ns), 250'000'000);
}

TEST(ScipClient, BadChecksumNamesTheLine) {
  ScipEmulatorOptions options;
  options.bad_checksum_frame = 1;
  ScipEmulator emulator(ScipEmulator::Link::kTcp, options);
  ScipClient client(emulator.uri(), FastOptions());
  client.StartMeasurement();
  ExpectEmulatorScan(client.ReadScan(), options);
  // The second data line of frame 1: readings 21.33..42.66, i.e. characters 64..127.
  std::string data;
  for (int step = 0; step <= 1080; ++step) data += ScipEncode(ScipEmulatorRangeMm(step, 1), 3);
  std::string bad = WithScipChecksum(data.substr(64, 64));
  bad.back() = static_cast<char>(0x30 + ((bad.back() - 0x30 + 1) & 0x3F));
  const std::string message = BadInputMessage([&] { client.ReadScan(); });
  EXPECT_NE(message.find("checksum error"), std::string::npos) << message;
  EXPECT_NE(message.find("\"" + bad + "\""), std::string::npos) << message;
  EXPECT_NE(message.find(emulator.uri()), std::string::npos) << message;
}

TEST(ScipClient, OverlongDataLineIsMalformed) {
  ScipEmulatorOptions options;
  options.long_line_frame = 0;
  ScipEmulator emulator(ScipEmulator::Link::kPseudoTerminal, options);
  ScipClient client(emulator.uri(), FastOptions());
  client.StartMeasurement();
  const std::string message = BadInputMessage([&] { client.ReadScan(); });
  EXPECT_NE(message.find("longer than 64"), std::string::npos) << message;
  EXPECT_NE(message.find(emulator.uri()), std::string::npos) << message;
}

TEST(ScipClient, BadChecksumInParametersFailsTheHandshake) {
  ScipEmulatorOptions options;
  options.bad_checksum_pp = true;
  ScipEmulator emulator(ScipEmulator::Link::kTcp, options);
  const std::string message =
      BadInputMessage([&] { ScipClient client(emulator.uri(), FastOptions()); });
  EXPECT_NE(message.find("PP reply"), std::string::npos) << message;
  EXPECT_NE(message.find("DMAX:60000;"), std::string::npos) << message;
}

TEST(ScipClient, RejectedScip2SwitchFailsTheHandshake) {
  ScipEmulatorOptions options;
  options.scip2_status_line = WithScipChecksum("01");
  ScipEmulator emulator(ScipEmulator::Link::kTcp, options);
  const std::string message =
      BadInputMessage([&] { ScipClient client(emulator.uri(), FastOptions()); });
  EXPECT_NE(message.find("status 01"), std::string::npos) << message;
}

TEST(ScipClient, SensorErrorStatusIsReported) {
  ScipEmulatorOptions options;
  options.error_status_frame = 1;
  ScipEmulator emulator(ScipEmulator::Link::kTcp, options);
  ScipClient client(emulator.uri(), FastOptions());
  client.StartMeasurement();
  client.ReadScan();
  const std::string message = BadInputMessage([&] { client.ReadScan(); });
  EXPECT_NE(message.find("status 50"), std::string::npos) << message;
}

TEST(ScipClient, SilentSensorTimesOutAsADisconnect) {
  // A listening socket nobody serves: connect succeeds, no reply ever comes.
  const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
  ASSERT_GE(fd, 0);
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  ASSERT_EQ(::bind(fd, reinterpret_cast<sockaddr*>(&address), sizeof address), 0);
  ASSERT_EQ(::listen(fd, 1), 0);
  socklen_t length = sizeof address;
  ::getsockname(fd, reinterpret_cast<sockaddr*>(&address), &length);
  const std::string uri = "scip://127.0.0.1:" + std::to_string(ntohs(address.sin_port));
  ScipClientOptions options = FastOptions();
  options.reply_timeout_s = 0.1;
  EXPECT_THROW(ScipClient(uri, options), SensorDisconnectedError);
  ::close(fd);
  // Nobody listening any more: connection refused.
  EXPECT_THROW(ScipClient(uri, options), SensorDisconnectedError);
}

TEST(ScipClient, RejectsOtherUris) {
  EXPECT_THROW(ScipClient("tcp://127.0.0.1:10940"), UsageError);
  EXPECT_THROW(ScipClient("scip://127.0.0.1"), UsageError);
  EXPECT_THROW(ScipClient("scip:/dev/null"), UsageError);  // not a terminal
}

}  // namespace
}  // namespace littermap::capture
