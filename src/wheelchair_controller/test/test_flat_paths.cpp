// The ten flat paths (flatTestPaths) fit the flat world: at every pose the chair's footprint,
// grown by a margin, covers no occupied or unknown map cell and stays on the map.
#include <wheelchair_controller_test/test_paths.h>
#include <wheelchair_core/map_io.h>
#include <wheelchair_core/polygon.h>
#include <wheelchair_description/chair_params.h>
#include <wheelchair_description_testing/chair_file.h>

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <string>

namespace wc = wheelchair_controller;
namespace wd = wheelchair_description;
namespace wm = wheelchair_core;

namespace {

constexpr double kMargin = 0.03;  // [m] around the footprint
constexpr double kSample = 0.02;  // [m] footprint sampling (< the 5 cm cells)

/// First footprint point (world) on a non-free cell at `pose`, or NaN if none.
Eigen::Vector2d collision(const wm::OccupancyMap& map, const wd::ChairParams& chair,
                          const wc::Pose2D& pose) {
  const wm::Box box = wm::boundingBox(chair.footprint);
  const double xmin = box.min.x(), xmax = box.max.x(), ymin = box.min.y(), ymax = box.max.y();
  const double c = std::cos(pose.yaw), s = std::sin(pose.yaw);
  for (double bx = xmin - kMargin; bx <= xmax + kMargin + 1e-9; bx += kSample) {
    for (double by = ymin - kMargin; by <= ymax + kMargin + 1e-9; by += kSample) {
      const Eigen::Vector2d w(pose.x + c * bx - s * by, pose.y + s * bx + c * by);
      int ix, iy;
      if (!map.worldToCell(w.x(), w.y(), ix, iy) || map.at(ix, iy) != wm::kFree) return w;
    }
  }
  return Eigen::Vector2d(NAN, NAN);
}

}  // namespace

TEST(FlatPaths, FootprintStaysInFreeSpaceWithMargin) {
  const std::string world = FLAT_WORLD_YAML;
  if (!std::ifstream(world).good()) GTEST_SKIP() << "no flat world at " << world;
  const wm::OccupancyMap map = wm::loadMap(world);
  const wd::ChairParams chair = wd::test::shippedChair();
  ASSERT_GE(chair.footprint.size(), 3u);
  const auto paths = wc::flatTestPaths();
  ASSERT_EQ(paths.size(), 10u);
  for (const wc::NamedPath& p : paths) {
    for (const wc::Pose2D& pose : p.poses) {
      const Eigen::Vector2d hit = collision(map, chair, pose);
      EXPECT_FALSE(hit.allFinite())
          << p.name << ": at (" << pose.x << ", " << pose.y << ", " << pose.yaw << ") the chair "
          << "touches (" << hit.transpose() << ")";
      if (hit.allFinite()) break;
    }
  }
}
