// The replay tool on a rosbag (issue 21): a slice of a real CARMEN log (../shared/data beside
// the repository; the test skips without it) is written in the test as a bag - /scan
// (sensor_msgs/LaserScan), /odom (nav_msgs/Odometry, odom -> base_link) and /tf_static
// (base_link -> laser) - and replayed; the CARMEN replay of the same slice is the comparison
// and the log's corrected poses the reference of both. No data is committed.
// About 2 s.
#include <geometry_msgs/TransformStamped.h>
#include <gtest/gtest.h>
#include <nav_msgs/Odometry.h>
#include <rosbag/bag.h>
#include <tf2_msgs/TFMessage.h>
#include <unistd.h>
#include <wheelchair_logs/carmen_log.h>
#include <wheelchair_ros/conversions.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <string>

namespace {

namespace fs = std::filesystem;
using wheelchair_logs::LogScan;

/// ../shared/data beside the repository, or $KLD_REAL_DATA (as bench/kld_real, e.g. from a
/// git worktree elsewhere).
const std::string kData =
    std::getenv("KLD_REAL_DATA") ? std::getenv("KLD_REAL_DATA") : WHEELCHAIR_SHARED_DATA_DIR;
const std::string kReplay = REPLAY_EXECUTABLE;
const std::string kBuildMap = BUILD_MAP_EXECUTABLE;
constexpr size_t kSliceScans = 500;  // 100 s of the Intel drive, ~35 m driven

class ReplayBag : public ::testing::Test {
 protected:
  void SetUp() override {
    log_ = kData + "/intel/derived_intel_gt_rawodom.clf";
    if (!fs::exists(log_)) GTEST_SKIP() << "no real logs at " << kData << " (../shared/data)";
    dir_ = fs::temp_directory_path() / ("kld_replay_bag_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override {
    if (!dir_.empty()) fs::remove_all(dir_);
  }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }

  std::string log_;
  fs::path dir_;
};

/// The first `n` FLASER lines of a CARMEN log, as a CARMEN log.
void writeCarmenSlice(const std::string& from, const std::string& to, size_t n) {
  std::ifstream in(from);
  std::ofstream out(to);
  size_t kept = 0;
  for (std::string line; kept < n && std::getline(in, line);) {
    if (line.rfind("FLASER ", 0) != 0) continue;
    out << line << "\n";
    ++kept;
  }
}

geometry_msgs::TransformStamped transform(const std::string& parent, const std::string& child,
                                          const wheelchair_core::Pose2D& p, const ros::Time& t) {
  geometry_msgs::TransformStamped m;
  m.header.stamp = t;
  m.header.frame_id = parent;
  m.child_frame_id = child;
  m.transform.translation.x = p.x;
  m.transform.translation.y = p.y;
  m.transform.rotation.z = std::sin(p.yaw / 2);
  m.transform.rotation.w = std::cos(p.yaw / 2);
  return m;
}

/// The same drive as a bag: each scan in frame "laser" with the raw odometry at its stamp.
size_t writeBag(const std::string& carmen, const std::string& bag_path) {
  wheelchair_logs::CarmenLogReader reader(carmen);
  rosbag::Bag bag(bag_path, rosbag::bagmode::Write);
  size_t n = 0;
  for (LogScan s; reader.next(s); ++n) {
    const ros::Time t(s.scan.stamp);
    if (n == 0) {
      tf2_msgs::TFMessage fixed;
      fixed.transforms.push_back(transform("base_link", "laser", {0, 0, 0}, t));
      bag.write("/tf_static", t, fixed);
    }
    nav_msgs::Odometry odom;
    const auto tf = transform("odom", "base_link", s.odom_pose, t);
    odom.header = tf.header;
    odom.child_frame_id = tf.child_frame_id;
    odom.pose.pose.position.x = s.odom_pose.x;
    odom.pose.pose.position.y = s.odom_pose.y;
    odom.pose.pose.orientation = tf.transform.rotation;
    bag.write("/odom", t, odom);
    auto msg = wheelchair_ros::toLaserScanMsg(s.scan, "laser");
    msg.header.stamp = t;
    bag.write("/scan", t, msg);
  }
  return n;
}

/// `command`'s standard output; the test fails if it does not exit 0.
std::string run(const std::string& command) {
  std::string out;
  FILE* p = ::popen(command.c_str(), "r");
  if (!p) return out;
  char buf[4096];
  for (size_t k; (k = std::fread(buf, 1, sizeof buf, p)) > 0;) out.append(buf, k);
  EXPECT_EQ(::pclose(p), 0) << command;
  return out;
}

/// The numbers of replay's --json object by key.
std::map<std::string, double> numbers(const std::string& json) {
  std::map<std::string, double> values;
  const std::regex pair("\"([a-z_0-9]+)\": (-?[0-9.eE+-]+)");
  for (std::sregex_iterator it(json.begin(), json.end(), pair), end; it != end; ++it)
    values[(*it)[1]] = std::stod((*it)[2]);
  return values;
}

TEST_F(ReplayBag, aBagOfARealLogSliceReplaysAsTheCarmenSliceDoes) {
  const std::string slice = path("slice.clf"), bag = path("slice.bag"), map = path("map.yaml");
  writeCarmenSlice(log_, slice, kSliceScans);
  ASSERT_EQ(writeBag(slice, bag), kSliceScans);
  run(kBuildMap + " --log " + slice + " --out " + map + " --quiet 2>/dev/null");
  ASSERT_TRUE(fs::exists(map));

  const std::string common = " --map " + map + " --reference " + slice + " --json --quiet";
  auto carmen = numbers(run(kReplay + " --log " + slice + common));
  auto from_bag = numbers(run(kReplay + " --log " + bag + " --odom-topic /odom" + common));
  std::cout << "carmen: " << carmen["position_rms_m"] << " m, " << carmen["heading_rms_deg"]
            << " deg; bag: " << from_bag["position_rms_m"] << " m, " << from_bag["heading_rms_deg"]
            << " deg\n";

  // Every scan of the bag found its tf and its reference pose.
  EXPECT_EQ(from_bag["scans"], kSliceScans);
  EXPECT_EQ(from_bag["matched"], carmen["matched"]);
  EXPECT_GE(carmen["matched"], kSliceScans - 1);
  // Both track the corrected poses (no re-localization) and agree with each other.
  EXPECT_EQ(carmen["relocalizations"], 0);
  EXPECT_EQ(from_bag["relocalizations"], 0);
  EXPECT_LT(carmen["position_rms_m"], 0.10);
  EXPECT_LT(from_bag["position_rms_m"], 0.10);
  EXPECT_NEAR(from_bag["position_rms_m"], carmen["position_rms_m"], 0.02);
  EXPECT_NEAR(from_bag["heading_rms_deg"], carmen["heading_rms_deg"], 0.5);
}

}  // namespace
