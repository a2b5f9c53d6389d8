// Checks every planner makes before planning: the map is there, start and goal are finite,
// inside the map and in free C-space. Failure reasons name the pose and the cause.
#pragma once

#include <wheelchair_planner/certificate.h>
#include <wheelchair_planner/config_space.h>

#include <string>

namespace wheelchair_planner {

/// On success returns true and the cells of start and goal; otherwise false and `reason`.
bool checkEndpoints(const ConfigSpace* cspace, const Pose2D& start, const Pose2D& goal, int& sx,
                    int& sy, int& gx, int& gy, std::string& reason);

}  // namespace wheelchair_planner
