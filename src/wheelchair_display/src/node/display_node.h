// The display's ROS side and its state: subscribes the map, the live obstacle layer, tf, the
// HMI's state and the typed statuses; sends goals, stops and initial poses; asks the route check
// (a wheelchair_msgs/MakePlan service) before the rider confirms; speaks. Everything runs in the
// Qt thread (tick() spins ROS); the window only draws this state and calls the actions.
#pragma once

#include "display_node_config.h"
#include "drive_source.h"
#include "speaker.h"

#include <wheelchair_core/occupancy_map.h>
#include <wheelchair_core/polygon.h>
#include <wheelchair_display/drive_tracker.h>
#include <wheelchair_display/map_view.h>
#include <wheelchair_display/rider_text.h>
#include <wheelchair_display/scene.h>
#include <wheelchair_display/switch_press.h>
#include <wheelchair_display/theme.h>
#include <wheelchair_hmi/places.h>

#include <nav_msgs/OccupancyGrid.h>
#include <ros/ros.h>
#include <std_msgs/Empty.h>
#include <tf2_ros/buffer.h>
#include <wheelchair_msgs/HmiState.h>
#include <wheelchair_msgs/LocalizationStatus.h>
#include <wheelchair_msgs/MakePlan.h>
#include <wheelchair_msgs/SafetyStatus.h>

#include <QImage>

#include <future>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace wheelchair_display {

class DisplayNode {
 public:
  explicit DisplayNode(const DisplayNodeConfig& config);

  /// Spins ROS once, reads the chair's pose, collects the route check's answer, lets old
  /// outcomes go, speaks what is new. Call at the display's frame rate.
  void tick();

  // What there is to draw.
  const DisplayNodeConfig& config() const { return config_; }
  const Theme& theme() const { return theme_; }
  Orientation orientation() const { return orientation_; }
  const wheelchair_core::OccupancyMap* map() const { return map_ ? &*map_ : nullptr; }
  const QImage& mapImage() const { return map_image_; }
  const QImage& obstacleImage() const { return obstacle_image_; }
  const wheelchair_core::OccupancyMap* obstacles() const {
    return obstacles_ ? &*obstacles_ : nullptr;
  }
  const wheelchair_core::Box& overview() const { return overview_; }
  const std::vector<wheelchair_hmi::Place>& places() const { return places_; }
  const std::vector<RoomArea>& rooms() const { return rooms_; }
  const std::optional<wheelchair_core::Pose2D>& chairPose() const { return chair_pose_; }
  const wheelchair_core::Polygon& footprint() const { return footprint_; }
  const DriveTracker& drive() const { return drive_; }
  /// The HMI's state, its time left counted down since it came.
  ScanView scan() const;
  DisplayInputs inputs() const;
  Message message() const { return describe(inputs()); }
  const std::string& pointerRoom() const { return pointer_room_; }

  // The rider's actions.
  void openRoom(const std::string& room);
  void closeRoom() { pointer_room_.clear(); }
  void choosePlace(size_t index);
  void chooseSpot(const Eigen::Vector2d& world);
  void confirm();   ///< drive to the checked choice
  void stop();      ///< stops the chair (and withdraws a choice)
  void withdraw();  ///< withdraws a choice not yet confirmed (nothing is sent)

  // The carer's actions; each returns "" or what went wrong.
  void setPose(const wheelchair_core::Pose2D& pose);
  std::string savePlaceHere(const std::string& typed_name, const std::string& room);
  std::string deletePlace(const std::string& name);
  void setTheme(const std::string& name);
  void setOrientation(Orientation orientation) { orientation_ = orientation; }
  void setSpeech(bool on);
  bool speechOn() const { return speaker_.settings().enabled; }

  /// Publishes (latched, on change) how the map is drawn: ~view = [scale px/m, rotation rad,
  /// world centre x, y (m), screen centre x, y (px), map region x, y, w, h (px)], so a tool or a
  /// test can find a world point on the screen.
  void publishView(const ViewTransform& view, const Rect& map_region);

 private:
  void onMap(const nav_msgs::OccupancyGrid::ConstPtr& msg);
  void onObstacles(const nav_msgs::OccupancyGrid::ConstPtr& msg);
  void onHmiState(const wheelchair_msgs::HmiState::ConstPtr& msg);
  void onLocalization(const wheelchair_msgs::LocalizationStatus::ConstPtr& msg);
  void onSafety(const wheelchair_msgs::SafetyStatus::ConstPtr& msg);
  void onSwitch(const std_msgs::Empty::ConstPtr&);
  void readPose();
  void startRouteCheck(const std::string& destination, const wheelchair_core::Pose2D& goal);
  void collectRouteCheck();
  void renderMapImages();
  void say(const std::string& text);
  void reloadPlaces();

  DisplayNodeConfig config_;
  Theme theme_;
  Orientation orientation_;
  ros::NodeHandle nh_, pnh_;
  std::shared_ptr<tf2_ros::Buffer> tf_;
  std::vector<wheelchair_hmi::Place> places_;
  std::vector<RoomArea> rooms_;
  wheelchair_core::Polygon footprint_;
  std::optional<wheelchair_core::OccupancyMap> map_, obstacles_;
  wheelchair_core::Box overview_;
  QImage map_image_, obstacle_image_;
  std::optional<wheelchair_core::Pose2D> chair_pose_;
  ScanView scan_;
  double scan_received_ = 0.0;
  LocalizationView localization_;
  SafetyView safety_;
  DriveTracker drive_;
  LegacyDriveSource drive_source_;
  std::string pointer_room_;
  bool was_driving_ = false;
  Announcer announcer_;
  Speaker speaker_;

  struct RouteCheck {
    wheelchair_core::Pose2D goal;
    double started = 0.0;  ///< [s, wall]
    std::future<std::optional<wheelchair_msgs::MakePlan::Response>> answer;
  };
  std::optional<RouteCheck> route_check_;
  /// Checks whose answer no longer matters: a std::async future blocks in its destructor until
  /// the call returns, so they wait here (never in the Qt thread) until they are done.
  std::vector<RouteCheck> abandoned_;
  void abandonRouteCheck();

  ros::Publisher goal_pub_, stop_pub_, initial_pose_pub_, said_pub_, status_pub_, view_pub_;
  std::vector<double> last_view_;
  std::vector<ros::Subscriber> subs_;
  std::string last_status_;
};

}  // namespace wheelchair_display
