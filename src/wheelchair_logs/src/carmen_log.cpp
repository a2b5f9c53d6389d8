#include <wheelchair_logs/carmen_log.h>
#include <zlib.h>

#include <cmath>
#include <filesystem>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace wheelchair_logs {
namespace {

bool toDouble(const std::string& token, double& value) {
  char* end = nullptr;
  value = std::strtod(token.c_str(), &end);
  return end && *end == '\0' && end != token.c_str();
}

/// Numbers tokens[first .. first+count); false (with `error`) if missing or not numeric.
bool numbers(const std::vector<std::string>& tokens, size_t first, size_t count,
             std::vector<double>& out, std::string& error) {
  if (tokens.size() < first + count) {
    error = "truncated line: " + std::to_string(tokens.size()) + " fields, expected at least " +
            std::to_string(first + count);
    return false;
  }
  out.resize(count);
  for (size_t i = 0; i < count; ++i) {
    if (!toDouble(tokens[first + i], out[i])) {
      error = "field " + std::to_string(first + i + 1) + " ('" + tokens[first + i] +
              "') is not a number";
      return false;
    }
  }
  return true;
}

void fillRanges(const std::vector<double>& readings, const CarmenOptions& options,
                wheelchair_core::LaserScan2D& scan) {
  scan.ranges.resize(readings.size());
  for (size_t i = 0; i < readings.size(); ++i) {
    scan.ranges[i] =
        readings[i] >= options.no_echo_range ? INFINITY : static_cast<float>(readings[i]);
  }
}

// FLASER n r1..rn x y theta odom_x odom_y odom_theta ipc_timestamp ipc_hostname logger_timestamp
bool parseFlaser(const std::vector<std::string>& t, const CarmenOptions& options, LogScan& out,
                 std::string& error) {
  std::vector<double> n;
  if (!numbers(t, 1, 1, n, error)) return false;
  if (!(n[0] >= 1 && n[0] <= 10000) || n[0] != std::floor(n[0])) {
    error = "bad beam count '" + t[1] + "'";
    return false;
  }
  const auto beams = static_cast<size_t>(n[0]);
  std::vector<double> readings, tail;
  if (!numbers(t, 2, beams, readings, error) || !numbers(t, 2 + beams, 7, tail, error)) {
    return false;
  }
  if (t.size() != beams + 11) {
    error = std::to_string(t.size()) + " fields, expected " + std::to_string(beams + 11);
    return false;
  }
  wheelchair_core::LaserScan2D& s = out.scan;
  const double fov = M_PI;
  s.angle_increment = beams % 2 == 0 ? fov / beams : fov / std::max<size_t>(beams - 1, 1);
  s.angle_min = -fov / 2;
  s.angle_max = s.angle_min + (beams - 1) * s.angle_increment;
  s.range_min = options.range_min;
  s.range_max = options.range_max;
  s.stamp = tail[6];
  fillRanges(readings, options, s);
  out.laser_pose = {tail[0], tail[1], tail[2]};
  out.odom_pose = {tail[3], tail[4], tail[5]};
  return true;
}

// ROBOTLASER1 laser_type start_angle fov angular_res max_range accuracy remission_mode
//   n r1..rn m rem1..remm laser_x laser_y laser_theta robot_x robot_y robot_theta laser_tv
//   laser_rv forward_safety_dist side_safety_dist turn_axis timestamp hostname logger_timestamp
bool parseRobotLaser(const std::vector<std::string>& t, const CarmenOptions& options, LogScan& out,
                     std::string& error) {
  std::vector<double> head, readings, m, tail;
  if (!numbers(t, 1, 8, head, error)) return false;
  if (!(head[7] >= 1 && head[7] <= 10000) || head[7] != std::floor(head[7])) {
    error = "bad beam count '" + t[8] + "'";
    return false;
  }
  const auto beams = static_cast<size_t>(head[7]);
  if (!numbers(t, 9, beams, readings, error) || !numbers(t, 9 + beams, 1, m, error)) {
    return false;
  }
  if (!(m[0] >= 0 && m[0] <= 10000) || m[0] != std::floor(m[0])) {
    error = "bad remission count";
    return false;
  }
  const size_t after = 10 + beams + static_cast<size_t>(m[0]);
  if (!numbers(t, after, 12, tail, error)) return false;
  if (t.size() != after + 14) {
    error = std::to_string(t.size()) + " fields, expected " + std::to_string(after + 14);
    return false;
  }
  wheelchair_core::LaserScan2D& s = out.scan;
  s.angle_min = head[1];
  s.angle_increment = head[3];
  s.angle_max = s.angle_min + (beams - 1) * s.angle_increment;
  s.range_min = options.range_min;
  s.range_max = std::min(head[4], options.range_max);
  s.stamp = tail[11];
  fillRanges(readings, options, s);
  out.laser_pose = {tail[0], tail[1], tail[2]};
  out.odom_pose = {tail[3], tail[4], tail[5]};
  return true;
}

}  // namespace

std::optional<LogScan> parseCarmenLine(const std::string& line, const CarmenOptions& options,
                                       std::string& error) {
  error.clear();
  std::istringstream in(line);
  std::vector<std::string> tokens;
  for (std::string tok; in >> tok;) tokens.push_back(tok);
  if (tokens.empty()) return std::nullopt;
  LogScan out;
  bool ok = false;
  if (tokens[0] == "FLASER") {
    ok = parseFlaser(tokens, options, out, error);
  } else if (tokens[0] == "ROBOTLASER1") {
    ok = parseRobotLaser(tokens, options, out, error);
  } else {
    return std::nullopt;
  }
  if (ok && !out.laser_pose.isFinite()) {
    error = "pose is not finite";
    ok = false;
  }
  if (ok && !std::isfinite(out.scan.stamp)) {
    error = "time stamp is not finite";
    ok = false;
  }
  if (!ok) {
    error = tokens[0] + ": " + error;
    return std::nullopt;
  }
  return out;
}

struct CarmenLogReader::Impl {
  gzFile file = nullptr;
  double size = 1.0;
  std::vector<char> buffer = std::vector<char>(1 << 16);
};

CarmenLogReader::CarmenLogReader(const std::string& path, const CarmenOptions& options)
    : impl_(std::make_unique<Impl>()), path_(path), options_(options) {
  std::error_code ec;
  const auto size = std::filesystem::file_size(path, ec);
  if (ec) throw std::runtime_error(path + ": cannot open log file (" + ec.message() + ")");
  impl_->size = std::max<double>(1.0, static_cast<double>(size));
  impl_->file = gzopen(path.c_str(), "rb");  // reads plain files too
  if (!impl_->file) throw std::runtime_error(path + ": cannot open log file");
  gzbuffer(impl_->file, 1 << 17);
}

CarmenLogReader::~CarmenLogReader() {
  if (impl_->file) gzclose(impl_->file);
}

double CarmenLogReader::progress() const {
  return std::min(1.0, static_cast<double>(gzoffset(impl_->file)) / impl_->size);
}

bool CarmenLogReader::readLine(std::string& line) {
  line.clear();
  while (gzgets(impl_->file, impl_->buffer.data(), static_cast<int>(impl_->buffer.size()))) {
    line += impl_->buffer.data();
    if (!line.empty() && line.back() == '\n') break;
  }
  if (line.empty()) return false;
  ++line_number_;
  return true;
}

bool CarmenLogReader::next(LogScan& out) {
  problems_.clear();
  std::string line, error;
  while (readLine(line)) {
    auto scan = parseCarmenLine(line, options_, error);
    if (scan) {
      out = std::move(*scan);
      out.line = line_number_;
      return true;
    }
    if (!error.empty()) {
      ++corrupt_lines_;
      if (!problems_.empty()) problems_ += "\n";
      problems_ += path_ + ":" + std::to_string(line_number_) + ": " + error;
    }
  }
  int zerr = Z_OK;
  const char* msg = gzerror(impl_->file, &zerr);
  if (zerr != Z_OK && zerr != Z_STREAM_END) {
    ++corrupt_lines_;
    if (!problems_.empty()) problems_ += "\n";
    problems_ += path_ + ":" + std::to_string(line_number_ + 1) + ": " + msg;
  }
  return false;
}

}  // namespace wheelchair_logs
