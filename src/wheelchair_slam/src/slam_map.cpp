#include <wheelchair_logs/map_preview.h>
#include <wheelchair_slam/slam_map.h>

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <stdexcept>

namespace wheelchair_slam {

wheelchair_mapping::InsertResult insertAtPose(wheelchair_mapping::BayesMapper& mapper,
                                              wheelchair_core::LaserScan2D scan,
                                              const wheelchair_core::Pose2D& pose, size_t order) {
  scan.stamp = static_cast<double>(order);
  return mapper.insert(scan, pose);
}

wheelchair_mapping::BayesMapper buildMap(const std::vector<wheelchair_core::LaserScan2D>& scans,
                                         const std::vector<wheelchair_core::Pose2D>& poses,
                                         const wheelchair_mapping::MapperConfig& config,
                                         size_t* skipped) {
  wheelchair_mapping::BayesMapper mapper(config);
  size_t refused = 0;
  for (size_t i = 0; i < scans.size() && i < poses.size(); ++i) {
    if (!insertAtPose(mapper, scans[i], poses[i], i).inserted) ++refused;
  }
  if (skipped) *skipped = refused;
  return mapper;
}

void savePreviewWithTrajectory(
    const wheelchair_mapping::BayesMapper& mapper, const std::vector<wheelchair_core::Pose2D>& path,
    const std::vector<std::pair<wheelchair_core::Pose2D, wheelchair_core::Pose2D>>& loops,
    const std::string& png_path) {
  wheelchair_logs::savePreviewPng(mapper.grid(), png_path);
  cv::Mat grey = cv::imread(png_path, cv::IMREAD_GRAYSCALE);
  if (grey.empty()) throw std::runtime_error(png_path + ": cannot read back the preview");
  cv::Mat image;
  cv::cvtColor(grey, image, cv::COLOR_GRAY2BGR);
  const auto& grid = mapper.grid();
  const int h = image.rows;
  auto pixel = [&](const wheelchair_core::Pose2D& p) {
    return cv::Point(grid.x2idx(p.x), h - 1 - grid.y2idx(p.y));
  };
  for (size_t i = 1; i < path.size(); ++i) {
    cv::line(image, pixel(path[i - 1]), pixel(path[i]), cv::Scalar(255, 80, 0), 1, cv::LINE_AA);
  }
  for (const auto& l : loops) {
    cv::line(image, pixel(l.first), pixel(l.second), cv::Scalar(0, 0, 255), 1, cv::LINE_AA);
  }
  if (!cv::imwrite(png_path, image)) throw std::runtime_error(png_path + ": cannot write");
}

}  // namespace wheelchair_slam
