// Test support: a planar world of wall segments, laser scans ray-cast in it from exact poses,
// and a drive around a block with drifting odometry. Independent of the code under test.
#pragma once

#include <wheelchair_core/laser_scan.h>
#include <wheelchair_core/pose2d.h>
#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace wheelchair_slam_test {

struct Segment {
  Eigen::Vector2d a, b;
};

/// An office floor: a 20 x 12 m outer wall, a 10 x 4 m block in the middle (the drive loops
/// around it) and a few pillars and wall stubs so that no stretch is featureless.
inline std::vector<Segment> officeWorld() {
  std::vector<Segment> w;
  auto box = [&](double x0, double y0, double x1, double y1) {
    w.push_back({{x0, y0}, {x1, y0}});
    w.push_back({{x1, y0}, {x1, y1}});
    w.push_back({{x1, y1}, {x0, y1}});
    w.push_back({{x0, y1}, {x0, y0}});
  };
  box(-10, -6, 10, 6);
  box(-5, -2, 5, 2);
  for (double x : {-7.5, -2.5, 2.5, 7.5}) {
    box(x - 0.15, 4.6, x + 0.15, 4.9);
    box(x + 0.6 - 0.15, -4.9, x + 0.6 + 0.15, -4.6);
  }
  w.push_back({{-10, 1.0}, {-8.8, 1.0}});
  w.push_back({{10, -1.5}, {8.7, -1.5}});
  w.push_back({{-3.0, 6}, {-3.0, 5.2}});
  w.push_back({{4.0, -6}, {4.0, -5.3}});
  return w;
}

/// A 361-beam, 180 deg scan from `pose` (range_max 30 m, beyond: +inf), Gaussian range noise.
inline wheelchair_core::LaserScan2D castScan(const std::vector<Segment>& world,
                                             const wheelchair_core::Pose2D& pose, double stamp,
                                             double noise_sigma, std::mt19937& rng) {
  wheelchair_core::LaserScan2D scan;
  scan.stamp = stamp;
  scan.angle_min = -M_PI / 2;
  scan.angle_increment = M_PI / 360;
  scan.angle_max = M_PI / 2;
  scan.range_min = 0.05;
  scan.range_max = 30.0;
  std::normal_distribution<double> noise(0.0, noise_sigma);
  const Eigen::Vector2d o(pose.x, pose.y);
  for (int i = 0; i <= 360; ++i) {
    const double a = pose.yaw + scan.angle_min + i * scan.angle_increment;
    const Eigen::Vector2d d(std::cos(a), std::sin(a));
    double best = INFINITY;
    for (const Segment& s : world) {
      const Eigen::Vector2d e = s.b - s.a;
      const double den = d.x() * e.y() - d.y() * e.x();
      if (std::abs(den) < 1e-12) continue;
      const Eigen::Vector2d q = s.a - o;
      const double t = (q.x() * e.y() - q.y() * e.x()) / den;
      const double u = (q.x() * d.y() - q.y() * d.x()) / den;
      if (t > 0 && u >= 0 && u <= 1) best = std::min(best, t);
    }
    const double r = best > scan.range_max ? INFINITY : best + noise(rng);
    scan.ranges.push_back(static_cast<float>(r));
  }
  return scan;
}

/// Poses every `step` metres along the rectangle x in [-7.5, 7.5], y in [-4, 4] around the
/// block (counter-clockwise, heading along the path), `laps` times.
inline std::vector<wheelchair_core::Pose2D> loopDrive(double step, int laps) {
  const std::vector<Eigen::Vector2d> corners = {{-7.5, -4}, {7.5, -4}, {7.5, 4}, {-7.5, 4}};
  std::vector<wheelchair_core::Pose2D> out;
  for (int lap = 0; lap < laps; ++lap) {
    for (size_t c = 0; c < corners.size(); ++c) {
      const Eigen::Vector2d a = corners[c], b = corners[(c + 1) % corners.size()];
      const double yaw = std::atan2(b.y() - a.y(), b.x() - a.x());
      const double length = (b - a).norm();
      // Turn on the spot at the corner in 4 steps, then drive the side.
      const double previous = out.empty() ? yaw : out.back().yaw;
      for (int k = 1; k <= 4 && !out.empty(); ++k) {
        const double t = previous + k * wheelchair_core::angleDifference(yaw, previous) / 4;
        out.push_back({a.x(), a.y(), wheelchair_core::normalizeAngle(t)});
      }
      for (double s = 0; s < length - 1e-9; s += step) {
        const Eigen::Vector2d p = a + (b - a) * (s / length);
        out.push_back({p.x(), p.y(), yaw});
      }
    }
  }
  return out;
}

/// Odometry of `truth` with a translation scale error, a heading drift per metre, and noise.
inline std::vector<wheelchair_core::Pose2D> driftingOdometry(
    const std::vector<wheelchair_core::Pose2D>& truth, double scale, double yaw_per_m, double noise,
    std::mt19937& rng) {
  std::normal_distribution<double> n(0.0, noise);
  std::vector<wheelchair_core::Pose2D> out = {truth.front()};
  for (size_t i = 1; i < truth.size(); ++i) {
    wheelchair_core::Pose2D d = wheelchair_core::between(truth[i - 1], truth[i]);
    const double length = std::hypot(d.x, d.y);
    d.x = d.x * scale + n(rng);
    d.y = d.y * scale + n(rng);
    d.yaw += yaw_per_m * length + 0.2 * n(rng);
    out.push_back(wheelchair_core::compose(out.back(), d));
  }
  return out;
}

/// Scans cast at the true poses, and the odometry at each.
struct Drive {
  std::vector<wheelchair_core::Pose2D> truth, odometry;
  std::vector<wheelchair_core::LaserScan2D> scans;
};

/// Two laps around the block, odometry with a 3 % scale error and 0.02 rad/m heading drift.
inline Drive syntheticDrive() {
  std::mt19937 rng(11);
  Drive d;
  d.truth = loopDrive(0.2, 2);
  d.odometry = driftingOdometry(d.truth, 1.03, 0.02, 0.002, rng);
  const auto world = officeWorld();
  for (size_t i = 0; i < d.truth.size(); ++i) {
    d.scans.push_back(castScan(world, d.truth[i], 0.2 * i, 0.01, rng));
  }
  return d;
}

/// Largest position error after aligning the first poses (the map frame starts there).
inline double maxError(const std::vector<wheelchair_core::Pose2D>& estimate,
                       const std::vector<wheelchair_core::Pose2D>& truth) {
  const wheelchair_core::Pose2D align =
      wheelchair_core::compose(truth[0], wheelchair_core::inverse(estimate[0]));
  double worst = 0.0;
  for (size_t i = 0; i < truth.size(); ++i) {
    const wheelchair_core::Pose2D p = wheelchair_core::compose(align, estimate[i]);
    worst = std::max(worst, std::hypot(p.x - truth[i].x, p.y - truth[i].y));
  }
  return worst;
}

}  // namespace wheelchair_slam_test
