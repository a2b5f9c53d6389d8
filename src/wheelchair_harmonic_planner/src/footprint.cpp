#include <wheelchair_harmonic_planner/footprint.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace wheelchair_harmonic_planner {

std::vector<Vertex> parseFootprint(const std::string& text) {
  std::vector<Vertex> polygon;
  std::stringstream all(text);
  std::string vertex;
  while (std::getline(all, vertex, ';')) {
    if (vertex.find_first_not_of(" \t") == std::string::npos) continue;
    std::stringstream v(vertex);
    Vertex p{};
    char comma = 0;
    if (!(v >> p[0] >> comma >> p[1]) || comma != ',' || !std::isfinite(p[0]) ||
        !std::isfinite(p[1])) {
      throw std::invalid_argument("footprint: cannot read vertex '" + vertex +
                                  "' (expected \"x,y;x,y;...\")");
    }
    polygon.push_back(p);
  }
  if (polygon.size() < 3) throw std::invalid_argument("footprint: needs at least 3 vertices");
  return polygon;
}

std::string formatFootprint(const std::vector<Vertex>& polygon) {
  std::ostringstream os;
  os.precision(17);
  for (size_t i = 0; i < polygon.size(); ++i)
    os << (i ? ";" : "") << polygon[i][0] << "," << polygon[i][1];
  return os.str();
}

namespace {

bool insidePolygon(const std::vector<Vertex>& poly, double x, double y) {
  bool inside = false;
  for (size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++) {
    const Vertex &a = poly[i], &b = poly[j];
    if ((a[1] > y) != (b[1] > y) && x < (b[0] - a[0]) * (y - a[1]) / (b[1] - a[1]) + a[0])
      inside = !inside;
  }
  return inside;
}

double distanceToSegment(double px, double py, const Vertex& a, const Vertex& b) {
  const double dx = b[0] - a[0], dy = b[1] - a[1];
  const double len2 = dx * dx + dy * dy;
  const double t =
      len2 > 0.0 ? std::clamp(((px - a[0]) * dx + (py - a[1]) * dy) / len2, 0.0, 1.0) : 0.0;
  return std::hypot(a[0] + t * dx - px, a[1] + t * dy - py);
}

struct Box {
  double x0 = 1e9, x1 = -1e9, y0 = 1e9, y1 = -1e9;
};

Box boundingBox(const std::vector<Vertex>& points) {
  Box b;
  for (const Vertex& v : points) {
    b.x0 = std::min(b.x0, v[0]);
    b.x1 = std::max(b.x1, v[0]);
    b.y0 = std::min(b.y0, v[1]);
    b.y1 = std::max(b.y1, v[1]);
  }
  return b;
}

/// The part of the polygon with x in [x0, x1] (Sutherland-Hodgman against the two lines): its
/// vertices span a convex hull that contains that part (also for a non-convex polygon).
std::vector<Vertex> clipToSlab(const std::vector<Vertex>& poly, double x0, double x1) {
  std::vector<Vertex> out = poly;
  for (const double sign : {1.0, -1.0}) {  // keep x >= x0, then x <= x1
    const double edge = sign > 0.0 ? x0 : x1;
    std::vector<Vertex> in;
    in.swap(out);
    for (size_t i = 0; i < in.size(); ++i) {
      const Vertex& a = in[i];
      const Vertex& b = in[(i + 1) % in.size()];
      const bool a_in = sign * (a[0] - edge) >= 0.0, b_in = sign * (b[0] - edge) >= 0.0;
      if (a_in) out.push_back(a);
      if (a_in != b_in) {
        const double t = (edge - a[0]) / (b[0] - a[0]);
        out.push_back({edge, a[1] + t * (b[1] - a[1])});
      }
    }
  }
  return out;
}

}  // namespace

FootprintChecker::FootprintChecker(const ConfigSpace& cspace, const std::vector<Vertex>& polygon)
    : cspace_(cspace), polygon_(polygon) {
  if (polygon.size() < 3) throw std::invalid_argument("footprint: needs at least 3 vertices");
  if (!insidePolygon(polygon, 0.0, 0.0))
    throw std::invalid_argument("footprint: base_link (0, 0) must lie inside the polygon");
  const double res = cspace.resolution();
  // Boundary: every edge sampled at most half a cell apart, vertices included.
  inscribed_radius_ = 1e9;
  for (size_t i = 0; i < polygon.size(); ++i) {
    const Vertex& a = polygon[i];
    const Vertex& b = polygon[(i + 1) % polygon.size()];
    const double len = std::hypot(b[0] - a[0], b[1] - a[1]);
    const int n = std::max(1, static_cast<int>(std::ceil(len / (0.5 * res))));
    for (int k = 0; k < n; ++k) {
      const double t = static_cast<double>(k) / n;
      boundary_.push_back({a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])});
    }
    circumscribed_radius_ = std::max(circumscribed_radius_, std::hypot(a[0], a[1]));
    inscribed_radius_ = std::min(inscribed_radius_, distanceToSegment(0.0, 0.0, a, b));
  }
  // Interior: a lattice of 0.7 cell spacing (every cell the polygon covers holds a sample),
  // grouped in columns of constant x.
  const Box box = boundingBox(polygon);
  const double x0 = box.x0, x1 = box.x1, y0 = box.y0, y1 = box.y1;
  // Cover: slabs along x about half the body's width long, each in the disc about its bounding
  // box's centre through its farthest vertex (the maximum distance over a polygon is at one).
  const int slabs = std::max(1, static_cast<int>(std::ceil((x1 - x0) / (0.5 * (y1 - y0)))));
  for (int i = 0; i < slabs; ++i) {
    const std::vector<Vertex> part =
        clipToSlab(polygon, x0 + (x1 - x0) * i / slabs, x0 + (x1 - x0) * (i + 1) / slabs);
    if (part.empty()) continue;
    const Box b = boundingBox(part);
    Disc disc{{0.5 * (b.x0 + b.x1), 0.5 * (b.y0 + b.y1)}, 0.0};
    for (const Vertex& v : part)
      disc.radius = std::max(disc.radius, std::hypot(v[0] - disc.centre[0], v[1] - disc.centre[1]));
    cover_.push_back(disc);
  }
  const double h = 0.7 * res;
  for (double x = x0 + 0.5 * h; x < x1; x += h) {
    Column col;
    for (double y = y0 + 0.5 * h; y < y1; y += h)
      if (insidePolygon(polygon, x, y)) col.points.push_back({x, y});
    if (col.points.empty()) continue;
    col.centre = {x, 0.5 * (col.points.front()[1] + col.points.back()[1])};
    for (const Vertex& p : col.points)
      col.radius = std::max(col.radius, std::hypot(p[0] - col.centre[0], p[1] - col.centre[1]));
    columns_.push_back(std::move(col));
  }
}

FootprintContact FootprintChecker::clearance(const Pose2D& pose, double stop_below,
                                             double enough) const {
  // The enclosing disc (less the interpolation error): a lower bound of the body's clearance.
  const double bound =
      cspace_.distanceAt(pose.x, pose.y) - circumscribed_radius_ - 0.5 * cspace_.resolution();
  if (bound >= enough) return {bound, pose.x, pose.y};
  const double c = std::cos(pose.yaw), s = std::sin(pose.yaw);
  if (enough < 1e9) {
    const FootprintContact covered = coverBound(pose, c, s);
    if (covered.clearance >= enough) return covered;
  }
  FootprintContact best;
  best.clearance = 1e9;
  for (const Vertex& v : boundary_) {
    const double x = pose.x + c * v[0] - s * v[1], y = pose.y + s * v[0] + c * v[1];
    const double d = cspace_.distanceAt(x, y);
    if (d < best.clearance) {
      best = {d, x, y};
      if (d < stop_below) return best;
    }
  }
  // An obstacle cell wholly inside the body: the boundary does not see it, the interior does.
  for (const Column& col : columns_) {
    const double cx = pose.x + c * col.centre[0] - s * col.centre[1];
    const double cy = pose.y + s * col.centre[0] + c * col.centre[1];
    if (cspace_.cellDistanceAt(cx, cy) >= col.radius) continue;  // the whole column is free
    for (const Vertex& v : col.points) {
      const double x = pose.x + c * v[0] - s * v[1], y = pose.y + s * v[0] + c * v[1];
      if (cspace_.cellDistanceAt(x, y) <= 0.0) return {-cspace_.resolution(), x, y};
    }
  }
  return best;
}

FootprintContact FootprintChecker::coverBound(const Pose2D& pose, double c, double s) const {
  // A body point within r of a disc centre is at least (distance there - r) from obstacles;
  // half a cell less for the bilinear interpolation, as for the enclosing disc.
  FootprintContact worst;
  worst.clearance = 1e9;
  for (const Disc& d : cover_) {
    const double x = pose.x + c * d.centre[0] - s * d.centre[1];
    const double y = pose.y + s * d.centre[0] + c * d.centre[1];
    const double bound = cspace_.distanceAt(x, y) - d.radius - 0.5 * cspace_.resolution();
    if (bound < worst.clearance) worst = {bound, x, y};
  }
  return worst;
}

}  // namespace wheelchair_harmonic_planner
