// rostest: map_server publishes the file's map, latched, on /map and /map_metadata.
#include <gtest/gtest.h>
#include <nav_msgs/OccupancyGrid.h>
#include <ros/ros.h>
#include <sys/wait.h>

#include <cstdio>

#include "child_process.h"
#include "map_test_files.h"

namespace wheelchair_mapping {
namespace {

template <typename Msg>
typename Msg::ConstPtr waitFor(const std::string& topic, double seconds) {
  typename Msg::ConstPtr received;
  ros::NodeHandle nh;
  ros::Subscriber sub =
      nh.subscribe<Msg>(topic, 1, [&received](const typename Msg::ConstPtr& m) { received = m; });
  const ros::WallTime end = ros::WallTime::now() + ros::WallDuration(seconds);
  while (!received && ros::ok() && ros::WallTime::now() < end) {
    ros::spinOnce();
    ros::WallDuration(0.02).sleep();
  }
  return received;
}

/// Runs `command` (stderr with stdout into `output`); its exit code, -1 if it did not exit.
int run(const std::string& command, std::string& output) {
  FILE* pipe = popen((command + " 2>&1").c_str(), "r");
  if (!pipe) return -1;
  char buf[512];
  while (fgets(buf, sizeof buf, pipe)) output += buf;
  const int status = pclose(pipe);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

TEST(MapServerNode, PublishesTheLatchedMapOfTheFile) {
  wheelchair_core::test::TempDir dir;
  // 4 x 3 image, top row first: occupied border on the top row, one unknown pixel.
  wheelchair_core::test::writePgm(dir.file("tiny.pgm"), 4, 3,
                                  {0, 0, 0, 0, 254, 205, 254, 254, 254, 254, 254, 0});
  wheelchair_core::test::writeText(
      dir.file("tiny.yaml"), wheelchair_core::test::mapYaml("tiny.pgm", "0.1", "[-1.0, 2.0, 0.0]"));
  test::ChildProcess server({"rosrun", "wheelchair_mapping", "map_server", dir.file("tiny.yaml")});
  // Subscribe only after the server is up: a latched topic must still deliver the map.
  ros::WallDuration(1.0).sleep();
  const auto map = waitFor<nav_msgs::OccupancyGrid>("/map", 20.0);
  ASSERT_TRUE(map) << "no /map within 20 s";
  EXPECT_EQ(map->header.frame_id, "map");
  EXPECT_EQ(map->info.width, 4u);
  EXPECT_EQ(map->info.height, 3u);
  EXPECT_FLOAT_EQ(map->info.resolution, 0.1f);
  EXPECT_DOUBLE_EQ(map->info.origin.position.x, -1.0);
  EXPECT_DOUBLE_EQ(map->info.origin.position.y, 2.0);
  // Row 0 of the message is the bottom image row.
  const std::vector<int8_t> expected = {0, 0, 0, 100, 0, -1, 0, 0, 100, 100, 100, 100};
  EXPECT_EQ(map->data, expected);
  const auto meta = waitFor<nav_msgs::MapMetaData>("/map_metadata", 10.0);
  ASSERT_TRUE(meta);
  EXPECT_EQ(meta->width, 4u);
}

// With the file given as ~map_file instead of an argument, a bad file still ends the process
// with one fatal line and exit code 1.
TEST(MapServerNode, BadMapFileParameterExitsWithOneFatalLine) {
  wheelchair_core::test::TempDir dir;
  const std::string missing = dir.file("missing.yaml");
  std::string output;
  EXPECT_EQ(run("rosrun wheelchair_mapping map_server __name:=bad_map_server _map_file:=" + missing,
                output),
            1)
      << output;
  EXPECT_NE(output.find("FATAL"), std::string::npos) << output;
  EXPECT_NE(output.find(missing + ": map file not found"), std::string::npos) << output;
}

// The old name of the frame parameter refuses the node, naming the new one.
TEST(MapServerNode, TheOldFrameParameterNameExitsNamingTheNewOne) {
  wheelchair_core::test::TempDir dir;
  wheelchair_core::test::writePgm(dir.file("tiny.pgm"), 1, 1, {254});
  wheelchair_core::test::writeText(dir.file("tiny.yaml"),
                                   wheelchair_core::test::mapYaml("tiny.pgm", "0.1"));
  std::string output;
  EXPECT_EQ(run("rosrun wheelchair_mapping map_server __name:=old_frame_map_server " +
                    dir.file("tiny.yaml") + " _frame_id:=map",
                output),
            1)
      << output;
  EXPECT_NE(output.find("'frame_id' is now called 'map_frame'"), std::string::npos) << output;
}

}  // namespace
}  // namespace wheelchair_mapping

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "test_map_server_node");
  ros::NodeHandle nh;
  return RUN_ALL_TESTS();
}
