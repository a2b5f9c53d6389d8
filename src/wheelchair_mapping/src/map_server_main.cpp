// rosrun wheelchair_mapping map_server <map.yaml>   (or _map_file:=<map.yaml>)
// Checks the map file first, so that a bad or missing file ends the process with one fatal
// line and exit code 1, then runs MapServerNodelet.
#include <wheelchair_core/map_io.h>
#include <wheelchair_ros/nodelet_main.h>

namespace {

/// True if `path` is a loadable map; else one FATAL line naming the file and the problem.
bool mapFileIsGood(const std::string& path) {
  try {
    wheelchair_core::loadMap(path);
    return true;
  } catch (const wheelchair_core::MapFileError& e) {
    ROS_FATAL("%s", e.what());
    return false;
  }
}

/// The private parameter ~map_file, read once the master is reachable (roscpp's init is
/// idempotent, so runNodeletMain's own ros::init is then a no-op).
bool mapFileParam(int& argc, char** argv, std::string& path) {
  ros::init(argc, argv, "map_server");
  while (!ros::master::check() && ros::ok()) ros::WallDuration(0.5).sleep();
  return ros::param::get("~map_file", path);
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> args;
  ros::removeROSArgs(argc, argv, args);
  std::string path;
  if (args.size() > 1) {
    path = args[1];
  } else if (!mapFileParam(argc, argv, path)) {
    ROS_FATAL("map_server: no map file (give it as the first argument or as _map_file:=)");
    return 1;
  }
  if (!mapFileIsGood(path)) return 1;
  return wheelchair_ros::runNodeletMain(argc, argv, "map_server",
                                        "wheelchair_mapping/MapServerNodelet");
}
