#include "reports/site_map_figure.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "core/error.hpp"
#include "heatmap/density_preview.hpp"
#include "reports/class_palette.hpp"

namespace littermap::reports {
namespace {

const cv::Scalar kInk(30, 30, 30);
const cv::Scalar kWhite(255, 255, 255);

struct PixelMapping {
  const heatmap::GridGeometry* grid;
  double pixels_per_m;
  cv::Point operator()(const db::PointXY& crs) const {
    return {static_cast<int>(std::lround((crs.x - grid->min_x_m) * pixels_per_m)),
            static_cast<int>(std::lround((grid->max_y_m - crs.y) * pixels_per_m))};
  }
};

// A bar of 1, 2 or 5 times a power of ten metres, about a fifth of the map wide.
double ScaleBarLengthM(const cv::Mat& image, double pixels_per_m) {
  const double wanted_m = image.cols / 5.0 / pixels_per_m;
  const double power = std::pow(10.0, std::floor(std::log10(wanted_m)));
  double length_m = power;
  for (const double step : {2.0, 5.0, 10.0}) {
    if (step * power <= wanted_m) length_m = step * power;
  }
  return length_m;
}

cv::Rect ScaleBarBox(const cv::Mat& image, double pixels_per_m) {
  const int length_px =
      static_cast<int>(std::lround(ScaleBarLengthM(image, pixels_per_m) * pixels_per_m));
  const cv::Point left(14, image.rows - 16);
  return {left + cv::Point(-8, -30), left + cv::Point(length_px + 8, 8)};
}

cv::Rect NorthArrowBox(const cv::Mat& image) {
  const cv::Point tip(image.cols - 28, 14);
  return {tip + cv::Point(-18, -8), tip + cv::Point(18, 50)};
}

void DrawScaleBar(cv::Mat& image, double pixels_per_m) {
  const double length_m = ScaleBarLengthM(image, pixels_per_m);
  const int length_px = static_cast<int>(std::lround(length_m * pixels_per_m));
  const cv::Point left(14, image.rows - 16);
  cv::rectangle(image, ScaleBarBox(image, pixels_per_m), kWhite, cv::FILLED);
  cv::rectangle(image, left + cv::Point(0, -6), left + cv::Point(length_px / 2, 0), kInk,
                cv::FILLED);
  cv::rectangle(image, left + cv::Point(0, -6), left + cv::Point(length_px, 0), kInk, 1);
  const std::string label =
      (length_m >= 1 ? std::to_string(static_cast<int>(length_m)) : std::to_string(length_m)) +
      " m";
  cv::putText(image, label, left + cv::Point(0, -12), cv::FONT_HERSHEY_SIMPLEX, 0.5, kInk, 1,
              cv::LINE_AA);
}

void DrawNorthArrow(cv::Mat& image) {
  const cv::Point tip(image.cols - 28, 14);
  cv::rectangle(image, NorthArrowBox(image), kWhite, cv::FILLED);
  const std::array<cv::Point, 3> arrow = {tip, tip + cv::Point(-10, 26), tip + cv::Point(10, 26)};
  cv::fillConvexPoly(image, arrow.data(), 3, kInk, cv::LINE_AA);
  cv::putText(image, "N", tip + cv::Point(-7, 46), cv::FONT_HERSHEY_SIMPLEX, 0.6, kInk, 2,
              cv::LINE_AA);
}

// An item's marker: a dark disc of 6 px radius under one of 4 px in the class's colour, both
// anti-aliased. OpenCV draws it once, on black and on white; each item then blends that picture
// onto the map, which is what drawing it there does (an anti-aliased fill is, per channel,
// colour x cover + background x (1 - cover)), to within a grey level. A city park's report draws a
// million markers, and two anti-aliased circles cost about a microsecond and a half each.
class Marker {
 public:
  explicit Marker(const cv::Scalar& bgr) {
    cv::Mat on_black(kSize, kSize, CV_8UC3, cv::Scalar::all(0));
    cv::Mat on_white(kSize, kSize, CV_8UC3, cv::Scalar::all(255));
    for (cv::Mat* patch : {&on_black, &on_white}) {
      cv::circle(*patch, {kHalf, kHalf}, 6, kInk, cv::FILLED, cv::LINE_AA);
      cv::circle(*patch, {kHalf, kHalf}, 4, bgr, cv::FILLED, cv::LINE_AA);
    }
    for (int r = 0; r < kSize; ++r) {
      for (int c = 0; c < kSize; ++c) {
        const auto& black = on_black.at<cv::Vec3b>(r, c);
        const auto& white = on_white.at<cv::Vec3b>(r, c);
        for (int k = 0; k < 3; ++k) {
          const int background = white[k] - black[k];  // 255: untouched, 0: covered
          if (background == 255) continue;
          pixels_.push_back({r - kHalf, c - kHalf, k, black[k], background});
        }
      }
    }
  }

  void Draw(cv::Mat& image, const cv::Point& centre) const {
    const bool inside = centre.x >= kHalf && centre.y >= kHalf && centre.x + kHalf < image.cols &&
                        centre.y + kHalf < image.rows;
    for (const Pixel& p : pixels_) {
      const int r = centre.y + p.dr, c = centre.x + p.dc;
      if (!inside && (r < 0 || c < 0 || r >= image.rows || c >= image.cols)) continue;
      std::uint8_t& value = image.ptr<std::uint8_t>(r)[3 * c + p.channel];
      value = static_cast<std::uint8_t>(p.colour + (p.background * value + 127) / 255);
    }
  }

 private:
  static constexpr int kHalf = 8;  // the 6 px disc and its anti-aliased edge
  static constexpr int kSize = 2 * kHalf + 1;
  struct Pixel {
    int dr, dc, channel;
    int colour;      // what the marker adds
    int background;  // how much of the background shows through, of 255
  };
  std::vector<Pixel> pixels_;
};

void DrawItems(cv::Mat& image, const SiteReport& report, const PixelMapping& to_pixel) {
  std::map<std::string, Marker, std::less<>> markers;
  for (const db::ItemRecord& item : report.heatmap.items) {
    auto marker = markers.find(item.class_name);
    if (marker == markers.end()) {
      marker = markers.emplace(item.class_name, Marker(StyleOf(item.class_name).bgr)).first;
    }
    marker->second.Draw(image, to_pixel(report.frame.ToCrs(item.site_xy)));
  }
}

constexpr int kLabelHeightPx = 26;
constexpr double kLabelFontScale = 0.55;

// A hotspot's number as a pill: wide enough for its digits.
cv::Size LabelSize(const std::string& text) {
  int baseline = 0;
  const cv::Size text_size =
      cv::getTextSize(text, cv::FONT_HERSHEY_SIMPLEX, kLabelFontScale, 2, &baseline);
  return {std::max(kLabelHeightPx, text_size.width + 12), kLabelHeightPx};
}

bool Free(const cv::Rect& box, const cv::Rect& map, const std::vector<cv::Rect>& taken) {
  return (box & map) == box && std::none_of(taken.begin(), taken.end(), [&](const cv::Rect& other) {
           return (box & other).area() > 0;
         });
}

// Where a hotspot's number goes: beside its outline, in the first of eight directions (north-east
// first) and rings outwards where its box covers no box placed before (numbers of denser
// hotspots, the north arrow, the scale bar) and stays on the map; failing that, the free place
// nearest the hotspot anywhere on the map. `anchor`: the outline point a leader line starts at.
cv::Rect PlaceLabel(const cv::Mat& image, cv::Point centre, const std::vector<cv::Point>& outline,
                    cv::Size size, const std::vector<cv::Rect>& taken, cv::Point* anchor) {
  const cv::Rect map(0, 0, image.cols, image.rows);
  const auto box_at = [&](cv::Point at) {
    return cv::Rect(at.x - size.width / 2, at.y - size.height / 2, size.width, size.height);
  };
  const auto nearest_outline_point = [&](cv::Point at) {
    cv::Point best = centre;
    double best_distance = 1e18;
    for (const cv::Point& p : outline) {
      const double d = cv::norm(p - at);
      if (d < best_distance) {
        best_distance = d;
        best = p;
      }
    }
    return best;
  };
  const double reach = std::hypot(size.width, size.height) / 2 + 3;
  for (int ring = 0; ring < 8; ++ring) {
    for (int k = 0; k < 8; ++k) {
      const double angle = std::numbers::pi / 4 - k * std::numbers::pi / 4;  // NE, E, SE, ...
      const cv::Point2d direction(std::cos(angle), -std::sin(angle));        // image y is down
      double extent = 0;  // how far the outline reaches in this direction
      for (const cv::Point& p : outline)
        extent = std::max(extent, cv::Point2d(p - centre).dot(direction));
      const double distance = extent + reach + ring * (size.height + 4);
      const cv::Point at(static_cast<int>(std::lround(centre.x + distance * direction.x)),
                         static_cast<int>(std::lround(centre.y + distance * direction.y)));
      if (Free(box_at(at), map, taken)) {
        *anchor = nearest_outline_point(at);
        return box_at(at);
      }
    }
  }
  std::optional<cv::Point> best;
  for (int y = size.height / 2; y < image.rows - size.height / 2; y += 4) {
    for (int x = size.width / 2; x < image.cols - size.width / 2; x += 4) {
      const cv::Point at(x, y);
      if ((!best || cv::norm(at - centre) < cv::norm(*best - centre)) &&
          Free(box_at(at), map, taken)) {
        best = at;
      }
    }
  }
  const cv::Point at = best.value_or(centre);  // a map full of numbers: on the hotspot itself
  *anchor = nearest_outline_point(at);
  return box_at(at);
}

std::vector<cv::Rect> DrawHotspots(cv::Mat& image, const SiteReport& report,
                                   const PixelMapping& to_pixel) {
  std::vector<std::vector<cv::Point>> outlines;
  for (const HotspotFigures& h : report.hotspots) {
    std::vector<cv::Point>& outline = outlines.emplace_back();
    for (const db::PointXY& p : h.outline) outline.push_back(to_pixel(p));
    if (outline.empty()) outline.push_back(to_pixel(h.crs));
    cv::polylines(image, outline, true, kWhite, 3, cv::LINE_AA);
    cv::polylines(image, outline, true, kInk, 1, cv::LINE_AA);
  }
  std::vector<cv::Rect> taken = {NorthArrowBox(image), ScaleBarBox(image, to_pixel.pixels_per_m)};
  std::vector<cv::Rect> labels;
  for (std::size_t i = 0; i < report.hotspots.size(); ++i) {
    const HotspotFigures& h = report.hotspots[i];
    const std::string rank = std::to_string(h.rank);
    const cv::Size size = LabelSize(rank);
    cv::Point anchor;
    const cv::Rect box = PlaceLabel(image, to_pixel(h.crs), outlines[i], size, taken, &anchor);
    const cv::Point centre(box.x + box.width / 2, box.y + box.height / 2);
    if (cv::norm(centre - anchor) > kLabelHeightPx) {  // set apart: a leader line
      cv::line(image, anchor, centre, kWhite, 3, cv::LINE_AA);
      cv::line(image, anchor, centre, kInk, 1, cv::LINE_AA);
    }
    const int radius = kLabelHeightPx / 2 - 1;
    const cv::Point left(box.x + radius + 1, centre.y), right(box.br().x - radius - 1, centre.y);
    cv::rectangle(image, left - cv::Point(0, radius), right + cv::Point(0, radius), kInk,
                  cv::FILLED);
    cv::circle(image, left, radius, kInk, cv::FILLED, cv::LINE_AA);
    cv::circle(image, right, radius, kInk, cv::FILLED, cv::LINE_AA);
    int baseline = 0;
    const cv::Size text =
        cv::getTextSize(rank, cv::FONT_HERSHEY_SIMPLEX, kLabelFontScale, 2, &baseline);
    cv::putText(image, rank, centre + cv::Point(-text.width / 2, text.height / 2),
                cv::FONT_HERSHEY_SIMPLEX, kLabelFontScale, kWhite, 2, cv::LINE_AA);
    taken.push_back(box);
    labels.push_back(box);
  }
  return labels;
}

cv::Mat CloseUp(const cv::Mat& map, cv::Point centre, int half_px, int size_px) {
  cv::Mat padded;
  cv::copyMakeBorder(map, padded, half_px, half_px, half_px, half_px, cv::BORDER_CONSTANT,
                     cv::Scalar(215, 215, 215));
  cv::Mat crop = padded(cv::Rect(centre.x, centre.y, 2 * half_px, 2 * half_px)).clone();
  cv::Mat scaled;
  cv::resize(crop, scaled, {size_px, size_px}, 0, 0,
             2 * half_px < size_px ? cv::INTER_NEAREST : cv::INTER_AREA);
  cv::rectangle(scaled, {0, 0}, {size_px - 1, size_px - 1}, kInk, 1);
  return scaled;
}

}  // namespace

SiteMapFigure DrawSiteMap(const SiteReport& report, const SiteMapFigureOptions& options) {
  const heatmap::Raster& density = report.heatmap.density.density;
  heatmap::DensityPreviewOptions preview;
  preview.max_size_px = options.max_size_px;
  if (report.site_map) {
    preview.occupancy_cell_size_m = report.site_map->image.resolution_m;
    preview.occupancy = [&](double x_m, double y_m) {
      return report.site_map->GreyAt(report.frame.FromCrs({x_m, y_m}));
    };
  }
  heatmap::DensityImage image =
      heatmap::RenderDensityImage(density, report.density_nodata, preview);
  SiteMapFigure figure;
  figure.peak_density_per_100m2 = image.peak;
  figure.map = std::move(image.bgr);
  const double pixels_per_m = image.pixels_per_cell / density.grid.cell_size_m;
  figure.metres_per_pixel = 1.0 / pixels_per_m;
  const PixelMapping to_pixel{&density.grid, pixels_per_m};
  DrawItems(figure.map, report, to_pixel);
  figure.label_boxes = DrawHotspots(figure.map, report, to_pixel);

  const int half_px = std::max(8, static_cast<int>(options.close_up_radius_m * pixels_per_m));
  for (const HotspotFigures& h : report.hotspots) {
    figure.close_ups.push_back(
        CloseUp(figure.map, to_pixel(h.crs), half_px, options.close_up_size_px));
  }
  DrawScaleBar(figure.map, pixels_per_m);
  DrawNorthArrow(figure.map);
  return figure;
}

std::vector<unsigned char> EncodePng(const cv::Mat& image) {
  std::vector<unsigned char> png;
  if (!cv::imencode(".png", image, png)) throw InternalError("cannot encode a PNG image");
  return png;
}

}  // namespace littermap::reports
