// The bring-up file: nodelets, parameters, remaps, $(find) and clear errors.
#include <wheelchair_bringup/bringup_config.h>

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>

using namespace wheelchair_bringup;

namespace {

std::string findFake(const std::string& package) {
  return package == "wheelchair_test" ? "/opt/share/wheelchair_test" : "";
}

std::string writeTemp(const std::string& text) {
  const std::string path = ::testing::TempDir() + "bringup_test.yaml";
  std::ofstream(path) << text;
  return path;
}

}  // namespace

TEST(BringupConfig, ReadsNodeletsParamsAndRemaps) {
  const std::string path = writeTemp(
      "params: {use_sim_time: true}\n"
      "nodelets:\n"
      "  - name: map_server\n"
      "    type: wheelchair_mapping/MapServerNodelet\n"
      "    params: {map_file: $(find wheelchair_test)/worlds/flat.yaml, rate: 2.5, "
      "list: [1, $(find wheelchair_test)]}\n"
      "  - name: hmi\n"
      "    type: wheelchair_hmi/HmiNodelet\n"
      "    remap: {switch: /tongue/switch}\n");
  const BringupConfig config = loadBringupConfig(path, findFake);
  ASSERT_EQ(config.nodelets.size(), 2u);
  EXPECT_TRUE(config.global_params["use_sim_time"].as<bool>());
  EXPECT_EQ(config.nodelets[0].type, "wheelchair_mapping/MapServerNodelet");
  EXPECT_EQ(config.nodelets[0].params["map_file"].as<std::string>(),
            "/opt/share/wheelchair_test/worlds/flat.yaml");
  EXPECT_DOUBLE_EQ(config.nodelets[0].params["rate"].as<double>(), 2.5);
  EXPECT_EQ(config.nodelets[0].params["list"][1].as<std::string>(), "/opt/share/wheelchair_test");
  EXPECT_EQ(config.nodelets[1].remaps.at("switch"), "/tongue/switch");
  EXPECT_EQ(config.num_worker_threads, 8);  // the default when the file does not say
  std::remove(path.c_str());
}

TEST(BringupConfig, ManagerThreadsFromTheFile) {
  const std::string path =
      writeTemp("num_worker_threads: 3\nnodelets:\n  - {name: a, type: x/A}\n");
  EXPECT_EQ(loadBringupConfig(path, findFake).num_worker_threads, 3);
  std::remove(path.c_str());
}

TEST(BringupConfig, BadFilesNameTheFileAndTheProblem) {
  const auto expectError = [](const std::string& text, const std::string& fragment) {
    const std::string path = writeTemp(text);
    try {
      loadBringupConfig(path, findFake);
      ADD_FAILURE() << "accepted: " << text;
    } catch (const std::runtime_error& e) {
      EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
      EXPECT_EQ(std::string(e.what()).rfind(path, 0), 0u) << e.what();
    }
  };
  expectError("params: {}\n", "no 'nodelets'");
  expectError("nodelets:\n  - {name: a}\n", "without name/type");
  expectError("nodelets:\n  - {name: a, type: x/A}\n  - {name: a, type: x/B}\n", "used twice");
  expectError("nodelets:\n  - {name: a, type: x/A, params: {f: $(find nope)/x}}\n",
              "package 'nope' not found");
  expectError("nodelets: [\n", "bad YAML");
  expectError("num_worker_threads: 0\nnodelets:\n  - {name: a, type: x/A}\n", "num_worker_threads");
  EXPECT_THROW(loadBringupConfig("/nonexistent/chair.yaml", findFake), std::runtime_error);
  // A misspelt key is refused with the known ones, at the top and in a nodelet.
  expectError("num_worker_thread: 3\nnodelets:\n  - {name: a, type: x/A}\n",
              "unknown key 'num_worker_thread' (known: nodelets, num_worker_threads, params)");
  expectError("nodelets:\n  - {name: a, type: x/A, param: {k: 1}}\n",
              "nodelet 'a': unknown key 'param' (known: name, params, remap, type)");
  expectError("nodelets:\n  - {name: a, type: x/A, params: {f: $(env WHEELCHAIR_TEST_UNSET)}}\n",
              "environment variable 'WHEELCHAIR_TEST_UNSET' is not set");
  expectError("nodelets:\n  - {name: a, type: x/A, params: {f: $(arg x)}}\n",
              "unknown substitution '$(arg ...)'");
}

TEST(BringupConfig, DeploymentPathsComeFromTheEnvironment) {
  ::setenv("WHEELCHAIR_TEST_HOME", "/etc/wheelchair/home", 1);
  const std::string path = writeTemp(
      "nodelets:\n"
      "  - name: map_server\n"
      "    type: wheelchair_mapping/MapServerNodelet\n"
      "    params: {map_file: $(env WHEELCHAIR_TEST_HOME)/map.yaml}\n");
  EXPECT_EQ(loadBringupConfig(path, findFake).nodelets[0].params["map_file"].as<std::string>(),
            "/etc/wheelchair/home/map.yaml");
  ::unsetenv("WHEELCHAIR_TEST_HOME");
  std::remove(path.c_str());
}

TEST(BringupConfig, ParametersNamedStarFileAreFilesTheChairNeeds) {
  EXPECT_TRUE(isFileParameter("/map_server/map_file"));
  EXPECT_TRUE(isFileParameter("places_file"));
  EXPECT_TRUE(isFileParameter("chair_file"));
  EXPECT_FALSE(isFileParameter("_file"));
  EXPECT_FALSE(isFileParameter("map_frame"));
  EXPECT_FALSE(isFileParameter("file_rate"));
}

TEST(BringupConfig, AMissingFileOfANodeletIsNamedWithItsKey) {
  const std::string path = writeTemp(
      "nodelets:\n"
      "  - {name: hmi, type: x/Hmi, params: {places_file: /nonexistent/places.yaml}}\n");
  const BringupConfig config = loadBringupConfig(path, findFake);
  EXPECT_EQ(missingFile(config.nodelets[0]),
            "/hmi/places_file: cannot read '/nonexistent/places.yaml'");
  EXPECT_EQ(missingFile(config.nodelets[0], {{"places_file", path}}), "");  // an override wins
  EXPECT_EQ(missingFile(config.nodelets[0], {{"places_file", path}, {"chair_file", "/no/chair"}}),
            "/hmi/chair_file: cannot read '/no/chair'");
  std::remove(path.c_str());
}
