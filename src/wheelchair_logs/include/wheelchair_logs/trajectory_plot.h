// A PNG of trajectories over their map (north up): e.g. a localizer's estimate (red) against
// the reference (green), with marks where something happened (a re-localization).
#pragma once

#include <wheelchair_core/occupancy_map.h>
#include <wheelchair_core/pose2d.h>

#include <string>
#include <vector>

namespace wheelchair_logs {

struct PlotPath {
  std::string label;
  unsigned char r = 0, g = 0, b = 0;
  std::vector<wheelchair_core::Pose2D> poses;  ///< drawn as a polyline
  std::vector<wheelchair_core::Pose2D> marks;  ///< drawn as circles
};

/// The map (white free, black occupied, grey unknown), each path in its colour with its label
/// in a legend. Throws std::runtime_error if the file cannot be written.
void saveTrajectoryPlot(const wheelchair_core::OccupancyMap& map,
                        const std::vector<PlotPath>& paths, const std::string& png_path);

}  // namespace wheelchair_logs
