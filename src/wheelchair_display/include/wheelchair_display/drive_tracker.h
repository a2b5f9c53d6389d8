// The drive as the display tells it: a chosen destination being checked, then the drive with
// the distance left along its route, then its outcome, which stays on screen for a while. Fed by
// the ROS layer from whatever owns drives (today the planner's /plan and the controller's path
// status; with the navigator, its move_base feedback and result).
#pragma once

#include <wheelchair_core/pose2d.h>
#include <wheelchair_display/display_model.h>

#include <Eigen/Core>

#include <optional>
#include <string>
#include <vector>

namespace wheelchair_display {

/// [m] the length of `path` left from the point nearest to `position`; `segment` (in: where to
/// start looking, out: the segment found) keeps the search moving forward along the route, so a
/// route that passes the chair twice is not cut short.
double remainingLength(const std::vector<wheelchair_core::Pose2D>& path,
                       const Eigen::Vector2d& position, size_t* segment = nullptr);

class DriveTracker {
 public:
  /// An outcome (arrived, stopped, refused) stays shown `outcome_hold` seconds.
  explicit DriveTracker(double outcome_hold) : outcome_hold_(outcome_hold) {}

  /// The rider chose `destination` ("" for a spot) at `goal`: checking whether it can be reached.
  void check(const std::string& destination, const wheelchair_core::Pose2D& goal, double now);
  /// The check's answer (ignored if the choice changed meanwhile: `goal` must match).
  void checked(const wheelchair_core::Pose2D& goal, bool reachable, double length,
               const std::string& sentence, double now);
  /// The choice is withdrawn (nothing confirmed).
  void cancelChoice();
  /// A goal was sent (by the display, the HMI or a tool): the chair drives there.
  void goal(const std::string& destination, const wheelchair_core::Pose2D& goal, double now);
  /// The route of the current goal; an empty one means the goal was refused.
  void route(const std::vector<wheelchair_core::Pose2D>& poses, double now);
  /// The chair is at `position`: the distance left.
  void progress(const Eigen::Vector2d& position);
  /// While driving: the navigator's sentence of why the drive is held up (something in the
  /// way, the way blocked), or "" once it drives on.
  void heldUp(const std::string& sentence);
  void arrived(double now, const std::string& sentence = "");
  /// The drive ended without a verdict on arrival (the controller gave up a few mm or degrees
  /// off): arrived if the chair's last position is within `radius` [m] of the goal, else failed.
  /// `sentence`: the navigator's words for how it ended, told if it did not arrive.
  void ended(double now, double radius, const std::string& sentence = "");
  void failed(double now, const std::string& sentence = "");
  void refused(double now, const std::string& sentence = "");
  void riderStopped(double now);
  /// Lets an old outcome go.
  void tick(double now);

  const DriveView& view() const { return view_; }
  bool driving() const { return view_.phase == DriveView::Phase::kDriving; }
  /// The destination chosen or driven to, if any.
  const std::optional<wheelchair_core::Pose2D>& goalPose() const { return goal_; }
  const std::vector<wheelchair_core::Pose2D>& routePoses() const { return route_; }

 private:
  /// A new choice or drive: what was shown before is forgotten.
  void begin(DriveView::Phase phase, const std::string& destination,
             const wheelchair_core::Pose2D& goal);
  void end(DriveView::Phase phase, const std::string& sentence, double now);

  double outcome_hold_;
  DriveView view_;
  std::optional<wheelchair_core::Pose2D> goal_;
  std::vector<wheelchair_core::Pose2D> route_;
  size_t segment_ = 0;
  std::optional<Eigen::Vector2d> position_;
  double outcome_time_ = 0.0;
};

}  // namespace wheelchair_display
