#include <wheelchair_slam/trajectory_io.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace wheelchair_slam {

void writeTrajectoryCsv(const std::string& path, const std::vector<TimedPose>& poses) {
  std::FILE* f = std::fopen(path.c_str(), "w");
  if (!f) throw std::runtime_error(path + ": cannot write the trajectory");
  std::fprintf(f, "stamp,x,y,yaw\n");
  for (const TimedPose& p : poses) {
    std::fprintf(f, "%.6f,%.6f,%.6f,%.6f\n", p.stamp, p.pose.x, p.pose.y, p.pose.yaw);
  }
  if (std::fclose(f) != 0) throw std::runtime_error(path + ": cannot write the trajectory");
}

std::vector<TimedPose> readTrajectoryCsv(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path + ": cannot open the trajectory");
  std::vector<TimedPose> out;
  std::string line;
  size_t number = 0;
  while (std::getline(in, line)) {
    ++number;
    if (line.empty() || line.rfind("stamp", 0) == 0) continue;
    for (char& c : line) {
      if (c == ',') c = ' ';
    }
    std::istringstream s(line);
    TimedPose p;
    if (!(s >> p.stamp >> p.pose.x >> p.pose.y >> p.pose.yaw) || !p.pose.isFinite()) {
      throw std::runtime_error(path + ":" + std::to_string(number) + ": expected stamp,x,y,yaw");
    }
    out.push_back(p);
  }
  return out;
}

void writeCarmenLog(const std::string& path, const std::vector<wheelchair_core::LaserScan2D>& scans,
                    const std::vector<wheelchair_core::Pose2D>& poses,
                    const std::vector<wheelchair_core::Pose2D>& odometry, double no_echo) {
  if (scans.size() != poses.size() || scans.size() != odometry.size())
    throw std::invalid_argument("writeCarmenLog: scans, poses and odometry differ in count");
  std::FILE* f = std::fopen(path.c_str(), "w");
  if (!f) throw std::runtime_error(path + ": cannot write the log");
  std::fprintf(f, "# wheelchair_slam: FLASER pose = SLAM estimate, odom = raw odometry\n");
  if (!scans.empty()) {
    // What FLASER does not say: the beam spacing (MRPT's carmen2rawlog reads it from here).
    std::fprintf(f, "PARAM laser_front_laser_resolution %g nohost 0\n",
                 std::abs(scans.front().angle_increment) * 180.0 / M_PI);
  }
  for (size_t i = 0; i < scans.size(); ++i) {
    const auto& s = scans[i];
    std::fprintf(f, "FLASER %zu", s.ranges.size());
    for (float r : s.ranges) std::fprintf(f, " %.3f", std::isfinite(r) ? r : no_echo);
    const auto& p = poses[i];
    const auto& o = odometry[i];
    std::fprintf(f, " %.6f %.6f %.6f %.6f %.6f %.6f %.6f wheelchair_slam %.6f\n", p.x, p.y, p.yaw,
                 o.x, o.y, o.yaw, s.stamp, s.stamp);
  }
  if (std::fclose(f) != 0) throw std::runtime_error(path + ": cannot write the log");
}

}  // namespace wheelchair_slam
