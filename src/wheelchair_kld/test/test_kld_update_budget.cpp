// The work of one update is bounded once the filter has been localized (update_max_particles,
// issue 21): a kidnapping in the office, noticed and recovered from, never weighs more particles
// in one update than the bound. Counts work (particles weighed), not wall time, so it holds on a
// loaded machine. (Its own file, linked after test_kld_localizer.cpp: the figures there depend
// on the order of the tests, MRPT's global generator feeding the simulated scans.)
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>

#include "drive_evaluation.h"

using wheelchair_core::Pose2D;
using namespace wheelchair_kld;
using namespace wheelchair_kld::test;

namespace {

std::shared_ptr<const LocalizationMap> officeMap() {
  static const auto map =
      std::make_shared<LocalizationMap>(loadWorldGrid(std::string(WORLDS_DIR) + "/office.yaml"),
                                        KldParams().measurement.max_distance);
  return map;
}

/// The office route, then (after a third of it) the chair carried to another route's start,
/// the odometry continuing seamlessly.
std::vector<DriveSample> kidnappedDrive(size_t& cut) {
  DriveParams p;
  p.seed = 3;
  auto first = simulateDrive(officeMap()->grid(), worldRoute("office"), p);
  cut = first.size() / 3;
  p.seed = 4;
  auto second =
      simulateDrive(officeMap()->grid(), {{2.0, 14.0, 0}, {10.5, 12.0, 0}, {29.35, 12.0, 0}}, p);
  std::vector<DriveSample> samples(first.begin(), first.begin() + cut);
  const Pose2D odom_at_cut = samples.back().odom;
  for (auto s : second) {
    s.odom = wheelchair_core::compose(odom_at_cut, s.odom);
    samples.push_back(s);
  }
  return samples;
}

struct KidnapRun {
  int max_weighings = 0;
  size_t max_particles = 0;
  int recovered_after = -1;  ///< updates after the kidnapping until within 0.2 m for good
  bool noticed = false;
};

KidnapRun runKidnapping(const KldParams& params, uint64_t seed) {
  size_t cut = 0;
  const auto samples = kidnappedDrive(cut);
  KldLocalizer loc(officeMap(), params, seed);
  loc.initGaussian(samples[0].truth, Eigen::Vector3d(0.01, 0.01, 0.0025).asDiagonal());
  KidnapRun r;
  int updates = 0;
  for (size_t i = 0; i < samples.size(); ++i) {
    const auto& s = samples[i];
    const bool updated = loc.update(s.odom, s.scan, s.sensor_pose) == UpdateResult::kUpdated;
    if (!updated) continue;
    r.max_weighings = std::max(r.max_weighings, loc.lastUpdateWeighings());
    r.max_particles = std::max(r.max_particles, loc.particleCount());
    if (i < cut) continue;
    ++updates;
    const auto& e = loc.estimate().mean;
    const bool ok = loc.status().localized() && std::hypot(e.x - s.truth.x, e.y - s.truth.y) < 0.2;
    r.noticed = r.noticed || !loc.status().localized();
    if (!ok)
      r.recovered_after = -1;
    else if (r.recovered_after < 0)
      r.recovered_after = updates;
  }
  return r;
}

}  // namespace

TEST(KldUpdateBudget, AKidnappingNeverWeighsMoreParticlesInOneUpdateThanTheBound) {
  KldParams params;  // update_max_particles 20000
  const int bound = params.update_max_particles;
  const KidnapRun bounded = runKidnapping(params, 5);
  params.update_max_particles = 0;
  const KidnapRun unbounded = runKidnapping(params, 5);
  std::cout << "kidnapping: bounded max " << bounded.max_weighings << " weighings, "
            << bounded.max_particles << " particles, recovered after " << bounded.recovered_after
            << " updates; unbounded max " << unbounded.max_weighings << ", "
            << unbounded.max_particles << ", recovered after " << unbounded.recovered_after << "\n";
  EXPECT_GT(unbounded.max_weighings, bound) << "the drive does not test the bound";
  EXPECT_LE(bounded.max_weighings, bound);
  EXPECT_LE(bounded.max_particles, static_cast<size_t>(bound));
  EXPECT_TRUE(bounded.noticed);
  EXPECT_GT(bounded.recovered_after, 0) << "not recovered within the bound";
  EXPECT_LE(bounded.recovered_after, 20);
}

// The requested global localization (the chair standing, waiting for it) is not bounded: its
// first update weighs the whole uniform set and its refinement passes.
TEST(KldUpdateBudget, TheRequestedGlobalLocalizationIsNotBounded) {
  size_t cut = 0;
  const auto samples = kidnappedDrive(cut);
  KldParams params;
  KldLocalizer loc(officeMap(), params, 5);
  loc.initGlobal();
  EXPECT_FALSE(loc.updatesBounded());
  ASSERT_EQ(loc.update(samples[0].odom, samples[0].scan, samples[0].sensor_pose),
            UpdateResult::kUpdated);
  EXPECT_GT(loc.lastUpdateWeighings(), params.update_max_particles);
  ASSERT_TRUE(loc.status().localized()) << loc.status().detail;
  EXPECT_TRUE(loc.updatesBounded());
}
