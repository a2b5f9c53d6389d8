// rostest: two planner hosts load the harmonic and the OMPL plugin by name, plan on a published
// map from tf map->base_link (make_plan service and /move_base_simple/goal) and replan when the
// map changes; a goal it rejects stops the chair (empty /plan); a plan request uses the map plus
// the live obstacle layer (/obstacles).
#include <wheelchair_msgs/MakePlan.h>
#include <wheelchair_msgs/PlanCertificate.h>
#include <wheelchair_planner_test/maze.h>
#include <wheelchair_ros/conversions.h>

#include <gtest/gtest.h>
#include <nav_msgs/Path.h>
#include <ros/ros.h>

#include <algorithm>
#include <cmath>

using wheelchair_msgs::MakePlan;
using wheelchair_msgs::PlanCertificate;

namespace {

geometry_msgs::PoseStamped pose(double x, double y) {
  geometry_msgs::PoseStamped p;
  p.header.frame_id = "map";
  p.pose.position.x = x;
  p.pose.position.y = y;
  p.pose.orientation.w = 1.0;
  return p;
}

/// Spins until `done` or the timeout.
template <typename F>
bool waitFor(F done, double timeout) {
  const ros::WallTime end = ros::WallTime::now() + ros::WallDuration(timeout);
  while (ros::ok() && !done() && ros::WallTime::now() < end) {
    ros::spinOnce();
    ros::WallDuration(0.01).sleep();
  }
  return done();
}

}  // namespace

TEST(PlannerHost, BothPluginsPlanOnAPublishedMapAndReplanWhenItChanges) {
  ros::NodeHandle nh;
  // 6 m x 1.4 m corridor (free from y = 0.1 to 1.5); the chair is at (1.0, 0.8) by tf.
  auto map = wheelchair_planner::makeCorridor(6.0, 1.4, 0.05);
  ros::Publisher map_pub = nh.advertise<nav_msgs::OccupancyGrid>("map", 1, true);
  ros::Publisher goal_pub = nh.advertise<geometry_msgs::PoseStamped>("move_base_simple/goal", 1);
  nav_msgs::Path::ConstPtr plan;
  PlanCertificate::ConstPtr cert;
  auto plan_sub =
      nh.subscribe<nav_msgs::Path>("plan", 1, [&](const nav_msgs::Path::ConstPtr& m) { plan = m; });
  auto cert_sub = nh.subscribe<PlanCertificate>(
      "plan_certificate", 1, [&](const PlanCertificate::ConstPtr& m) { cert = m; });
  nav_msgs::OccupancyGrid::ConstPtr potential;
  auto potential_sub = nh.subscribe<nav_msgs::OccupancyGrid>(
      "harmonic_host/potential", 1,
      [&](const nav_msgs::OccupancyGrid::ConstPtr& m) { potential = m; });
  map_pub.publish(wheelchair_ros::toOccupancyGrid(map, "map", ros::Time::now()));

  for (const std::string host : {"harmonic_host", "ompl_host"}) {
    ASSERT_TRUE(ros::service::waitForService(host + "/make_plan", ros::Duration(20.0))) << host;
    MakePlan srv;
    srv.request.use_start = false;  // from tf
    srv.request.goal = pose(5.0, 0.8);
    bool ok = false;
    // The host may not have the map or the tf yet: retry for a few seconds.
    waitFor(
        [&] {
          ok = ros::service::call(host + "/make_plan", srv) && srv.response.success;
          return ok;
        },
        15.0);
    ASSERT_TRUE(ok) << host << ": " << srv.response.reason;
    ASSERT_GE(srv.response.plan.poses.size(), 2u);
    EXPECT_EQ(srv.response.plan.header.frame_id, "map");
    EXPECT_NEAR(srv.response.plan.poses.front().pose.position.x, 1.0, 1e-6);
    EXPECT_NEAR(srv.response.plan.poses.back().pose.position.x, 5.0, 1e-6);
    EXPECT_TRUE(srv.response.certificate.success);
    EXPECT_GE(srv.response.certificate.min_clearance, 0.05 - 0.025);
    EXPECT_NE(srv.response.certificate.planner.find(host == "harmonic_host" ? "Harmonic" : "Ompl"),
              std::string::npos);
  }

  // The harmonic host's potential for rviz (latched): on the map's cells, 0 at the goal (5.0,
  // 0.8), rising towards the start, 100 at the farthest cell, -1 in the walls.
  ASSERT_TRUE(waitFor([&] { return potential != nullptr; }, 5.0));
  ASSERT_EQ(potential->info.width, static_cast<unsigned>(map.width));
  ASSERT_EQ(potential->info.height, static_cast<unsigned>(map.height));
  EXPECT_EQ(potential->header.frame_id, "map");
  auto cell = [&](double x, double y) {  // as the planner sees the map: float resolution
    const double res = potential->info.resolution;
    const int ix = static_cast<int>(std::floor((x - potential->info.origin.position.x) / res));
    const int iy = static_cast<int>(std::floor((y - potential->info.origin.position.y) / res));
    return potential->data[static_cast<size_t>(iy) * map.width + ix];
  };
  EXPECT_EQ(cell(5.0, 0.8), 0);
  EXPECT_GT(cell(1.0, 0.8), cell(3.0, 0.8));
  EXPECT_GT(cell(3.0, 0.8), cell(4.5, 0.8));
  EXPECT_EQ(*std::max_element(potential->data.begin(), potential->data.end()), 100);
  EXPECT_EQ(cell(3.0, 0.02), -1);

  // A goal from rviz: /plan from the harmonic host.
  plan.reset();
  goal_pub.publish(pose(4.0, 0.8));
  ASSERT_TRUE(waitFor(
      [&] {
        return plan && !plan->poses.empty() &&
               std::abs(plan->poses.back().pose.position.x - 4.0) < 1e-6;
      },
      10.0));

  // The map changes: a wall closes the corridor at x = 3 m, and the host replans and fails.
  for (int iy = 0; iy < map.height; ++iy) map.at(60, iy) = wheelchair_core::kOccupied;
  cert.reset();
  map_pub.publish(wheelchair_ros::toOccupancyGrid(map, "map", ros::Time::now()));
  ASSERT_TRUE(waitFor([&] { return cert && !cert->success; }, 10.0));
  EXPECT_NE(cert->failure_reason.find("not connected"), std::string::npos) << cert->failure_reason;
  ASSERT_TRUE(plan);
  EXPECT_TRUE(waitFor([&] { return plan->poses.empty(); }, 5.0));

  // A goal on this side of the wall is planned; then a goal the host must reject (wrong frame)
  // stops the chair: an empty /plan, and a certificate that names the reason.
  plan.reset();
  goal_pub.publish(pose(2.0, 0.8));
  ASSERT_TRUE(waitFor([&] { return plan && !plan->poses.empty(); }, 10.0));
  cert.reset();
  auto wrong_frame = pose(2.5, 0.8);
  wrong_frame.header.frame_id = "odom";
  goal_pub.publish(wrong_frame);
  ASSERT_TRUE(waitFor([&] { return cert && !cert->success; }, 10.0));
  EXPECT_NE(cert->failure_reason.find("frame 'odom'"), std::string::npos) << cert->failure_reason;
  EXPECT_TRUE(waitFor([&] { return plan->poses.empty(); }, 5.0)) << "the old path was kept";
}

// /obstacles (the obstacle layer) closes the corridor where /map is free: make_plan fails with
// the reason; the layer cleared, the same request is planned again. (Fails on the old host: it
// did not read /obstacles.)
TEST(PlannerHost, APlanRequestUsesTheMapPlusTheObstacleLayer) {
  ros::NodeHandle nh;
  const auto map = wheelchair_planner::makeCorridor(6.0, 1.4, 0.05);
  ros::Publisher map_pub = nh.advertise<nav_msgs::OccupancyGrid>("map", 1, true);
  ros::Publisher obstacles_pub = nh.advertise<nav_msgs::OccupancyGrid>("obstacles", 1, true);
  map_pub.publish(wheelchair_ros::toOccupancyGrid(map, "map", ros::Time::now()));
  MakePlan srv;
  srv.request.goal = pose(5.0, 0.8);
  const auto plans = [&] {
    return ros::service::call("harmonic_host/make_plan", srv) && srv.response.success;
  };
  ASSERT_TRUE(waitFor(plans, 15.0)) << srv.response.reason;
  wheelchair_core::OccupancyMap layer = map;
  layer.data.assign(map.data.size(), wheelchair_core::kUnknown);
  for (int iy = 0; iy < map.height; ++iy)  // a 0.4 m x 1.5 m block across at x = 2.8-3.2 m
    for (int ix = 56; ix < 64; ++ix) layer.at(ix, iy) = wheelchair_core::kOccupied;
  obstacles_pub.publish(wheelchair_ros::toOccupancyGrid(layer, "map", ros::Time::now()));
  ASSERT_TRUE(waitFor([&] { return !plans(); }, 10.0)) << "planned through the obstacle layer";
  EXPECT_NE(srv.response.reason.find("not connected"), std::string::npos) << srv.response.reason;
  EXPECT_TRUE(srv.response.plan.poses.empty());
  layer.data.assign(map.data.size(), wheelchair_core::kUnknown);  // the block went away
  obstacles_pub.publish(wheelchair_ros::toOccupancyGrid(layer, "map", ros::Time::now()));
  EXPECT_TRUE(waitFor(plans, 10.0)) << srv.response.reason;
}

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "test_planner_host");
  return RUN_ALL_TESTS();
}
