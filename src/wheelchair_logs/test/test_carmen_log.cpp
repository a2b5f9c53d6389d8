// CARMEN log parsing: FLASER / ROBOTLASER1 fields, no-echo readings, corrupt lines with their
// line numbers, gzip files, truncated files.
#include <gtest/gtest.h>
#include <wheelchair_logs/carmen_log.h>
#include <zlib.h>

#include <cmath>
#include <sstream>

#include "map_test_files.h"

namespace wheelchair_logs {
namespace {

std::string flaser(int n, double r, double x, double y, double th, double ts) {
  std::ostringstream s;
  s << "FLASER " << n;
  for (int i = 0; i < n; ++i) s << " " << (i == 1 ? 81.91 : r);
  s << " " << x << " " << y << " " << th << " " << x << " " << y << " " << th << " " << ts
    << " host " << ts;
  return s.str();
}

TEST(CarmenLog, FlaserFieldsAndAngles) {
  std::string error;
  const auto s = parseCarmenLine(flaser(180, 2.5, 1.0, -2.0, 0.3, 12.75), CarmenOptions{}, error);
  ASSERT_TRUE(s) << error;
  EXPECT_EQ(s->scan.ranges.size(), 180u);
  EXPECT_FLOAT_EQ(s->scan.ranges[0], 2.5f);
  EXPECT_TRUE(std::isinf(s->scan.ranges[1]) && s->scan.ranges[1] > 0) << "no echo is +inf";
  EXPECT_NEAR(s->scan.angle_min, -M_PI / 2, 1e-12);
  EXPECT_NEAR(s->scan.angle_increment, M_PI / 180, 1e-12);  // -90 .. +89 deg
  EXPECT_DOUBLE_EQ(s->laser_pose.x, 1.0);
  EXPECT_DOUBLE_EQ(s->laser_pose.y, -2.0);
  EXPECT_DOUBLE_EQ(s->laser_pose.yaw, 0.3);
  EXPECT_DOUBLE_EQ(s->scan.stamp, 12.75);
  const auto odd = parseCarmenLine(flaser(361, 1.0, 0, 0, 0, 1), CarmenOptions{}, error);
  ASSERT_TRUE(odd);
  EXPECT_NEAR(odd->scan.angle_max, M_PI / 2, 1e-12);  // 361 beams: -90 .. +90 deg
}

// derived_*_gt_rawodom logs: the corrected laser pose first, the raw odometry second.
TEST(CarmenLog, FlaserKeepsItsSecondPoseAsOdometry) {
  std::string error;
  const auto s =
      parseCarmenLine("FLASER 2 1.0 2.0 1 2 0.5 -3 4 0.25 7.5 host 7.5", CarmenOptions{}, error);
  ASSERT_TRUE(s) << error;
  EXPECT_DOUBLE_EQ(s->laser_pose.x, 1.0);
  EXPECT_DOUBLE_EQ(s->odom_pose.x, -3.0);
  EXPECT_DOUBLE_EQ(s->odom_pose.y, 4.0);
  EXPECT_DOUBLE_EQ(s->odom_pose.yaw, 0.25);
  CarmenOptions limits;
  limits.range_min = 0.05;
  limits.range_max = 50.0;
  const auto l = parseCarmenLine("FLASER 2 1.0 2.0 1 2 0.5 -3 4 0.25 7.5 host 7.5", limits, error);
  ASSERT_TRUE(l) << error;
  EXPECT_DOUBLE_EQ(l->scan.range_min, 0.05);
  EXPECT_DOUBLE_EQ(l->scan.range_max, 50.0);
}

TEST(CarmenLog, RobotLaserUsesItsOwnGeometryAndLaserPose) {
  std::ostringstream s;
  s << "ROBOTLASER1 0 -1.5 3.0 0.5 30.0 0.01 0 7";
  for (int i = 0; i < 7; ++i) s << " " << 1.0 + i;
  s << " 0 4.0 5.0 0.25 3.9 5.0 0.25 0.1 0.0 0.5 0.3 1.0 99.5 host 99.6";
  std::string error;
  const auto r = parseCarmenLine(s.str(), CarmenOptions{}, error);
  ASSERT_TRUE(r) << error;
  EXPECT_EQ(r->scan.ranges.size(), 7u);
  EXPECT_DOUBLE_EQ(r->scan.angle_min, -1.5);
  EXPECT_DOUBLE_EQ(r->scan.angle_increment, 0.5);
  EXPECT_DOUBLE_EQ(r->scan.range_max, 30.0);
  EXPECT_DOUBLE_EQ(r->laser_pose.x, 4.0);
  EXPECT_DOUBLE_EQ(r->odom_pose.x, 3.9);  // the robot's pose
  EXPECT_DOUBLE_EQ(r->scan.stamp, 99.5);
}

TEST(CarmenLog, OtherMessagesAreIgnoredCorruptLasersReported) {
  std::string error;
  EXPECT_FALSE(parseCarmenLine("ODOM 1 2 3 0 0 0 5.0 host 5.0", CarmenOptions{}, error));
  EXPECT_TRUE(error.empty());
  EXPECT_FALSE(parseCarmenLine("# comment", CarmenOptions{}, error));
  EXPECT_TRUE(error.empty());
  std::string line = flaser(180, 2.0, 0, 0, 0, 1);
  EXPECT_FALSE(parseCarmenLine(line.substr(0, line.size() / 2), CarmenOptions{}, error));
  EXPECT_NE(error.find("truncated"), std::string::npos) << error;
  EXPECT_FALSE(parseCarmenLine("FLASER 3 1 x 3 0 0 0 0 0 0 1 h 1", CarmenOptions{}, error));
  EXPECT_NE(error.find("not a number"), std::string::npos) << error;
  EXPECT_FALSE(parseCarmenLine(flaser(3, 1.0, NAN, 0, 0, 1), CarmenOptions{}, error));
  EXPECT_NE(error.find("not finite"), std::string::npos) << error;
}

void writeGz(const std::string& path, const std::string& text, size_t cut = 0) {
  gzFile f = gzopen(path.c_str(), "wb");
  gzwrite(f, text.data(), static_cast<unsigned>(text.size()));
  gzclose(f);
  if (cut > 0) std::filesystem::resize_file(path, std::filesystem::file_size(path) - cut);
}

TEST(CarmenLog, ReaderReportsCorruptLinesByNumberAndReadsGzip) {
  wheelchair_core::test::TempDir dir;
  const std::string text = "PARAM a b\n" + flaser(180, 2.0, 0, 0, 0, 1) + "\n" +
                           "FLASER 180 1 2 3\n" + flaser(180, 2.0, 0.1, 0, 0, 2) + "\n";
  for (const std::string name : {"log.txt", "log.gz"}) {
    if (name == "log.gz") {
      writeGz(dir.file(name), text);
    } else {
      wheelchair_core::test::writeText(dir.file(name), text);
    }
    CarmenLogReader reader(dir.file(name));
    LogScan s;
    ASSERT_TRUE(reader.next(s));
    EXPECT_EQ(s.line, 2u);
    EXPECT_TRUE(reader.problemsOfLastCall().empty());
    ASSERT_TRUE(reader.next(s));
    EXPECT_EQ(s.line, 4u);
    EXPECT_NE(reader.problemsOfLastCall().find(dir.file(name) + ":3: FLASER: truncated"),
              std::string::npos)
        << reader.problemsOfLastCall();
    EXPECT_FALSE(reader.next(s));
    EXPECT_EQ(reader.corruptLines(), 1u);
    EXPECT_DOUBLE_EQ(reader.progress(), 1.0);
  }
}

TEST(CarmenLog, TruncatedGzipEndsWithAReportedProblem) {
  wheelchair_core::test::TempDir dir;
  std::string text;
  for (int i = 0; i < 200; ++i) text += flaser(180, 2.0 + i * 0.001, 0, 0, 0, i) + "\n";
  writeGz(dir.file("cut.gz"), text, 2000);
  CarmenLogReader reader(dir.file("cut.gz"));
  LogScan s;
  int scans = 0;
  while (reader.next(s)) ++scans;
  EXPECT_GT(scans, 0);
  EXPECT_LT(scans, 200);
  EXPECT_GE(reader.corruptLines(), 1u);
  EXPECT_NE(reader.problemsOfLastCall().find(dir.file("cut.gz") + ":"), std::string::npos);
}

TEST(CarmenLog, MissingFileThrowsNamingIt) {
  try {
    CarmenLogReader reader("/nonexistent/x.log");
    FAIL();
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/x.log"), std::string::npos);
  }
}

}  // namespace
}  // namespace wheelchair_logs

namespace wheelchair_logs {
namespace {

std::string flaserWith(const std::vector<double>& readings, double x, double ts) {
  std::ostringstream s;
  s << "FLASER " << readings.size();
  for (double r : readings) s << " " << r;
  s << " " << x << " 0 0 " << x << " 0 0 " << ts << " host " << ts;
  return s.str();
}

// A log clipped at 50 m (ACES) codes "no echo" as 50.0; before the per-log detection anything
// below 80 m was a real return (and build_map inserted it as a 20 m free ray).
TEST(CarmenLog, TheNoEchoCodeIsDetectedPerLog) {
  wheelchair_core::test::TempDir dir;
  for (const double code : {50.0, 32.767, 81.91}) {
    std::string text;
    for (int i = 0; i < 20; ++i)
      text += flaserWith({code, 3.0 + 0.01 * i, code - 0.05}, i, i) + "\n";
    wheelchair_core::test::writeText(dir.file("log"), text);
    CarmenLogReader reader(dir.file("log"));
    EXPECT_TRUE(reader.noEcho().found) << code;
    EXPECT_DOUBLE_EQ(reader.noEcho().code, code);
    EXPECT_EQ(reader.noEcho().at_code, 20u);
    EXPECT_EQ(reader.noEcho().readings, 60u);
    LogScan s;
    ASSERT_TRUE(reader.next(s));
    EXPECT_TRUE(std::isinf(s.scan.ranges[0]) && s.scan.ranges[0] > 0) << code;
    EXPECT_TRUE(std::isinf(s.scan.ranges[2])) << "another code just below the largest: " << code;
    EXPECT_FLOAT_EQ(s.scan.ranges[1], 3.0f);
  }
  // No code: the largest reading is not repeated; nothing becomes +inf.
  std::string text;
  for (int i = 0; i < 20; ++i) text += flaserWith({40.0 + i, 3.0}, i, i) + "\n";
  wheelchair_core::test::writeText(dir.file("plain"), text);
  CarmenLogReader reader(dir.file("plain"));
  EXPECT_FALSE(reader.noEcho().found);
  LogScan s;
  ASSERT_TRUE(reader.next(s));
  EXPECT_FLOAT_EQ(s.scan.ranges[0], 40.0f);
  CarmenOptions fixed;
  fixed.detect_no_echo = false;
  fixed.no_echo_range = 30.0;
  CarmenLogReader given(dir.file("plain"), fixed);
  ASSERT_TRUE(given.next(s));
  EXPECT_TRUE(std::isinf(s.scan.ranges[0]));
}

std::string robotLaser(const std::vector<double>& readings, double x, double ts) {
  std::ostringstream s;
  s << "ROBOTLASER1 0 -1.5707963 3.1415927 " << 3.1415927 / (readings.size() - 1) << " 81.9 0.01 0 "
    << readings.size();
  for (double r : readings) s << " " << r;
  s << " 0 " << x << " 0 0 " << x << " 0 0 0 0 0.5 0.3 1.0 " << ts << " host " << ts;
  return s.str();
}

// Some public logs carry every scan twice (ROBOTLASER1 and FLASER, same stamp and readings).
TEST(CarmenLog, AScanGivenTwiceIsReturnedOnceAndCounted) {
  wheelchair_core::test::TempDir dir;
  const std::vector<double> a = {1.0, 2.0, 3.0}, b = {1.5, 2.5, 3.5};
  const std::string text = robotLaser(a, 0.0, 10.0) + "\n" + flaserWith(a, 0.0, 10.0) + "\n" +
                           flaserWith(b, 0.1, 10.0) + "\n" +  // same stamp, other readings
                           robotLaser(b, 0.2, 10.2) + "\n" + flaserWith(b, 0.2, 10.2) + "\n";
  wheelchair_core::test::writeText(dir.file("log"), text);
  CarmenLogReader reader(dir.file("log"));
  std::vector<size_t> lines;
  for (LogScan s; reader.next(s);) lines.push_back(s.line);
  EXPECT_EQ(lines, (std::vector<size_t>{1, 3, 4}));
  EXPECT_EQ(reader.duplicatesDropped(), 2u);
  CarmenOptions keep;
  keep.drop_duplicates = false;
  CarmenLogReader all(dir.file("log"), keep);
  size_t n = 0;
  for (LogScan s; all.next(s);) ++n;
  EXPECT_EQ(n, 5u);
}

// GMapping's corrected log: the last ODOM before a scan is the previous corrected pose (+) the
// raw increment since the previous scan.
TEST(CarmenLog, TheRawOdometryOfACorrectedLogIsTheChainOfItsOdomIncrements) {
  using wheelchair_core::Pose2D;
  const Pose2D c1{1.0, 2.0, 0.5}, c2{1.5, 2.2, 0.7};        // corrected poses of scans 1, 2
  const Pose2D inc1{0.3, 0.0, 0.1}, inc2{0.2, 0.05, -0.2};  // raw odometry increments
  const Pose2D o1 = wheelchair_core::compose(c1, inc1), o2 = wheelchair_core::compose(c2, inc2);
  std::ostringstream text;
  text.precision(12);
  auto scan = [&](const Pose2D& p, double ts) {
    text << "FLASER 3 1 2 3 " << p.x << " " << p.y << " " << p.yaw << " " << p.x << " " << p.y
         << " " << p.yaw << " " << ts << " pippo " << ts << "\n";
  };
  auto odom = [&](const Pose2D& p, double ts) {
    text << "ODOM " << p.x << " " << p.y << " " << p.yaw << " 0 0 0 " << ts << " pippo " << ts
         << "\n";
  };
  odom({0, 0, 0}, 0.5);
  scan(c1, 1.0);
  odom({9, 9, 9}, 1.1);  // an earlier ODOM line: only the last one before the scan counts
  odom(o1, 1.2);
  scan(c2, 2.0);
  odom(o2, 2.5);
  scan({2, 2, 0}, 3.0);
  wheelchair_core::test::TempDir dir;
  wheelchair_core::test::writeText(dir.file("log.gfs"), text.str());
  CarmenOptions gfs;
  gfs.odometry = odometrySourceFromName("gfs");
  CarmenLogReader reader(dir.file("log.gfs"), gfs);
  std::vector<Pose2D> odometry;
  for (LogScan s; reader.next(s);) odometry.push_back(s.odom_pose);
  ASSERT_EQ(odometry.size(), 3u);
  const Pose2D expected2 = wheelchair_core::compose(inc1, inc2);
  EXPECT_NEAR(odometry[0].x, 0.0, 1e-9);
  EXPECT_NEAR(odometry[1].x, inc1.x, 1e-9);
  EXPECT_NEAR(odometry[1].yaw, inc1.yaw, 1e-9);
  EXPECT_NEAR(odometry[2].x, expected2.x, 1e-9);
  EXPECT_NEAR(odometry[2].y, expected2.y, 1e-9);
  EXPECT_NEAR(odometry[2].yaw, expected2.yaw, 1e-9);
  EXPECT_THROW(odometrySourceFromName("odom"), std::invalid_argument);
}

TEST(CarmenLog, TheFrontLaserOffsetParamIsKept) {
  wheelchair_core::test::TempDir dir;
  wheelchair_core::test::writeText(
      dir.file("log"),
      "PARAM robot_frontlaser_offset -0.04 nohost 0\n" + flaserWith({1, 2}, 0, 1) + "\n");
  CarmenLogReader reader(dir.file("log"));
  EXPECT_FALSE(reader.frontLaserOffset());
  LogScan s;
  ASSERT_TRUE(reader.next(s));
  ASSERT_TRUE(reader.frontLaserOffset());
  EXPECT_DOUBLE_EQ(*reader.frontLaserOffset(), -0.04);
}

}  // namespace
}  // namespace wheelchair_logs
