// `rosrun wheelchair_mapping map_server <bad file>` prints one FATAL line naming the file and
// exits non-zero (no ROS master needed: the file is checked before the node starts).
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <sstream>

#include "map_test_files.h"

namespace wheelchair_mapping {
namespace {

struct RunResult {
  int exit_code = -1;
  std::string output;
};

RunResult runMapServer(const std::string& yaml) {
  const std::string cmd =
      "ROS_MASTER_URI=http://127.0.0.1:1 rosrun wheelchair_mapping map_server '" + yaml + "' 2>&1";
  RunResult r;
  FILE* pipe = popen(cmd.c_str(), "r");
  std::array<char, 512> buf{};
  while (fgets(buf.data(), buf.size(), pipe)) r.output += buf.data();
  const int status = pclose(pipe);
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

std::vector<std::string> fatalLines(const std::string& output) {
  std::vector<std::string> lines;
  std::istringstream in(output);
  for (std::string line; std::getline(in, line);) {
    if (line.find("FATAL") != std::string::npos) lines.push_back(line);
  }
  return lines;
}

TEST(MapServerExit, MissingYaml) {
  wheelchair_core::test::TempDir dir;
  const RunResult r = runMapServer(dir.file("missing.yaml"));
  EXPECT_EQ(r.exit_code, 1) << r.output;
  const auto lines = fatalLines(r.output);
  ASSERT_EQ(lines.size(), 1u) << r.output;
  EXPECT_NE(lines[0].find(dir.file("missing.yaml") + ": map file not found"), std::string::npos)
      << lines[0];
}

TEST(MapServerExit, NegativeResolution) {
  wheelchair_core::test::TempDir dir;
  wheelchair_core::test::writePgm(dir.file("n.pgm"), 1, 1, {0});
  wheelchair_core::test::writeText(dir.file("n.yaml"),
                                   wheelchair_core::test::mapYaml("n.pgm", "-0.05"));
  const RunResult r = runMapServer(dir.file("n.yaml"));
  EXPECT_EQ(r.exit_code, 1) << r.output;
  const auto lines = fatalLines(r.output);
  ASSERT_EQ(lines.size(), 1u) << r.output;
  EXPECT_NE(lines[0].find("resolution must be positive"), std::string::npos) << lines[0];
}

}  // namespace
}  // namespace wheelchair_mapping
