#include <wheelchair_harmonic_planner/gradient_descent.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace wheelchair_harmonic_planner {

namespace {

/// log u with obstacles and unreachable cells replaced by a finite floor below every free value,
/// so that interpolation near walls points away from them.
class LogField {
 public:
  explicit LogField(const HarmonicSolution& s) : s_(s) {
    double lowest = 0.0;
    for (const double v : s.log_u)
      if (std::isfinite(v)) lowest = std::min(lowest, v);
    floor_ = lowest - 10.0;
  }
  double at(int ix, int iy) const {
    if (ix < 0 || iy < 0 || ix >= s_.width || iy >= s_.height) return floor_;
    const double v = s_.at(ix, iy);
    return std::isfinite(v) ? v : floor_;
  }
  /// Central-difference gradient at a cell centre [1/cell].
  void nodeGradient(int ix, int iy, double& dx, double& dy) const {
    dx = 0.5 * (at(ix + 1, iy) - at(ix - 1, iy));
    dy = 0.5 * (at(ix, iy + 1) - at(ix, iy - 1));
  }
  /// Bilinear interpolation of the node gradients at continuous grid coordinates.
  void gradient(double gx, double gy, double& dx, double& dy) const {
    const int x0 = static_cast<int>(std::floor(gx)), y0 = static_cast<int>(std::floor(gy));
    const double tx = gx - x0, ty = gy - y0;
    dx = dy = 0.0;
    for (int j = 0; j < 2; ++j) {
      for (int i = 0; i < 2; ++i) {
        const double wgt = (i ? tx : 1.0 - tx) * (j ? ty : 1.0 - ty);
        double nx, ny;
        nodeGradient(x0 + i, y0 + j, nx, ny);
        dx += wgt * nx;
        dy += wgt * ny;
      }
    }
  }

 private:
  const HarmonicSolution& s_;
  double floor_ = -10.0;
};

int cellOf(double g) { return static_cast<int>(std::floor(g + 0.5)); }

std::string where(const ConfigSpace& cs, double gx, double gy) {
  double x, y;
  cs.gridToWorld(gx, gy, x, y);
  std::ostringstream os;
  os.precision(3);
  os << "(" << x << ", " << y << ")";
  return os.str();
}

}  // namespace

DescentResult descend(const ConfigSpace& cs, const HarmonicSolution& sol, double start_x,
                      double start_y, const DescentParams& params) {
  DescentResult r;
  const LogField field(sol);
  double gx, gy;
  cs.worldToGrid(start_x, start_y, gx, gy);
  int cx = cellOf(gx), cy = cellOf(gy);
  if (!cs.isFree(cx, cy)) {
    r.failure_reason = "start " + where(cs, gx, gy) + " is not in free C-space";
    return r;
  }
  if (!sol.reachable(cx, cy)) {
    r.failure_reason = "start " + where(cs, gx, gy) + " is not connected to the goal";
    return r;
  }
  auto push = [&](double px, double py) {
    Pose2D p;
    cs.gridToWorld(px, py, p.x, p.y);
    r.path.push_back(p);
  };
  push(gx, gy);
  r.min_gradient = std::numeric_limits<double>::infinity();
  const long max_steps = 4L * static_cast<long>(cs.width()) * cs.height();
  int same_cell = 0;
  while (!(cx == sol.goal_ix && cy == sol.goal_iy)) {
    if (++r.steps > max_steps) {
      r.failure_reason = "descent did not reach the goal within the step limit";
      return r;
    }
    double dx, dy;
    field.gradient(gx, gy, dx, dy);
    const double norm = std::hypot(dx, dy);
    if (norm > 1e-12 && same_cell < params.max_steps_per_cell) {
      const double nx = gx + params.step_cells * dx / norm, ny = gy + params.step_cells * dy / norm;
      const int ncx = cellOf(nx), ncy = cellOf(ny);
      const bool same = ncx == cx && ncy == cy;
      if (cs.isFree(ncx, ncy) && sol.reachable(ncx, ncy) &&
          (same || field.at(ncx, ncy) > field.at(cx, cy))) {
        same_cell = same ? same_cell + 1 : 0;
        gx = nx;
        gy = ny;
        cx = ncx;
        cy = ncy;
        r.min_gradient = std::min(r.min_gradient, norm / cs.resolution());
        push(gx, gy);
        continue;
      }
    }
    // Discrete step: a free cell's log u is a weighted mean of its four neighbours, so unless it
    // is the goal one neighbour is strictly higher.
    int bx = cx, by = cy;
    const int nb[4][2] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
    for (const auto& d : nb) {
      if (sol.reachable(cx + d[0], cy + d[1]) &&
          field.at(cx + d[0], cy + d[1]) > field.at(bx, by)) {
        bx = cx + d[0];
        by = cy + d[1];
      }
    }
    if (bx == cx && by == cy) {
      r.failure_reason = "descent stopped on a plateau at " + where(cs, gx, gy);
      return r;
    }
    ++r.fallback_steps;
    same_cell = 0;
    cx = bx;
    cy = by;
    gx = cx;
    gy = cy;
    push(gx, gy);
  }
  if (!std::isfinite(r.min_gradient)) r.min_gradient = 0.0;
  r.reached_goal = true;
  return r;
}

}  // namespace wheelchair_harmonic_planner
