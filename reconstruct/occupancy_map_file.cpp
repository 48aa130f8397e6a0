#include "reconstruct/occupancy_map_file.hpp"

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>

#include <yaml-cpp/yaml.h>

#include "core/error.hpp"
#include "core/yaml_fields.hpp"

namespace littermap::reconstruct {
namespace {

// Next PGM header token, skipping whitespace and # comments.
std::string HeaderToken(std::istream& in) {
  std::string token;
  char c = 0;
  while (in.get(c)) {
    if (c == '#') {
      std::string comment;
      std::getline(in, comment);
    } else if (std::isspace(static_cast<unsigned char>(c)) != 0) {
      if (!token.empty()) return token;
    } else {
      token.push_back(c);
    }
  }
  return token;
}

int HeaderNumber(std::istream& in, const std::filesystem::path& file, const char* field) {
  const std::string token = HeaderToken(in);
  try {
    std::size_t used = 0;
    const int value = std::stoi(token, &used);
    if (used == token.size() && value > 0) return value;
  } catch (const std::exception&) {
  }
  throw BadInputError(file.string() + ": PGM header field " + field + " is '" + token +
                      "', not a positive number");
}

}  // namespace

OccupancyImage ReadOccupancyMap(const std::filesystem::path& yaml_path) {
  const YAML::Node yaml = LoadYamlFile(yaml_path);
  const auto field = [&](const char* name) {
    const YAML::Node node = yaml[name];
    if (!node) throw BadInputError(yaml_path.string() + ": no '" + name + "'");
    return node;
  };
  OccupancyImage map;
  std::filesystem::path image;
  try {
    map.resolution_m = field("resolution").as<double>();
    const YAML::Node origin = field("origin");
    if (!origin.IsSequence() || origin.size() != 3) {
      throw BadInputError(yaml_path.string() + ": 'origin' must be [x, y, yaw]");
    }
    map.origin_x_m = origin[0].as<double>();
    map.origin_y_m = origin[1].as<double>();
    if (origin[2].as<double>() != 0) {
      throw BadInputError(yaml_path.string() +
                          ": 'origin' yaw must be 0 (rotated maps are not read)");
    }
    if (yaml["occupied_thresh"]) map.occupied_threshold = yaml["occupied_thresh"].as<double>();
    if (yaml["negate"] && yaml["negate"].as<int>() != 0) {
      throw BadInputError(yaml_path.string() + ": 'negate' must be 0");
    }
    image = field("image").as<std::string>();
  } catch (const YAML::Exception& e) {
    throw BadInputError(yaml_path.string() + ": " + e.what());
  }
  if (!(map.resolution_m >= 0.001 && map.resolution_m <= 100))
    throw BadInputError(yaml_path.string() + ": 'resolution' must be from 0.001 to 100 m");
  if (!std::isfinite(map.origin_x_m) || !std::isfinite(map.origin_y_m))
    throw BadInputError(yaml_path.string() + ": 'origin' must be finite numbers");
  if (image.is_relative()) image = yaml_path.parent_path() / image;
  std::error_code error;
  if (!std::filesystem::is_regular_file(image, error)) {
    throw BadInputError(image.string() + ": the map image named by " + yaml_path.string() +
                        " is not a regular file");
  }
  const std::uintmax_t file_bytes = std::filesystem::file_size(image, error);
  std::ifstream pgm(image, std::ios::binary);
  if (!pgm || error)
    throw BadInputError(image.string() + ": cannot open the map image named by " +
                        yaml_path.string());
  if (HeaderToken(pgm) != "P5") throw BadInputError(image.string() + ": not a binary PGM (P5)");
  map.width = HeaderNumber(pgm, image, "width");
  map.height = HeaderNumber(pgm, image, "height");
  if (HeaderNumber(pgm, image, "maxval") != 255) {
    throw BadInputError(image.string() + ": only 8-bit PGM (maxval 255) is read");
  }
  // The header's size is checked against the file before memory is taken for it.
  const std::uintmax_t pixels =
      static_cast<std::uintmax_t>(map.width) * static_cast<std::uintmax_t>(map.height);
  const std::streamoff header_bytes = pgm.tellg();
  if (header_bytes < 0 || pixels > file_bytes - static_cast<std::uintmax_t>(header_bytes)) {
    throw BadInputError(image.string() + ": truncated (the header says " +
                        std::to_string(map.width) + "x" + std::to_string(map.height) +
                        " pixels, the file has " + std::to_string(file_bytes) + " bytes)");
  }
  map.pixels.resize(static_cast<std::size_t>(pixels));
  pgm.read(reinterpret_cast<char*>(map.pixels.data()),
           static_cast<std::streamsize>(map.pixels.size()));
  if (pgm.gcount() != static_cast<std::streamsize>(map.pixels.size())) {
    throw BadInputError(image.string() + ": truncated (" + std::to_string(pgm.gcount()) + " of " +
                        std::to_string(map.pixels.size()) + " pixels)");
  }
  return map;
}

Points2 OccupiedCellCentres(const OccupancyImage& map) {
  Points2 points;
  const double occupied_below = (1 - map.occupied_threshold) * 255;
  for (int row = 0; row < map.height; ++row) {
    const int y = map.height - 1 - row;  // the top row is the largest y
    for (int x = 0; x < map.width; ++x) {
      const std::uint8_t grey =
          map.pixels[static_cast<std::size_t>(row) * static_cast<std::size_t>(map.width) +
                     static_cast<std::size_t>(x)];
      if (grey < occupied_below) {
        points.emplace_back(map.origin_x_m + (x + 0.5) * map.resolution_m,
                            map.origin_y_m + (y + 0.5) * map.resolution_m);
      }
    }
  }
  return points;
}

}  // namespace littermap::reconstruct
