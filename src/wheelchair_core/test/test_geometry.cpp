#include <gtest/gtest.h>
#include <wheelchair_core/polygon.h>
#include <wheelchair_core/pose2d.h>

#include <cmath>
#include <random>

namespace wheelchair_core {
namespace {

TEST(Pose2D, ComposeThenBetweenGivesTheRelativePoseBack) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-5.0, 5.0);
  for (int i = 0; i < 100; ++i) {
    const Pose2D a{u(rng), u(rng), u(rng)};
    const Pose2D rel{u(rng), u(rng), normalizeAngle(u(rng))};
    const Pose2D b = compose(a, rel);
    const Pose2D back = between(a, b);
    EXPECT_NEAR(back.x, rel.x, 1e-12);
    EXPECT_NEAR(back.y, rel.y, 1e-12);
    EXPECT_NEAR(angleDifference(back.yaw, rel.yaw), 0.0, 1e-12);
  }
}

TEST(Pose2D, ComposeMatchesAHandWorkedExample) {
  // A robot at (1, 2) facing +y; a point 1 m ahead and 0.5 m to its left is at (0.5, 3).
  const Pose2D robot{1.0, 2.0, M_PI / 2};
  const Pose2D p = compose(robot, {1.0, 0.5, 0.0});
  EXPECT_NEAR(p.x, 0.5, 1e-12);
  EXPECT_NEAR(p.y, 3.0, 1e-12);
  EXPECT_NEAR(p.yaw, M_PI / 2, 1e-12);
  const Eigen::Vector2d q = transformPoint(robot, {1.0, 0.5});
  EXPECT_NEAR(q.x(), 0.5, 1e-12);
  EXPECT_NEAR(q.y(), 3.0, 1e-12);
}

TEST(Pose2D, InverseComposedWithThePoseIsTheIdentity) {
  const Pose2D a{3.0, -1.0, 2.5};
  const Pose2D id = compose(inverse(a), a);
  EXPECT_NEAR(id.x, 0.0, 1e-12);
  EXPECT_NEAR(id.y, 0.0, 1e-12);
  EXPECT_NEAR(id.yaw, 0.0, 1e-12);
}

TEST(Pose2D, AnglesWrapIntoMinusPiToPi) {
  EXPECT_NEAR(normalizeAngle(3 * M_PI / 2), -M_PI / 2, 1e-12);
  EXPECT_NEAR(angleDifference(-3.0, 3.0), 2 * M_PI - 6.0, 1e-12);
  EXPECT_FALSE((Pose2D{NAN, 0, 0}.isFinite()));
}

TEST(Polygon, PointSegmentDistanceIsThePerpendicularOrTheNearerEnd) {
  const Eigen::Vector2d a(0, 0), b(2, 0);
  double along = -1;
  EXPECT_NEAR(pointSegmentDistance({1, 3}, a, b, &along), 3.0, 1e-12);
  EXPECT_NEAR(along, 1.0, 1e-12);
  EXPECT_NEAR(pointSegmentDistance({5, 4}, a, b, &along), 5.0, 1e-12);  // 3-4-5 from b
  EXPECT_NEAR(along, 2.0, 1e-12);
  EXPECT_NEAR(pointSegmentDistance({-1, 0}, a, a), 1.0, 1e-12);  // degenerate segment
}

TEST(Polygon, InsideOutsideOfAnLShape) {
  const Polygon l = {{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
  EXPECT_TRUE(insidePolygon(l, {0.5, 1.5}));
  EXPECT_TRUE(insidePolygon(l, {1.5, 0.5}));
  EXPECT_FALSE(insidePolygon(l, {1.5, 1.5}));  // the notch
  EXPECT_FALSE(insidePolygon(l, {-0.1, 0.5}));
  EXPECT_NEAR(distanceToBoundary(l, {1.5, 1.5}), 0.5, 1e-12);
  EXPECT_NEAR(signedArea2(l), 6.0, 1e-12);  // area 3, counter-clockwise
}

TEST(Polygon, FootprintFiguresOfARectangleAboutItsAxle) {
  // 1.2 m long, 0.6 m wide, axle 0.4 m from the front.
  const Polygon body = {{0.4, -0.3}, {0.4, 0.3}, {-0.8, 0.3}, {-0.8, -0.3}};
  EXPECT_EQ(polygonProblem(body, true), "");
  EXPECT_NEAR(circumscribedRadius(body), std::hypot(0.8, 0.3), 1e-12);
  EXPECT_NEAR(inscribedRadius(body), 0.3, 1e-12);
  const Box box = boundingBox(body);
  EXPECT_DOUBLE_EQ(box.min.x(), -0.8);
  EXPECT_DOUBLE_EQ(box.max.y(), 0.3);
  const Polygon moved = transformPolygon(body, {1.0, 1.0, M_PI});
  EXPECT_NEAR(moved[0].x(), 0.6, 1e-12);
  EXPECT_NEAR(moved[0].y(), 1.3, 1e-12);
}

TEST(Polygon, ProblemsAreNamed) {
  EXPECT_NE(polygonProblem({{0, 0}, {1, 0}}), "");
  EXPECT_NE(polygonProblem({{0, 0}, {1, 0}, {2, 0}}), "");        // no area
  EXPECT_NE(polygonProblem({{1, 1}, {2, 1}, {2, 2}}, true), "");  // origin outside
  EXPECT_NE(polygonProblem({{0, 0}, {1, NAN}, {2, 2}}), "");
}

}  // namespace
}  // namespace wheelchair_core
