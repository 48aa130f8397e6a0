#include "capture/openni2_camera.hpp"

#include <OpenNI.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <deque>
#include <mutex>
#include <numbers>
#include <regex>

#include <opencv2/imgproc.hpp>

#include "capture/byte_stream.hpp"
#include "capture/clock_offset.hpp"
#include "core/error.hpp"

namespace littermap::capture {
namespace {

constexpr std::string_view kScheme = "openni2";

// OpenNI2 is started once per process and never shut down: Debian's DummyDevice driver leaves
// its frame threads running after a device closes, and they crash once OpenNI::shutdown()
// unloads the driver. Process exit releases everything.
void StartOpenNi() {
  static std::once_flag once;
  static std::string failure;
  std::call_once(once, [] {
    if (openni::OpenNI::initialize() != openni::STATUS_OK) {
      failure = openni::OpenNI::getExtendedError();
      if (failure.empty()) failure = "initialisation failed";
    }
  });
  if (!failure.empty()) throw InternalError("OpenNI2 cannot start: " + failure);
}

std::string OpenNiError() {
  std::string text = openni::OpenNI::getExtendedError();
  while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.pop_back();
  while (!text.empty() && (text.front() == '\t' || text.front() == ' ')) text.erase(0, 1);
  return text.empty() ? "no detail from OpenNI2" : text;
}

std::string DescribeMode(const openni::VideoMode& mode) {
  return std::to_string(mode.getResolutionX()) + "x" + std::to_string(mode.getResolutionY()) + "@" +
         std::to_string(mode.getFps());
}

// The mode of `format` nearest in size, then rate, to the one asked for.
openni::VideoMode NearestMode(const openni::SensorInfo& sensor, openni::PixelFormat format,
                              const Openni2CameraOptions& options, const std::string& what,
                              const std::string& uri) {
  const openni::Array<openni::VideoMode>& modes = sensor.getSupportedVideoModes();
  const openni::VideoMode* best = nullptr;
  long best_cost = 0;
  for (int i = 0; i < modes.getSize(); ++i) {
    const openni::VideoMode& mode = modes[i];
    if (mode.getPixelFormat() != format) continue;
    const long cost = 1000L * (std::labs(mode.getResolutionX() - options.width) +
                               std::labs(mode.getResolutionY() - options.height)) +
                      std::labs(mode.getFps() - options.fps);
    if (best == nullptr || cost < best_cost) {
      best = &mode;
      best_cost = cost;
    }
  }
  if (best == nullptr) throw UsageError(uri + ": the " + what + " stream offers no usable mode");
  return *best;
}

bool SameMode(const openni::VideoMode& a, const openni::VideoMode& b) {
  return a.getPixelFormat() == b.getPixelFormat() && a.getResolutionX() == b.getResolutionX() &&
         a.getResolutionY() == b.getResolutionY() && a.getFps() == b.getFps();
}

// Puts `stream` in the mode nearest to the one asked for and returns the mode it is in; notes
// when that is not the one asked for.
openni::VideoMode SetNearestMode(openni::VideoStream& stream, openni::PixelFormat format,
                                 const Openni2CameraOptions& options, const std::string& what,
                                 const std::string& uri, std::vector<std::string>& notes) {
  const openni::VideoMode wanted = NearestMode(stream.getSensorInfo(), format, options, what, uri);
  if (!SameMode(stream.getVideoMode(), wanted) &&
      stream.setVideoMode(wanted) != openni::STATUS_OK) {
    notes.push_back("cannot set the " + what + " mode " + DescribeMode(wanted) + " (" +
                    OpenNiError() + ")");
  }
  const openni::VideoMode mode = stream.getVideoMode();
  if (mode.getPixelFormat() != format) {
    throw UsageError(uri + ": the " + what + " stream stays in another pixel format");
  }
  if (mode.getResolutionX() != options.width || mode.getResolutionY() != options.height ||
      mode.getFps() != options.fps) {
    notes.push_back(what + " mode " + std::to_string(options.width) + "x" +
                    std::to_string(options.height) + "@" + std::to_string(options.fps) +
                    " not available; recording " + DescribeMode(mode));
  }
  return mode;
}

double Radians(double degrees) { return degrees * std::numbers::pi / 180.0; }

struct PendingFrame {
  cv::Mat image;
  std::uint64_t device_us = 0;
  TimestampNs host_ns = 0;
};

constexpr std::size_t kMaxPendingFrames = 4;

}  // namespace

struct Openni2Camera::Device {
  explicit Device(int clock_offset_frames) : clock(clock_offset_frames) {}
  ~Device() {
    depth->stop();
    colour->stop();
    if (driver_frees_unsafely) {
      // Debian's DummyDevice driver keeps its frame threads running after a stream is destroyed
      // or its device closed, and they crash the process within a frame period. Stopped and
      // left alone, they are harmless, so its objects are kept until the process ends.
      static_cast<void>(depth.release());
      static_cast<void>(colour.release());
      static_cast<void>(device.release());
      return;
    }
    depth->destroy();
    colour->destroy();
    device->close();
  }
  Device(const Device&) = delete;
  Device& operator=(const Device&) = delete;

  std::unique_ptr<openni::Device> device = std::make_unique<openni::Device>();
  std::unique_ptr<openni::VideoStream> depth = std::make_unique<openni::VideoStream>();
  std::unique_ptr<openni::VideoStream> colour = std::make_unique<openni::VideoStream>();
  bool driver_frees_unsafely = false;
  ClockOffset clock;
  msg::CameraInfo info;
  double half_period_us = 0;
  // Frames waiting for their partner from the other stream, oldest first, a few of each: the
  // driver may deliver one stream a frame or two ahead of the other.
  std::deque<PendingFrame> pending[2];  // depth, colour
};

void Openni2CameraOptions::Validate() const {
  if (width < 1 || height < 1 || fps < 1) throw UsageError("camera mode must be positive");
  if (clock_offset_frames < 1) throw UsageError("camera clock_offset_frames must be at least 1");
  if (!(fallback_horizontal_fov_deg > 0 && fallback_horizontal_fov_deg < 180) ||
      !(fallback_vertical_fov_deg > 0 && fallback_vertical_fov_deg < 180)) {
    throw UsageError("camera fallback field of view must be in (0, 180) degrees");
  }
}

Openni2Camera::Openni2Camera(std::string uri, const Openni2CameraOptions& options)
    : uri_(std::move(uri)), options_(options) {
  options_.Validate();
  if (uri_ != kScheme &&
      !(uri_.starts_with(std::string(kScheme) + ":") && uri_.size() > kScheme.size() + 1)) {
    throw UsageError("camera URI " + uri_ + " is neither openni2 nor openni2:DEVICE");
  }
}

Openni2Camera::~Openni2Camera() { Disconnect(); }

std::vector<std::string> Openni2Camera::ListDevices() {
  StartOpenNi();
  openni::Array<openni::DeviceInfo> devices;
  openni::OpenNI::enumerateDevices(&devices);
  std::vector<std::string> out;
  for (int i = 0; i < devices.getSize(); ++i) {
    out.push_back(std::string(devices[i].getUri()) + " (" + devices[i].getVendor() + " " +
                  devices[i].getName() + ")");
  }
  return out;
}

void Openni2Camera::Connect() {
  Disconnect();
  StartOpenNi();
  const std::string device_uri =
      uri_.size() > kScheme.size() ? uri_.substr(kScheme.size() + 1) : std::string();
  auto d = std::make_unique<Device>(options_.clock_offset_frames);
  if (d->device->open(device_uri.empty() ? openni::ANY_DEVICE : device_uri.c_str()) !=
      openni::STATUS_OK) {
    throw SensorDisconnectedError(uri_ + ": cannot open the device: " + OpenNiError());
  }
  d->driver_frees_unsafely = std::string(d->device->getDeviceInfo().getUri()) == "Dummy";
  if (d->depth->create(*d->device, openni::SENSOR_DEPTH) != openni::STATUS_OK ||
      d->colour->create(*d->device, openni::SENSOR_COLOR) != openni::STATUS_OK) {
    throw UsageError(uri_ + ": the device lacks a depth or colour stream: " + OpenNiError());
  }
  SetNearestMode(*d->depth, openni::PIXEL_FORMAT_DEPTH_1_MM, options_, "depth (millimetre)", uri_,
                 notes_);
  const openni::VideoMode colour_mode = SetNearestMode(*d->colour, openni::PIXEL_FORMAT_RGB888,
                                                       options_, "colour (RGB888)", uri_, notes_);
  if (!d->device->isImageRegistrationModeSupported(openni::IMAGE_REGISTRATION_DEPTH_TO_COLOR) ||
      d->device->setImageRegistrationMode(openni::IMAGE_REGISTRATION_DEPTH_TO_COLOR) !=
          openni::STATUS_OK) {
    notes_.push_back(
        "the device cannot register depth to colour; depth is recorded as the "
        "depth camera sees it");
  }
  if (d->device->setDepthColorSyncEnabled(true) != openni::STATUS_OK) {
    notes_.push_back(
        "the device cannot synchronise depth and colour frames; frames are paired "
        "by time stamp only");
  }
  if (d->depth->start() != openni::STATUS_OK || d->colour->start() != openni::STATUS_OK) {
    throw SensorDisconnectedError(uri_ + ": cannot start the streams: " + OpenNiError());
  }

  double hfov = d->colour->getHorizontalFieldOfView();
  double vfov = d->colour->getVerticalFieldOfView();
  if (!(hfov > 0 && hfov < std::numbers::pi) || !(vfov > 0 && vfov < std::numbers::pi)) {
    hfov = Radians(options_.fallback_horizontal_fov_deg);
    vfov = Radians(options_.fallback_vertical_fov_deg);
    char note[160];
    std::snprintf(note, sizeof note,
                  "the device reports no field of view; intrinsics assume %.1f x %.1f degrees",
                  options_.fallback_horizontal_fov_deg, options_.fallback_vertical_fov_deg);
    notes_.push_back(note);
  }
  const double w = colour_mode.getResolutionX(), h = colour_mode.getResolutionY();
  const double fx = w / 2.0 / std::tan(hfov / 2.0), fy = h / 2.0 / std::tan(vfov / 2.0);
  const double cx = (w - 1.0) / 2.0, cy = (h - 1.0) / 2.0;
  msg::CameraInfo& info = d->info;
  info.width = static_cast<std::uint32_t>(w);
  info.height = static_cast<std::uint32_t>(h);
  info.distortion_model = "plumb_bob";
  info.d.assign(5, 0.0);
  info.k = {fx, 0, cx, 0, fy, cy, 0, 0, 1};
  info.r = {1, 0, 0, 0, 1, 0, 0, 0, 1};
  info.p = {fx, 0, cx, 0, 0, fy, cy, 0, 0, 0, 1, 0};
  d->half_period_us = 0.5e6 / std::max(1, colour_mode.getFps());
  device_ = std::move(d);
}

std::optional<SensorSample> Openni2Camera::Read(double timeout_s) {
  if (!device_) throw SensorDisconnectedError(uri_ + ": not connected");
  Device& d = *device_;
  const TimestampNs deadline_ns = HostNowNs() + FromSeconds(timeout_s);
  for (;;) {
    const TimestampNs left_ns = deadline_ns - HostNowNs();
    if (left_ns <= 0) return std::nullopt;
    openni::VideoStream* streams[] = {d.depth.get(), d.colour.get()};
    int ready = -1;
    const openni::Status waited = openni::OpenNI::waitForAnyStream(
        streams, 2, &ready, static_cast<int>(std::max<TimestampNs>(1, left_ns / 1'000'000)));
    if (waited == openni::STATUS_TIME_OUT) return std::nullopt;
    if (waited != openni::STATUS_OK || ready < 0 || ready > 1) {
      throw SensorDisconnectedError(uri_ + ": waiting for frames failed: " + OpenNiError());
    }
    openni::VideoFrameRef frame;
    if (streams[ready]->readFrame(&frame) != openni::STATUS_OK || !frame.isValid()) {
      throw SensorDisconnectedError(uri_ + ": reading a frame failed: " + OpenNiError());
    }
    const TimestampNs arrival_ns = HostNowNs();
    const std::uint64_t device_us = frame.getTimestamp();
    const TimestampNs host_ns =
        d.clock.ToHost(static_cast<TimestampNs>(device_us) * 1000, arrival_ns);
    const cv::Mat view(frame.getHeight(), frame.getWidth(), ready == 0 ? CV_16UC1 : CV_8UC3,
                       const_cast<void*>(frame.getData()),
                       static_cast<std::size_t>(frame.getStrideInBytes()));
    PendingFrame arrived;
    arrived.device_us = device_us;
    arrived.host_ns = host_ns;
    if (ready == 0) {
      arrived.image = view.clone();
    } else {
      cv::cvtColor(view, arrived.image, cv::COLOR_RGB2BGR);
    }
    // Pair with the other stream's frame of the same moment, dropping what is older than it.
    std::deque<PendingFrame>& others = d.pending[1 - ready];
    const auto partner = std::find_if(others.begin(), others.end(), [&](const PendingFrame& f) {
      return std::abs(static_cast<double>(f.device_us) - static_cast<double>(device_us)) <=
             d.half_period_us;
    });
    if (partner == others.end()) {
      std::deque<PendingFrame>& mine = d.pending[ready];
      mine.push_back(std::move(arrived));
      if (mine.size() > kMaxPendingFrames) mine.pop_front();
      continue;
    }
    PendingFrame& depth = ready == 0 ? arrived : *partner;
    PendingFrame& colour = ready == 0 ? *partner : arrived;
    RgbdFrame out;
    out.stamp_ns = colour.host_ns;
    out.colour_bgr = std::move(colour.image);
    out.depth_mm = std::move(depth.image);
    out.camera_info = d.info;
    others.erase(others.begin(), partner + 1);
    std::erase_if(d.pending[ready],
                  [&](const PendingFrame& f) { return f.device_us <= device_us; });
    return out;
  }
}

void Openni2Camera::Disconnect() { device_.reset(); }

std::vector<std::string> Openni2Camera::TakeNotes() { return std::exchange(notes_, {}); }

Openni2CameraOptions ParseCameraMode(const std::string& text) {
  static const std::regex kMode(R"((\d{2,5})x(\d{2,5})@(\d{1,3}))");
  std::smatch match;
  if (!std::regex_match(text, match, kMode)) {
    throw UsageError("--camera-mode '" + text + "': expected WIDTHxHEIGHT@FPS, e.g. 640x480@30");
  }
  Openni2CameraOptions options;
  options.width = std::stoi(match[1]);
  options.height = std::stoi(match[2]);
  options.fps = std::stoi(match[3]);
  options.Validate();
  return options;
}

}  // namespace littermap::capture
