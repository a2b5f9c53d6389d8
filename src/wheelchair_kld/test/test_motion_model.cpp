// sample_motion_model_odometry: unbiased, with the variance the alpha parameters prescribe.
#include <gtest/gtest.h>
#include <mrpt/math/wrap2pi.h>
#include <wheelchair_kld/odometry_motion_model.h>

#include <cmath>

using mrpt::math::TPose2D;
using namespace wheelchair_kld;

TEST(OdometryMotionModel, DecomposesForwardAndBackwardMotion) {
  const auto f = decomposeOdometry(TPose2D(1, 1, 0), TPose2D(2, 2, M_PI / 2));
  EXPECT_NEAR(f.rot1, M_PI / 4, 1e-12);
  EXPECT_NEAR(f.trans, std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(f.rot2, M_PI / 4, 1e-12);
  const auto b = decomposeOdometry(TPose2D(0, 0, 0), TPose2D(-0.5, 0, 0));
  EXPECT_NEAR(b.rot1, 0, 1e-12);
  EXPECT_NEAR(b.trans, -0.5, 1e-12);
  EXPECT_NEAR(b.rot2, 0, 1e-12);
}

TEST(OdometryMotionModel, NoiseFreeSampleReproducesTheOdometryMotion) {
  MotionNoise none{0, 0, 0, 0, 0, 0};
  mrpt::random::CRandomGenerator rng(3);
  const TPose2D from(1, 2, 0.3), to(1.5, 2.4, 1.0);
  const auto u = decomposeOdometry(from, to);
  // Applied to a pose rotated by 90 deg about the origin, the motion is rotated too.
  const TPose2D start(-2, 1, 0.3 + M_PI / 2);
  const TPose2D s = sampleMotionModel(u, start, none, rng);
  EXPECT_NEAR(s.x, -2 - 0.4, 1e-9);
  EXPECT_NEAR(s.y, 1 + 0.5, 1e-9);
  EXPECT_NEAR(mrpt::math::wrapToPi(s.phi - (1.0 + M_PI / 2)), 0, 1e-9);
}

TEST(OdometryMotionModel, TranslationVarianceFollowsAlpha3) {
  MotionNoise n{0, 0, 0.04, 0, 0, 0};
  mrpt::random::CRandomGenerator rng(5);
  const auto u = decomposeOdometry(TPose2D(0, 0, 0), TPose2D(2, 0, 0));
  const int N = 20000;
  double sum = 0, sq = 0;
  for (int i = 0; i < N; ++i) {
    const TPose2D s = sampleMotionModel(u, TPose2D(0, 0, 0), n, rng);
    sum += s.x;
    sq += s.x * s.x;
  }
  const double mean = sum / N, var = sq / N - mean * mean;
  EXPECT_NEAR(mean, 2.0, 0.01);
  EXPECT_NEAR(var, 0.04 * 4, 0.01);  // alpha3 * trans^2
}

// A turn on the spot whose axle swings a few millimetres backwards (the simulated chair while
// aligning: 7.5 mm back per 0.077 rad). Below 1 cm the direction of travel must still be the
// odometry's: it used to be taken as straight ahead, so every step moved the particles 15 mm
// the wrong way and a half turn left the estimate ~13 cm off (system test kidnap.test).
TEST(OdometryMotionModel, SmallBackwardMotionDuringATurnIsAppliedBackwards) {
  MotionNoise none{0, 0, 0, 0, 0, 0};
  mrpt::random::CRandomGenerator rng(4);
  const TPose2D from(1, 2, 3.0),
      to(1 - 0.0075 * std::cos(2.96), 2 - 0.0075 * std::sin(2.96), 2.923);
  const TPose2D s = sampleMotionModel(decomposeOdometry(from, to), from, none, rng);
  EXPECT_NEAR(s.x, to.x, 1e-9);
  EXPECT_NEAR(s.y, to.y, 1e-9);
  EXPECT_NEAR(mrpt::math::wrapToPi(s.phi - to.phi), 0, 1e-9);
}

// Below 1 cm of travel the direction of travel is numerically meaningless: it must not add
// rotation noise (a 2 mm sideways jitter during a 0.05 rad turn would otherwise spread the
// headings by alpha1 * (pi/2)^2).
TEST(OdometryMotionModel, TinyTranslationAddsNoDirectionNoise) {
  MotionNoise n{0.05, 0, 0, 0, 0, 0};
  mrpt::random::CRandomGenerator rng(6);
  const auto u = decomposeOdometry(TPose2D(0, 0, 0), TPose2D(0, 0.002, 0.05));
  const int N = 20000;
  double sq = 0;
  for (int i = 0; i < N; ++i) {
    const double e =
        mrpt::math::wrapToPi(sampleMotionModel(u, TPose2D(0, 0, 0), n, rng).phi - 0.05);
    sq += e * e;
  }
  EXPECT_NEAR(sq / N, 0.05 * 0.05 * 0.05, 2e-5);  // alpha1 * dtheta^2 only
}
