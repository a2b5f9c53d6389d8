// The direct solver's map-change path: the ordering adapted to a map whose free cells changed a
// little (ordering_update.h), a valid elimination order of the new free cells whose factor gives
// the same harmonic function as a fresh AMD ordering's, with about the same fill; and the factor
// itself adapted to cells blocked and freed again (LogLdlt::update), giving the same harmonic
// function as a fresh factorization.
#include "../src/log_cholesky.h"
#include "../src/ordering_update.h"

#include <wheelchair_planner_test/maze.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <utility>

using namespace wheelchair_harmonic_planner;
using namespace wheelchair_planner;
using wheelchair_core::OccupancyMap;

namespace {

ConfigSpaceParams chair() { return ConfigSpaceParams(); }
/// The free cells are the map's (a point robot), with the clearance band's conductances.
ConfigSpaceParams point() {
  ConfigSpaceParams p;
  p.inscribed_radius = 0.0;
  p.min_clearance = 0.0;
  return p;
}

/// A 200 x 200 perfect maze (18-cell passages, 4-cell walls) and a 120 x 120 room with 25 %
/// random obstacles, each seeded.
OccupancyMap maze() { return makeMaze(200, 18, 4, 7); }
OccupancyMap randomObstacles(uint32_t seed) {
  OccupancyMap m = makeCorridor(6.0, 6.0, 0.05, 1);
  std::mt19937 rng(seed);
  std::bernoulli_distribution blocked(0.25);
  for (int iy = 1; iy + 1 < m.height; ++iy)
    for (int ix = 1; ix + 1 < m.width; ++ix)
      if (blocked(rng)) m.at(ix, iy) = wheelchair_core::kOccupied;
  return m;
}

/// Blocks a 4 x 4 cell square at (x, y) and frees every cell of a w x w window at (fx, fy).
OccupancyMap changed(OccupancyMap m, int x, int y, int fx, int fy, int w) {
  for (int iy = y; iy < y + 4; ++iy)
    for (int ix = x; ix < x + 4; ++ix) m.at(ix, iy) = wheelchair_core::kOccupied;
  for (int iy = fy; iy < fy + w; ++iy)
    for (int ix = fx; ix < fx + w; ++ix) m.at(ix, iy) = wheelchair_core::kFree;
  return m;
}

size_t countChanged(const ConfigSpace& a, const ConfigSpace& b, bool added) {
  size_t n = 0;
  for (size_t k = 0; k < a.freeMask().size(); ++k)
    n += added ? b.freeMask()[k] && !a.freeMask()[k] : a.freeMask()[k] && !b.freeMask()[k];
  return n;
}

/// Solutions for a few goals agree to `tolerance` relative on log u and on the cells cut off.
void expectSameSolutions(const ConfigSpace& cs, const LogLdlt& expected, const LogLdlt& actual,
                         double tolerance) {
  std::vector<double> a, b;
  int goals = 0;
  for (size_t g = cs.freeMask().size() / 7; goals < 4; g += cs.freeMask().size() / 5) {
    while (!cs.freeMask()[g]) ++g;
    expected.solve(g, a);
    actual.solve(g, b);
    for (size_t k = 0; k < a.size(); ++k) {
      ASSERT_EQ(std::isfinite(a[k]), std::isfinite(b[k])) << "goal " << g << " cell " << k;
      if (std::isfinite(a[k])) {
        ASSERT_NEAR(b[k], a[k], tolerance * std::max(1.0, std::abs(a[k])))
            << "goal " << g << " cell " << k;
      }
    }
    ++goals;
  }
}

}  // namespace

// Every free cell of the new map exactly once, for blocked and freed cells, and none when the
// grid size differs or too many cells changed.
TEST(OrderingUpdate, IsAPermutationOfTheNewFreeCells) {
  const OccupancyMap m = maze();
  const ConfigSpace before(m, chair());
  const LogLdlt first(before, true);
  const auto previous = first.ordering(before);
  ASSERT_TRUE(previous);
  const ConfigSpace after(changed(m, 100, 100, 40, 60, 12), chair());
  ASSERT_GT(countChanged(before, after, true), 0u);
  ASSERT_GT(countChanged(before, after, false), 0u);
  LargeVector<size_t> cells;
  LargeVector<int> id(after.freeMask().size(), -1);
  for (size_t k = 0; k < id.size(); ++k) {
    if (!after.freeMask()[k]) continue;
    id[k] = static_cast<int>(cells.size());
    cells.push_back(k);
  }
  const size_t n = cells.size();
  const LargeVector<int> order =
      deriveOrdering(*previous, after.freeMask(), cells, id, after.width(), n, n);
  ASSERT_EQ(order.size(), n);
  std::vector<int> seen(n, 0);
  for (const int u : order) {
    ASSERT_GE(u, 0);
    ASSERT_LT(static_cast<size_t>(u), n);
    ++seen[u];
  }
  for (size_t u = 0; u < n; ++u) EXPECT_EQ(seen[u], 1) << "unknown " << u;
  EXPECT_TRUE(deriveOrdering(*previous, after.freeMask(), cells, id, after.width(), 0, n).empty());
  EXPECT_TRUE(deriveOrdering(*previous, after.freeMask(), cells, id, after.width(), n, 0).empty());
  const ConfigSpace other_size(makeMaze(180, 18, 4, 7), chair());
  EXPECT_FALSE(LogLdlt(other_size, true, previous.get()).orderingDerived());
}

// On a maze and on random obstacle grids, after a 20 cm block is dropped and a window of wall
// is opened: the factor with the adapted ordering gives the fresh AMD factor's solutions
// (1e-12 relative on log u) with at most 15 % more fill (measured: +7 to +12 % here, where the
// 12 x 12 window joins passages or pockets, 0.2-0.6 % of the cells; +0.3 % on maze1024 for 282
// new cells in a 40 x 40 window); blocking cells alone never adds fill. The next map starts
// from the fresh ordering again (adaptations do not accumulate).
TEST(OrderingUpdate, GivesTheSameSolutionsAsAFreshOrderingWithAboutItsFill) {
  const std::pair<OccupancyMap, ConfigSpaceParams> cases[] = {
      {maze(), point()}, {randomObstacles(1), point()}, {randomObstacles(2), point()}};
  for (const auto& [m, params] : cases) {
    const ConfigSpace before(m, params);
    const LogLdlt first(before, true);
    ASSERT_TRUE(first.ok());
    const auto previous = first.ordering(before);
    for (const int window : {0, 12}) {
      const ConfigSpace after(changed(m, m.width / 2, m.height / 2, 40, 40, window), params);
      const LogLdlt fresh(after, true);
      const LogLdlt derived(after, true, previous.get());
      ASSERT_TRUE(fresh.ok());
      ASSERT_TRUE(derived.ok());
      ASSERT_TRUE(derived.orderingDerived()) << "window " << window;
      EXPECT_FALSE(fresh.orderingDerived());
      EXPECT_LE(derived.factorNonZeros(), 1.15 * fresh.factorNonZeros()) << "window " << window;
      ASSERT_EQ(countChanged(before, after, true) > 0, window > 0);
      if (window == 0) {
        EXPECT_LE(derived.factorNonZeros(), first.factorNonZeros());
      }
      EXPECT_EQ(derived.ordering(after)->free_mask, before.freeMask());
      expectSameSolutions(after, fresh, derived, 1e-12);
    }
  }
}

namespace {

// log u of `actual` equals `expected`'s to `tolerance` relative, for a goal at the corridor's
// near end, with the same cells cut off; and u falls far below the smallest double there.
void expectSameFarDownTheCorridor(const ConfigSpace& cs, const LogLdlt& expected,
                                  const LogLdlt& actual, double tolerance) {
  std::vector<double> a, b;
  int gx = 12, gy = cs.height() / 2;
  while (!cs.isFree(gx, gy)) ++gx;
  expected.solve(cs.index(gx, gy), a);
  actual.solve(cs.index(gx, gy), b);
  double lowest = 0.0;
  for (size_t k = 0; k < a.size(); ++k) {
    ASSERT_EQ(std::isfinite(a[k]), std::isfinite(b[k])) << "cell " << k;
    if (!std::isfinite(a[k])) continue;
    lowest = std::min(lowest, a[k]);
    ASSERT_NEAR(b[k], a[k], tolerance * std::max(1.0, std::abs(a[k]))) << "cell " << k;
  }
  EXPECT_LT(lowest, -700.0);  // far below the smallest double
}

}  // namespace

// A 200 m corridor, where u falls far below the smallest double (log u < -700), with a niche
// opened in the wall at the far end: the adapted factor keeps the tiny values' relative
// precision (the fresh AMD factor's log u to 1e-12).
TEST(OrderingUpdate, KeepsRelativePrecisionFarDownALongCorridor) {
  const OccupancyMap m = makeCorridor(200.0, 1.0, 0.05, 10);
  const ConfigSpace before(m, chair());
  const LogLdlt first(before, true);
  const auto previous = first.ordering(before);
  OccupancyMap opened = m;
  for (int iy = 3; iy < 10; ++iy)
    for (int ix = m.width - 120; ix < m.width - 100; ++ix)
      opened.at(ix, iy) = wheelchair_core::kFree;
  const ConfigSpace after(opened, chair());
  ASSERT_GT(countChanged(before, after, true), 0u);
  const LogLdlt fresh(after, true);
  const LogLdlt derived(after, true, previous.get());
  ASSERT_TRUE(derived.orderingDerived());
  expectSameFarDownTheCorridor(after, fresh, derived, 1e-12);
}

// ---- The factor adapted to blocked cells and changed conductances (LogLdlt::update) ----------

namespace {

/// `m` with a square of `size` cells occupied at (x, y) (clipped to the grid).
OccupancyMap withSquare(OccupancyMap m, int x, int y, int size) {
  for (int iy = std::max(0, y); iy < std::min(m.height, y + size); ++iy)
    for (int ix = std::max(0, x); ix < std::min(m.width, x + size); ++ix)
      m.at(ix, iy) = wheelchair_core::kOccupied;
  return m;
}

}  // namespace

// Obstacles of 1 to 24 cells appearing on a maze and a random room, and the older ones going
// again, 16 times in a row (the live obstacle layer over the map the factor was made for): after
// each update the factor gives the solutions of a fresh AMD factorization of that C-space to
// 1e-10 relative on log u, with the same cells cut off, recomputing only a few percent of the
// columns. (Fails on the code before: there was no update; every change refactored.)
TEST(FactorUpdate, GivesAFreshFactorizationsSolutionsAfterEveryChange) {
  std::mt19937 rng(11);
  for (const auto& [base, params] :
       {std::make_pair(maze(), chair()), std::make_pair(randomObstacles(3), point())}) {
    ConfigSpace cs(base, params);
    LogLdlt factor(cs, true);
    ASSERT_TRUE(factor.ok());
    std::vector<std::array<int, 3>> dropped;
    size_t most_columns = 0;
    for (int step = 0; step < 16; ++step) {
      if (dropped.size() < 3 || rng() % 2) {
        dropped.push_back({static_cast<int>(rng() % base.width),
                           static_cast<int>(rng() % base.height),
                           1 + static_cast<int>(rng() % 24)});
      } else {
        dropped.erase(dropped.begin());
      }
      OccupancyMap m = base;
      for (const auto& d : dropped) m = withSquare(m, d[0], d[1], d[2]);
      const ConfigSpaceChange change = cs.update(m);
      ASSERT_FALSE(change.rebuilt);
      ASSERT_TRUE(factor.update(cs, change.cells)) << "step " << step;
      ASSERT_TRUE(factor.ok());
      most_columns = std::max(most_columns, factor.updatedColumns());
      const ConfigSpace fresh_cs(m, params);
      const LogLdlt fresh(fresh_cs, true);
      ASSERT_TRUE(fresh.ok());
      expectSameSolutions(fresh_cs, fresh, factor, 1e-10);
    }
    EXPECT_LT(most_columns, factor.unknowns() / 4);
  }
}

// A cell free now that was not free when the factor was made is not in its pattern: refused,
// and the factor still solves the C-space it had.
TEST(FactorUpdate, RefusesACellThatWasNotFreeWhenFactored) {
  const OccupancyMap blocked = withSquare(maze(), 100, 100, 6);
  ConfigSpace cs(blocked, chair());
  LogLdlt factor(cs, true);
  const ConfigSpace before(blocked, chair());
  const ConfigSpaceChange change = cs.update(maze());
  ASSERT_FALSE(change.cells.empty());
  EXPECT_FALSE(factor.update(cs, change.cells));
  EXPECT_TRUE(factor.ok());
  expectSameSolutions(before, LogLdlt(before, true), factor, 1e-12);
}

// The 200 m corridor, where u falls far below the smallest double, with an obstacle near its far
// end that narrows it: the updated factor keeps the tiny values' relative precision (a fresh
// factorization's log u to 1e-10).
TEST(FactorUpdate, KeepsRelativePrecisionFarDownALongCorridor) {
  const OccupancyMap m = makeCorridor(200.0, 1.0, 0.05, 10);
  ConfigSpace cs(m, chair());
  LogLdlt factor(cs, true);
  const OccupancyMap narrowed = withSquare(m, m.width - 200, 10, 3);
  const ConfigSpaceChange change = cs.update(narrowed);
  ASSERT_FALSE(change.cells.empty());
  ASSERT_TRUE(factor.update(cs, change.cells));
  const ConfigSpace fresh_cs(narrowed, chair());
  const LogLdlt fresh(fresh_cs, true);
  expectSameFarDownTheCorridor(cs, fresh, factor, 1e-10);
}
