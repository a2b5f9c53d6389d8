#include <wheelchair_logs/carmen_log.h>
#include <zlib.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
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

OdometrySource odometrySourceFromName(const std::string& name) {
  if (name == "fields") return OdometrySource::kFields;
  if (name == "gfs") return OdometrySource::kGfsIncrements;
  throw std::invalid_argument("unknown odometry source '" + name + "' (fields or gfs)");
}

namespace {

/// A gzip or plain text file read line by line.
class GzLines {
 public:
  explicit GzLines(const std::string& path) {
    std::error_code ec;
    const auto size = std::filesystem::file_size(path, ec);
    if (ec) throw std::runtime_error(path + ": cannot open log file (" + ec.message() + ")");
    size_ = std::max<double>(1.0, static_cast<double>(size));
    file_ = gzopen(path.c_str(), "rb");  // reads plain files too
    if (!file_) throw std::runtime_error(path + ": cannot open log file");
    gzbuffer(file_, 1 << 17);
  }
  ~GzLines() { gzclose(file_); }
  GzLines(const GzLines&) = delete;
  GzLines& operator=(const GzLines&) = delete;

  bool read(std::string& line) {
    line.clear();
    while (gzgets(file_, buffer_.data(), static_cast<int>(buffer_.size()))) {
      line += buffer_.data();
      if (!line.empty() && line.back() == '\n') break;
    }
    return !line.empty();
  }
  double progress() const { return std::min(1.0, static_cast<double>(gzoffset(file_)) / size_); }
  /// "" or the zlib error that ended the file early (a truncated gzip).
  std::string error() const {
    int zerr = Z_OK;
    const char* msg = gzerror(file_, &zerr);
    return zerr != Z_OK && zerr != Z_STREAM_END ? msg : "";
  }

 private:
  gzFile file_ = nullptr;
  double size_ = 1.0;
  std::vector<char> buffer_ = std::vector<char>(1 << 16);
};

std::vector<std::string> tokenize(const std::string& line) {
  std::istringstream in(line);
  std::vector<std::string> tokens;
  for (std::string tok; in >> tok;) tokens.push_back(tok);
  return tokens;
}

/// The readings of a FLASER / ROBOTLASER1 line (nothing for other or corrupt lines).
bool readings(const std::vector<std::string>& t, std::vector<double>& out) {
  std::string error;
  std::vector<double> n;
  if (t[0] == "FLASER") {
    if (!numbers(t, 1, 1, n, error) || !(n[0] >= 1 && n[0] <= 10000)) return false;
    return numbers(t, 2, static_cast<size_t>(n[0]), out, error);
  }
  if (t[0] == "ROBOTLASER1") {
    if (!numbers(t, 8, 1, n, error) || !(n[0] >= 1 && n[0] <= 10000)) return false;
    return numbers(t, 9, static_cast<size_t>(n[0]), out, error);
  }
  return false;
}

}  // namespace

NoEchoCode detectNoEcho(const std::string& path) {
  GzLines file(path);
  NoEchoCode c;
  std::map<double, size_t> top;  // counts of the largest readings seen (a few distinct values)
  std::string line;
  std::vector<double> values;
  while (file.read(line)) {
    if (line.compare(0, 6, "FLASER") != 0 && line.compare(0, 11, "ROBOTLASER1") != 0) continue;
    const auto t = tokenize(line);
    if (t.empty() || !readings(t, values)) continue;
    for (double v : values) {
      if (!std::isfinite(v)) continue;
      ++c.readings;
      if (top.size() >= 64 && v < top.begin()->first) continue;
      ++top[v];
      if (top.size() > 64) top.erase(top.begin());
    }
  }
  if (top.empty()) return c;
  const auto& [largest, count] = *top.rbegin();
  c.code = largest;
  c.at_code = count;
  c.threshold = largest - kNoEchoBand;
  c.found = count >= 10 && count >= kNoEchoMinShare * c.readings;
  return c;
}

struct CarmenLogReader::Impl {
  explicit Impl(const std::string& path) : lines(path) {}
  GzLines lines;
};

CarmenLogReader::CarmenLogReader(const std::string& path, const CarmenOptions& options)
    : path_(path), options_(options) {
  if (options_.detect_no_echo) {
    no_echo_ = detectNoEcho(path);
    if (no_echo_.found) options_.no_echo_range = no_echo_.threshold;
  }
  impl_ = std::make_unique<Impl>(path);
}

CarmenLogReader::~CarmenLogReader() = default;

double CarmenLogReader::progress() const { return impl_->lines.progress(); }

bool CarmenLogReader::readLine(std::string& line) {
  if (!impl_->lines.read(line)) return false;
  ++line_number_;
  return true;
}

void CarmenLogReader::report(const std::string& problem) {
  ++corrupt_lines_;
  if (!problems_.empty()) problems_ += "\n";
  problems_ += path_ + ":" + std::to_string(line_number_) + ": " + problem;
}

bool CarmenLogReader::isDuplicate(const LogScan& scan) {
  if (!options_.drop_duplicates) return false;
  for (const LogScan& r : recent_) {
    if (std::abs(r.scan.stamp - scan.scan.stamp) <= kDuplicateStampTolerance &&
        r.scan.ranges.size() == scan.scan.ranges.size() &&
        std::equal(r.scan.ranges.begin(), r.scan.ranges.end(), scan.scan.ranges.begin(),
                   [](float a, float b) { return a == b || (std::isinf(a) && std::isinf(b)); }))
      return true;
  }
  recent_.push_back(scan);
  if (recent_.size() > kDuplicateWindow) recent_.pop_front();
  return false;
}

void CarmenLogReader::applyOdometry(LogScan& scan) {
  if (options_.odometry == OdometrySource::kFields) return;
  if (have_previous_ && have_odom_line_)
    odometry_ = wheelchair_core::compose(
        odometry_, wheelchair_core::between(previous_corrected_, last_odom_line_));
  previous_corrected_ = scan.laser_pose;
  last_odom_line_ = scan.laser_pose;  // no ODOM line before the next scan: no motion
  have_previous_ = true;
  scan.odom_pose = odometry_;
}

bool CarmenLogReader::next(LogScan& out) {
  problems_.clear();
  std::string line, error;
  while (readLine(line)) {
    if (line.compare(0, 5, "ODOM ") == 0) {
      std::vector<double> p;
      if (!numbers(tokenize(line), 1, 3, p, error) || !std::isfinite(p[0] + p[1] + p[2])) {
        report("ODOM: " + (error.empty() ? std::string("pose is not finite") : error));
        continue;
      }
      last_odom_line_ = {p[0], p[1], p[2]};
      have_odom_line_ = true;
      continue;
    }
    if (line.compare(0, 6, "PARAM ") == 0) {
      const auto t = tokenize(line);
      double v = 0;
      if (t.size() >= 3 && t[1] == "robot_frontlaser_offset" && toDouble(t[2], v))
        front_laser_offset_ = v;
      continue;
    }
    auto scan = parseCarmenLine(line, options_, error);
    if (!scan) {
      if (!error.empty()) report(error);
      continue;
    }
    scan->line = line_number_;
    if (isDuplicate(*scan)) {
      ++duplicates_;
      continue;
    }
    applyOdometry(*scan);
    out = std::move(*scan);
    return true;
  }
  const std::string zerr = impl_->lines.error();
  if (!zerr.empty()) {
    ++line_number_;
    report(zerr);
  }
  return false;
}

}  // namespace wheelchair_logs
