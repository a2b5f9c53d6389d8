#include <wheelchair_ros/nodelet_main.h>

int main(int argc, char** argv) {
  return wheelchair_ros::runNodeletMain(argc, argv, "slam_node", "wheelchair_slam/SlamNodelet");
}
