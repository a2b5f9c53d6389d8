// The KLD localizer on synthetic drives (laserScanSimulator, noisy odometry) in the built-in
// worlds: tracking accuracy, global localization, ambiguity, kidnapping, the paper's Table 1,
// bad input.
#include <gtest/gtest.h>
#include <mrpt/math/wrap2pi.h>
#include <wheelchair_kld/drive_evaluation.h>

#include <cmath>
#include <limits>
#include <map>
#include <memory>

using mrpt::math::TPose2D;
using namespace wheelchair_kld;

namespace {

std::shared_ptr<const LocalizationMap> worldMap(const std::string& name) {
  static std::map<std::string, std::shared_ptr<const LocalizationMap>> cache;
  auto& m = cache[name];
  if (!m)
    m = std::make_shared<LocalizationMap>(makeBuiltinWorld(name),
                                          KldParams().measurement.max_distance);
  return m;
}

std::vector<DriveSample> drive(const std::string& world, uint32_t seed) {
  DriveParams p;
  p.seed = seed;
  return simulateDrive(worldMap(world)->grid(), builtinRoute(world), p);
}

mrpt::math::CMatrixDouble33 diagCov(double sxy, double sth) {
  mrpt::math::CMatrixDouble33 c;
  c.setZero();
  c(0, 0) = c(1, 1) = sxy * sxy;
  c(2, 2) = sth * sth;
  return c;
}

/// Index of the first step from which the filter is localized within `tol` for good.
int convergedAt(const std::vector<StepRecord>& steps, double tol) {
  int at = -1;
  for (size_t i = 0; i < steps.size(); ++i) {
    const bool ok = steps[i].localized && steps[i].error_xy < tol;
    if (ok && at < 0) at = static_cast<int>(i);
    if (!ok) at = -1;
  }
  return at;
}

}  // namespace

TEST(KldLocalizer, TracksTheFlatRouteWithinFiveCentimetresAndTwoDegrees) {
  const auto samples = drive("flat", 1);
  KldLocalizer loc(worldMap("flat"), KldParams(), 1);
  loc.initGaussian(samples[0].truth, diagCov(0.1, 0.05));
  const auto steps = runDrive(loc, samples);
  const auto s = summarize(steps, 5);
  RecordProperty("rms_xy_cm", std::to_string(100 * s.rms_xy));
  RecordProperty("rms_theta_deg", std::to_string(s.rms_theta * 180 / M_PI));
  RecordProperty("mean_particles", std::to_string(s.mean_particles));
  std::cout << "tracking: rms " << 100 * s.rms_xy << " cm, " << s.rms_theta * 180 / M_PI << " deg, "
            << s.mean_particles << " particles mean, " << s.mean_ms << " ms mean, " << s.updates
            << " updates\n";
  EXPECT_GT(s.updates, static_cast<int>(samples.size()) / 2);
  EXPECT_LE(s.rms_xy, 0.05);
  EXPECT_LE(s.rms_theta, 2 * M_PI / 180);
  EXPECT_TRUE(steps.back().localized) << loc.status().reason;
}
