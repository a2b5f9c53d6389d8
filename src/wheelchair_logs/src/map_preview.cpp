#include <wheelchair_logs/map_preview.h>

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <stdexcept>

namespace wheelchair_logs {

void savePreviewPng(const mrpt::maps::COccupancyGridMap2D& grid, const std::string& png_path) {
  const int w = static_cast<int>(grid.getSizeX());
  const int h = static_cast<int>(grid.getSizeY());
  cv::Mat image(h, w, CV_8UC1);
  const auto& raw = grid.getRawMap();
  for (int iy = 0; iy < h; ++iy) {
    uint8_t* row = image.ptr<uint8_t>(h - 1 - iy);
    for (int ix = 0; ix < w; ++ix) {
      const auto logodds_free = raw[static_cast<size_t>(iy) * w + ix];
      // More likely occupied than free (log-odds of free < 0): black.
      row[ix] = logodds_free < 0 ? 0 : mrpt::maps::COccupancyGridMap2D::l2p_255(logodds_free);
    }
  }
  bool ok = false;
  try {
    ok = cv::imwrite(png_path, image);
  } catch (const cv::Exception&) {
    ok = false;
  }
  if (!ok) throw std::runtime_error(png_path + ": cannot write the preview image");
}

}  // namespace wheelchair_logs
