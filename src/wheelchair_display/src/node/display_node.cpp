#include "display_node.h"

#include <wheelchair_description/chair_file.h>
#include <wheelchair_hmi/places_file.h>
#include <wheelchair_ros/conversions.h>
#include <wheelchair_ros/shared_tf.h>

#include <geometry_msgs/PoseStamped.h>
#include <geometry_msgs/PoseWithCovarianceStamped.h>
#include <std_msgs/Float64MultiArray.h>
#include <std_msgs/String.h>

#include <algorithm>
#include <chrono>

namespace wheelchair_display {
using wheelchair_hmi::placeId;
using wheelchair_hmi::placeNameProblem;
using wheelchair_hmi::savePlaces;
namespace {

/// The name of the service that checks a route without driving it (remap it to the planner that
/// answers). It must not be the planner that feeds the controller: the planner host's make_plan
/// also publishes its answer on /plan, and the controller drives every /plan.
constexpr char kRouteCheckService[] = "route_check/make_plan";

QRgb qrgb(const Rgb& c) { return qRgb(c.r, c.g, c.b); }

ScanView::State scanStateOf(uint8_t state) {
  using M = wheelchair_msgs::HmiState;
  switch (state) {
    case M::SCANNING_ROOMS:
      return ScanView::State::kRooms;
    case M::SCANNING_PLACES:
      return ScanView::State::kPlaces;
    case M::CONFIRMING:
      return ScanView::State::kConfirming;
    case M::DRIVING:
      return ScanView::State::kDriving;
    default:
      return ScanView::State::kIdle;
  }
}

}  // namespace

DisplayNode::DisplayNode(const DisplayNodeConfig& config)
    : config_(config),
      theme_(themeNamed(config.display.theme)),
      orientation_(orientationNamed(config.display.orientation)),
      pnh_("~"),
      tf_(wheelchair_ros::sharedTfBuffer()),
      places_(wheelchair_hmi::loadPlaces(config.places_file)),
      rooms_(roomAreas(places_, config.display.room_pad)),
      drive_(config.display.outcome_hold),
      drive_source_(nh_, drive_, places_),
      announcer_(config.display.speak_highlight),
      speaker_(config.display.speech, config.speech_wav_dir) {
  const std::string chair_file = wheelchair_description::resolveChairFile(config.chair_file);
  footprint_ = wheelchair_description::loadChairParams(chair_file).footprint;
  goal_pub_ = nh_.advertise<geometry_msgs::PoseStamped>("move_base_simple/goal", 1);
  stop_pub_ = nh_.advertise<std_msgs::Empty>("user_stop", 1);
  initial_pose_pub_ = nh_.advertise<geometry_msgs::PoseWithCovarianceStamped>("initialpose", 1);
  said_pub_ = pnh_.advertise<std_msgs::String>("said", 20);
  status_pub_ = pnh_.advertise<std_msgs::String>("status", 1, true);
  view_pub_ = pnh_.advertise<std_msgs::Float64MultiArray>("view", 1, true);
  subs_.push_back(nh_.subscribe("map", 1, &DisplayNode::onMap, this));
  subs_.push_back(nh_.subscribe("obstacles", 1, &DisplayNode::onObstacles, this));
  subs_.push_back(nh_.subscribe("hmi/state", 5, &DisplayNode::onHmiState, this));
  subs_.push_back(nh_.subscribe("localization/status", 5, &DisplayNode::onLocalization, this));
  subs_.push_back(nh_.subscribe("safety/status", 5, &DisplayNode::onSafety, this));
  subs_.push_back(nh_.subscribe("switch", 10, &DisplayNode::onSwitch, this));
  ROS_INFO("display: %zu places in %zu rooms from %s; chair footprint from %s", places_.size(),
           rooms_.size(), config.places_file.c_str(), chair_file.c_str());
}

void DisplayNode::tick() {
  ros::spinOnce();
  readPose();
  collectRouteCheck();
  const double now = ros::Time::now().toSec();
  drive_.tick(now);
  if (chair_pose_) drive_.progress(chair_pose_->position());
  // A drive started anywhere (this display, another one, the switch, a tool) ends the pointer's
  // browsing: afterwards every display shows all the rooms again.
  if (drive_.driving() && !was_driving_) pointer_room_.clear();
  was_driving_ = drive_.driving();
  const Message m = message();
  say(announcer_.onStatus(m.status));
  say(announcer_.onScan(scan()));
  if (m.status != last_status_) {
    last_status_ = m.status;
    std_msgs::String msg;
    msg.data = m.status;
    status_pub_.publish(msg);
    ROS_INFO("display: %s", m.status.c_str());
  }
}

ScanView DisplayNode::scan() const {
  ScanView s = scan_;
  s.time_left = std::max(0.0, s.time_left - (ros::Time::now().toSec() - scan_received_));
  return s;
}

DisplayInputs DisplayNode::inputs() const {
  DisplayInputs in;
  in.have_map = map_.has_value();
  in.have_pose = chair_pose_.has_value();
  in.localization = localization_;
  in.safety = safety_;
  in.scan = scan();
  in.drive = drive_.view();
  in.pointer_room = pointer_room_;
  return in;
}

void DisplayNode::readPose() {
  try {
    const auto t = tf_->lookupTransform(config_.map_frame, config_.base_frame, ros::Time(0));
    const double age = (ros::Time::now() - t.header.stamp).toSec();
    if (t.header.stamp.isZero() || age <= config_.pose_timeout) {
      chair_pose_ = wheelchair_ros::toPose2D(t.transform);
      return;
    }
  } catch (const tf2::TransformException&) {
  }
  chair_pose_.reset();
}

void DisplayNode::onMap(const nav_msgs::OccupancyGrid::ConstPtr& msg) {
  try {
    map_ = wheelchair_ros::fromOccupancyGrid(*msg);
  } catch (const std::invalid_argument& e) {
    ROS_ERROR("display: map refused: %s", e.what());
    return;
  }
  overview_ = knownBounds(*map_);
  renderMapImages();
}

void DisplayNode::onObstacles(const nav_msgs::OccupancyGrid::ConstPtr& msg) {
  try {
    obstacles_ = wheelchair_ros::fromOccupancyGrid(*msg);
  } catch (const std::invalid_argument& e) {
    ROS_WARN_THROTTLE(10.0, "display: obstacle layer refused: %s", e.what());
    return;
  }
  renderMapImages();
}

void DisplayNode::renderMapImages() {
  // Images are top row first; grids are bottom row first.
  if (map_) {
    map_image_ = QImage(map_->width, map_->height, QImage::Format_RGB32);
    for (int iy = 0; iy < map_->height; ++iy) {
      auto* row = reinterpret_cast<QRgb*>(map_image_.scanLine(map_->height - 1 - iy));
      for (int ix = 0; ix < map_->width; ++ix) {
        const int8_t v = map_->at(ix, iy);
        row[ix] = qrgb(v == wheelchair_core::kUnknown ? theme_.unknown
                       : v >= 50                      ? theme_.wall
                                                      : theme_.floor);
      }
    }
  }
  if (obstacles_) {
    obstacle_image_ = QImage(obstacles_->width, obstacles_->height, QImage::Format_ARGB32);
    obstacle_image_.fill(Qt::transparent);
    for (int iy = 0; iy < obstacles_->height; ++iy)
      for (int ix = 0; ix < obstacles_->width; ++ix)
        if (obstacles_->at(ix, iy) >= 50)
          obstacle_image_.setPixel(ix, obstacles_->height - 1 - iy, qrgb(theme_.obstacle));
  }
}

void DisplayNode::onHmiState(const wheelchair_msgs::HmiState::ConstPtr& msg) {
  const ScanView before = scan_;
  scan_.state = scanStateOf(msg->state);
  scan_.items = msg->items;
  scan_.highlighted = msg->highlighted;
  scan_.room = msg->room;
  scan_.place = msg->place;
  scan_.time_left = msg->time_left;
  scan_.step_time = msg->step_time;
  scan_.sentence = msg->sentence;
  scan_received_ = ros::Time::now().toSec();
  // The switch's choice leads: a room the pointer had opened, and a choice of the pointer not
  // yet confirmed, give way to the one pressed. Only at that press: the HMI's later states (every
  // highlight step) leave alone what the pointer opens meanwhile (the carer's tools).
  if (switchTakesOver(before, scan_)) {
    pointer_room_.clear();
    withdraw();
  }
}

void DisplayNode::onLocalization(const wheelchair_msgs::LocalizationStatus::ConstPtr& msg) {
  localization_.state = msg->state == wheelchair_msgs::LocalizationStatus::LOCALIZED
                            ? LocalizationView::State::kLocalized
                            : LocalizationView::State::kNotLocalized;
  localization_.sentence = msg->sentence;
}

void DisplayNode::onSafety(const wheelchair_msgs::SafetyStatus::ConstPtr& msg) {
  safety_.known = true;
  // Waiting for the first sensor data is no stop to tell the rider about.
  safety_.stop = msg->stop && msg->reason != wheelchair_msgs::SafetyStatus::NO_DATA;
  safety_.sentence = msg->sentence;
}

void DisplayNode::onSwitch(const std_msgs::Empty::ConstPtr&) {
  // One meaning per press (switch_press.h): the HMI's while it scans, a stop while driving.
  switch (pressMeaning(scan_, drive_.view())) {
    case PressMeaning::kStop:
      stop();
      break;
    case PressMeaning::kConfirm:
      confirm();
      break;
    case PressMeaning::kHmis:
    case PressMeaning::kNothing:
      break;
  }
}

void DisplayNode::openRoom(const std::string& room) {
  if (roomNamed(rooms_, room) >= 0) pointer_room_ = room;
}

void DisplayNode::choosePlace(size_t index) {
  if (index >= places_.size()) return;
  const auto& p = places_[index];
  startRouteCheck(p.name, p.pose);
}

void DisplayNode::chooseSpot(const Eigen::Vector2d& world) {
  // Arrive facing away from where the chair is now (the way it drives in).
  const double yaw =
      chair_pose_ ? std::atan2(world.y() - chair_pose_->y, world.x() - chair_pose_->x) : 0.0;
  const wheelchair_core::Pose2D goal{world.x(), world.y(), yaw};
  int ix = 0, iy = 0;
  const bool free = map_ && map_->worldToCell(world.x(), world.y(), ix, iy) &&
                    map_->at(ix, iy) != wheelchair_core::kUnknown && map_->at(ix, iy) < 50;
  if (!free) {
    drive_.check("", goal, ros::Time::now().toSec());
    drive_.checked(goal, false, 0.0, "The chair cannot stand there.", ros::Time::now().toSec());
    return;
  }
  startRouteCheck("", goal);
}

void DisplayNode::startRouteCheck(const std::string& destination,
                                  const wheelchair_core::Pose2D& goal) {
  const double now = ros::Time::now().toSec();
  drive_.check(destination, goal, now);
  wheelchair_msgs::MakePlan srv;
  srv.request.use_start = false;  // from where the chair is (tf map -> base_link)
  srv.request.goal.header.frame_id = config_.map_frame;
  srv.request.goal.header.stamp = ros::Time::now();
  srv.request.goal.pose = wheelchair_ros::toPoseMsg(goal);
  abandonRouteCheck();
  const std::string service = nh_.resolveName(kRouteCheckService);
  if (!ros::service::exists(service, false)) {
    ROS_WARN("display: no route check (%s): the choice is not checked before it is confirmed",
             service.c_str());
    drive_.checked(goal, true, std::nan(""), "", now);
    return;
  }
  route_check_ = RouteCheck{
      goal, ros::WallTime::now().toSec(),
      std::async(std::launch::async,
                 [service, srv]() mutable -> std::optional<wheelchair_msgs::MakePlan::Response> {
                   if (!ros::service::call(service, srv)) return std::nullopt;
                   return srv.response;
                 })};
}

void DisplayNode::abandonRouteCheck() {
  if (route_check_) abandoned_.push_back(std::move(*route_check_));
  route_check_.reset();
}

void DisplayNode::collectRouteCheck() {
  abandoned_.erase(std::remove_if(abandoned_.begin(), abandoned_.end(),
                                  [](const RouteCheck& c) {
                                    return !c.answer.valid() ||
                                           c.answer.wait_for(std::chrono::seconds(0)) ==
                                               std::future_status::ready;
                                  }),
                   abandoned_.end());
  if (!route_check_) return;
  if (route_check_->answer.wait_for(std::chrono::seconds(0)) != std::future_status::ready) {
    if (ros::WallTime::now().toSec() - route_check_->started < config_.route_check_timeout) return;
    ROS_WARN("display: no answer from the route check within %.1f s", config_.route_check_timeout);
    const auto goal = route_check_->goal;
    abandonRouteCheck();
    drive_.checked(goal, true, std::nan(""), "", ros::Time::now().toSec());
    return;
  }
  const auto answer = route_check_->answer.get();
  const auto goal = route_check_->goal;
  route_check_.reset();  // answered: its future no longer waits
  const double now = ros::Time::now().toSec();
  if (!answer) {
    ROS_WARN("display: the route check did not answer");
    drive_.checked(goal, true, std::nan(""), "", now);
    return;
  }
  if (!answer->success) ROS_INFO("display: route check refused: %s", answer->reason.c_str());
  drive_.checked(goal, answer->success, answer->certificate.length, "", now);
}

void DisplayNode::confirm() {
  if (drive_.view().phase != DriveView::Phase::kReachable || !drive_.goalPose()) return;
  const auto goal = *drive_.goalPose();
  const std::string destination = drive_.view().destination;
  drive_source_.expectOwnGoal(destination, goal);
  geometry_msgs::PoseStamped msg;
  msg.header.frame_id = config_.map_frame;
  msg.header.stamp = ros::Time::now();
  msg.pose = wheelchair_ros::toPoseMsg(goal);
  goal_pub_.publish(msg);
  // Shown as driving at once; the goal's echo on the topic confirms it.
  drive_.goal(destination, goal, ros::Time::now().toSec());
  pointer_room_.clear();
}

void DisplayNode::stop() {
  stop_pub_.publish(std_msgs::Empty());
  drive_.riderStopped(ros::Time::now().toSec());
  abandonRouteCheck();
}

void DisplayNode::withdraw() {
  drive_.cancelChoice();
  abandonRouteCheck();
}

void DisplayNode::setPose(const wheelchair_core::Pose2D& pose) {
  geometry_msgs::PoseWithCovarianceStamped msg;
  msg.header.frame_id = config_.map_frame;
  msg.header.stamp = ros::Time::now();
  msg.pose.pose = wheelchair_ros::toPoseMsg(pose);
  // As rviz's 2D Pose Estimate: 0.2 m and 0.2 rad standard deviations.
  msg.pose.covariance =
      wheelchair_ros::toRosCovariance(Eigen::Vector3d(0.04, 0.04, 0.04).asDiagonal());
  initial_pose_pub_.publish(msg);
  ROS_INFO("display: the carer set the chair's pose to (%.2f, %.2f, %.2f)", pose.x, pose.y,
           pose.yaw);
}

std::string DisplayNode::savePlaceHere(const std::string& typed_name, const std::string& room) {
  if (!chair_pose_) return "the chair's position is not known";
  const std::string id = placeId(typed_name);
  const std::string problem = placeNameProblem(id, places_);
  if (!problem.empty()) return problem;
  const std::string room_id = placeId(room).empty() ? "places" : placeId(room);
  auto edited = places_;
  edited.push_back({id, room_id, *chair_pose_});
  try {
    savePlaces(config_.places_file, edited);
    reloadPlaces();
  } catch (const std::exception& e) {
    return e.what();
  }
  ROS_INFO("display: saved place '%s' in room '%s'", id.c_str(), room_id.c_str());
  return "";
}

std::string DisplayNode::deletePlace(const std::string& name) {
  auto edited = places_;
  edited.erase(std::remove_if(edited.begin(), edited.end(),
                              [&](const wheelchair_hmi::Place& p) { return p.name == name; }),
               edited.end());
  if (edited.size() == places_.size()) return "no place called '" + name + "'";
  if (edited.empty()) return "the last place cannot be deleted";
  try {
    savePlaces(config_.places_file, edited);
    reloadPlaces();
  } catch (const std::exception& e) {
    return e.what();
  }
  ROS_INFO("display: deleted place '%s'", name.c_str());
  return "";
}

void DisplayNode::reloadPlaces() {
  places_ = wheelchair_hmi::loadPlaces(config_.places_file);
  rooms_ = roomAreas(places_, config_.display.room_pad);
  if (roomNamed(rooms_, pointer_room_) < 0) pointer_room_.clear();
}

void DisplayNode::setTheme(const std::string& name) {
  theme_ = themeNamed(name);
  renderMapImages();
}

void DisplayNode::setSpeech(bool on) {
  SpeechSettings s = speaker_.settings();
  s.enabled = on;
  speaker_.setSettings(s);
}

void DisplayNode::publishView(const ViewTransform& view, const Rect& map_region) {
  const std::vector<double> values = {view.scale,
                                      view.rotation,
                                      view.world_centre.x(),
                                      view.world_centre.y(),
                                      view.screen_centre.x(),
                                      view.screen_centre.y(),
                                      double(map_region.x),
                                      double(map_region.y),
                                      double(map_region.w),
                                      double(map_region.h)};
  if (values == last_view_) return;
  last_view_ = values;
  std_msgs::Float64MultiArray msg;
  msg.data = values;
  view_pub_.publish(msg);
}

void DisplayNode::say(const std::string& text) {
  if (text.empty()) return;
  speaker_.say(spokenText(text));
  std_msgs::String msg;
  msg.data = text;
  said_pub_.publish(msg);
}

}  // namespace wheelchair_display
