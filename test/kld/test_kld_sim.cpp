// rostests of the localizer node in the simulator (wheelchair_sim, flat world, sim time): the
// test drives the chair with wheel torques along the flat route (a velocity loop on the
// simulator's ground truth, which only the test sees) and scores /kld_pose against
// /sim/ground_truth. One test case per .test file (gtest filter): tracking, kidnapping,
// bad input.
#include <geometry_msgs/PoseWithCovarianceStamped.h>
#include <gtest/gtest.h>
#include <nav_msgs/OccupancyGrid.h>
#include <nav_msgs/Odometry.h>
#include <ros/ros.h>
#include <rosgraph_msgs/Log.h>
#include <sensor_msgs/LaserScan.h>
#include <wheelchair_core/map_io.h>
#include <wheelchair_msgs/LocalizationStatus.h>
#include <wheelchair_msgs/WheelTorques.h>
#include <wheelchair_ros/conversions.h>
#include <wheelchair_sim/SetPose.h>

#include <cmath>
#include <deque>
#include <functional>
#include <limits>
#include <mutex>
#include <string>
#include <vector>

using wheelchair_core::Pose2D;
using wheelchair_ros::toPose2D;
using wheelchair_ros::toPoseMsg;
using Status = wheelchair_msgs::LocalizationStatus;

namespace {

// Waypoints in the flat's living room (the chair starts at the first) where the footprint can
// turn in place (0.86 m from every obstacle), and a straight run up the hallway.
const std::vector<Pose2D> kLivingRoomLoop = {
    {3.0, 4.7, 0}, {5.0, 4.7, 0}, {1.5, 4.5, 0}, {3.0, 4.7, 0}};
const Pose2D kHallwaySouth{5.1, 7.0, M_PI / 2}, kHallwayNorth{5.1, 11.2, M_PI / 2};

struct PoseError {
  double xy, theta;
};

class KldSim : public ::testing::Test {
 protected:
  void SetUp() override {
    ros::NodeHandle pnh("~");
    ASSERT_TRUE(pnh.getParam("world", world_));
    pnh.param("scan_relay", relay_, false);
    truth_sub_ = nh_.subscribe("sim/ground_truth", 50, &KldSim::onTruth, this);
    pose_sub_ = nh_.subscribe("kld_pose", 50, &KldSim::onPose, this);
    status_sub_ = nh_.subscribe("localization/status", 50, &KldSim::onStatus, this);
    log_sub_ = nh_.subscribe("/rosout", 100, &KldSim::onLog, this);
    torque_pub_ = nh_.advertise<wheelchair_msgs::WheelTorques>("wheel_torques", 5);
    map_pub_ = nh_.advertise<nav_msgs::OccupancyGrid>("map", 1, true);
    init_pub_ = nh_.advertise<geometry_msgs::PoseWithCovarianceStamped>("initialpose", 1, true);
    if (relay_) {  // the localizer listens to scan_in: the test forwards or corrupts scans
      relay_pub_ = nh_.advertise<sensor_msgs::LaserScan>("scan_in", 10);
      scan_sub_ = nh_.subscribe("scan", 10, &KldSim::onScan, this);
    }
    map_ = wheelchair_ros::toOccupancyGrid(wheelchair_core::loadMap(world_), "map", ros::Time(0));
    map_pub_.publish(map_);
    ASSERT_TRUE(waitFor([&] { return haveTruth() && haveStatus(); }, 30.0))
        << "no ground truth or no localizer status";
    ASSERT_TRUE(waitFor([&] { return statusNow().state != Status::NO_DATA; }, 20.0))
        << "map not taken: " << statusNow().detail;
    // Initial pose at the truth with a 10 cm / 3 deg prior, as from rviz.
    geometry_msgs::PoseWithCovarianceStamped init;
    init.header.frame_id = "map";
    init.header.stamp = ros::Time::now();
    init.pose.pose = toPoseMsg(truthNow());
    init.pose.covariance[0] = init.pose.covariance[7] = 0.01;
    init.pose.covariance[35] = 0.0025;
    init_pub_.publish(init);
  }

  void TearDown() override {  // no callback may run into a destroyed fixture
    for (auto* sub : {&truth_sub_, &pose_sub_, &status_sub_, &log_sub_, &scan_sub_})
      sub->shutdown();
    torques(0, 0);
  }

  /// Spins (sim time runs in the simulator) until `done` or `wall_timeout` seconds.
  bool waitFor(const std::function<bool()>& done, double wall_timeout) {
    const ros::WallTime end = ros::WallTime::now() + ros::WallDuration(wall_timeout);
    while (ros::ok() && ros::WallTime::now() < end) {
      if (done()) return true;
      ros::WallDuration(0.01).sleep();
    }
    return done();
  }

  void onTruth(const nav_msgs::Odometry::ConstPtr& m) {
    std::lock_guard<std::mutex> lock(mutex_);
    truth_.push_back({m->header.stamp, toPose2D(m->pose.pose), m->twist.twist.linear.x,
                      m->twist.twist.angular.z});
    while (truth_.size() > 2000) truth_.pop_front();
  }
  void onPose(const geometry_msgs::PoseWithCovarianceStamped::ConstPtr& m) {
    std::lock_guard<std::mutex> lock(mutex_);
    poses_.push_back({m->header.stamp, toPose2D(m->pose.pose), 0, 0});
  }
  void onStatus(const Status::ConstPtr& m) {
    std::lock_guard<std::mutex> lock(mutex_);
    status_ = *m;
    states_.push_back(m->state);
  }
  void onLog(const rosgraph_msgs::Log::ConstPtr& m) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (m->level >= rosgraph_msgs::Log::WARN && m->name.find("kld") != std::string::npos)
      warnings_.push_back(m->msg);
  }
  void onScan(const sensor_msgs::LaserScan::ConstPtr& m) {
    sensor_msgs::LaserScan s = *m;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      if (corrupt_) corrupt_(s);
    }
    relay_pub_.publish(s);
  }

  struct Stamped {
    ros::Time stamp;
    Pose2D pose;
    double v, w;
  };
  bool haveTruth() {
    std::lock_guard<std::mutex> lock(mutex_);
    return !truth_.empty();
  }
  Pose2D truthNow() {
    std::lock_guard<std::mutex> lock(mutex_);
    return truth_.back().pose;
  }
  bool haveStatus() {
    std::lock_guard<std::mutex> lock(mutex_);
    return !states_.empty();
  }
  Status statusNow() {
    std::lock_guard<std::mutex> lock(mutex_);
    return status_;
  }
  bool localizedNow() {
    std::lock_guard<std::mutex> lock(mutex_);
    return !states_.empty() && status_.state == Status::LOCALIZED;
  }
  /// Truth nearest to `stamp` (published every simulator step).
  Pose2D truthAt(const ros::Time& stamp) {
    const Stamped* best = &truth_.front();
    for (const auto& t : truth_)
      if (std::abs((t.stamp - stamp).toSec()) < std::abs((best->stamp - stamp).toSec())) best = &t;
    return best->pose;
  }
  /// Errors of the /kld_pose messages received since index `from`.
  std::vector<PoseError> poseErrors(size_t from) {
    std::lock_guard<std::mutex> lock(mutex_);
    std::vector<PoseError> out;
    for (size_t i = from; i < poses_.size(); ++i) {
      const Pose2D t = truthAt(poses_[i].stamp), &e = poses_[i].pose;
      out.push_back({std::hypot(e.x - t.x, e.y - t.y),
                     std::abs(wheelchair_core::angleDifference(e.yaw, t.yaw))});
      if (getenv("KLD_SIM_DEBUG"))
        std::cout << "along " << (e.x - t.x) * std::cos(t.yaw) + (e.y - t.y) * std::sin(t.yaw)
                  << " across " << -(e.x - t.x) * std::sin(t.yaw) + (e.y - t.y) * std::cos(t.yaw)
                  << " dx " << e.x - t.x << " dy " << e.y - t.y << " truth " << t.x << " " << t.y
                  << " " << t.yaw << " stamp " << poses_[i].stamp.toSec() << "\n";
    }
    return out;
  }
  size_t poseCount() {
    std::lock_guard<std::mutex> lock(mutex_);
    return poses_.size();
  }

  void torques(double left, double right) {
    wheelchair_msgs::WheelTorques t;
    t.header.stamp = ros::Time::now();
    t.left = left;
    t.right = right;
    torque_pub_.publish(t);
  }

  /// Turns towards, then drives to `goal` (x, y) at 0.4 m/s with a velocity loop on the truth.
  bool driveTo(const Pose2D& goal, double wall_timeout = 40.0) {
    const ros::WallTime end = ros::WallTime::now() + ros::WallDuration(wall_timeout);
    ros::Rate rate(50.0);  // sim time
    while (ros::ok() && ros::WallTime::now() < end) {
      Stamped t;
      {
        std::lock_guard<std::mutex> lock(mutex_);
        t = truth_.back();
      }
      const double dx = goal.x - t.pose.x, dy = goal.y - t.pose.y, dist = std::hypot(dx, dy);
      const double heading_error = wheelchair_core::angleDifference(std::atan2(dy, dx), t.pose.yaw);
      if (dist < 0.08) {
        torques(0, 0);
        return waitFor([&] { return std::abs(truthSpeed()) < 0.02; }, 10.0);
      }
      const bool turn = std::abs(heading_error) > 0.15;
      const double v = turn ? 0.0 : std::min(0.4, 0.8 * dist);
      const double w = std::clamp(1.5 * heading_error, -0.6, 0.6);
      const double common = 60.0 * (v - t.v) + (v > 0 ? 4.0 : 0.0);
      const double diff = 25.0 * (w - t.w);
      torques(std::clamp(common - diff, -30.0, 30.0), std::clamp(common + diff, -30.0, 30.0));
      rate.sleep();
    }
    torques(0, 0);
    return false;
  }
  double truthSpeed() {
    std::lock_guard<std::mutex> lock(mutex_);
    return truth_.back().v;
  }
  bool driveRoute(const std::vector<Pose2D>& route) {
    for (const auto& p : route)
      if (!driveTo(p)) return false;
    return true;
  }

  ros::NodeHandle nh_;
  std::string world_;
  bool relay_ = false;
  nav_msgs::OccupancyGrid map_;
  std::mutex mutex_;
  std::deque<Stamped> truth_;
  std::vector<Stamped> poses_;
  Status status_;
  std::vector<uint8_t> states_;  ///< state of every status received
  std::vector<std::string> warnings_;
  std::function<void(sensor_msgs::LaserScan&)> corrupt_;  ///< called under mutex_
  int relayed_ = 0;
  ros::Subscriber truth_sub_, pose_sub_, status_sub_, log_sub_, scan_sub_;
  ros::Publisher torque_pub_, map_pub_, init_pub_, relay_pub_;
};

double rms(const std::vector<PoseError>& e, double PoseError::*field) {
  double s = 0;
  for (const auto& x : e) s += x.*field * x.*field;
  return e.empty() ? std::numeric_limits<double>::infinity() : std::sqrt(s / e.size());
}

}  // namespace

// Tracking along a living-room loop in the flat: position and heading RMS vs ground truth.
TEST_F(KldSim, TracksTheFlatRoute) {
  ASSERT_TRUE(waitFor([&] { return localizedNow() || poseCount() > 0; }, 20.0));
  const size_t from = poseCount();
  ASSERT_TRUE(driveRoute({kLivingRoomLoop.begin() + 1, kLivingRoomLoop.end()}))
      << "drive did not finish";
  const auto errors = poseErrors(from + 5);  // after 5 updates from the 10 cm prior
  const double pos = rms(errors, &PoseError::xy), head = rms(errors, &PoseError::theta);
  std::cout << "sim tracking: " << errors.size() << " poses, RMS " << 100 * pos << " cm, "
            << head * 180 / M_PI << " deg\n";
  RecordProperty("position_rms_cm", std::to_string(100 * pos));
  RecordProperty("heading_rms_deg", std::to_string(head * 180 / M_PI));
  EXPECT_GT(errors.size(), 30u);
  // The bounds. (4.6-5.2 cm before the likelihood field measured the depth inside
  // thick walls: endpoints overshooting into a wall were free, pulling the estimate ~3 cm
  // towards the walls the 180-degree scan sees; 3.1 cm after.)
  EXPECT_LE(pos, 0.05);
  EXPECT_LE(head, 2 * M_PI / 180);
  EXPECT_TRUE(localizedNow()) << statusNow().detail;
}

// Kidnapping: /sim/teleport mid-route (odometry does not notice); the filter must report
// "not localized" and then recover to within 20 cm while the chair drives on.
TEST_F(KldSim, NoticesAndRecoversFromKidnapping) {
  ASSERT_TRUE(driveTo(kLivingRoomLoop[1]));
  ASSERT_TRUE(waitFor([&] { return localizedNow(); }, 20.0)) << statusNow().detail;
  ros::ServiceClient teleport = nh_.serviceClient<wheelchair_sim::SetPose>("sim/teleport");
  ASSERT_TRUE(teleport.waitForExistence(ros::Duration(10.0)));
  wheelchair_sim::SetPose srv;
  srv.request.x = kHallwaySouth.x;  // the hallway, 2.5 m away, turned by 90 deg
  srv.request.y = kHallwaySouth.y;
  srv.request.yaw = kHallwaySouth.yaw;
  ASSERT_TRUE(teleport.call(srv) && srv.response.success) << srv.response.message;
  size_t seen;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    seen = states_.size();
  }
  // Drive on up the hallway.
  bool noticed = false;
  driveTo(kHallwayNorth);
  {
    std::lock_guard<std::mutex> lock(mutex_);
    for (size_t i = seen; i < states_.size(); ++i) noticed |= states_[i] != Status::LOCALIZED;
  }
  EXPECT_TRUE(noticed) << "the kidnapping was never reported";
  // Recovered: localized and the last poses within 20 cm.
  EXPECT_TRUE(waitFor([&] { return localizedNow(); }, 10.0)) << statusNow().detail;
  const size_t n = poseCount();
  ASSERT_GT(n, 5u);
  for (const auto& e : poseErrors(n - 3)) EXPECT_LT(e.xy, 0.2);
}

// Bad input relayed into the localizer while the chair drives: NaN and inf ranges, a wrong beam
// count, a scan from a frame without tf, a map of another size. No crash, no jump of the
// estimate, a warning naming each reason.
TEST_F(KldSim, SurvivesBadInputWithoutAJump) {
  ASSERT_TRUE(relay_);
  ASSERT_TRUE(waitFor([&] { return localizedNow(); }, 20.0)) << statusNow().detail;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    corrupt_ = [this](sensor_msgs::LaserScan& s) {
      switch (relayed_++ % 8) {
        case 1:
          s.ranges[100] = std::numeric_limits<float>::quiet_NaN();
          break;
        case 3:
          s.ranges.resize(180);
          break;
        case 5:
          s.header.frame_id = "no_such_laser";
          break;
        case 6:
          for (size_t i = 0; i < s.ranges.size(); i += 4)
            s.ranges[i] = std::numeric_limits<float>::infinity();
          break;
        default:
          break;
      }
    };
  }
  const size_t from = poseCount();
  ASSERT_TRUE(driveTo(kLivingRoomLoop[1]));
  // A map of another size (the same floor padded by 1 m of unknown on every side).
  nav_msgs::OccupancyGrid padded = map_;
  const int pad = static_cast<int>(std::round(1.0 / map_.info.resolution));
  padded.info.width += 2 * pad;
  padded.info.height += 2 * pad;
  padded.info.origin.position.x -= pad * map_.info.resolution;
  padded.info.origin.position.y -= pad * map_.info.resolution;
  padded.data.assign(static_cast<size_t>(padded.info.width) * padded.info.height, -1);
  for (unsigned y = 0; y < map_.info.height; ++y)
    for (unsigned x = 0; x < map_.info.width; ++x)
      padded.data[(y + pad) * padded.info.width + x + pad] = map_.data[y * map_.info.width + x];
  map_pub_.publish(padded);
  ASSERT_TRUE(driveTo(kLivingRoomLoop[2]));
  {
    std::lock_guard<std::mutex> lock(mutex_);
    corrupt_ = nullptr;
  }
  const auto errors = poseErrors(from);
  double worst = 0;
  for (const auto& e : errors) worst = std::max(worst, e.xy);
  std::cout << "bad input: " << relayed_ << " scans relayed, " << errors.size()
            << " poses, worst error " << 100 * worst << " cm\n";
  EXPECT_GT(errors.size(), 20u);
  EXPECT_LT(worst, 0.15) << "the estimate jumped";
  std::lock_guard<std::mutex> lock(mutex_);
  auto warned = [&](const std::string& what) {
    for (const auto& w : warnings_)
      if (w.find(what) != std::string::npos) return true;
    return false;
  };
  EXPECT_TRUE(warned("nan")) << "no warning about NaN ranges";
  EXPECT_TRUE(warned("180 beams")) << "no warning about the beam count";
  EXPECT_TRUE(warned("tf missing")) << "no warning about the missing tf";
  EXPECT_TRUE(warned("new map")) << "no warning about the map change";
}

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "test_kld_sim");
  ros::AsyncSpinner spinner(2);
  spinner.start();
  return RUN_ALL_TESTS();
}
