// rostest, the chair's mapping mode end to end (issue 23): the simulator's chair (odometry with
// sim.yaml's systematic and random errors) is driven like a carer pushing it along the launch
// file's route while `wheelchair mapping.yaml` maps live: in `flat` from the living room through
// the doorway into the kitchen (sim_slam.test), in `office` from the lobby down the main
// corridor, its doors the only features along it (sim_slam_office.test). Checked against the
// simulator's ground truth, not against the SLAM itself:
// - the live /map, brought into the world frame (the map frame is where odometry started: the
//   chair's initial pose), classifies at least ~min_correct_share of its observed cells like the
//   world file (flat: 0.98, the known-pose mapping test's criterion, test/mapping; office: see
//   its launch file), and observes at least ~min_observed;
// - tf map -> base_link at the end of the drive is within 10 cm / 0.05 rad of the true pose
//   and closer to it than the odometry's (flat measured: 3 cm vs 32 cm);
// - ~save_place writes the chair's pose into a new places file the HMI's reader loads: the
//   SLAM's own pose within 2 cm, so the true pose within ~max_end_error; ~save_map writes a map
//   file that loads, the trajectory and the graph.
#include <geometry_msgs/TransformStamped.h>
#include <gtest/gtest.h>
#include <nav_msgs/OccupancyGrid.h>
#include <ros/callback_queue.h>
#include <ros/ros.h>
#include <std_srvs/Trigger.h>
#include <tf2_ros/buffer.h>
#include <tf2_ros/transform_listener.h>
#include <wheelchair_core/map_io.h>
#include <wheelchair_hmi/places.h>
#include <wheelchair_msgs/SavePlace.h>
#include <wheelchair_ros/conversions.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <mutex>
#include <string>

#include "map_accuracy.h"
#include "sim_drive.h"

namespace {

using wheelchair_core::Pose2D;

/// The launch file's ~route: [x0, y0, x1, y1, ...] in the world frame (empty if malformed).
std::vector<wheelchair_test_drive::Waypoint> routeParam(const ros::NodeHandle& pnh) {
  std::vector<double> flat;
  std::vector<wheelchair_test_drive::Waypoint> route;
  if (!pnh.getParam("route", flat) || flat.size() < 2 || flat.size() % 2 != 0) return route;
  for (size_t i = 0; i < flat.size(); i += 2) route.push_back({flat[i], flat[i + 1]});
  return route;
}

/// The SLAM map (map frame) resampled into the world grid's cells: T_world_map = `origin`.
wheelchair_core::OccupancyMap inWorldFrame(const wheelchair_core::OccupancyMap& slam,
                                           const wheelchair_core::OccupancyMap& world,
                                           const Pose2D& origin) {
  wheelchair_core::OccupancyMap out = world;
  std::fill(out.data.begin(), out.data.end(), wheelchair_core::kUnknown);
  const Pose2D to_map = wheelchair_core::inverse(origin);
  for (int iy = 0; iy < out.height; ++iy) {
    for (int ix = 0; ix < out.width; ++ix) {
      double x, y;
      out.cellToWorld(ix, iy, x, y);
      const Eigen::Vector2d p = wheelchair_core::transformPoint(to_map, Eigen::Vector2d(x, y));
      int sx, sy;
      if (slam.worldToCell(p.x(), p.y(), sx, sy)) out.at(ix, iy) = slam.at(sx, sy);
    }
  }
  return out;
}

TEST(SimSlam, ALiveMapAlongTheRouteMatchesTheWorldAndPlacesAreSavedAtTheTruePose) {
  ros::NodeHandle nh, pnh("~");
  std::string world_file, save_dir, places_file, place_name, place_room, place_key;
  ASSERT_TRUE(pnh.getParam("world", world_file));
  ASSERT_TRUE(pnh.getParam("save_dir", save_dir));
  ASSERT_TRUE(pnh.getParam("places_file", places_file));
  ASSERT_TRUE(pnh.getParam("place_name", place_name));  // as the carer types it
  ASSERT_TRUE(pnh.getParam("place_room", place_room));
  ASSERT_TRUE(pnh.getParam("place_key", place_key));  // the name as the places file keeps it
  const std::vector<wheelchair_test_drive::Waypoint> route = routeParam(pnh);
  ASSERT_FALSE(route.empty()) << "~route must be [x0, y0, x1, y1, ...]";
  double final_yaw = 0.0, drive_limit = 0.0, max_end_error = 0.0;
  double min_correct_share = 0.0;
  int min_observed = 0;
  ASSERT_TRUE(pnh.getParam("final_yaw", final_yaw));
  ASSERT_TRUE(pnh.getParam("max_end_error", max_end_error));  // [m] SLAM's end pose vs truth
  ASSERT_TRUE(pnh.getParam("drive_limit", drive_limit));      // [s simulated]
  ASSERT_TRUE(pnh.getParam("min_observed_cells", min_observed));
  ASSERT_TRUE(pnh.getParam("min_correct_share", min_correct_share));
  std::filesystem::remove_all(save_dir);
  std::filesystem::create_directories(std::filesystem::path(places_file).parent_path());
  std::filesystem::remove(places_file);
  const wheelchair_core::OccupancyMap truth = wheelchair_core::loadMap(world_file);
  Pose2D origin;  // where the odometry (and so the SLAM's map frame) started
  ASSERT_TRUE(ros::param::get("/simulator/initial_x", origin.x));
  ASSERT_TRUE(ros::param::get("/simulator/initial_y", origin.y));
  ASSERT_TRUE(ros::param::get("/simulator/initial_yaw", origin.yaw));

  std::mutex map_mutex;
  nav_msgs::OccupancyGrid::ConstPtr last_map;
  ros::Subscriber map_sub = nh.subscribe<nav_msgs::OccupancyGrid>(
      "/map", 1, [&](const nav_msgs::OccupancyGrid::ConstPtr& m) {
        std::lock_guard<std::mutex> lock(map_mutex);
        last_map = m;
      });
  tf2_ros::Buffer buffer;
  tf2_ros::TransformListener listener(buffer);
  std::string error;
  ASSERT_TRUE(buffer.canTransform("map", "base_link", ros::Time(0), ros::Duration(60.0), &error))
      << "the SLAM nodelet never published map -> odom: " << error;

  wheelchair_test_drive::SimDrive drive(route, final_yaw);
  std::vector<Pose2D> truth_poses;
  ros::Subscriber truth_sub = nh.subscribe<nav_msgs::Odometry>(
      "/sim/ground_truth", 10, [&](const nav_msgs::Odometry::ConstPtr& m) {
        truth_poses.push_back(wheelchair_ros::toPose2D(m->pose.pose));
      });
  const ros::WallTime start = ros::WallTime::now();
  while (ros::ok() && !drive.done() && !drive.collided() && drive.simSeconds() < drive_limit) {
    ros::getGlobalCallbackQueue()->callAvailable(ros::WallDuration(0.01));
  }
  const double wall_s = (ros::WallTime::now() - start).toSec();
  ASSERT_FALSE(drive.collided()) << "the chair touched an obstacle";
  ASSERT_TRUE(drive.done()) << "the drive did not finish within " << drive_limit << " s simulated";

  // Let the chair stand: the last scans are mapped and /map is republished (map_period 2 s).
  const ros::Time stopped = ros::Time::now();
  while (ros::ok() && (ros::Time::now() - stopped).toSec() < 5.0)
    ros::getGlobalCallbackQueue()->callAvailable(ros::WallDuration(0.01));
  ASSERT_FALSE(truth_poses.empty());
  const Pose2D true_end = truth_poses.back();

  // The pose: SLAM vs truth, in the world frame; the odometry's, for comparison.
  const Pose2D slam_end = wheelchair_core::compose(
      origin,
      wheelchair_ros::toPose2D(buffer.lookupTransform("map", "base_link", ros::Time(0)).transform));
  const Pose2D odom_end = wheelchair_core::compose(
      origin, wheelchair_ros::toPose2D(
                  buffer.lookupTransform("odom", "base_link", ros::Time(0)).transform));
  const double slam_error = std::hypot(slam_end.x - true_end.x, slam_end.y - true_end.y);
  const double odom_error = std::hypot(odom_end.x - true_end.x, odom_end.y - true_end.y);
  EXPECT_LT(slam_error, max_end_error);
  EXPECT_LT(slam_error, odom_error) << "the SLAM corrects the odometry's drift";
  EXPECT_LT(std::abs(wheelchair_core::angleDifference(slam_end.yaw, true_end.yaw)), 0.05);

  nav_msgs::OccupancyGrid::ConstPtr map;
  {
    std::lock_guard<std::mutex> lock(map_mutex);
    map = last_map;
  }
  ASSERT_TRUE(map) << "no /map from the SLAM nodelet";
  EXPECT_EQ(map->header.frame_id, "map");
  const wheelchair_core::OccupancyMap built =
      inWorldFrame(wheelchair_ros::fromOccupancyGrid(*map), truth, origin);
  const wheelchair_mapping::test::Accuracy a = wheelchair_mapping::test::compare(built, truth);
  std::cout << "sim slam " << std::filesystem::path(world_file).stem().string() << ": drive "
            << drive.simSeconds() << " s simulated, " << wall_s << " s wall; " << a.correct << " / "
            << a.observed << " observed cells correct (" << 100 * a.fraction()
            << " %), thickest wall " << a.max_wall_run << " cells, farthest off a wall "
            << a.max_spill << " cells; end pose error SLAM " << slam_error << " m, odometry "
            << odom_error << " m\n";
  RecordProperty("observed_cells", a.observed);
  RecordProperty("correct_percent", std::to_string(100 * a.fraction()));
  RecordProperty("max_spill_cells", a.max_spill);
  RecordProperty("slam_end_error_m", std::to_string(slam_error));
  RecordProperty("odometry_end_error_m", std::to_string(odom_error));
  RecordProperty("drive_wall_seconds", std::to_string(wall_s));
  EXPECT_GT(a.observed, min_observed) << "the rooms along the route should be largely observed";
  EXPECT_GE(a.fraction(), min_correct_share);

  // A place named at the chair's pose, into a places file that does not exist yet.
  ros::param::set("/slam/places_file", places_file);
  wheelchair_msgs::SavePlace place;
  place.request.name = place_name;
  place.request.room = place_room;
  ASSERT_TRUE(ros::service::waitForService("/slam/save_place", ros::Duration(10.0)));
  ASSERT_TRUE(ros::service::call("/slam/save_place", place));
  EXPECT_TRUE(place.response.success) << place.response.message;
  const std::vector<wheelchair_hmi::Place> places = wheelchair_hmi::loadPlaces(places_file);
  ASSERT_EQ(places.size(), 1u);
  EXPECT_EQ(places[0].name, place_key);
  EXPECT_EQ(places[0].room, place_room);
  const Pose2D saved = wheelchair_core::compose(origin, places[0].pose);
  EXPECT_LT(std::hypot(saved.x - slam_end.x, saved.y - slam_end.y), 0.02)
      << "the place is the chair's pose as the SLAM has it";
  EXPECT_LT(std::hypot(saved.x - true_end.x, saved.y - true_end.y), max_end_error);
  ASSERT_TRUE(ros::service::call("/slam/save_place", place));
  EXPECT_FALSE(place.response.success) << "a second place of the same name is refused";

  std_srvs::Trigger save;
  ASSERT_TRUE(ros::service::call("/slam/save_map", save));
  EXPECT_TRUE(save.response.success) << save.response.message;
  const wheelchair_core::OccupancyMap file = wheelchair_core::loadMap(save_dir + "/map.yaml");
  EXPECT_GT(file.width, 0);
  for (const char* name : {"trajectory.csv", "graph.graph", "graph.scans"})
    EXPECT_TRUE(std::filesystem::exists(save_dir + "/" + name)) << name;
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "test_sim_slam");
  ros::NodeHandle nh;
  return RUN_ALL_TESTS();
}
