// Path quality figures shared by the planners, the tests and the benchmark.
#pragma once

#include <wheelchair_planner/certificate.h>
#include <wheelchair_planner/config_space.h>

#include <vector>

namespace wheelchair_planner {

double pathLength(const std::vector<Pose2D>& path);

/// Sets each pose's yaw to the direction of travel; the last pose gets `final_yaw`.
void assignHeadings(std::vector<Pose2D>& path, double final_yaw);

/// Max |heading change| / distance over the path resampled every `spacing` metres [1/m].
double maxCurvature(const std::vector<Pose2D>& path, double spacing = 0.1);

/// Fills length, curvature and the clearance profile (min and where) of a certificate.
void fillPathFigures(const ConfigSpace& cspace, const std::vector<Pose2D>& path,
                     Certificate& certificate);

/// True if every segment of the path, sampled at a quarter cell, stays in the map with the
/// minimum clearance (less half a cell of discretization): the footprint never meets a wall.
bool pathIsCollisionFree(const ConfigSpace& cspace, const std::vector<Pose2D>& path);

}  // namespace wheelchair_planner
