#include <gtest/gtest.h>
#include <wheelchair_core/laser_scan.h>

#include <cmath>
#include <limits>

namespace wheelchair_core {
namespace {

LaserScan2D threeBeams() {
  LaserScan2D s;
  s.angle_min = -M_PI / 2;
  s.angle_max = M_PI / 2;
  s.angle_increment = M_PI / 2;
  s.range_min = 0.1;
  s.range_max = 10.0;
  s.ranges = {1.0f, 2.0f, 3.0f};
  return s;
}

TEST(LaserScan, BeamsFollowRep117) {
  const LaserScan2D s = threeBeams();
  EXPECT_EQ(classifyBeam(5.0f, s), Beam::kReturn);
  EXPECT_EQ(classifyBeam(10.0f, s), Beam::kReturn);
  EXPECT_EQ(classifyBeam(std::numeric_limits<float>::infinity(), s), Beam::kNoReturn);
  EXPECT_EQ(classifyBeam(-std::numeric_limits<float>::infinity(), s), Beam::kTooClose);
  EXPECT_EQ(classifyBeam(std::numeric_limits<float>::quiet_NaN(), s), Beam::kInvalid);
  EXPECT_EQ(classifyBeam(0.05f, s), Beam::kOutOfLimits);
  EXPECT_EQ(classifyBeam(10.5f, s), Beam::kOutOfLimits);
}

TEST(LaserScan, EndpointsLieWhereTheBeamsPoint) {
  LaserScan2D s = threeBeams();
  s.ranges[1] = std::numeric_limits<float>::infinity();     // no return: no endpoint
  const auto pts = scanEndpoints(s, {1.0, 1.0, M_PI / 2});  // sensor facing +y
  ASSERT_EQ(pts.size(), 2u);
  EXPECT_NEAR(pts[0].x(), 2.0, 1e-6);  // beam -90 deg from +y points to +x
  EXPECT_NEAR(pts[0].y(), 1.0, 1e-6);
  EXPECT_NEAR(pts[1].x(), -2.0, 1e-6);
  EXPECT_NEAR(pts[1].y(), 1.0, 1e-6);
  EXPECT_EQ(countReturns(s), 2u);
}

TEST(LaserScan, GeometryProblemsAreNamed) {
  LaserScan2D s = threeBeams();
  EXPECT_EQ(scanGeometryProblem(s), "");
  EXPECT_NE(scanGeometryProblem(s, 361), "");
  s.ranges.push_back(1.0f);
  EXPECT_NE(scanGeometryProblem(s).find("beam count"), std::string::npos);
  s = threeBeams();
  s.angle_increment = 0;
  EXPECT_NE(scanGeometryProblem(s), "");
  s = threeBeams();
  s.range_max = NAN;
  EXPECT_NE(scanGeometryProblem(s), "");
}

TEST(LaserScan, MirroringTurnsTheAnglesTheOtherWay) {
  LaserScan2D s = threeBeams();
  mirrorScanAngles(s);
  EXPECT_NEAR(s.angle(0), M_PI / 2, 1e-12);
  EXPECT_NEAR(s.angle(2), -M_PI / 2, 1e-12);
  EXPECT_EQ(scanGeometryProblem(s), "");
}

}  // namespace
}  // namespace wheelchair_core
