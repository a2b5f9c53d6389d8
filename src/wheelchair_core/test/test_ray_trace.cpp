#include <gtest/gtest.h>
#include <wheelchair_core/ray_trace.h>

#include <random>
#include <vector>

namespace wheelchair_core {
namespace {

struct Cell {
  int x, y;
};

std::vector<Cell> trace(double x0, double y0, double x1, double y1) {
  std::vector<Cell> cells;
  traceCells(x0, y0, x1, y1, [&](int ix, int iy, bool) { cells.push_back({ix, iy}); });
  return cells;
}

TEST(RayTrace, AxisAlignedSegment) {
  const auto cells = trace(0.5, 0.5, 4.5, 0.5);
  ASSERT_EQ(cells.size(), 5u);
  for (int i = 0; i < 5; ++i) EXPECT_EQ(cells[i].x, i);
}

// For random segments: starts in the start cell, ends in the end cell, 4-connected steps, and
// every visited cell really is crossed by the segment (checked by dense sampling).
TEST(RayTrace, RandomSegmentsAreContiguousAndExact) {
  std::mt19937 rng(42);
  std::uniform_real_distribution<double> u(-20.0, 20.0);
  for (int k = 0; k < 500; ++k) {
    const double x0 = u(rng), y0 = u(rng), x1 = u(rng), y1 = u(rng);
    const auto cells = trace(x0, y0, x1, y1);
    ASSERT_EQ(cells.front().x, static_cast<int>(std::floor(x0)));
    ASSERT_EQ(cells.front().y, static_cast<int>(std::floor(y0)));
    ASSERT_EQ(cells.back().x, static_cast<int>(std::floor(x1)));
    ASSERT_EQ(cells.back().y, static_cast<int>(std::floor(y1)));
    for (size_t i = 1; i < cells.size(); ++i) {
      ASSERT_EQ(std::abs(cells[i].x - cells[i - 1].x) + std::abs(cells[i].y - cells[i - 1].y), 1);
    }
    // Dense samples of the segment all fall in visited cells.
    for (int s = 0; s <= 2000; ++s) {
      const double t = s / 2000.0;
      const int cx = static_cast<int>(std::floor(x0 + t * (x1 - x0)));
      const int cy = static_cast<int>(std::floor(y0 + t * (y1 - y0)));
      bool found = false;
      for (const auto& c : cells) found = found || (c.x == cx && c.y == cy);
      ASSERT_TRUE(found) << "segment " << k << " sample " << s;
    }
  }
}

// The digital line between two cells: starts and ends there, 8-connected, one cell per step of
// the major axis, and every cell within half a cell (across the major axis) of the segment
// between the two cell centres.
TEST(RayTrace, LineCellsAreOnePerMajorAxisStepAndNearTheLine) {
  std::mt19937 rng(7);
  std::uniform_int_distribution<int> u(-30, 30);
  for (int k = 0; k < 500; ++k) {
    const int x0 = u(rng), y0 = u(rng), x1 = u(rng), y1 = u(rng);
    std::vector<Cell> cells;
    int lasts = 0;
    traceLineCells(x0, y0, x1, y1, [&](int ix, int iy, bool last) {
      cells.push_back({ix, iy});
      lasts += last;
    });
    const int dx = x1 - x0, dy = y1 - y0;
    ASSERT_EQ(cells.size(), static_cast<size_t>(std::max(std::abs(dx), std::abs(dy)) + 1));
    ASSERT_EQ(lasts, 1);
    ASSERT_EQ(cells.front().x, x0);
    ASSERT_EQ(cells.front().y, y0);
    ASSERT_EQ(cells.back().x, x1);
    ASSERT_EQ(cells.back().y, y1);
    const bool x_major = std::abs(dx) >= std::abs(dy);
    for (size_t i = 0; i < cells.size(); ++i) {
      if (i > 0) {
        ASSERT_LE(std::abs(cells[i].x - cells[i - 1].x), 1);
        ASSERT_LE(std::abs(cells[i].y - cells[i - 1].y), 1);
      }
      if (dx == 0 && dy == 0) continue;
      // Where the segment is at this cell's major coordinate, the minor one is within 0.5.
      const double t = x_major ? double(cells[i].x - x0) / dx : double(cells[i].y - y0) / dy;
      const double minor = x_major ? y0 + t * dy : x0 + t * dx;
      ASSERT_LE(std::abs((x_major ? cells[i].y : cells[i].x) - minor), 0.5 + 1e-9);
    }
  }
}

}  // namespace
}  // namespace wheelchair_core
