// The one file of this package that includes the CARMEN reader (wheelchair_logs).
#include <wheelchair_logs/carmen_log.h>
#include <wheelchair_slam/odometry_log.h>
#include <zlib.h>

#include <algorithm>
#include <filesystem>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace wheelchair_slam {

using wheelchair_core::Pose2D;

OdometrySource odometrySourceFromName(const std::string& name) {
  if (name == "fields") return OdometrySource::kFields;
  if (name == "gfs") return OdometrySource::kGfsIncrements;
  throw std::invalid_argument("unknown odometry source '" + name + "' (fields or gfs)");
}

namespace {

std::vector<std::string> tokens(const std::string& line) {
  std::istringstream in(line);
  std::vector<std::string> out;
  for (std::string t; in >> t;) out.push_back(t);
  return out;
}

bool pose(const std::vector<std::string>& t, size_t first, Pose2D& out) {
  if (t.size() < first + 3) return false;
  try {
    out = {std::stod(t[first]), std::stod(t[first + 1]), std::stod(t[first + 2])};
  } catch (const std::exception&) {
    return false;
  }
  return out.isFinite();
}

/// The robot's odometry fields of a laser line that parsed as a scan.
bool odometryFields(const std::vector<std::string>& t, Pose2D& out) {
  if (t[0] == "FLASER") return pose(t, 2 + std::stoul(t[1]) + 3, out);
  // ROBOTLASER1 ... n r1..rn m rem1..remm laser_x laser_y laser_theta robot_x robot_y robot_theta
  const size_t n = std::stoul(t[8]);
  const size_t m = std::stoul(t[9 + n]);
  return pose(t, 10 + n + m + 3, out);
}

}  // namespace

struct OdometryLogReader::Impl {
  std::string path;
  OdometrySource source;
  gzFile file = nullptr;
  double size = 1.0;
  std::vector<char> buffer = std::vector<char>(1 << 16);
  size_t line_number = 0;
  wheelchair_logs::CarmenOptions options;
  // kGfsIncrements state
  bool have_previous = false;
  Pose2D previous_corrected, odometry, last_odom_line;
  bool have_odom_line = false;

  bool readLine(std::string& line) {
    line.clear();
    while (gzgets(file, buffer.data(), static_cast<int>(buffer.size()))) {
      line += buffer.data();
      if (!line.empty() && line.back() == '\n') break;
    }
    if (line.empty()) return false;
    ++line_number;
    return true;
  }
};

OdometryLogReader::OdometryLogReader(const std::string& path, OdometrySource source)
    : impl_(std::make_unique<Impl>()) {
  impl_->path = path;
  impl_->source = source;
  std::error_code ec;
  const auto size = std::filesystem::file_size(path, ec);
  if (ec) throw std::runtime_error(path + ": cannot open log file (" + ec.message() + ")");
  impl_->size = std::max<double>(1.0, static_cast<double>(size));
  impl_->file = gzopen(path.c_str(), "rb");
  if (!impl_->file) throw std::runtime_error(path + ": cannot open log file");
  gzbuffer(impl_->file, 1 << 17);
}

OdometryLogReader::~OdometryLogReader() {
  if (impl_->file) gzclose(impl_->file);
}

double OdometryLogReader::progress() const {
  return std::min(1.0, static_cast<double>(gzoffset(impl_->file)) / impl_->size);
}

bool OdometryLogReader::next(OdometryScan& out) {
  problems_.clear();
  Impl& s = *impl_;
  std::string line, error;
  auto report = [&](const std::string& what) {
    ++corrupt_lines_;
    if (!problems_.empty()) problems_ += "\n";
    problems_ += s.path + ":" + std::to_string(s.line_number) + ": " + what;
  };
  while (s.readLine(line)) {
    const std::vector<std::string> t = tokens(line);
    if (t.empty()) continue;
    if (t[0] == "ODOM") {
      Pose2D p;
      if (!pose(t, 1, p)) {
        report("ODOM: bad pose");
        continue;
      }
      s.last_odom_line = p;
      s.have_odom_line = true;
      continue;
    }
    auto scan = wheelchair_logs::parseCarmenLine(line, s.options, error);
    if (!scan) {
      if (!error.empty()) report(error);
      continue;
    }
    out.scan = std::move(scan->scan);
    out.logged_pose = scan->laser_pose;
    out.line = s.line_number;
    if (s.source == OdometrySource::kFields) {
      if (!odometryFields(t, out.odometry)) {
        report(t[0] + ": bad odometry fields");
        continue;
      }
      return true;
    }
    // kGfsIncrements
    if (s.have_previous && s.have_odom_line) {
      s.odometry = wheelchair_core::compose(
          s.odometry, wheelchair_core::between(s.previous_corrected, s.last_odom_line));
    }
    s.previous_corrected = out.logged_pose;
    s.last_odom_line = out.logged_pose;  // no ODOM line before the next scan: no motion
    s.have_previous = true;
    out.odometry = s.odometry;
    return true;
  }
  int zerr = Z_OK;
  const char* msg = gzerror(s.file, &zerr);
  if (zerr != Z_OK && zerr != Z_STREAM_END) report(msg);
  return false;
}

}  // namespace wheelchair_slam
