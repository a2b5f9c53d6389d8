// Scan insertion: REP-117 range conventions, any beam geometry, skipped scans, grid growth.
#include <gtest/gtest.h>
#include <wheelchair_mapping/bayes_mapper.h>

#include <cmath>

namespace wheelchair_mapping {
namespace {

wheelchair_core::LaserScan2D fan(double angle_min, double angle_increment,
                                 const std::vector<float>& ranges, double stamp = 1.0) {
  wheelchair_core::LaserScan2D scan;
  scan.stamp = stamp;
  scan.angle_min = angle_min;
  scan.angle_increment = angle_increment;
  scan.angle_max = angle_min + (ranges.size() - 1) * angle_increment;
  scan.range_min = 0.2;
  scan.range_max = 8.0;
  scan.ranges = ranges;
  return scan;
}

double occ(const BayesMapper& m, double x, double y) {
  return 1.0 - m.grid().getPos(static_cast<float>(x), static_cast<float>(y));
}

const wheelchair_core::Pose2D kOrigin{0.025, 0.025, 0.0};

TEST(BayesMapper, HitMarksFreeThenOccupied) {
  BayesMapper m(MapperConfig{});
  ASSERT_TRUE(m.insert(fan(0.0, 0.1, {3.0f}), kOrigin).inserted);
  EXPECT_LT(occ(m, 1.5, 0.025), 0.5);
  EXPECT_GT(occ(m, 3.03, 0.025), 0.5);
  EXPECT_EQ(occ(m, 3.5, 0.025), 0.5) << "behind the return nothing is known";
}

// A beam grazing a wall crosses wall cells another beam ended in; on real logs the old sensor
// model (p_occ_hit 0.7: one return = 1.4 passes) then erased walls. A return now outweighs two
// passes (0.8: log-odds 22 against 10 per pass, in MRPT's 1/16 steps); fails with 0.7.
TEST(BayesMapper, AWallCellHitOnceSurvivesTwoGrazingPasses) {
  BayesMapper m(MapperConfig{});
  ASSERT_TRUE(m.insert(fan(0.0, 0.1, {3.0f}), kOrigin).inserted);
  ASSERT_GT(occ(m, 3.03, 0.025), 0.5);
  for (int k = 0; k < 2; ++k)  // beams along the same line ending 1 m beyond the wall cell
    ASSERT_TRUE(m.insert(fan(0.0, 0.1, {4.0f}, 2.0 + k), kOrigin).inserted);
  EXPECT_GT(occ(m, 3.03, 0.025), 0.5) << "a return outweighs two passes";
  EXPECT_GT(m.effectiveHitProbability(), 0.75);
}

// A wall face on a cell boundary (x = 3), echoes 1 cm short and 1 cm long in turn (range noise):
// the short ones end in the free cell in front. With hit_depth 2 cm their evidence goes behind
// the echo, into the wall's cell, and the cell in front stays free; with the echo's own cell
// (hit_depth 0, the default) its hits outweigh the passes of the long echoes: two cells thick.
TEST(BayesMapper, AnEchoOnACellBoundaryMarksTheCellBehindTheSurface) {
  auto build = [](double hit_depth) {
    MapperConfig config;
    config.model.hit_depth = hit_depth;
    BayesMapper m(config);
    for (int k = 0; k < 10; ++k) {
      const float r = 3.0f - 0.025f + (k % 2 ? 0.01f : -0.01f);
      EXPECT_TRUE(m.insert(fan(0.0, 0.1, {r}, 1.0 + k), kOrigin).inserted);
    }
    return m;
  };
  const BayesMapper behind = build(0.02);
  EXPECT_GT(occ(behind, 3.025, 0.025), 0.9) << "the wall's own cell";
  EXPECT_LT(occ(behind, 2.975, 0.025), 0.5) << "the cell in front of the face is free";
  const BayesMapper own_cell = build(0.0);
  EXPECT_GT(occ(own_cell, 2.975, 0.025), 0.5) << "the echo's own cell thickens the wall";
  EXPECT_DOUBLE_EQ(returnCellRange(2.0, 0.02), 2.02);
}

TEST(BayesMapper, PlusInfinityIsFreeUpToRangeMaxAndConfigurable) {
  BayesMapper m(MapperConfig{});
  ASSERT_TRUE(m.insert(fan(0.0, 0.1, {INFINITY}), kOrigin).inserted);
  EXPECT_LT(occ(m, 7.9, 0.025), 0.5);
  EXPECT_EQ(occ(m, 8.2, 0.025), 0.5);
  MapperConfig shorter;
  shorter.model.no_return_range = 4.0;
  BayesMapper m2(shorter);
  ASSERT_TRUE(m2.insert(fan(0.0, 0.1, {INFINITY}), kOrigin).inserted);
  EXPECT_LT(occ(m2, 3.9, 0.025), 0.5);
  EXPECT_EQ(occ(m2, 4.2, 0.025), 0.5);
  MapperConfig off;
  off.model.no_return_is_free = false;
  BayesMapper m3(off);
  const auto r = m3.insert(fan(0.0, 0.1, {INFINITY}), kOrigin);
  EXPECT_FALSE(r.inserted);
  EXPECT_EQ(occ(m3, 1.0, 0.025), 0.5);
}

TEST(BayesMapper, NanMinusInfAndOutOfRangeBeamsAreSkipped) {
  BayesMapper m(MapperConfig{});
  // Beams at 0, 90, 180, 270 degrees; only the last one (2 m) is usable.
  const auto r =
      m.insert(fan(0.0, M_PI / 2, {NAN, -INFINITY, 0.1f /* < range_min */, 2.0f}), kOrigin);
  ASSERT_TRUE(r.inserted);
  EXPECT_EQ(r.beams_used, 1);
  EXPECT_EQ(occ(m, 1.0, 0.025), 0.5);
  EXPECT_EQ(occ(m, 0.025, 1.0), 0.5);
  EXPECT_EQ(occ(m, -1.0, 0.025), 0.5);
  EXPECT_LT(occ(m, 0.025, -1.0), 0.5);
  EXPECT_FALSE(m.insert(fan(0.0, 0.1, {9.0f /* > range_max */}, 2.0), kOrigin).inserted);
}

TEST(BayesMapper, AsymmetricFieldOfViewAndClockwiseScanners) {
  BayesMapper m(MapperConfig{});
  // Clockwise: ranges[0] at +90 deg, ranges[2] at -90 deg; the sensor faces +y (yaw 90 deg).
  const wheelchair_core::Pose2D pose{0.025, 0.025, M_PI / 2};
  ASSERT_TRUE(m.insert(fan(M_PI / 2, -M_PI / 2, {1.0f, 2.0f, 3.0f}), pose).inserted);
  EXPECT_GT(occ(m, -0.975, 0.025), 0.5);  // +90 deg from +y is -x
  EXPECT_GT(occ(m, 0.025, 2.025), 0.5);   // straight ahead
  EXPECT_GT(occ(m, 3.025, 0.025), 0.5);   // -90 deg from +y is +x
}

TEST(BayesMapper, SkipsBadScansWithAReasonAndLeavesTheGridUntouched) {
  MapperConfig config;
  config.expected_beams = 361;
  BayesMapper m(config);
  std::vector<float> good(361, 3.0f);
  ASSERT_TRUE(m.insert(fan(-M_PI / 2, M_PI / 360, good, 10.0), kOrigin).inserted);
  const auto before = m.grid().getRawMap();
  struct Case {
    wheelchair_core::LaserScan2D scan;
    wheelchair_core::Pose2D pose;
    std::string reason;
  };
  std::vector<Case> cases;
  cases.push_back({fan(-M_PI / 2, M_PI / 359, std::vector<float>(360, 3.0f), 11.0), kOrigin,
                   "wrong beam count"});
  wheelchair_core::LaserScan2D lying = fan(-M_PI / 2, M_PI / 360, good, 11.0);
  lying.angle_max = 0.3;  // angles say fewer beams than there are ranges
  cases.push_back({lying, kOrigin, "wrong beam count"});
  cases.push_back(
      {fan(-M_PI / 2, M_PI / 360, std::vector<float>(361, NAN), 11.0), kOrigin, "no usable beam"});
  cases.push_back({fan(-M_PI / 2, M_PI / 360, good, 9.5), kOrigin, "time went backwards"});
  cases.push_back(
      {fan(-M_PI / 2, M_PI / 360, good, 11.0), wheelchair_core::Pose2D{NAN, 0, 0}, "not finite"});
  cases.push_back({fan(-M_PI / 2, 0.0, good, 11.0), kOrigin, "increment is zero"});
  for (const auto& c : cases) {
    const auto r = m.insert(c.scan, c.pose);
    EXPECT_FALSE(r.inserted) << c.reason;
    EXPECT_NE(r.reason.find(c.reason), std::string::npos) << r.reason;
  }
  EXPECT_EQ(m.grid().getRawMap(), before);
  EXPECT_EQ(m.scansInserted(), 1u);
}

TEST(BayesMapper, GrowsToFitScansAndKeepsWhatItHad) {
  MapperConfig config;
  config.initial_size = 4.0;
  BayesMapper m(config);
  ASSERT_TRUE(m.insert(fan(0.0, 0.1, {1.0f}), kOrigin).inserted);
  ASSERT_TRUE(m.insert(fan(0.0, 0.1, {7.0f}, 2.0), wheelchair_core::Pose2D{20.025, -30.025, M_PI})
                  .inserted);
  EXPECT_GT(occ(m, 1.03, 0.025), 0.5);
  EXPECT_GT(occ(m, 13.03, -30.025), 0.5);
  EXPECT_LE(m.grid().getXMin(), 0.0f);
  EXPECT_LE(m.grid().getYMin(), -30.1f);
}

// A return whose border lies 1.7 mm off the 5 cm lattice (the office's live map grew to
// y_min -16.8517 so): the grid grows by whole cells and its borders stay on the lattice it
// started on, so a wall face on a cell boundary of the world stays on one of the map's.
TEST(BayesMapper, GrowsByWholeCellsSoItsBordersStayOnTheLattice) {
  MapperConfig config;
  config.initial_size = 4.0;  // [-2, 2]
  config.growth_margin = 1.0;
  BayesMapper m(config);
  const wheelchair_core::Pose2D below{0.025, -1.0, -M_PI / 2};
  ASSERT_TRUE(m.insert(fan(0.0, 0.1, {4.8517f}), below).inserted);
  ASSERT_TRUE(
      m.insert(fan(0.0, 0.1, {3.3333f}, 2.0), wheelchair_core::Pose2D{0.7, 0.3, 0.4}).inserted);
  const double res = m.grid().getResolution();
  for (double border :
       {m.grid().getXMin(), m.grid().getXMax(), m.grid().getYMin(), m.grid().getYMax()}) {
    EXPECT_NEAR(border / res, std::round(border / res), 1e-3) << "border " << border;
  }
  EXPECT_LT(m.grid().getYMin(), -1.0 - 4.8517 - 1.0 + 1e-4);  // the return and the margin
  EXPECT_NEAR(m.grid().getXMin(), -2.0f, 1e-6);               // a side that did not need to grow
  EXPECT_GT(occ(m, 0.025, -5.8517), 0.5);  // the return's cell, where it was inserted
}

TEST(BayesMapper, ReturnsBeyondTheInsertionRangeOnlyClearSpace) {
  MapperConfig config;
  config.model.max_insertion_range = 2.0;
  BayesMapper m(config);
  ASSERT_TRUE(m.insert(fan(0.0, 0.1, {5.0f}), kOrigin).inserted);
  EXPECT_LT(occ(m, 1.9, 0.025), 0.5);
  EXPECT_EQ(occ(m, 2.2, 0.025), 0.5);
  EXPECT_EQ(occ(m, 5.03, 0.025), 0.5);
}

TEST(BayesMapper, BeamWidthMarksTheFootprintAcrossTheBeam) {
  MapperConfig config;
  config.model.beam_width = 0.1;  // 0.4 m wide at 4 m
  BayesMapper m(config);
  ASSERT_TRUE(m.insert(fan(0.0, 0.1, {4.0f}), kOrigin).inserted);
  EXPECT_GT(occ(m, 4.0, 0.15), 0.5);
  EXPECT_GT(occ(m, 4.0, -0.1), 0.5);
  EXPECT_EQ(occ(m, 4.0, 0.4), 0.5);
}

}  // namespace
}  // namespace wheelchair_mapping
