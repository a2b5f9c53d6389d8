// rosrun wheelchair_display display _places_file:=... [_fullscreen:=false _width:=1024 ...]
// The rider's display: a Qt window, ROS spun from its event loop. A refused parameter (unknown
// key, bad value) ends the node with exit code 1 and the reason.
#include "display_node.h"
#include "display_window.h"

#include <wheelchair_ros/parameters.h>

#include <QApplication>
#include <QScreen>

int main(int argc, char** argv) {
  ros::init(argc, argv, "display");
  using wheelchair_display::DisplayNodeConfig;
  DisplayNodeConfig config;
  try {
    config = wheelchair_ros::loadParameters<DisplayNodeConfig>(
        ros::NodeHandle("~"), wheelchair_display::readDisplayNodeConfig);
  } catch (const wheelchair_core::ConfigError&) {
    return 1;  // loadParameters logged why
  }
  QApplication app(argc, argv);  // after the parameters: a refusal needs no screen
  std::unique_ptr<wheelchair_display::DisplayNode> node;
  try {
    node = std::make_unique<wheelchair_display::DisplayNode>(config);
  } catch (const std::exception& e) {
    ROS_FATAL("display: %s", e.what());
    return 1;
  }
  wheelchair_display::DisplayWindow window(*node);
  if (config.fullscreen) {
    window.setGeometry(QApplication::primaryScreen()->geometry());
    window.showFullScreen();
  } else {
    window.resize(config.width > 0 ? config.width : 1024, config.height > 0 ? config.height : 768);
    window.show();
  }
  return app.exec();
}
