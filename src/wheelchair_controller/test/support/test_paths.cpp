#include <wheelchair_controller_test/test_paths.h>

#include <cmath>

namespace wheelchair_controller {

PathBuilder::PathBuilder(const Pose2D& start, double spacing) : poses_{start}, spacing_(spacing) {}

PathBuilder& PathBuilder::straight(double length) {
  const Pose2D p0 = poses_.back();
  const int n = std::max(1, static_cast<int>(std::round(length / spacing_)));
  for (int i = 1; i <= n; ++i) {
    const double s = sign_ * length * i / n;
    poses_.push_back({p0.x + s * std::cos(p0.yaw), p0.y + s * std::sin(p0.yaw), p0.yaw});
  }
  return *this;
}

PathBuilder& PathBuilder::arc(double radius, double angle) {
  const Pose2D p0 = poses_.back();
  // In reverse the heading turns left (angle > 0) about the centre on the right of the chair.
  const double side = (angle >= 0.0 ? 1.0 : -1.0) * sign_;
  const Eigen::Vector2d centre(p0.x - side * radius * std::sin(p0.yaw),
                               p0.y + side * radius * std::cos(p0.yaw));
  const int n = std::max(1, static_cast<int>(std::round(std::abs(angle) * radius / spacing_)));
  for (int i = 1; i <= n; ++i) {
    const double th = p0.yaw + angle * i / n;
    poses_.push_back(
        {centre.x() + side * radius * std::sin(th), centre.y() - side * radius * std::cos(th), th});
  }
  return *this;
}

std::vector<Pose2D> PathBuilder::posesWithGoalHeading(double goal_heading) const {
  std::vector<Pose2D> p = poses_;
  p.back().yaw = goal_heading;
  return p;
}

std::vector<NamedPath> homeTestPaths() {
  const double q = M_PI / 2.0;
  std::vector<NamedPath> paths;
  paths.push_back({"hallway", PathBuilder({0.0, 0.0, 0.0}).straight(4.0).poses()});
  paths.push_back({"room_to_hall",
                   PathBuilder({1.0, 1.0, 0.0}).straight(2.0).arc(1.0, q).straight(2.0).poses()});
  paths.push_back({"doorway", PathBuilder({0.0, 0.0, q})
                                  .straight(1.5)
                                  .arc(0.8, -q)
                                  .straight(1.5)
                                  .arc(0.8, q)
                                  .straight(1.0)
                                  .poses()});
  paths.push_back(
      {"s_curve",
       PathBuilder({0.0, 0.0, 0.0}).arc(1.5, q / 2).arc(1.5, -q / 2).straight(1.0).poses()});
  paths.push_back(
      {"around_table",
       PathBuilder({0.0, 0.0, 0.0}).straight(1.0).arc(1.2, M_PI).straight(1.0).poses()});
  paths.push_back({"kitchen_to_bedroom", PathBuilder({0.0, 0.0, -q})
                                             .straight(3.0)
                                             .arc(0.7, -q)
                                             .straight(3.0)
                                             .arc(1.0, q)
                                             .straight(1.5)
                                             .poses()});
  paths.push_back({"slalom", PathBuilder({0.0, 0.0, 0.0})
                                 .arc(1.0, q / 3)
                                 .arc(1.0, -2 * q / 3)
                                 .arc(1.0, 2 * q / 3)
                                 .arc(1.0, -q / 3)
                                 .straight(1.0)
                                 .poses()});
  paths.push_back(
      {"tight_turn",
       PathBuilder({0.0, 0.0, M_PI}).straight(1.0).arc(0.6, 4 * q / 3).straight(1.5).poses()});
  paths.push_back({"living_room", PathBuilder({0.0, 0.0, 0.3})
                                      .arc(4.0, 0.35)
                                      .straight(2.0)
                                      .arc(4.0, -0.35)
                                      .straight(1.0)
                                      .poses()});
  paths.push_back({"to_bedside", PathBuilder({0.0, 0.0, 0.0})
                                     .straight(2.0)
                                     .arc(1.0, q)
                                     .straight(1.0)
                                     .posesWithGoalHeading(M_PI)});
  return paths;
}

std::vector<NamedPath> flatTestPaths() {
  const double q = M_PI / 2.0;
  std::vector<NamedPath> paths;
  const auto add = [&paths](const char* name, const PathBuilder& b) {
    paths.push_back({name, b.poses()});
  };
  add("living_to_hallway", PathBuilder({2.8, 4.5, 0.0}).straight(1.5).arc(0.8, q).straight(3.0));
  add("hallway_to_living", PathBuilder({5.1, 8.5, -q}).straight(3.3).arc(0.8, -q).straight(1.5));
  add("living_to_kitchen", PathBuilder({3.0, 4.9, 0.0}).straight(4.5).arc(1.0, -q).straight(1.5));
  add("kitchen_to_living", PathBuilder({8.4, 2.3, q}).straight(1.6).arc(1.0, q).straight(4.0));
  add("around_table", PathBuilder({2.9, 2.0, 0.0})
                          .straight(1.4)
                          .arc(0.9, q)
                          .straight(1.1)
                          .arc(0.9, q)
                          .straight(1.5)
                          .arc(0.9, q)
                          .straight(0.5));
  add("s_curve", PathBuilder({2.9, 1.85, 0.0}).arc(1.5, 0.6).arc(1.5, -0.6).straight(0.5));
  add("around_island", PathBuilder({8.6, 1.8, q}).straight(2.2).arc(1.025, M_PI).straight(2.0));
  add("living_loop", PathBuilder({2.8, 2.2, q})
                         .straight(2.1)
                         .arc(0.8, -q)
                         .straight(1.0)
                         .arc(0.9, -q)
                         .straight(1.0));
  add("tv_to_centre", PathBuilder({2.0, 4.6, -q}).arc(1.0, 1.0).arc(1.0, -1.0).straight(0.3));
  add("to_tv", PathBuilder({2.95, 3.0, q}).arc(1.0, 1.0).arc(1.0, -1.0).straight(0.2));
  return paths;
}

std::vector<Pose2D> cosinePath(double amplitude, double wavelength, double length, double spacing) {
  std::vector<Pose2D> p;
  const double k = 2.0 * M_PI / wavelength;
  for (double x = 0.0; x <= length + 1e-9; x += spacing)
    p.push_back({x, amplitude * std::cos(k * x), std::atan(-amplitude * k * std::sin(k * x))});
  return p;
}

std::vector<Pose2D> threePointTurnPath() {
  return PathBuilder({0.0, 0.0, 0.0})
      .straight(0.3)
      .arc(0.8, M_PI / 2)
      .reverse()
      .arc(0.8, M_PI / 2)
      .forward()
      .arc(1.0, M_PI / 2)
      .straight(0.5)
      .poses();
}

}  // namespace wheelchair_controller
