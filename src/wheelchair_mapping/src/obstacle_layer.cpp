#include <wheelchair_core/ray_trace.h>
#include <wheelchair_mapping/obstacle_layer.h>
#include <wheelchair_mapping/scan_checks.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace wheelchair_mapping {
namespace {

double logit(double p) { return std::log(p / (1.0 - p)); }

}  // namespace

std::string ObstacleLayerConfig::validate() const {
  const std::string model_problem = model.validate();
  return wheelchair_core::ConfigChecks()
      .check(model_problem.empty(), model_problem)
      .check(obstacle_probability > 0.5 && obstacle_probability < max_probability,
             "obstacle_probability must be in (0.5, max_probability)")
      .check(max_probability < 1.0, "max_probability must be below 1")
      .positive("forget_time", forget_time)
      .nonNegative("map_margin", map_margin)
      .result();
}

void readObstacleLayerConfig(wheelchair_core::ConfigReader& r, ObstacleLayerConfig& c) {
  r.read("p_occ_hit", c.model.p_occ_hit);
  r.read("p_occ_pass", c.model.p_occ_pass);
  r.read("max_insertion_range", c.model.max_insertion_range);
  r.read("no_return_is_free", c.model.no_return_is_free);
  r.read("no_return_range", c.model.no_return_range);
  r.read("obstacle_probability", c.obstacle_probability);
  r.read("max_probability", c.max_probability);
  r.read("forget_time", c.forget_time);
  r.read("map_margin", c.map_margin);
}

ObstacleLayer::ObstacleLayer(const wheelchair_core::OccupancyMap& map,
                             const ObstacleLayerConfig& config)
    : config_(config) {
  const std::string problem = config.validate();
  if (!problem.empty()) throw std::invalid_argument("obstacle layer: " + problem);
  if (map.width <= 0 || map.height <= 0 || !(map.resolution > 0.0) ||
      map.data.size() != static_cast<size_t>(map.width) * map.height || map.origin_yaw != 0.0 ||
      !std::isfinite(map.origin_x) || !std::isfinite(map.origin_y)) {
    throw std::invalid_argument("obstacle layer: the static map is empty, inconsistent or rotated");
  }
  geometry_ = map;
  geometry_.data.clear();
  const size_t n = map.data.size();
  near_map_.assign(n, 0);
  logodds_.assign(n, 0.0f);
  active_flag_.assign(n, 0);
  updated_in_.assign(n, 0);
  // Every cell within map_margin (centre to centre, plus half a cell) of a static obstacle.
  const double reach = config.map_margin / map.resolution + 0.5;
  const int r = static_cast<int>(std::floor(reach));
  for (int iy = 0; iy < map.height; ++iy) {
    for (int ix = 0; ix < map.width; ++ix) {
      if (map.at(ix, iy) < wheelchair_core::kOccupied) continue;
      for (int dy = -r; dy <= r; ++dy)
        for (int dx = -r; dx <= r; ++dx)
          if (dx * dx + dy * dy <= reach * reach && map.inBounds(ix + dx, iy + dy))
            near_map_[static_cast<size_t>(iy + dy) * map.width + ix + dx] = 1;
    }
  }
  // Eq. (1) in log-odds form: logit of elfesUpdate(p_s, p) = logit(p_s) + logit(p).
  logodds_hit_ = logit(config.model.p_occ_hit);
  logodds_pass_ = logit(config.model.p_occ_pass);
  logodds_obstacle_ = logit(config.obstacle_probability);
  logodds_max_ = logit(config.max_probability);
  decay_rate_ = std::log(logodds_max_ / logodds_obstacle_) / config.forget_time;
}

void ObstacleLayer::touch(size_t k) {
  if (active_flag_[k]) return;
  active_flag_[k] = 1;
  active_.push_back(k);
}

void ObstacleLayer::update(size_t k, double l) {
  logodds_[k] = static_cast<float>(std::clamp(logodds_[k] + l, -logodds_max_, logodds_max_));
  touch(k);
}

void ObstacleLayer::decayTo(double stamp) {
  if (!(stamp > decay_stamp_)) return;
  if (decay_stamp_ > -1e299) {
    const auto f = static_cast<float>(std::exp(-decay_rate_ * (stamp - decay_stamp_)));
    size_t kept = 0;
    for (const size_t k : active_) {
      logodds_[k] *= f;
      if (std::abs(logodds_[k]) < 1e-3f) {  // back at the prior
        logodds_[k] = 0.0f;
        active_flag_[k] = 0;
      } else {
        active_[kept++] = k;
      }
    }
    active_.resize(kept);
  }
  decay_stamp_ = stamp;
}

InsertResult ObstacleLayer::insert(const wheelchair_core::LaserScan2D& scan,
                                   const wheelchair_core::Pose2D& pose) {
  InsertResult result;
  result.reason = scanInsertProblem(scan, pose, 0, last_stamp_);
  if (!result.reason.empty()) return result;
  last_stamp_ = scan.stamp;
  decayTo(scan.stamp);  // nothing if the layer was already decayed beyond it (decayTo(now))
  // One eq. (1) update per cell and scan (several beams reach a near cell): returns first, then
  // the cells the beams passed that no return of this scan marked.
  ++scan_count_;
  const double res = geometry_.resolution;
  const double gx0 = (pose.x - geometry_.origin_x) / res;
  const double gy0 = (pose.y - geometry_.origin_y) / res;
  std::vector<BeamUse> uses(scan.ranges.size());
  const auto end = [&](size_t i, double& gx, double& gy) {
    const double a = pose.yaw + scan.angle_min + i * scan.angle_increment;
    gx = gx0 + uses[i].length * std::cos(a) / res;
    gy = gy0 + uses[i].length * std::sin(a) / res;
  };
  for (size_t i = 0; i < uses.size(); ++i) {
    uses[i] = useOfBeam(scan.ranges[i], scan, config_.model);
    if (uses[i].kind == BeamUse::kSkip) continue;
    ++result.beams_used;
    if (uses[i].kind != BeamUse::kHit) continue;
    double gx, gy;
    end(i, gx, gy);
    const int ix = static_cast<int>(std::floor(gx)), iy = static_cast<int>(std::floor(gy));
    if (!geometry_.inBounds(ix, iy)) continue;
    const size_t k = static_cast<size_t>(iy) * geometry_.width + ix;
    if (updated_in_[k] == scan_count_) continue;
    updated_in_[k] = scan_count_;
    if (!near_map_[k]) update(k, logodds_hit_);
  }
  for (size_t i = 0; i < uses.size(); ++i) {
    if (uses[i].kind == BeamUse::kSkip) continue;
    double gx, gy;
    end(i, gx, gy);
    const bool hit = uses[i].kind == BeamUse::kHit;
    wheelchair_core::traceCells(gx0, gy0, gx, gy, [&](int ix, int iy, bool last) {
      if ((hit && last) || !geometry_.inBounds(ix, iy)) return;
      const size_t k = static_cast<size_t>(iy) * geometry_.width + ix;
      if (updated_in_[k] == scan_count_) return;
      updated_in_[k] = scan_count_;
      update(k, logodds_pass_);
    });
  }
  if (result.beams_used == 0) {
    result.reason = "no usable beam (all NaN, -inf or out of range)";
    return result;
  }
  result.inserted = true;
  return result;
}

double ObstacleLayer::probability(int ix, int iy) const {
  const double l = logodds_[static_cast<size_t>(iy) * geometry_.width + ix];
  return 1.0 / (1.0 + std::exp(-l));
}

bool ObstacleLayer::isObstacle(int ix, int iy) const {
  return logodds_[static_cast<size_t>(iy) * geometry_.width + ix] >= logodds_obstacle_;
}

size_t ObstacleLayer::obstacleCount() const {
  size_t count = 0;
  for (const size_t k : active_) count += logodds_[k] >= logodds_obstacle_ ? 1 : 0;
  return count;
}

wheelchair_core::OccupancyMap ObstacleLayer::layer() const {
  wheelchair_core::OccupancyMap out = geometry_;
  out.data.assign(logodds_.size(), wheelchair_core::kUnknown);
  for (const size_t k : active_) {
    if (logodds_[k] >= logodds_obstacle_) {
      out.data[k] = wheelchair_core::kOccupied;
    } else if (logodds_[k] < 0.0f) {
      out.data[k] = wheelchair_core::kFree;
    }
  }
  return out;
}

}  // namespace wheelchair_mapping
