// The chair's footprint polygon against the map: the clearance of the oriented polygon to the
// nearest obstacle cell, from the C-space's distance field (boundary sampled at half a cell,
// interior checked column by column). Cheap enough for ~10^5 calls per plan.
#pragma once

#include <wheelchair_harmonic_planner/config_space.h>
#include <wheelchair_harmonic_planner/plan_types.h>

#include <array>
#include <string>
#include <vector>

namespace wheelchair_harmonic_planner {

/// A polygon vertex in base_link [m] (x forward, y left).
using Vertex = std::array<double, 2>;

/// Parses "x,y;x,y;..." (at least 3 finite vertices); throws std::invalid_argument otherwise.
std::vector<Vertex> parseFootprint(const std::string& text);
/// The inverse of parseFootprint.
std::string formatFootprint(const std::vector<Vertex>& polygon);

/// Where the footprint is closest to an obstacle.
struct FootprintContact {
  double clearance = 0.0;  ///< [m], <= 0: the body overlaps an obstacle cell
  double x = 0.0;          ///< the body point nearest to the obstacle (map frame) [m]
  double y = 0.0;
};

class FootprintChecker {
 public:
  /// `cspace` must outlive the checker. Throws std::invalid_argument on a bad polygon.
  FootprintChecker(const ConfigSpace& cspace, const std::vector<Vertex>& polygon);

  /// Clearance of the footprint at `pose` to the nearest obstacle cell edge [m] (unknown cells
  /// and the outside of the map are obstacles as in the C-space). Boundary samples are at most
  /// half a cell apart and bilinearly interpolated (error below ~1 cm); an obstacle cell inside
  /// the polygon gives -resolution. Stops early once below `stop_below` (then the value is only
  /// known to be below it), and returns a lower bound at once when the disc about base_link
  /// that encloses the body, or else every disc of a cover of the body by a few smaller discs,
  /// is clear by at least `enough`.
  FootprintContact clearance(const Pose2D& pose, double stop_below = -1e9,
                             double enough = 1e9) const;

  const std::vector<Vertex>& polygon() const { return polygon_; }
  /// Largest distance of a footprint vertex from base_link [m] (e.g. tail swing radius).
  double circumscribedRadius() const { return circumscribed_radius_; }
  /// Radius of the largest disc about base_link inside the polygon [m].
  double inscribedRadius() const { return inscribed_radius_; }
  const ConfigSpace& configSpace() const { return cspace_; }

 private:
  /// Interior sample points of one column; `centre` certifies all of them when the distance
  /// there is at least `radius`.
  struct Column {
    Vertex centre;
    double radius = 0.0;
    std::vector<Vertex> points;
  };
  /// A disc in base_link; the cover's discs together contain the polygon.
  struct Disc {
    Vertex centre;
    double radius = 0.0;
  };
  /// Lower bound of the clearance from the cover: the smallest disc clearance, with its centre.
  FootprintContact coverBound(const Pose2D& pose, double c, double s) const;

  const ConfigSpace& cspace_;
  std::vector<Vertex> polygon_;
  std::vector<Vertex> boundary_;  ///< boundary samples in base_link
  std::vector<Column> columns_;
  std::vector<Disc> cover_;  ///< slabs along x about half the body's width long
  double circumscribed_radius_ = 0.0;
  double inscribed_radius_ = 0.0;
};

}  // namespace wheelchair_harmonic_planner
