// Loading the chair file: every fault names the file and the parameter.
#include <wheelchair_description/chair_params.h>
#include <wheelchair_description_testing/chair_file.h>

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <functional>
#include <sstream>
#include <stdexcept>
#include <string>

using namespace wheelchair_description;

namespace {

/// Lines of the shipped chair file (the test edits copies of them).
std::vector<std::string> defaultLines() {
  std::ifstream in(test::chairFile());
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

/// True if `line` sets the top-level key `key`.
bool setsKey(const std::string& line, const std::string& key) {
  return line.rfind(key + ":", 0) == 0;
}

/// Writes the shipped chair file with the line of `key` replaced by `replacement`
/// (or dropped if it is empty) to a temporary file and returns its path.
std::string chairFileWith(const std::string& key, const std::string& replacement) {
  const std::string path = ::testing::TempDir() + "chair_" + key + ".yaml";
  std::ofstream out(path);
  bool found = false;
  for (const std::string& line : defaultLines()) {
    if (setsKey(line, key)) {
      found = true;
      if (!replacement.empty()) out << replacement << "\n";
    } else {
      out << line << "\n";
    }
  }
  EXPECT_TRUE(found) << "chair.yaml has no key " << key;
  return path;
}

/// The message of the exception loadChairParams throws for `path` ("" if none).
std::string loadError(const std::string& path) {
  try {
    loadChairParams(path);
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

void expectErrorNaming(const std::string& path, const std::string& parameter) {
  const std::string message = loadError(path);
  EXPECT_NE(message.find(path), std::string::npos) << "message does not name the file: " << message;
  EXPECT_NE(message.find("'" + parameter + "'"), std::string::npos)
      << "message does not name '" << parameter << "': " << message;
}

const char* const kScalarKeys[] = {"total_mass",    "wheel_mass",
                                   "wheel_inertia", "wheel_inertia_diam",
                                   "body_inertia",  "wheel_radius",
                                   "half_track",    "cm_offset",
                                   "lookahead",     "max_wheel_torque",
                                   "max_speed",     "rolling_resistance",
                                   "width",         "length"};

/// Keys that must be strictly positive (cm_offset and lookahead may be negative).
const char* const kPositiveKeys[] = {
    "total_mass",   "wheel_mass",   "wheel_inertia", "wheel_inertia_diam",
    "body_inertia", "wheel_radius", "half_track",    "max_wheel_torque",
    "max_speed",    "width",        "length"};

}  // namespace

TEST(ChairParams, ShippedFileLoadsAndValidates) {
  const ChairParams p = test::shippedChair();
  EXPECT_EQ(p.validate(), "");
  EXPECT_EQ(p.footprint.size(), 4u);
}

TEST(ChairParams, EachKeyFillsItsOwnMember) {
  // Distinct values, so a swapped key is caught.
  const std::string path = ::testing::TempDir() + "chair_distinct.yaml";
  std::ofstream(path) << "total_mass: 101\nwheel_mass: 3.1\nwheel_inertia: 0.21\n"
                         "wheel_inertia_diam: 0.031\nbody_inertia: 14.1\nwheel_radius: 0.171\n"
                         "half_track: 0.281\ncm_offset: -0.05\nlookahead: -0.2\n"
                         "max_wheel_torque: 41\nmax_speed: 1.2\nrolling_resistance: 0.02\n"
                         "width: 0.6\nlength: 1.0\n"
                         "footprint: [[0.3, 0.4], [-0.6, 0.4], [-0.6, -0.4], [0.3, -0.4]]\n"
                         "laser: {x: 0.31, y: -0.02, z: 0.12, yaw: 0.1}\n"
                         "rear_laser: {x: -0.71, y: 0.03, z: 0.09, yaw: 3.0}\n"
                         "protective_field: {reaction_time: 0.31, brake_decel: 0.51, "
                         "brake_jerk: 1.1, drive_accel: 0.36, margin: 0.21}\n";
  const ChairParams p = loadChairParams(path);
  EXPECT_EQ(p.total_mass, 101.0);
  EXPECT_EQ(p.wheel_mass, 3.1);
  EXPECT_EQ(p.wheel_inertia, 0.21);
  EXPECT_EQ(p.wheel_inertia_diam, 0.031);
  EXPECT_EQ(p.body_inertia, 14.1);
  EXPECT_EQ(p.wheel_radius, 0.171);
  EXPECT_EQ(p.half_track, 0.281);
  EXPECT_EQ(p.cm_offset, -0.05);
  EXPECT_EQ(p.lookahead, -0.2);
  EXPECT_EQ(p.max_wheel_torque, 41.0);
  EXPECT_EQ(p.max_speed, 1.2);
  EXPECT_EQ(p.rolling_resistance, 0.02);
  EXPECT_EQ(p.width, 0.6);
  EXPECT_EQ(p.length, 1.0);
  ASSERT_EQ(p.footprint.size(), 4u);
  EXPECT_EQ(p.footprint[1], Eigen::Vector2d(-0.6, 0.4));
  EXPECT_EQ(p.laser_x, 0.31);
  EXPECT_EQ(p.laser_y, -0.02);
  EXPECT_EQ(p.laser_z, 0.12);
  EXPECT_EQ(p.laser_yaw, 0.1);
  EXPECT_EQ(p.rear_laser_x, -0.71);
  EXPECT_EQ(p.rear_laser_y, 0.03);
  EXPECT_EQ(p.rear_laser_z, 0.09);
  EXPECT_EQ(p.rear_laser_yaw, 3.0);
  EXPECT_EQ(p.stop.reaction_time, 0.31);
  EXPECT_EQ(p.stop.brake_decel, 0.51);
  EXPECT_EQ(p.stop.brake_jerk, 1.1);
  EXPECT_EQ(p.stop.drive_accel, 0.36);
  EXPECT_EQ(p.stop.margin, 0.21);
  EXPECT_DOUBLE_EQ(p.inscribedRadius(), 0.3);
  EXPECT_DOUBLE_EQ(p.circumscribedRadius(), std::hypot(0.6, 0.4));
}

TEST(ChairParams, MissingFileIsNamed) {
  const std::string path = ::testing::TempDir() + "no_such_chair.yaml";
  const std::string message = loadError(path);
  EXPECT_NE(message.find(path), std::string::npos) << message;
  EXPECT_NE(message.find("cannot open"), std::string::npos) << message;
}

TEST(ChairParams, BadYamlIsNamed) {
  const std::string path = ::testing::TempDir() + "chair_bad_syntax.yaml";
  std::ofstream(path) << "total_mass: [130\nwheel_mass: {\n";
  const std::string message = loadError(path);
  EXPECT_NE(message.find(path), std::string::npos) << message;
  EXPECT_NE(message.find("bad YAML"), std::string::npos) << message;
}

TEST(ChairParams, EachMissingKeyIsNamed) {
  for (const char* key : kScalarKeys) expectErrorNaming(chairFileWith(key, ""), key);
  expectErrorNaming(chairFileWith("footprint", ""), "footprint");
  expectErrorNaming(chairFileWith("laser", ""), "laser");
  expectErrorNaming(chairFileWith("laser", "laser: {x: 0.28, y: 0.0, yaw: 0.0}"), "laser/z");
  expectErrorNaming(chairFileWith("rear_laser", ""), "rear_laser");
  expectErrorNaming(chairFileWith("rear_laser", "rear_laser: {x: -0.75, y: 0.0, z: 0.08}"),
                    "rear_laser/yaw");
  expectErrorNaming(chairFileWith("protective_field", ""), "protective_field");
  expectErrorNaming(chairFileWith("protective_field",
                                  "protective_field: {reaction_time: 0.3, brake_decel: 0.5, "
                                  "brake_jerk: 1.0, drive_accel: 0.35}"),
                    "protective_field/margin");
}

TEST(ChairParams, AStopThatCannotBrakeIsNamed) {
  expectErrorNaming(chairFileWith("protective_field",
                                  "protective_field: {reaction_time: 0.3, brake_decel: 0.0, "
                                  "brake_jerk: 1.0, drive_accel: 0.35, margin: 0.2}"),
                    "protective_field/brake_decel");
  expectErrorNaming(chairFileWith("protective_field",
                                  "protective_field: {reaction_time: -0.1, brake_decel: 0.5, "
                                  "brake_jerk: 1.0, drive_accel: 0.35, margin: 0.2}"),
                    "protective_field/reaction_time");
}

TEST(ChairParams, EachNonFiniteValueIsNamed) {
  for (const char* key : kScalarKeys)
    for (const char* bad : {".nan", ".inf", "-.inf"})
      expectErrorNaming(chairFileWith(key, std::string(key) + ": " + bad), key);
  expectErrorNaming(chairFileWith("laser", "laser: {x: .nan, y: 0.0, z: 0.25, yaw: 0.0}"),
                    "laser/x");
  expectErrorNaming(chairFileWith("laser", "laser: {x: 0.2, y: 0.0, z: 0.25, yaw: .inf}"),
                    "laser/yaw");
  expectErrorNaming(
      chairFileWith("rear_laser", "rear_laser: {x: .nan, y: 0.0, z: 0.08, yaw: 3.1416}"),
      "rear_laser/x");
  expectErrorNaming(chairFileWith("footprint", "footprint: [[0.3, .nan], [-0.8, 0.3], [0, -1]]"),
                    "footprint");
}

TEST(ChairParams, EachNonNumberIsNamed) {
  for (const char* key : kScalarKeys)
    expectErrorNaming(chairFileWith(key, std::string(key) + ": heavy"), key);
  expectErrorNaming(chairFileWith("footprint", "footprint: [[0.3, a], [-0.8, 0.3], [0, -1]]"),
                    "footprint[0][1]");
  expectErrorNaming(chairFileWith("footprint", "footprint: [[0.3], [-0.8, 0.3], [0, -1]]"),
                    "footprint[0]");
}

TEST(ChairParams, EachNegativeOrZeroPhysicalQuantityIsNamed) {
  for (const char* key : kPositiveKeys) {
    expectErrorNaming(chairFileWith(key, std::string(key) + ": -1.0"), key);
    expectErrorNaming(chairFileWith(key, std::string(key) + ": 0"), key);
  }
  expectErrorNaming(chairFileWith("rolling_resistance", "rolling_resistance: -0.01"),
                    "rolling_resistance");
}

TEST(ChairParams, ZeroLookaheadIsRejectedBecauseTheDecouplingMatrixIsSingular) {
  expectErrorNaming(chairFileWith("lookahead", "lookahead: 0.0"), "lookahead");
  // A point behind the axle is allowed: det(Phi) = -2 b L c^2 only needs L != 0.
  EXPECT_EQ(loadError(chairFileWith("lookahead", "lookahead: -0.15")), "");
}

TEST(ChairParams, FootprintNeedsThreeVertices) {
  expectErrorNaming(chairFileWith("footprint", "footprint: [[0.3, 0.3], [-0.8, 0.3]]"),
                    "footprint");
}

TEST(ChairParams, ValidateNamesTheBadMember) {
  ChairParams p = test::shippedChair();
  p.half_track = -0.2;
  const std::string problem = p.validate();
  EXPECT_NE(problem.find("'half_track'"), std::string::npos)
      << "negative half_track accepted: " << problem;
}

TEST(ChairParams, AnUnknownKeyIsRefusedNamingItAndTheKnownKeys) {
  const std::string path = chairFileWith("length", "length: 1.10\nlenght: 1.10");
  const std::string message = loadError(path);
  EXPECT_NE(message.find(path), std::string::npos) << message;
  EXPECT_NE(message.find("unknown parameter 'lenght'"), std::string::npos) << message;
  EXPECT_NE(message.find("laser/yaw"), std::string::npos) << "the known keys: " << message;
}
