// bench support: rawlog_from_log --log FILE [--odometry fields|gfs] --out FILE.rawlog
// An observation-only MRPT rawlog (odometry + 2-D scan per laser line, with the log's stamps)
// for Debian's icp-slam. carmen2rawlog of MRPT 2.5 gives every observation the same time
// stamp, so icp-slam's pose extrapolator drops all odometry (its "Diff. in timestamps between
// odometry should be >0" warning) and never moves; bench/slam reports both.
#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/serialization/CArchive.h>
#include <wheelchair_logs/carmen_log.h>

#include <cmath>
#include <iostream>
#include <string>

int main(int argc, char** argv) {
  std::string log, out, odometry = "fields";
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string k = argv[i], v = argv[i + 1];
    if (k == "--log")
      log = v;
    else if (k == "--out")
      out = v;
    else if (k == "--odometry")
      odometry = v;
  }
  if (log.empty() || out.empty()) {
    std::cerr << "usage: rawlog_from_log --log FILE [--odometry fields|gfs] --out FILE.rawlog\n";
    return 2;
  }
  try {
    wheelchair_logs::CarmenOptions options;
    options.odometry = wheelchair_logs::odometrySourceFromName(odometry);
    wheelchair_logs::CarmenLogReader reader(log, options);
    mrpt::io::CFileGZOutputStream file(out);
    auto archive = mrpt::serialization::archiveFrom(file);
    size_t scans = 0;
    for (wheelchair_logs::LogScan s; reader.next(s);) {
      // Relative log times start near 0: put them after 2001 (MRPT clocks count from 1601).
      const double stamp = s.scan.stamp < 1e8 ? 1e9 + s.scan.stamp : s.scan.stamp;
      const auto t = mrpt::Clock::fromDouble(stamp);
      mrpt::obs::CObservationOdometry odo;
      odo.timestamp = t;
      odo.sensorLabel = "ODOMETRY";
      odo.odometry = mrpt::poses::CPose2D(s.odom_pose.x, s.odom_pose.y, s.odom_pose.yaw);
      archive << odo;
      mrpt::obs::CObservation2DRangeScan obs;
      obs.timestamp = t;
      obs.sensorLabel = "LASER";
      const size_t n = s.scan.ranges.size();
      const double span = (n - 1) * s.scan.angle_increment;
      // MRPT spreads the beams over the aperture centred on the sensor's x axis; the scan's own
      // centre becomes the sensor's yaw, so every beam keeps its angle.
      obs.aperture = static_cast<float>(std::abs(span));
      obs.rightToLeft = s.scan.angle_increment > 0;
      obs.maxRange = static_cast<float>(s.scan.range_max);
      obs.sensorPose = mrpt::poses::CPose3D(0, 0, 0, s.scan.angle_min + span / 2, 0, 0);
      obs.resizeScan(n);
      for (size_t i = 0; i < n; ++i) {
        const float r = s.scan.ranges[i];
        const bool valid = std::isfinite(r) && r > s.scan.range_min && r < s.scan.range_max;
        obs.setScanRange(i, valid ? r : 0.0f);
        obs.setScanRangeValidity(i, valid);
      }
      archive << obs;
      ++scans;
    }
    std::cerr << "rawlog_from_log: " << scans << " scans to " << out << "\n";
  } catch (const std::exception& e) {
    std::cerr << "rawlog_from_log: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
