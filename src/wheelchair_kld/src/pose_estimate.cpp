#include <mrpt/math/wrap2pi.h>
#include <wheelchair_kld/pose_estimate.h>

#include <cmath>
#include <cstdint>
#include <deque>
#include <unordered_map>

namespace wheelchair_kld {

namespace {
struct Cell {
  int ix, iy, it;
};
int64_t cellKey(int ix, int iy, int it) {
  return (static_cast<int64_t>(ix + (1 << 20)) << 42) |
         (static_cast<int64_t>(iy + (1 << 20)) << 20) | static_cast<int64_t>(it);
}
}  // namespace

PoseEstimate estimateDominantCluster(const std::vector<Particle>& particles, double cell_xy,
                                     double cell_theta) {
  PoseEstimate est;
  if (particles.empty()) return est;
  const int n_theta = std::max(1, static_cast<int>(std::ceil(2 * M_PI / cell_theta)));
  // Cell of every particle, and the cell -> cluster map.
  std::unordered_map<int64_t, int> cluster_of;  // -1: not yet labelled
  std::vector<int64_t> keys(particles.size());
  std::unordered_map<int64_t, Cell> cells;
  for (size_t i = 0; i < particles.size(); ++i) {
    const auto& p = particles[i].d;
    const Cell c{
        static_cast<int>(std::floor(p.x / cell_xy)), static_cast<int>(std::floor(p.y / cell_xy)),
        static_cast<int>(std::floor((mrpt::math::wrapTo2Pi(p.phi)) / cell_theta)) % n_theta};
    keys[i] = cellKey(c.ix, c.iy, c.it);
    if (cells.emplace(keys[i], c).second) cluster_of[keys[i]] = -1;
  }
  int clusters = 0;
  for (const auto& kv : cells) {
    if (cluster_of[kv.first] >= 0) continue;
    std::deque<Cell> open{kv.second};
    cluster_of[kv.first] = clusters;
    while (!open.empty()) {
      const Cell c = open.front();
      open.pop_front();
      for (int dx = -1; dx <= 1; ++dx)
        for (int dy = -1; dy <= 1; ++dy)
          for (int dt = -1; dt <= 1; ++dt) {
            const Cell nb{c.ix + dx, c.iy + dy, (c.it + dt + n_theta) % n_theta};
            const auto it = cluster_of.find(cellKey(nb.ix, nb.iy, nb.it));
            if (it == cluster_of.end() || it->second >= 0) continue;
            it->second = clusters;
            open.push_back(nb);
          }
    }
    ++clusters;
  }
  est.cluster_weights.assign(clusters, 0.0);
  est.particle_cluster.resize(particles.size());
  double total = 0;
  for (size_t i = 0; i < particles.size(); ++i) {
    const double w = std::exp(particles[i].log_w);
    est.particle_cluster[i] = cluster_of[keys[i]];
    est.cluster_weights[est.particle_cluster[i]] += w;
    total += w;
  }
  if (!(total > 0)) return est;
  int best = 0;
  for (int c = 0; c < clusters; ++c) {
    est.cluster_weights[c] /= total;
    if (est.cluster_weights[c] > est.cluster_weights[best]) best = c;
    if (est.cluster_weights[c] >= 0.01) ++est.cluster_count;
  }
  est.best_cluster = best;
  est.cluster_weight = est.cluster_weights[best];
  // Weighted mean and covariance of the dominant cluster.
  est.mean = clusterMean(particles, est, best);
  double sw = 0;
  est.cov.setZero();
  for (size_t i = 0; i < particles.size(); ++i) {
    if (est.particle_cluster[i] != best) continue;
    const double w = std::exp(particles[i].log_w);
    const auto& p = particles[i].d;
    const double e[3] = {p.x - est.mean.x, p.y - est.mean.y,
                         mrpt::math::wrapToPi(p.phi - est.mean.yaw)};
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) est.cov(r, c) += w * e[r] * e[c];
    sw += w;
  }
  if (sw > 0) est.cov *= 1.0 / sw;
  return est;
}

wheelchair_core::Pose2D clusterMean(const std::vector<Particle>& particles, const PoseEstimate& est,
                                    int c) {
  double sx = 0, sy = 0, sc = 0, ss = 0, sw = 0;
  for (size_t i = 0; i < particles.size(); ++i) {
    if (est.particle_cluster[i] != c) continue;
    const double w = std::exp(particles[i].log_w);
    const auto& p = particles[i].d;
    sx += w * p.x;
    sy += w * p.y;
    sc += w * std::cos(p.phi);
    ss += w * std::sin(p.phi);
    sw += w;
  }
  if (!(sw > 0)) return wheelchair_core::Pose2D();
  return {sx / sw, sy / sw, std::atan2(ss, sc)};
}

}  // namespace wheelchair_kld
