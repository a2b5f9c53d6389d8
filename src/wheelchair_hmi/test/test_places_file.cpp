#include <gtest/gtest.h>
#include <wheelchair_hmi/places_file.h>
#include <yaml-cpp/yaml.h>

#include <cstdio>
#include <fstream>

namespace wheelchair_hmi {

TEST(PlacesFile, TypedNamesBecomeIdentifiers) {
  EXPECT_EQ(placeId("Front door "), "front_door");
  EXPECT_EQ(placeId("  Mum's  chair #2"), "mum_s_chair_2");
  EXPECT_EQ(placeId("!!"), "");
}

TEST(PlacesFile, ANewNameMustBeFreeAndPlain) {
  const std::vector<Place> places = {{"sofa", "living_room", {1, 1, 0}}};
  EXPECT_EQ(placeNameProblem("armchair", places), "");
  EXPECT_NE(placeNameProblem("sofa", places), "");
  EXPECT_NE(placeNameProblem("", places), "");
  EXPECT_NE(placeNameProblem("Sofa 2", places), "");
}

TEST(PlacesFile, SavedPlacesReadBackWithTheHmisReaderKeepingTheOtherKeys) {
  const std::string path = ::testing::TempDir() + "/display_places_test.yaml";
  {
    std::ofstream out(path);
    out << "map: flat.yaml\nrooms: [living_room, kitchen]\nplaces:\n"
           "  - {name: sofa, room: living_room, x: 3.2, y: 1.0, yaw: 3.1416}\n";
  }
  auto places = loadPlaces(path);
  places.push_back({"by_the_window", "study", {7.25, 6.5, -1.2}});
  savePlaces(path, places);
  const auto back = loadPlaces(path);
  ASSERT_EQ(back.size(), 2u);
  EXPECT_EQ(back[1].name, "by_the_window");
  EXPECT_EQ(back[1].room, "study");
  EXPECT_NEAR(back[1].pose.x, 7.25, 1e-9);
  EXPECT_NEAR(back[1].pose.yaw, -1.2, 1e-9);
  EXPECT_NEAR(back[0].pose.yaw, 3.1416, 1e-9);
  const YAML::Node root = YAML::LoadFile(path);
  EXPECT_EQ(root["map"].as<std::string>(), "flat.yaml");
  ASSERT_EQ(root["rooms"].size(), 3u);  // the new room is listed
  EXPECT_EQ(root["rooms"][2].as<std::string>(), "study");
  std::remove(path.c_str());
}

TEST(PlacesFile, TheTestWorldsPlacesSurviveARewrite) {
  const auto places = loadPlaces(std::string(WORLDS_DIR) + "/flat.places.yaml");
  const std::string path = ::testing::TempDir() + "/display_flat_copy.yaml";
  savePlaces(path, places);
  const auto back = loadPlaces(path);
  ASSERT_EQ(back.size(), places.size());
  for (size_t i = 0; i < places.size(); ++i) {
    EXPECT_EQ(back[i].name, places[i].name);
    EXPECT_NEAR(back[i].pose.x, places[i].pose.x, 1e-9);
  }
  std::remove(path.c_str());
}

}  // namespace wheelchair_hmi
