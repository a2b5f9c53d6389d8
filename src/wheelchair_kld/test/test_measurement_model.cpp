// Distance transform against brute force; both measurement models prefer the true pose.
#include <gtest/gtest.h>
#include <wheelchair_kld/kld_localizer.h>
#include <wheelchair_kld/likelihood_peak.h>
#include <wheelchair_kld/measurement_model.h>
#include <wheelchair_mapping/mrpt_conversions.h>

#include <cmath>

#include "synthetic_drive.h"

using mrpt::math::TPose2D;
using namespace wheelchair_kld;
using wheelchair_kld::test::DriveParams;
using wheelchair_kld::test::loadWorldGrid;

namespace {
wheelchair_core::OccupancyMap freeGrid(double resolution, int width, int height) {
  wheelchair_core::OccupancyMap g;
  g.resolution = resolution;
  g.width = width;
  g.height = height;
  g.data.assign(g.width * g.height, wheelchair_core::kFree);
  return g;
}
}  // namespace

TEST(LocalizationMap, DistanceTransformMatchesBruteForce) {
  wheelchair_core::OccupancyMap g = freeGrid(0.1, 37, 23);
  const int occ[][2] = {{3, 4}, {30, 20}, {12, 12}, {13, 12}, {0, 22}};
  for (auto& c : occ) g.at(c[0], c[1]) = wheelchair_core::kOccupied;
  const LocalizationMap map(wheelchair_mapping::toMrptGrid(g), 10.0);
  for (int iy = 0; iy < g.height; ++iy)
    for (int ix = 0; ix < g.width; ++ix) {
      double best = 1e9;
      for (auto& c : occ) best = std::min(best, std::hypot(ix - c[0], iy - c[1]) * g.resolution);
      ASSERT_NEAR(map.obstacleDistance()[iy * g.width + ix], best, 1e-4) << ix << "," << iy;
    }
}

// Inside a thick wall the distance grows with the depth below the surface (an endpoint that
// overshoots into a wall is as unlikely as one that falls short by as much).
TEST(LocalizationMap, DistanceInsideAThickWallIsTheDepthBelowItsSurface) {
  wheelchair_core::OccupancyMap g = freeGrid(0.05, 30, 20);
  for (int iy = 5; iy < 15; ++iy)  // a wall 8 cells thick, x = 10..17
    for (int ix = 10; ix < 18; ++ix) g.at(ix, iy) = wheelchair_core::kOccupied;
  const LocalizationMap map(wheelchair_mapping::toMrptGrid(g), 10.0);
  const auto d = [&](int ix, int iy) { return map.obstacleDistance()[iy * g.width + ix]; };
  EXPECT_NEAR(d(10, 10), 0.0, 1e-6);   // surface
  EXPECT_NEAR(d(11, 10), 0.05, 1e-6);  // one cell deep
  EXPECT_NEAR(d(13, 10), 0.15, 1e-6);  // three cells deep (nearest surface: x = 10)
  EXPECT_NEAR(d(7, 10), 0.15, 1e-6);   // three cells in front of the surface
  EXPECT_NEAR(d(20, 10), 0.15, 1e-6);  // behind the wall
}

TEST(LocalizationMap, SamplesPosesOnlyInKnownFreeSpace) {
  const LocalizationMap map(loadWorldGrid(WORLDS_DIR "/office.yaml"), 2.0);
  mrpt::random::CRandomGenerator rng(2);
  for (int i = 0; i < 2000; ++i) {
    const TPose2D p = map.sampleFreePose(rng);
    ASSERT_TRUE(map.isFree(map.cellIndex(p.x, p.y))) << p.asString();
  }
}

class MeasurementModelTest : public ::testing::TestWithParam<MeasurementModelType> {};

TEST_P(MeasurementModelTest, TruePoseIsMoreLikelyThanOffsetPoses) {
  const auto grid = loadWorldGrid(WORLDS_DIR "/office.yaml");
  const LocalizationMap map(grid, 2.0);
  MeasurementParams p;
  p.type = GetParam();
  MeasurementModel model(map, p);
  const TPose2D truth(5.0, 11.0, 0.2);
  const DriveParams drive;
  model.setScan(test::simulateScan(grid, {truth.x, truth.y, truth.phi}, drive, 11),
                drive.sensor_pose);
  EXPECT_EQ(model.beamCount(), 61);
  const double at_truth = model.logLikelihood(truth);
  for (const TPose2D off : {TPose2D(5.15, 11.0, 0.2), TPose2D(5.0, 10.85, 0.2),
                            TPose2D(5.0, 11.0, 0.25), TPose2D(9.0, 11.0, 0.2)})
    EXPECT_GT(at_truth, model.logLikelihood(off)) << off.asString();
}

// The published estimate's last step: from 12 cm / 2 deg off, the search ends at the true pose
// (within a cell), and never leaves its bounds.
TEST(LikelihoodPeak, SearchFromAnOffsetPoseEndsAtTheTruePoseWithinItsBounds) {
  const auto grid = loadWorldGrid(WORLDS_DIR "/office.yaml");
  const LocalizationMap map(grid, 2.0);
  MeasurementParams p;
  p.beam_step = 1;
  MeasurementModel model(map, p);
  const TPose2D truth(5.0, 11.0, 0.2);
  const DriveParams drive;
  model.setScan(test::simulateScan(grid, {truth.x, truth.y, truth.phi}, drive, 11),
                drive.sensor_pose);
  const TPose2D start(5.08, 10.91, 0.235);
  const TPose2D peak = likelihoodPeakNear(model, start, PeakSearch());
  EXPECT_LT(std::hypot(peak.x - truth.x, peak.y - truth.y), 0.03) << peak.asString();
  EXPECT_LT(std::abs(peak.phi - truth.phi), 0.01) << peak.asString();
  PeakSearch tight;
  tight.max_xy = 0.05;
  tight.max_theta = 0.01;
  const TPose2D bounded = likelihoodPeakNear(model, start, tight);
  EXPECT_LE(std::hypot(bounded.x - start.x, bounded.y - start.y), 0.05 + 1e-9);
  EXPECT_LE(std::abs(bounded.phi - start.phi), 0.01 + 1e-9);
  EXPECT_GT(model.logLikelihood(bounded), model.logLikelihood(start));
}

INSTANTIATE_TEST_SUITE_P(Models, MeasurementModelTest,
                         ::testing::Values(MeasurementModelType::kLikelihoodField,
                                           MeasurementModelType::kBeam));

// Issue 22: a 0.4 m box the map lacks, 1 m in front of the chair, gives short returns (echoes in
// mapped free space before the map's wall); left out of the inlier share, the true pose fits as
// well as without the box, while a pose 0.3 m off still fits poorly.
TEST(MeasurementModel, ShortReturnsOfAnUnmappedBoxDoNotMakeTheTruePoseAPoorFit) {
  const auto grid = loadWorldGrid(WORLDS_DIR "/office.yaml");
  const LocalizationMap map(grid, 2.0);
  auto with_box = grid;
  const TPose2D truth(5.0, 11.0, 0.2);
  const double bx = truth.x + std::cos(truth.phi), by = truth.y + std::sin(truth.phi);
  for (double x = bx - 0.2; x <= bx + 0.2; x += 0.02)
    for (double y = by - 0.2; y <= by + 0.2; y += 0.02) with_box.setPos(x, y, 0.0f);
  MeasurementParams p;
  p.beam_step = 1;
  MeasurementModel model(map, p);
  const DriveParams drive;
  model.setScan(test::simulateScan(with_box, {truth.x, truth.y, truth.phi}, drive, 11),
                drive.sensor_pose);
  const auto fit = model.fitCounts(truth, 0.15);
  EXPECT_GT(fit.shorts, 0.05 * fit.echoes) << fit.echoes;
  EXPECT_LE(fit.shorts, fit.contradictions);
  EXPECT_LT(inlierShare(fit, 0.0), 0.95);
  EXPECT_GT(inlierShare(fit, 0.3), 0.95);
  EXPECT_GT(inlierShare(fit, 0.3), inlierShare(fit, 0.0));
  const auto off = model.fitCounts(TPose2D(5.3, 11.0, 0.2), 0.15);
  EXPECT_LT(inlierShare(off, 0.3), 0.7);
}
