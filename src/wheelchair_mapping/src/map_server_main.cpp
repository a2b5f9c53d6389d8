// rosrun wheelchair_mapping map_server <map.yaml>: checks the file first, so that a bad file
// ends the process with one fatal line and exit code 1, then runs MapServerNodelet.
#include <wheelchair_common/nodelet_main.h>
#include <wheelchair_mapping/map_io.h>

int main(int argc, char** argv) {
  std::vector<std::string> args;
  ros::removeROSArgs(argc, argv, args);
  if (args.size() > 1) {
    try {
      wheelchair_mapping::loadMap(args[1]);
    } catch (const wheelchair_mapping::MapFileError& e) {
      ROS_FATAL("%s", e.what());
      return 1;
    }
  }
  return wheelchair_common::runNodeletMain(argc, argv, "map_server",
                                           "wheelchair_mapping/MapServerNodelet");
}
