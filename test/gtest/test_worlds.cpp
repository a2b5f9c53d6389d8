// The test worlds measured on their grids against what the worlds are specified to be
// (test/worlds/README.md): size, closed outer wall, wall thickness, door widths, places with
// clearance that a chair can reach, and the properties each world exists for.
#include <gtest/gtest.h>

#include "grid_measures.h"
#include "world_files.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <ostream>
#include <set>
#include <string>

namespace wheelchair_test {
namespace {

constexpr double kResolution = 0.05;        // [m], all worlds
constexpr double kPlaceClearance = 0.6;     // [m] from a place to any obstacle
constexpr double kChairHalfWidth = 0.3;     // [m] a 0.6 m wide chair must reach every place
constexpr double kMinWallThickness = 0.10;  // [m]

struct WorldSpec {
  std::string name;
  double width, height;  // [m]
};

void PrintTo(const WorldSpec& spec, std::ostream* os) { *os << spec.name; }

std::string worldFile(const std::string& name, const std::string& suffix) {
  return std::string(WORLDS_DIR) + "/" + name + suffix;
}

class World : public ::testing::TestWithParam<WorldSpec> {
 protected:
  void SetUp() override {
    grid_ = loadWorldMap(worldFile(GetParam().name, ".yaml"));
    places_ = loadPlaces(worldFile(GetParam().name, ".places.yaml"));
    doors_ = loadDoors(worldFile(GetParam().name, ".doors.yaml"));
  }
  Grid grid_;
  std::vector<Place> places_;
  std::vector<Door> doors_;
};

TEST_P(World, IsATrinaryMapServerMapWithOriginAtZero) {
  EXPECT_DOUBLE_EQ(grid_.resolution, kResolution);
  EXPECT_EQ(grid_.origin_x, 0.0);
  EXPECT_EQ(grid_.origin_y, 0.0);
  EXPECT_EQ(grid_.origin_yaw, 0.0);
  EXPECT_EQ(grid_.mode, "trinary");
  for (int value : grid_.values) {  // trinary: only free, occupied or unknown cells
    EXPECT_TRUE(value == -1 || value == 0 || value == 100) << "cell value " << value;
  }
}

TEST_P(World, HasItsSpecifiedSize) {
  EXPECT_NEAR(grid_.width * grid_.resolution, GetParam().width, 1e-9);
  EXPECT_NEAR(grid_.height * grid_.resolution, GetParam().height, 1e-9);
}

TEST_P(World, OuterWallClosesIt) {
  const int band = static_cast<int>(std::lround(kMinWallThickness / grid_.resolution));
  int open = 0;
  for (int iy = 0; iy < grid_.height; ++iy) {
    for (int ix = 0; ix < grid_.width; ++ix) {
      const bool near_border =
          ix < band || iy < band || ix >= grid_.width - band || iy >= grid_.height - band;
      if (near_border && !grid_.occupied(ix, iy)) ++open;
    }
  }
  EXPECT_EQ(open, 0) << "cells of the outer " << kMinWallThickness << " m are not occupied";
}

TEST_P(World, WallsAndFurnitureAreAtLeast10cmThick) {
  ASSERT_LE(2 * kResolution, kMinWallThickness + 1e-9);
  EXPECT_EQ(thinOccupiedCells(grid_), 0);
}

TEST_P(World, PlacesAreFreeWithClearance) {
  ASSERT_FALSE(places_.empty());
  for (const auto& p : places_) {
    EXPECT_TRUE(grid_.free(grid_.cellX(p.x), grid_.cellY(p.y))) << p.name;
    EXPECT_GE(clearanceAt(grid_, p.x, p.y, 2.0), kPlaceClearance - 1e-9) << p.name;
    EXPECT_TRUE(std::isfinite(p.yaw) && std::abs(p.yaw) <= M_PI + 1e-3) << p.name;
  }
}

TEST_P(World, PlacesHaveUniqueNamesAndAreGroupedByRoom) {
  std::set<std::string> names, rooms_done;
  std::string room;
  for (const auto& p : places_) {
    EXPECT_TRUE(names.insert(p.name).second) << "duplicate place " << p.name;
    if (p.room != room) {
      EXPECT_TRUE(rooms_done.insert(p.room).second) << "room " << p.room << " is split";
      room = p.room;
    }
  }
}

TEST_P(World, ChairReachesEveryPlaceFromTheFirst) {
  ASSERT_FALSE(places_.empty());
  const auto passable = passableCells(grid_, kChairHalfWidth);
  const auto& start = places_.front();
  const auto reached = reachableFrom(grid_, passable, grid_.cellX(start.x), grid_.cellY(start.y));
  for (const auto& p : places_) {
    const size_t i = static_cast<size_t>(grid_.cellY(p.y)) * grid_.width + grid_.cellX(p.x);
    EXPECT_TRUE(reached[i]) << p.name << " unreachable from " << start.name;
  }
}

TEST_P(World, DoorsHaveTheirWidthOnTheGridAndJoinWiderSpaces) {
  for (const auto& d : doors_) {
    const int ix = grid_.cellX(d.x), iy = grid_.cellY(d.y);
    bool bounded = false;
    const int cells = freeRun(grid_, ix, iy, d.axis, &bounded);
    EXPECT_TRUE(bounded) << d.name << ": the opening is not between two jambs";
    EXPECT_NEAR(cells * grid_.resolution, d.width, grid_.resolution / 2) << d.name;
    const int step = static_cast<int>(std::lround(0.5 / grid_.resolution));  // 0.5 m each side
    for (int side : {-1, 1}) {
      const int nx = d.axis == 'y' ? ix + side * step : ix;
      const int ny = d.axis == 'x' ? iy + side * step : iy;
      EXPECT_GT(freeRun(grid_, nx, ny, d.axis), cells) << d.name << " side " << side;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(TestWorlds, World,
                         ::testing::Values(WorldSpec{"flat", 10.0, 12.0},
                                           WorldSpec{"office", 60.0, 24.0},
                                           WorldSpec{"hall", 50.0, 50.0},
                                           WorldSpec{"symmetric", 24.0, 10.0},
                                           WorldSpec{"loop", 15.0, 6.5}),
                         [](const auto& info) { return info.param.name; });

TEST(Flat, HasAtLeast30PlacesInAtLeast5Rooms) {
  const auto places = loadPlaces(worldFile("flat", ".places.yaml"));
  std::set<std::string> rooms;
  for (const auto& p : places) rooms.insert(p.room);
  EXPECT_GE(places.size(), 30u);
  EXPECT_GE(rooms.size(), 5u);
}

TEST(Flat, DoorsMeasure80To90cmAndOneExactly80) {
  const auto grid = loadWorldMap(worldFile("flat", ".yaml"));
  const auto doors = loadDoors(worldFile("flat", ".doors.yaml"));
  ASSERT_GE(doors.size(), 4u);
  int exactly_80 = 0;
  for (const auto& d : doors) {
    const double width = freeRun(grid, grid.cellX(d.x), grid.cellY(d.y), d.axis) * grid.resolution;
    EXPECT_GE(width, 0.80 - 1e-9) << d.name;
    EXPECT_LE(width, 0.90 + 1e-9) << d.name;
    exactly_80 += std::abs(width - 0.80) < 1e-9;
  }
  EXPECT_GE(exactly_80, 1);
}

TEST(Flat, HallwayIsNarrowAndLong) {
  const auto grid = loadWorldMap(worldFile("flat", ".yaml"));
  const auto doors = loadDoors(worldFile("flat", ".doors.yaml"));
  const auto entry = std::find_if(doors.begin(), doors.end(),
                                  [](const Door& d) { return d.name == "living_hallway"; });
  ASSERT_NE(entry, doors.end());
  // Walk north from the hallway's door; the narrowest cross-section is the hallway's width.
  const int ix = grid.cellX(entry->x);
  int iy = grid.cellY(entry->y + 0.5);
  int narrowest = grid.width, length = 0;
  for (; grid.free(ix, iy); ++iy, ++length)
    narrowest = std::min(narrowest, freeRun(grid, ix, iy, 'x'));
  EXPECT_GE(narrowest * grid.resolution, 1.0 - 1e-9);
  EXPECT_LE(narrowest * grid.resolution, 1.2 + 1e-9);
  EXPECT_GE(length * grid.resolution, 4.0);
}

TEST(Office, HasA40mCorridorAbout1_8mWide) {
  const auto grid = loadWorldMap(worldFile("office", ".yaml"));
  EXPECT_GE(longestFreeBandAlongX(grid, 1.75), 40.0);
  EXPECT_LT(longestFreeBandAlongX(grid, 1.90), 40.0);  // not wider: a corridor, not a hall
}

enum class Symmetry { kRotation180, kMirrorLeftRight, kMirrorTopBottom };

/// Cells that differ between the grid and its image under `symmetry`.
int cellsDifferingUnder(const Grid& grid, Symmetry symmetry) {
  int differ = 0;
  for (int iy = 0; iy < grid.height; ++iy) {
    for (int ix = 0; ix < grid.width; ++ix) {
      const int jx = symmetry == Symmetry::kMirrorTopBottom ? ix : grid.width - 1 - ix;
      const int jy = symmetry == Symmetry::kMirrorLeftRight ? iy : grid.height - 1 - iy;
      differ += grid.at(ix, iy) != grid.at(jx, jy);
    }
  }
  return differ;
}

TEST(Office, IsNotSymmetric) {
  const auto grid = loadWorldMap(worldFile("office", ".yaml"));
  for (auto symmetry :
       {Symmetry::kRotation180, Symmetry::kMirrorLeftRight, Symmetry::kMirrorTopBottom}) {
    EXPECT_GT(cellsDifferingUnder(grid, symmetry), 1000) << static_cast<int>(symmetry);
  }
}

TEST(Symmetric, MapAndPlacesEqualTheir180DegreeRotation) {
  const auto grid = loadWorldMap(worldFile("symmetric", ".yaml"));
  EXPECT_EQ(cellsDifferingUnder(grid, Symmetry::kRotation180), 0);
  EXPECT_GT(cellsDifferingUnder(grid, Symmetry::kMirrorLeftRight), 100)
      << "the two rooms are mirror images, not rotated copies";
  const auto places = loadPlaces(worldFile("symmetric", ".places.yaml"));
  const double cx = grid.width * grid.resolution / 2, cy = grid.height * grid.resolution / 2;
  for (const auto& p : places) {
    const bool has_twin = std::any_of(places.begin(), places.end(), [&](const Place& q) {
      return q.room != p.room && std::abs(q.x - (2 * cx - p.x)) < 1e-6 &&
             std::abs(q.y - (2 * cy - p.y)) < 1e-6 &&
             std::abs(std::remainder(q.yaw - p.yaw - M_PI, 2 * M_PI)) < 1e-3;
    });
    EXPECT_TRUE(has_twin) << p.name;
  }
}

TEST(Worlds, FilesAreWhatTheGeneratorDraws) {
  const std::string command =
      std::string(PYTHON3) + " " + WORLDS_DIR + "/make_worlds.py --check --out " + WORLDS_DIR;
  EXPECT_EQ(std::system(command.c_str()), 0) << command;
}

}  // namespace
}  // namespace wheelchair_test
