#include <gtest/gtest.h>
#include <wheelchair_core/map_io.h>

#include <fstream>
#include <iterator>
#include <random>

#include "map_test_files.h"

namespace wheelchair_core {
namespace {

using test::mapYaml;
using test::TempDir;
using test::writePgm;
using test::writeText;

// map_server's rule, written out independently: p = (255 - v) / 255.
int8_t expectedTrinary(uint8_t v, double occ = 0.65, double free = 0.196) {
  const double p = (255.0 - v) / 255.0;
  return p > occ ? 100 : (p < free ? 0 : -1);
}

TEST(MapIo, LoadsPixelsWithMapServerSemanticsAndFlipsRows) {
  TempDir dir;
  // 3 x 2 image; top row first.
  const std::vector<uint8_t> px = {0, 254, 205, 100, 128, 255};
  writePgm(dir.file("m.pgm"), 3, 2, px);
  writeText(dir.file("m.yaml"), mapYaml("m.pgm", "0.1", "[-1.5, 2.25, 0.0]"));
  const OccupancyMap map = loadMap(dir.file("m.yaml"));
  EXPECT_EQ(map.width, 3);
  EXPECT_EQ(map.height, 2);
  EXPECT_DOUBLE_EQ(map.resolution, 0.1);
  EXPECT_DOUBLE_EQ(map.origin_x, -1.5);
  EXPECT_DOUBLE_EQ(map.origin_y, 2.25);
  for (int c = 0; c < 3; ++c) {
    EXPECT_EQ(map.at(c, 1), expectedTrinary(px[c])) << "top image row is the map's last row";
    EXPECT_EQ(map.at(c, 0), expectedTrinary(px[3 + c]));
  }
  EXPECT_EQ(map.at(0, 1), kOccupied);
  EXPECT_EQ(map.at(1, 1), kFree);
  EXPECT_EQ(map.at(2, 1), kUnknown);
}

TEST(MapIo, NegateInvertsTheGreyScale) {
  TempDir dir;
  writePgm(dir.file("n.pgm"), 2, 1, {0, 255});
  writeText(dir.file("n.yaml"),
            "image: n.pgm\nresolution: 0.05\norigin: [0, 0, 0]\n"
            "negate: 1\noccupied_thresh: 0.65\nfree_thresh: 0.196\n");
  const OccupancyMap map = loadMap(dir.file("n.yaml"));
  EXPECT_EQ(map.at(0, 0), kFree);
  EXPECT_EQ(map.at(1, 0), kOccupied);
}

// Nav2 PR #5138: map_saver writes unknown as 205, i.e. p = 50/255 = 0.196; with Nav2's default
// free_thresh 0.25 that p is below the threshold and every unknown pixel loaded as free.
TEST(MapIo, TrinaryUnknownStaysUnknownWhateverFreeThreshSays) {
  TempDir dir;
  writePgm(dir.file("u.pgm"), 4, 1, {205, 205, 254, 0});
  for (const char* negate : {"0", "1"}) {
    const bool negated = negate[0] == '1';
    if (negated) writePgm(dir.file("u.pgm"), 4, 1, {50, 50, 1, 255});  // map_saver, negated
    writeText(dir.file("u.yaml"),
              "image: u.pgm\nresolution: 0.05\norigin: [0, 0, 0]\nnegate: " + std::string(negate) +
                  "\nmode: trinary\noccupied_thresh: 0.65\nfree_thresh: 0.25\n");
    const OccupancyMap map = loadMap(dir.file("u.yaml"));
    EXPECT_EQ(map.at(0, 0), kUnknown) << "negate " << negate;
    EXPECT_EQ(map.at(1, 0), kUnknown) << "negate " << negate;
    EXPECT_EQ(map.at(2, 0), kFree) << "negate " << negate;
    EXPECT_EQ(map.at(3, 0), kOccupied) << "negate " << negate;
  }
}

TEST(MapIo, ScaleModeInterpolatesBetweenThresholds) {
  TempDir dir;
  const uint8_t v = 150;
  writePgm(dir.file("s.pgm"), 1, 1, {v});
  writeText(dir.file("s.yaml"), mapYaml("s.pgm", "0.05", "[0, 0, 0]", "mode: scale\n"));
  const double p = (255.0 - v) / 255.0;
  const int expected = static_cast<int>(1 + 98 * (p - 0.196) / (0.65 - 0.196));
  EXPECT_EQ(loadMap(dir.file("s.yaml")).at(0, 0), expected);
}

TEST(MapIo, RawModeKeepsPixelValues) {
  TempDir dir;
  writePgm(dir.file("r.pgm"), 3, 1, {0, 42, 100});
  writeText(dir.file("r.yaml"), mapYaml("r.pgm", "0.05", "[0, 0, 0]", "mode: raw\n"));
  const OccupancyMap map = loadMap(dir.file("r.yaml"));
  EXPECT_EQ(map.at(0, 0), 0);
  EXPECT_EQ(map.at(1, 0), 42);
  EXPECT_EQ(map.at(2, 0), 100);
}

TEST(MapIo, ImagePathIsRelativeToTheYamlDirectory) {
  TempDir dir;
  std::filesystem::create_directory(dir.file("sub"));
  writePgm(dir.file("sub/i.pgm"), 1, 1, {0});
  writeText(dir.file("sub/i.yaml"), mapYaml("i.pgm"));
  const auto cwd = std::filesystem::current_path();
  std::filesystem::current_path(dir.file("."));
  const OccupancyMap map = loadMap("sub/i.yaml");
  std::filesystem::current_path(cwd);
  EXPECT_EQ(map.at(0, 0), kOccupied);
  // An absolute image path is used as is.
  writeText(dir.file("abs.yaml"), mapYaml(dir.file("sub/i.pgm")));
  EXPECT_EQ(loadMap(dir.file("abs.yaml")).at(0, 0), kOccupied);
}

OccupancyMap randomTrinaryMap(int width, int height, unsigned seed) {
  OccupancyMap map;
  map.resolution = 0.05;
  map.origin_x = -3.2749999999999999;
  map.origin_y = 12.345678901234567;
  map.origin_yaw = 0.0;
  map.width = width;
  map.height = height;
  std::mt19937 rng(seed);
  const int8_t values[] = {kUnknown, kFree, kOccupied};
  for (int i = 0; i < width * height; ++i) map.data.push_back(values[rng() % 3]);
  return map;
}

TEST(MapIo, TrinaryRoundTripIsExact) {
  TempDir dir;
  const OccupancyMap map = randomTrinaryMap(37, 23, 7);
  saveMap(map, dir.file("rt.yaml"));
  const OccupancyMap back = loadMap(dir.file("rt.yaml"));
  EXPECT_EQ(back.width, map.width);
  EXPECT_EQ(back.height, map.height);
  EXPECT_EQ(back.resolution, map.resolution);
  EXPECT_EQ(back.origin_x, map.origin_x);
  EXPECT_EQ(back.origin_y, map.origin_y);
  EXPECT_EQ(back.data, map.data);
}

TEST(MapIo, NegatedAndRawRoundTripsAreExact) {
  TempDir dir;
  const OccupancyMap map = randomTrinaryMap(11, 5, 3);
  MapFileOptions negated;
  negated.negate = true;
  saveMap(map, dir.file("neg.yaml"), negated);
  EXPECT_EQ(loadMap(dir.file("neg.yaml")).data, map.data);
  OccupancyMap graded = map;
  for (size_t i = 0; i < graded.data.size(); ++i) graded.data[i] = static_cast<int8_t>(i % 101);
  graded.data[0] = kUnknown;
  MapFileOptions raw;
  raw.mode = MapMode::kRaw;
  saveMap(graded, dir.file("raw.yaml"), raw);
  EXPECT_EQ(loadMap(dir.file("raw.yaml")).data, graded.data);
}

TEST(MapIo, SavedImageUsesMapSaverGreyLevelsTopRowFirst) {
  TempDir dir;
  OccupancyMap map;
  map.width = 3;
  map.height = 2;
  map.data = {kOccupied, kFree, kUnknown, kFree, kFree, kOccupied};  // bottom row first
  saveMap(map, dir.file("g.yaml"));
  std::ifstream in(dir.file("g.pgm"), std::ios::binary);
  std::string magic;
  int w = 0, h = 0, maxval = 0;
  in >> magic >> w >> h >> maxval;
  in.get();
  const std::vector<uint8_t> px((std::istreambuf_iterator<char>(in)),
                                std::istreambuf_iterator<char>());
  EXPECT_EQ(magic, "P5");
  EXPECT_EQ(w, 3);
  EXPECT_EQ(h, 2);
  EXPECT_EQ(px, (std::vector<uint8_t>{254, 254, 0, 0, 254, 205}));
}

// ---- bad files: one line, naming the file and the problem ----

std::string loadError(const std::string& yaml) {
  try {
    loadMap(yaml);
  } catch (const MapFileError& e) {
    return e.what();
  }
  return "no error";
}

void expectOneLineError(const std::string& what, const std::string& file,
                        const std::string& problem) {
  EXPECT_EQ(what.find('\n'), std::string::npos) << what;
  EXPECT_EQ(what.rfind(file, 0), 0u) << what;
  EXPECT_NE(what.find(problem), std::string::npos) << what;
}

TEST(MapIoErrors, MissingYaml) {
  TempDir dir;
  expectOneLineError(loadError(dir.file("none.yaml")), dir.file("none.yaml"), "not found");
}

TEST(MapIoErrors, MissingImage) {
  TempDir dir;
  writeText(dir.file("a.yaml"), mapYaml("gone.pgm"));
  expectOneLineError(loadError(dir.file("a.yaml")), dir.file("a.yaml"), "gone.pgm");
}

TEST(MapIoErrors, BadYaml) {
  TempDir dir;
  writeText(dir.file("b.yaml"), "image: b.pgm\nresolution: [0.05\norigin: {\n");
  expectOneLineError(loadError(dir.file("b.yaml")), dir.file("b.yaml"), "bad YAML");
  writeText(dir.file("c.yaml"), "just a string");
  expectOneLineError(loadError(dir.file("c.yaml")), dir.file("c.yaml"), "bad YAML");
}

TEST(MapIoErrors, NonPositiveOrNonNumericResolution) {
  TempDir dir;
  writePgm(dir.file("r.pgm"), 1, 1, {0});
  for (const std::string res : {"-0.05", "0", ".nan", "fine"}) {
    writeText(dir.file("r.yaml"), mapYaml("r.pgm", res));
    const std::string what = loadError(dir.file("r.yaml"));
    expectOneLineError(what, dir.file("r.yaml"), "resolution");
  }
}

TEST(MapIoErrors, UnreadablePgm) {
  TempDir dir;
  writeText(dir.file("u.pgm"), "P5\n this is not an image");
  writeText(dir.file("u.yaml"), mapYaml("u.pgm"));
  expectOneLineError(loadError(dir.file("u.yaml")), dir.file("u.pgm"), "unreadable image");
}

TEST(MapIoErrors, NonFiniteOrMalformedOrigin) {
  TempDir dir;
  writePgm(dir.file("o.pgm"), 1, 1, {0});
  for (const std::string origin : {"[.nan, 0, 0]", "[0, .inf, 0]", "[0, 0]", "7"}) {
    writeText(dir.file("o.yaml"), mapYaml("o.pgm", "0.05", origin));
    expectOneLineError(loadError(dir.file("o.yaml")), dir.file("o.yaml"), "origin");
  }
}

TEST(MapIoErrors, MissingKeysAndBadMode) {
  TempDir dir;
  writePgm(dir.file("k.pgm"), 1, 1, {0});
  const std::string full = mapYaml("k.pgm");
  for (const std::string key :
       {"image", "resolution", "origin", "negate", "occupied_thresh", "free_thresh"}) {
    std::string text;
    std::istringstream lines(full);
    for (std::string line; std::getline(lines, line);) {
      if (line.rfind(key + ":", 0) != 0) text += line + "\n";
    }
    writeText(dir.file("k.yaml"), text);
    expectOneLineError(loadError(dir.file("k.yaml")), dir.file("k.yaml"),
                       "missing key '" + key + "'");
  }
  writeText(dir.file("k.yaml"), full + "mode: fancy\n");
  expectOneLineError(loadError(dir.file("k.yaml")), dir.file("k.yaml"), "mode");
}

TEST(MapIoErrors, SavingAnInconsistentMapOrToAMissingDirectory) {
  TempDir dir;
  OccupancyMap map;
  map.width = 2;
  map.height = 2;
  map.data = {0, 0, 0};
  EXPECT_THROW(saveMap(map, dir.file("x.yaml")), MapFileError);
  map.data.push_back(0);
  EXPECT_THROW(saveMap(map, dir.file("no/such/dir/x.yaml")), MapFileError);
}

}  // namespace
}  // namespace wheelchair_core
