// The URDF (generated from the chair file and committed as urdf/wheelchair.urdf) parses with
// liburdf and agrees with the chair file.
#include <wheelchair_description/chair_params.h>
#include <wheelchair_description/urdf_generator.h>
#include <wheelchair_description_testing/chair_file.h>

#include <gtest/gtest.h>
#include <urdf/model.h>

#include <cmath>
#include <fstream>
#include <random>
#include <sstream>

using namespace wheelchair_description;

namespace {

const std::string kCommittedUrdf =
    std::string(WHEELCHAIR_DESCRIPTION_SOURCE_DIR) + "/urdf/wheelchair.urdf";

std::string readFile(const std::string& path) {
  std::ifstream in(path);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

urdf::Model parse(const std::string& xml) {
  urdf::Model model;
  EXPECT_TRUE(model.initString(xml)) << "liburdf cannot parse the URDF";
  return model;
}

double yawOf(const urdf::Pose& pose) {
  double roll, pitch, yaw;
  pose.rotation.getRPY(roll, pitch, yaw);
  EXPECT_NEAR(roll, 0.0, 1e-12);
  EXPECT_NEAR(pitch, 0.0, 1e-12);
  return yaw;
}

/// Checks everything the rest of the stack relies on against the chair's parameters.
/// A fixed joint from base_link to `child` at (x, y, z) with yaw `yaw` (modulo 2 pi).
void expectSensorMount(const urdf::Model& model, const std::string& joint, const std::string& child,
                       double x, double y, double z, double yaw) {
  const auto j = model.getJoint(joint);
  ASSERT_TRUE(j) << joint;
  EXPECT_EQ(j->type, urdf::Joint::FIXED);
  EXPECT_EQ(j->parent_link_name, "base_link");
  EXPECT_EQ(j->child_link_name, child);
  const auto& mount = j->parent_to_joint_origin_transform;
  EXPECT_DOUBLE_EQ(mount.position.x, x) << joint;
  EXPECT_DOUBLE_EQ(mount.position.y, y) << joint;
  EXPECT_DOUBLE_EQ(mount.position.z, z) << joint;
  EXPECT_NEAR(std::remainder(yawOf(mount) - yaw, 2 * M_PI), 0.0, 1e-12) << joint;
}

void expectModelMatchesChair(const urdf::Model& model, const ChairParams& p) {
  ASSERT_TRUE(model.getRoot());
  EXPECT_EQ(model.getRoot()->name, "base_link");  // odom -> base_link owns the chair's tree
  // base_link (P) is the axle centre, r above the floor (base_footprint).
  const auto footprint = model.getJoint("base_footprint_joint");
  ASSERT_TRUE(footprint);
  EXPECT_EQ(footprint->parent_link_name, "base_link");
  EXPECT_EQ(footprint->child_link_name, "base_footprint");
  EXPECT_DOUBLE_EQ(footprint->parent_to_joint_origin_transform.position.z, -p.wheel_radius);
  // Drive wheels: on the axle, track 2b, radius r, rolling forward for a positive angle.
  for (const auto& [name, side] : {std::pair<std::string, double>{"left_wheel_joint", 1.0},
                                   std::pair<std::string, double>{"right_wheel_joint", -1.0}}) {
    const auto joint = model.getJoint(name);
    ASSERT_TRUE(joint) << name;
    EXPECT_EQ(joint->type, urdf::Joint::CONTINUOUS) << name;
    EXPECT_EQ(joint->parent_link_name, "base_link") << name;
    const auto& at = joint->parent_to_joint_origin_transform.position;
    EXPECT_EQ(at.x, 0.0) << name;
    EXPECT_DOUBLE_EQ(at.y, side * p.half_track) << name;
    EXPECT_EQ(at.z, 0.0) << name;
    EXPECT_EQ(joint->axis.y, 1.0) << name;
    const auto wheel = model.getLink(joint->child_link_name);
    ASSERT_TRUE(wheel && wheel->visual && wheel->visual->geometry) << name;
    ASSERT_EQ(wheel->visual->geometry->type, urdf::Geometry::CYLINDER);
    const auto& cylinder = static_cast<const urdf::Cylinder&>(*wheel->visual->geometry);
    EXPECT_DOUBLE_EQ(cylinder.radius, p.wheel_radius) << name;
    ASSERT_TRUE(wheel->inertial);
    EXPECT_DOUBLE_EQ(wheel->inertial->mass, p.wheel_mass);
    EXPECT_DOUBLE_EQ(wheel->inertial->iyy, p.wheel_inertia);  // about the axle
    EXPECT_DOUBLE_EQ(wheel->inertial->izz, p.wheel_inertia_diam);
  }
  EXPECT_DOUBLE_EQ(
      model.getJoint("left_wheel_joint")->parent_to_joint_origin_transform.position.y -
          model.getJoint("right_wheel_joint")->parent_to_joint_origin_transform.position.y,
      2.0 * p.half_track);
  // The lasers at their mounts: the front one, and the rear one looking behind.
  expectSensorMount(model, "laser_joint", "laser", p.laser_x, p.laser_y, p.laser_z, p.laser_yaw);
  expectSensorMount(model, "rear_laser_joint", "rear_laser", p.rear_laser_x, p.rear_laser_y,
                    p.rear_laser_z, p.rear_laser_yaw);
  // Body + rider at P_c, d behind P, with M_T and I_T.
  const auto body = model.getJoint("body_joint");
  ASSERT_TRUE(body);
  EXPECT_DOUBLE_EQ(body->parent_to_joint_origin_transform.position.x, -p.cm_offset);
  const auto body_link = model.getLink("body");
  ASSERT_TRUE(body_link && body_link->inertial);
  EXPECT_DOUBLE_EQ(body_link->inertial->mass, p.total_mass);
  EXPECT_DOUBLE_EQ(body_link->inertial->izz, p.body_inertia);
  // Casters stand on the floor, behind the axle, inside the footprint's rear.
  for (const char* name : {"left_caster_joint", "right_caster_joint"}) {
    const auto caster = model.getJoint(name);
    ASSERT_TRUE(caster) << name;
    EXPECT_EQ(caster->type, urdf::Joint::FIXED);
    const auto link = model.getLink(caster->child_link_name);
    ASSERT_TRUE(link && link->visual);
    const double radius = static_cast<const urdf::Cylinder&>(*link->visual->geometry).radius;
    const auto& at = caster->parent_to_joint_origin_transform.position;
    EXPECT_NEAR(at.z - radius, -p.wheel_radius, 1e-12) << name;
    EXPECT_LT(at.x, 0.0) << name;
    EXPECT_LT(std::abs(at.y), 0.5 * p.width) << name;
  }
}

}  // namespace

TEST(Urdf, CommittedFileMatchesTheChairFile) {
  const ChairParams p = test::shippedChair();
  const std::string committed = readFile(kCommittedUrdf);
  ASSERT_FALSE(committed.empty()) << kCommittedUrdf << " is missing";
  expectModelMatchesChair(parse(committed), p);
  EXPECT_EQ(committed, chairUrdf(p))
      << kCommittedUrdf << " is out of date with config/chair.yaml; regenerate it with\n"
      << "  rosrun wheelchair_description generate_urdf "
      << "$(rospack find wheelchair_description)/config/chair.yaml "
      << "$(rospack find wheelchair_description)/urdf/wheelchair.urdf";
}

TEST(Urdf, GeneratedModelFollowsOtherChairs) {
  std::mt19937 rng(23);
  std::uniform_real_distribution<double> u(0.8, 1.2);
  for (int i = 0; i < 20; ++i) {
    ChairParams p = test::shippedChair();
    p.wheel_radius *= u(rng);
    p.half_track *= u(rng);
    p.cm_offset *= u(rng);
    p.total_mass *= u(rng);
    p.laser_x *= u(rng);
    p.laser_y = u(rng) - 1.0;
    p.laser_z *= u(rng);
    p.laser_yaw = 3.0 * (u(rng) - 1.0);
    p.rear_laser_x *= u(rng);
    p.rear_laser_yaw = M_PI * u(rng);
    expectModelMatchesChair(parse(chairUrdf(p)), p);
  }
}

TEST(Urdf, AllLinksHangFromBaseFootprint) {
  const urdf::Model model = parse(readFile(kCommittedUrdf));
  std::vector<urdf::LinkSharedPtr> links;
  model.getLinks(links);
  EXPECT_EQ(links.size(), 9u);  // footprint, base, body, 2 wheels, 2 casters, 2 lasers
  for (const auto& link : links) {
    int depth = 0;
    for (auto l = link; l->getParent(); l = l->getParent()) ++depth;
    EXPECT_LE(depth, 2) << link->name;
  }
}

TEST(Urdf, InvalidChairIsRejected) {
  ChairParams p = test::shippedChair();
  p.wheel_radius = std::nan("");
  EXPECT_THROW(chairUrdf(p), std::invalid_argument);
}
