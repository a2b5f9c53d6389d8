// The map view: a similarity transform world (map frame, metres) -> screen (pixels, y down),
// north-up (the map's +y up) or chair-up (the chair's heading up), zoomed to fit what matters
// now (the whole map, a room's places, or the chair and its route).
#pragma once

#include <wheelchair_display/layout.h>

#include <Eigen/Core>

#include <string>
#include <vector>

namespace wheelchair_display {

enum class Orientation { kNorthUp, kChairUp };
/// "north_up" / "chair_up"; throws std::invalid_argument naming both.
Orientation orientationNamed(const std::string& name);

struct ViewTransform {
  double scale = 1.0;     ///< [px / m]
  double rotation = 0.0;  ///< [rad] the world is turned by this before drawing
  Eigen::Vector2d world_centre{0.0, 0.0};
  Eigen::Vector2d screen_centre{0.0, 0.0};

  Eigen::Vector2d toScreen(const Eigen::Vector2d& world) const;
  Eigen::Vector2d toWorld(const Eigen::Vector2d& screen) const;
  /// The screen direction [rad, counter-clockwise as seen, 0 = right] of a world heading.
  double screenHeading(double world_yaw) const { return world_yaw + rotation; }
};

/// The view's rotation: 0 north-up; chair-up turns the chair's heading `chair_yaw` to point up.
double viewRotation(Orientation orientation, double chair_yaw);

/// The view that shows every point of `frame` inside `viewport`, `margin_px` from its edges,
/// and at least `min_extent` metres across in both directions (a chair alone is not zoomed in
/// to fill the screen). An empty frame gives a view centred on the origin.
ViewTransform fitView(const Rect& viewport, const std::vector<Eigen::Vector2d>& frame,
                      double rotation, double margin_px, double min_extent);

}  // namespace wheelchair_display
