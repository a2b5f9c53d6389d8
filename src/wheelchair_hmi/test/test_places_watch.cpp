// The HMI sees a place the carer saved: the places file replaced on disk (as the display's
// atomic writer does: a new file renamed over the old) is read again; a bad edit is reported
// once and the old places stay.
#include <wheelchair_hmi/places_watch.h>

#include <gtest/gtest.h>

#include <unistd.h>
#include <cstdio>
#include <fstream>
#include <string>

using namespace wheelchair_hmi;

namespace {

const char* kTwoPlaces =
    "places:\n"
    "  - {name: sink, room: kitchen, x: 4.0, y: 2.0, yaw: 1.5708}\n"
    "  - {name: bed, room: bedroom, x: 8.0, y: 6.0, yaw: 0.0}\n";

/// Writes `text` to `path` as the display does: a temporary file renamed over it.
void replaceFile(const std::string& path, const std::string& text) {
  const std::string tmp = path + ".tmp";
  std::ofstream(tmp) << text;
  ASSERT_EQ(std::rename(tmp.c_str(), path.c_str()), 0);
}

std::string tempPath() {
  char name[] = "/tmp/places_watch_XXXXXX";
  const int fd = mkstemp(name);
  close(fd);
  return name;
}

}  // namespace

TEST(PlacesFileWatch, ASavedPlaceIsReadOnceAndAnUnchangedFileIsNoNews) {
  const std::string path = tempPath();
  replaceFile(path, kTwoPlaces);
  PlacesFileWatch watch(path);
  std::string problem;
  EXPECT_FALSE(watch.changed(problem));
  EXPECT_EQ(problem, "");

  replaceFile(path, std::string(kTwoPlaces) +
                        "  - {name: desk, room: study, x: 1.0, y: 7.5, yaw: -1.5708}\n");
  const auto places = watch.changed(problem);
  ASSERT_TRUE(places) << problem;
  ASSERT_EQ(places->size(), 3u);
  EXPECT_EQ(places->back().name, "desk");
  EXPECT_EQ(places->back().room, "study");
  EXPECT_DOUBLE_EQ(places->back().pose.y, 7.5);
  EXPECT_FALSE(watch.changed(problem)) << "the same change reported twice";
  std::remove(path.c_str());
}

TEST(PlacesFileWatch, ABadEditIsReportedOnceAndTheNextGoodOneIsRead) {
  const std::string path = tempPath();
  replaceFile(path, kTwoPlaces);
  PlacesFileWatch watch(path);
  std::string problem;
  replaceFile(path, "places:\n  - {name: sink, room: kitchen, x: 4.0}\n");  // no y, no yaw
  EXPECT_FALSE(watch.changed(problem));
  EXPECT_NE(problem.find(path), std::string::npos) << problem;
  EXPECT_FALSE(watch.changed(problem));
  EXPECT_EQ(problem, "") << "a bad file reported again without a change";
  replaceFile(path, kTwoPlaces);
  const auto places = watch.changed(problem);
  ASSERT_TRUE(places) << problem;
  EXPECT_EQ(places->size(), 2u);
  std::remove(path.c_str());
}

TEST(PlacesFileWatch, ARemovedFileIsAProblemNotAnEmptyList) {
  const std::string path = tempPath();
  replaceFile(path, kTwoPlaces);
  PlacesFileWatch watch(path);
  std::remove(path.c_str());
  std::string problem;
  EXPECT_FALSE(watch.changed(problem));
  EXPECT_FALSE(problem.empty());
}
