#include <wheelchair_core/map_io.h>
#include <wheelchair_core/map_pixels.h>
#include <yaml-cpp/yaml.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <sstream>

namespace wheelchair_core {
namespace {

namespace fs = std::filesystem;

std::string oneLine(std::string text) {
  for (char& c : text) {
    if (c == '\n' || c == '\r') c = ' ';
  }
  return text;
}

[[noreturn]] void fail(const std::string& file, const std::string& problem) {
  throw MapFileError(file + ": " + oneLine(problem));
}

template <typename T>
T readKey(const YAML::Node& doc, const std::string& file, const std::string& key) {
  const YAML::Node node = doc[key];
  if (!node) fail(file, "missing key '" + key + "'");
  try {
    return node.as<T>();
  } catch (const YAML::Exception&) {
    fail(file, "key '" + key + "' has an invalid value");
  }
}

MapMode parseMode(const YAML::Node& doc, const std::string& file) {
  if (!doc["mode"]) return MapMode::kTrinary;
  const auto mode = readKey<std::string>(doc, file, "mode");
  if (mode == "trinary") return MapMode::kTrinary;
  if (mode == "scale") return MapMode::kScale;
  if (mode == "raw") return MapMode::kRaw;
  fail(file, "mode must be trinary, scale or raw (got '" + mode + "')");
}

const char* modeName(MapMode mode) {
  switch (mode) {
    case MapMode::kScale:
      return "scale";
    case MapMode::kRaw:
      return "raw";
    case MapMode::kTrinary:
      break;
  }
  return "trinary";
}

YAML::Node parseYaml(const std::string& yaml_path) {
  if (!fs::is_regular_file(yaml_path)) fail(yaml_path, "map file not found");
  YAML::Node doc;
  try {
    doc = YAML::LoadFile(yaml_path);
  } catch (const YAML::Exception& e) {
    fail(yaml_path, std::string("bad YAML: ") + e.what());
  }
  if (!doc.IsMap()) fail(yaml_path, "bad YAML: expected a mapping of keys");
  return doc;
}

/// Reads origin, resolution and the thresholds; checks each value.
void readMetadata(const YAML::Node& doc, const std::string& file, OccupancyMap& map,
                  MapFileOptions& options) {
  map.resolution = readKey<double>(doc, file, "resolution");
  if (!std::isfinite(map.resolution) || map.resolution <= 0) {
    std::ostringstream msg;
    msg << "resolution must be positive (got " << map.resolution << ")";
    fail(file, msg.str());
  }
  const auto origin = readKey<std::vector<double>>(doc, file, "origin");
  if (origin.size() != 3) fail(file, "origin must be [x, y, yaw]");
  for (double v : origin) {
    if (!std::isfinite(v)) fail(file, "origin must be finite");
  }
  map.origin_x = origin[0];
  map.origin_y = origin[1];
  map.origin_yaw = origin[2];
  options.occupied_thresh = readKey<double>(doc, file, "occupied_thresh");
  options.free_thresh = readKey<double>(doc, file, "free_thresh");
  if (!(options.free_thresh >= 0 && options.free_thresh <= options.occupied_thresh &&
        options.occupied_thresh <= 1)) {
    fail(file, "thresholds must satisfy 0 <= free_thresh <= occupied_thresh <= 1");
  }
  options.negate = readKey<int>(doc, file, "negate") != 0;
  options.mode = parseMode(doc, file);
}

std::string imagePath(const std::string& yaml_path, const std::string& image) {
  const fs::path p(image);
  return p.is_absolute() ? image : (fs::path(yaml_path).parent_path() / p).string();
}

/// Pixel (row r from the top, column c) -> cell (c, height - 1 - r), as map_server does.
void fillCells(const cv::Mat& image, const MapFileOptions& options, OccupancyMap& map) {
  const int channels = image.channels();
  const bool has_alpha = channels == 4 || channels == 2;
  const int averaged = (options.mode == MapMode::kTrinary || !has_alpha) ? channels : channels - 1;
  map.width = image.cols;
  map.height = image.rows;
  map.data.assign(static_cast<size_t>(map.width) * map.height, kUnknown);
  for (int r = 0; r < image.rows; ++r) {
    const uint8_t* row = image.ptr<uint8_t>(r);
    for (int c = 0; c < image.cols; ++c) {
      const uint8_t* px = row + static_cast<size_t>(c) * channels;
      double sum = 0;
      for (int k = 0; k < averaged; ++k) sum += px[k];
      const double alpha = has_alpha ? px[channels - 1] : 255.0;
      map.at(c, map.height - 1 - r) = pixelToCell(sum / averaged, alpha, options);
    }
  }
}

void writeYaml(const std::string& yaml_path, const std::string& image_name, const OccupancyMap& map,
               const MapFileOptions& options) {
  std::ofstream out(yaml_path);
  if (!out) fail(yaml_path, "cannot write map file");
  out.precision(17);
  out << "image: " << image_name << "\n"
      << "mode: " << modeName(options.mode) << "\n"
      << "resolution: " << map.resolution << "\n"
      << "origin: [" << map.origin_x << ", " << map.origin_y << ", " << map.origin_yaw << "]\n"
      << "negate: " << (options.negate ? 1 : 0) << "\n"
      << "occupied_thresh: " << options.occupied_thresh << "\n"
      << "free_thresh: " << options.free_thresh << "\n";
  if (!out.flush()) fail(yaml_path, "cannot write map file");
}

}  // namespace

OccupancyMap loadMap(const std::string& yaml_path) {
  const YAML::Node doc = parseYaml(yaml_path);
  OccupancyMap map;
  MapFileOptions options;
  readMetadata(doc, yaml_path, map, options);
  const auto image_name = readKey<std::string>(doc, yaml_path, "image");
  const std::string image_path = imagePath(yaml_path, image_name);
  if (!fs::is_regular_file(image_path)) fail(yaml_path, "image file not found: " + image_path);
  cv::Mat image;
  try {
    image = cv::imread(image_path, cv::IMREAD_UNCHANGED);
  } catch (const cv::Exception&) {
    image.release();
  }
  if (image.empty()) fail(image_path, "unreadable image (not a valid PGM/PNG/...)");
  if (image.depth() != CV_8U) fail(image_path, "only 8-bit images are supported");
  fillCells(image, options, map);
  return map;
}

void saveMap(const OccupancyMap& map, const std::string& yaml_path, const MapFileOptions& options) {
  if (map.width <= 0 || map.height <= 0 ||
      map.data.size() != static_cast<size_t>(map.width) * map.height) {
    fail(yaml_path, "map to save has inconsistent size");
  }
  if (!std::isfinite(map.resolution) || map.resolution <= 0) {
    fail(yaml_path, "map to save has a non-positive resolution");
  }
  const fs::path yaml(yaml_path);
  const std::string image_name = yaml.stem().string() + ".pgm";
  const std::string image_path = (yaml.parent_path() / image_name).string();
  cv::Mat image(map.height, map.width, CV_8UC1);
  for (int iy = 0; iy < map.height; ++iy) {
    uint8_t* row = image.ptr<uint8_t>(map.height - 1 - iy);
    for (int ix = 0; ix < map.width; ++ix) row[ix] = cellToPixel(map.at(ix, iy), options);
  }
  bool written = false;
  try {
    written = cv::imwrite(image_path, image);
  } catch (const cv::Exception&) {
    written = false;
  }
  if (!written) fail(image_path, "cannot write image");
  writeYaml(yaml_path, image_name, map, options);
}

}  // namespace wheelchair_core
