// Eq. (1) and the prior of the paper's map making, checked against MRPT's log-odds cells.
#include <gtest/gtest.h>
#include <wheelchair_mapping/bayes_mapper.h>

#include <cmath>

namespace wheelchair_mapping {
namespace {

double sigmoid(double l) { return 1.0 / (1.0 + std::exp(-l)); }

// One beam straight along +x, returning at `range`.
wheelchair_core::LaserScan2D singleBeam(double range, double stamp = 0.0) {
  wheelchair_core::LaserScan2D scan;
  scan.stamp = stamp;
  scan.angle_min = scan.angle_max = 0.0;
  scan.angle_increment = 0.01;
  scan.range_min = 0.1;
  scan.range_max = 30.0;
  scan.ranges = {static_cast<float>(range)};
  return scan;
}

double occupancyAt(const BayesMapper& m, double x, double y) {
  return 1.0 - m.grid().getPos(static_cast<float>(x), static_cast<float>(y));
}

TEST(ElfesUpdate, FormulaByHand) {
  // P = Ps Pm / (Ps Pm + (1-Ps)(1-Pm)), worked by hand for Ps = 0.7, Pm = 0.6:
  // 0.42 / (0.42 + 0.12) = 0.7777...
  EXPECT_NEAR(elfesUpdate(0.7, 0.6), 0.42 / 0.54, 1e-15);
  EXPECT_DOUBLE_EQ(elfesUpdate(0.7, 0.5), 0.7);  // the prior 0.5 is neutral
  EXPECT_DOUBLE_EQ(elfesUpdate(0.5, 0.3), 0.3);  // an uninformative reading changes nothing
}

TEST(ElfesUpdate, EveryCellStartsAtExactlyOneHalf) {
  BayesMapper mapper(MapperConfig{});
  const auto& g = mapper.grid();
  for (unsigned y = 0; y < g.getSizeY(); y += 7) {
    for (unsigned x = 0; x < g.getSizeX(); x += 7) ASSERT_EQ(g.getCell(x, y), 0.5f);
  }
  EXPECT_EQ(mrpt::maps::COccupancyGridMap2D::p2l(0.5f), 0);
}

// With P_s chosen on MRPT's log-odds lattice (steps of 1/16) the cell follows eq. (1) to float
// precision, update after update.
TEST(ElfesUpdate, MrptCellsFollowEquationOneExactlyOnTheLattice) {
  MapperConfig config;
  config.model.p_occ_hit = sigmoid(16.0 / 16);    // log-odds 1.0
  config.model.p_occ_pass = sigmoid(-12.0 / 16);  // log-odds -0.75
  BayesMapper mapper(config);
  EXPECT_NEAR(mapper.effectiveHitProbability(), config.model.p_occ_hit, 1e-6);
  double p_hit_cell = 0.5, p_free_cell = 0.5;
  for (int k = 0; k < 4; ++k) {
    ASSERT_TRUE(
        mapper.insert(singleBeam(2.025, k), wheelchair_core::Pose2D{0.0, 0.025, 0.0}).inserted);
    p_hit_cell = elfesUpdate(config.model.p_occ_hit, p_hit_cell);
    p_free_cell = elfesUpdate(config.model.p_occ_pass, p_free_cell);
    EXPECT_NEAR(occupancyAt(mapper, 2.025, 0.025), p_hit_cell, 1e-5) << "update " << k;
    EXPECT_NEAR(occupancyAt(mapper, 1.0, 0.025), p_free_cell, 1e-5) << "update " << k;
  }
}

// Any P_s: eq. (1) within the quantization of MRPT's 8-bit log-odds (half a step, 1/32, in
// log-odds, i.e. at most p(1-p)/32 in probability per update).
TEST(ElfesUpdate, MrptCellsFollowEquationOneWithinQuantization) {
  for (double p_hit : {0.6, 0.7, 0.85, 0.95}) {
    MapperConfig config;
    config.model.p_occ_hit = p_hit;
    BayesMapper mapper(config);
    ASSERT_TRUE(
        mapper.insert(singleBeam(3.525), wheelchair_core::Pose2D{0.0, 0.025, 0.0}).inserted);
    const double expected = elfesUpdate(p_hit, 0.5);
    EXPECT_NEAR(occupancyAt(mapper, 3.525, 0.025), expected, expected * (1 - expected) / 32 + 1e-6)
        << "P_s = " << p_hit;
    EXPECT_EQ(occupancyAt(mapper, 3.525, 1.0), 0.5) << "cells off the beam keep the prior";
  }
}

TEST(ElfesUpdate, RejectsInconsistentModels) {
  MapperConfig config;
  config.model.p_occ_hit = 0.4;
  EXPECT_THROW(BayesMapper{config}, std::invalid_argument);
  config = MapperConfig{};
  config.model.p_occ_pass = 0.6;
  EXPECT_THROW(BayesMapper{config}, std::invalid_argument);
}

}  // namespace
}  // namespace wheelchair_mapping
