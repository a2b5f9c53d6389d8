#include <wheelchair_logs/trajectory_plot.h>

#include <algorithm>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <stdexcept>

namespace wheelchair_logs {

void saveTrajectoryPlot(const wheelchair_core::OccupancyMap& map,
                        const std::vector<PlotPath>& paths, const std::string& png_path) {
  if (map.width <= 0 || map.height <= 0) throw std::runtime_error(png_path + ": empty map");
  cv::Mat image(map.height, map.width, CV_8UC3);
  for (int iy = 0; iy < map.height; ++iy) {
    auto* row = image.ptr<cv::Vec3b>(map.height - 1 - iy);
    for (int ix = 0; ix < map.width; ++ix) {
      const int8_t v = map.at(ix, iy);
      const uint8_t grey =
          v < 0 ? 205 : static_cast<uint8_t>(255 - 255 * std::min<int>(v, 100) / 100);
      row[ix] = cv::Vec3b(grey, grey, grey);
    }
  }
  auto pixel = [&](const wheelchair_core::Pose2D& p) {
    return cv::Point(static_cast<int>((p.x - map.origin_x) / map.resolution),
                     map.height - 1 - static_cast<int>((p.y - map.origin_y) / map.resolution));
  };
  const int thickness = std::max(1, std::min(map.width, map.height) / 400);
  for (const PlotPath& path : paths) {
    const cv::Scalar colour(path.b, path.g, path.r);
    std::vector<cv::Point> points;
    for (const auto& p : path.poses) points.push_back(pixel(p));
    if (points.size() >= 2) cv::polylines(image, points, false, colour, thickness, cv::LINE_AA);
    for (const auto& m : path.marks)
      cv::circle(image, pixel(m), 6 * thickness, colour, thickness, cv::LINE_AA);
  }
  const double font = std::max(0.4, map.width / 1500.0);
  int y = static_cast<int>(20 * font / 0.4);
  for (const PlotPath& path : paths) {
    cv::putText(image, path.label, cv::Point(10, y), cv::FONT_HERSHEY_SIMPLEX, font,
                cv::Scalar(path.b, path.g, path.r), thickness + 1, cv::LINE_AA);
    y += static_cast<int>(22 * font / 0.4);
  }
  bool ok = false;
  try {
    ok = cv::imwrite(png_path, image);
  } catch (const cv::Exception&) {
    ok = false;
  }
  if (!ok) throw std::runtime_error(png_path + ": cannot write the plot");
}

}  // namespace wheelchair_logs
