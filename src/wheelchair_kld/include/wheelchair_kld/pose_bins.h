// The histogram H of Algorithm 1: which (x, y, theta) bins hold at least one particle.
#pragma once

#include <mrpt/math/TPose2D.h>

#include <cstdint>
#include <unordered_set>

namespace wheelchair_kld {

class PoseBins {
 public:
  PoseBins(double bin_xy, double bin_theta);
  /// Marks the bin of `pose` non-empty; true if it was empty (Algorithm 1, lines 10-12).
  bool insert(const mrpt::math::TPose2D& pose);
  /// k: number of non-empty bins.
  int count() const { return static_cast<int>(occupied_.size()); }

 private:
  double inv_xy_, inv_theta_;
  std::unordered_set<int64_t> occupied_;
};

}  // namespace wheelchair_kld
