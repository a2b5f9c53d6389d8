// Test helpers: a fresh temporary directory and hand-written PGM/YAML files (written byte by
// byte here, independently of the code under test).
#pragma once

#include <unistd.h>

#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace wheelchair_core::test {

class TempDir {
 public:
  TempDir() {
    std::string pattern = (std::filesystem::temp_directory_path() / "wcmapXXXXXX").string();
    path_ = mkdtemp(pattern.data());
  }
  ~TempDir() { std::filesystem::remove_all(path_); }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  std::string file(const std::string& name) const { return (path_ / name).string(); }

 private:
  std::filesystem::path path_;
};

/// Binary PGM (P5) with rows given top row first, as in the image.
inline void writePgm(const std::string& path, int width, int height,
                     const std::vector<uint8_t>& pixels_top_first) {
  std::ofstream out(path, std::ios::binary);
  out << "P5\n" << width << " " << height << "\n255\n";
  out.write(reinterpret_cast<const char*>(pixels_top_first.data()),
            static_cast<std::streamsize>(pixels_top_first.size()));
}

inline void writeText(const std::string& path, const std::string& text) {
  std::ofstream(path) << text;
}

/// A map_server YAML with the usual keys; `extra` is appended verbatim.
inline std::string mapYaml(const std::string& image, const std::string& resolution = "0.05",
                           const std::string& origin = "[-1.0, -2.0, 0.0]",
                           const std::string& extra = "") {
  return "image: " + image + "\nresolution: " + resolution + "\norigin: " + origin +
         "\nnegate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\n" + extra;
}

}  // namespace wheelchair_core::test
