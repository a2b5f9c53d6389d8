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

}  // namespace
}  // namespace wheelchair_core
