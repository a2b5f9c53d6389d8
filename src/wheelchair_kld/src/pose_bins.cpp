#include <mrpt/math/wrap2pi.h>
#include <wheelchair_kld/pose_bins.h>

#include <cmath>

namespace wheelchair_kld {

PoseBins::PoseBins(double bin_xy, double bin_theta)
    : inv_xy_(1.0 / bin_xy), inv_theta_(1.0 / bin_theta) {
  occupied_.reserve(4096);
}

bool PoseBins::insert(const mrpt::math::TPose2D& pose) {
  const int64_t ix = static_cast<int64_t>(std::floor(pose.x * inv_xy_)) + (1 << 20);
  const int64_t iy = static_cast<int64_t>(std::floor(pose.y * inv_xy_)) + (1 << 20);
  const int64_t it = static_cast<int64_t>(std::floor(mrpt::math::wrapTo2Pi(pose.phi) * inv_theta_));
  return occupied_.insert((ix << 42) | (iy << 20) | it).second;
}

}  // namespace wheelchair_kld
