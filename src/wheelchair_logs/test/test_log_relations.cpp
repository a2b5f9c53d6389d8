// The Kuemmerle relation metric on trajectories whose errors are known by construction.
#include <gtest/gtest.h>
#include <wheelchair_logs/relations.h>

#include <cmath>
#include <cstdio>
#include <fstream>

namespace wheelchair_logs {
namespace {

using wheelchair_core::Pose2D;

std::vector<TimedPose> line(double step, size_t n) {
  std::vector<TimedPose> t;
  for (size_t i = 0; i < n; ++i) t.push_back({10.0 + i, {step * i, 0.0, 0.0}});
  return t;
}

TEST(Relations, ReadsTheKuemmerleFormatAndRefusesABadLine) {
  const std::string path = testing::TempDir() + "/test.relations";
  std::ofstream(path) << "976052905.167303 976052911.885496 -0.056990 -0.128430 0.000000 "
                         "0.000000 0.000000 -1.682210\n\n";
  const auto r = readRelations(path);
  ASSERT_EQ(r.size(), 1u);
  EXPECT_DOUBLE_EQ(r[0].t1, 976052905.167303);
  EXPECT_DOUBLE_EQ(r[0].delta.x, -0.056990);
  EXPECT_DOUBLE_EQ(r[0].delta.yaw, -1.682210);
  std::ofstream(path) << "1 2 3\n";
  EXPECT_THROW(readRelations(path), std::runtime_error);
}

TEST(Relations, AnExactTrajectoryHasZeroErrorAndAScaledOneItsScaleError) {
  const auto truth = line(1.0, 5);
  const auto relations = referenceRelations(truth, false);
  ASSERT_EQ(relations.size(), 4u);
  const auto exact = relationErrors(relations, truth, 0.0, 1e-6);
  ASSERT_EQ(exact.translational.size(), 4u);
  EXPECT_NEAR(summarize(exact.translational).max, 0.0, 1e-12);
  // 10 % too long: every 1 m relation is 0.1 m off.
  const auto scaled = relationErrors(relations, line(1.1, 5), 0.0, 1e-6);
  const ErrorSummary s = summarize(scaled.translational);
  EXPECT_NEAR(s.mean, 0.1, 1e-9);
  EXPECT_NEAR(s.std, 0.0, 1e-9);
  EXPECT_EQ(referenceRelations(truth, true).size(), 10u);
}

TEST(Relations, StampsAreMatchedWithTheOffsetAndTheTolerance) {
  auto estimate = line(1.0, 5);
  estimate[3].pose.yaw = 0.1;  // a rotation error on one pose
  std::vector<Relation> relations = {{1012.0 + 0.03, 1013.0, {1.0, 0.0, 0.0}}};
  // relation time = trajectory time + 1000 s; 0.03 s apart: matched within 0.05 s only.
  EXPECT_TRUE(relationErrors(relations, estimate, 1000.0, 0.01).translational.empty());
  const auto e = relationErrors(relations, estimate, 1000.0, 0.05);
  ASSERT_EQ(e.rotational.size(), 1u);
  EXPECT_NEAR(e.rotational[0], 0.1, 1e-12);
}

}  // namespace
}  // namespace wheelchair_logs
