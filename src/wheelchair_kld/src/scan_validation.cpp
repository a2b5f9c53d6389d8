#include <wheelchair_kld/scan_validation.h>

#include <sstream>

namespace wheelchair_kld {

using wheelchair_core::Beam;

std::string validateScan(const wheelchair_core::LaserScan2D& scan, int expected_beams,
                         double min_echo_fraction) {
  std::ostringstream why;
  if (!scan.ranges.empty() && expected_beams > 0 &&
      static_cast<int>(scan.ranges.size()) != expected_beams) {
    why << "scan has " << scan.ranges.size() << " beams, expected " << expected_beams;
    return why.str();
  }
  const std::string geometry = wheelchair_core::scanGeometryProblem(scan);
  if (!geometry.empty()) return geometry;
  for (size_t i = 0; i < scan.ranges.size(); ++i) {
    const Beam beam = wheelchair_core::classifyBeam(scan.ranges[i], scan);
    if (beam == Beam::kInvalid || beam == Beam::kTooClose) {
      why << "scan range " << i << " is " << scan.ranges[i];
      return why.str();
    }
  }
  const size_t echoes = wheelchair_core::countReturns(scan);
  if (echoes < min_echo_fraction * scan.ranges.size()) {
    why << "only " << echoes << " of " << scan.ranges.size() << " beams have an echo";
    return why.str();
  }
  return "";
}

}  // namespace wheelchair_kld
