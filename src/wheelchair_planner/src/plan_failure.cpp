#include <wheelchair_planner/plan_failure.h>

#include <cmath>
#include <sstream>

namespace wheelchair_planner {

namespace {

bool checkOne(const ConfigSpace& cs, const char* what, const Pose2D& p, int& ix, int& iy,
              std::string& reason) {
  std::ostringstream os;
  os.precision(3);
  os << what << " (" << p.x << ", " << p.y << ")";
  if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.yaw)) {
    reason = std::string(what) + " pose is not finite";
    return false;
  }
  if (!cs.worldToCell(p.x, p.y, ix, iy)) {
    reason = os.str() + " is outside the map";
    return false;
  }
  if (!cs.isFree(ix, iy)) {
    const double c = cs.clearanceAt(p.x, p.y);
    os << (c <= 0.0 ? " is in an obstacle" : " is too close to an obstacle") << " (clearance " << c
       << " m, minimum " << cs.params().min_clearance << " m)";
    reason = os.str();
    return false;
  }
  return true;
}

}  // namespace

bool checkEndpoints(const ConfigSpace* cs, const Pose2D& start, const Pose2D& goal, int& sx,
                    int& sy, int& gx, int& gy, std::string& reason) {
  if (cs == nullptr) {
    reason = "planner has no map (initialize was not called)";
    return false;
  }
  return checkOne(*cs, "start", start, sx, sy, reason) &&
         checkOne(*cs, "goal", goal, gx, gy, reason);
}

}  // namespace wheelchair_planner
