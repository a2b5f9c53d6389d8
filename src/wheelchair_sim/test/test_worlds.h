// Small ground-truth grids built in code for the unit tests.
#pragma once

#include <wheelchair_description/chair_params.h>
#include <wheelchair_description_testing/chair_file.h>

#include <wheelchair_core/kinematics.h>
#include <wheelchair_core/pose2d.h>

#include <mrpt/maps/COccupancyGridMap2D.h>

#include <Eigen/Core>

#include <memory>

namespace wheelchair_sim {
namespace test {

/// Free grid [x_min, x_max] x [y_min, y_max] at `res`, with one occupied column of cells
/// whose left face is at x = wall_x (the wall fills [wall_x, wall_x + thickness]).
inline std::shared_ptr<mrpt::maps::COccupancyGridMap2D> wallWorld(double wall_x,
                                                                  double x_min = -5.0,
                                                                  double x_max = 10.0,
                                                                  double res = 0.05) {
  auto grid = std::make_shared<mrpt::maps::COccupancyGridMap2D>(x_min, x_max, -5.0f, 5.0f, res);
  grid->fill(1.0f);  // free (MRPT stores P(free))
  const int first = grid->x2idx(wall_x + 0.5 * res);
  for (int ix = first; ix < first + 4; ++ix) {
    for (unsigned iy = 0; iy < grid->getSizeY(); ++iy) grid->setCell(ix, iy, 0.0f);
  }
  return grid;
}

inline wheelchair_description::ChairParams chair() {
  return wheelchair_description::test::shippedChair();
}

/// A pose as the vector (x, y, yaw), for comparisons of whole poses.
inline Eigen::Vector3d asVector(const wheelchair_core::Pose2D& p) { return {p.x, p.y, p.yaw}; }

/// A twist as the vector (v, omega).
inline Eigen::Vector2d asVector(const wheelchair_core::BodyTwist& t) { return {t.v, t.omega}; }

}  // namespace test
}  // namespace wheelchair_sim
