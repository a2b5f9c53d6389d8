#include <wheelchair_logs/reference.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>

namespace wheelchair_logs {

ReferenceMatch referenceMatchFromName(const std::string& name) {
  if (name == "readings") return ReferenceMatch::kReadings;
  if (name == "stamp") return ReferenceMatch::kStamp;
  throw std::invalid_argument("unknown reference matching '" + name + "' (readings or stamp)");
}

uint64_t readingsHash(const wheelchair_core::LaserScan2D& scan) {
  uint64_t h = 1469598103934665603ull;  // FNV-1a over the readings' bits
  for (float r : scan.ranges) {
    if (std::isinf(r)) r = INFINITY;
    uint32_t bits = 0;
    std::memcpy(&bits, &r, sizeof bits);
    for (int k = 0; k < 4; ++k) {
      h ^= (bits >> (8 * k)) & 0xffu;
      h *= 1099511628211ull;
    }
  }
  return h;
}

bool sameReadings(const wheelchair_core::LaserScan2D& a, const wheelchair_core::LaserScan2D& b) {
  return a.ranges.size() == b.ranges.size() &&
         std::equal(a.ranges.begin(), a.ranges.end(), b.ranges.begin(), [](float x, float y) {
           return x == y || (std::isinf(x) && std::isinf(y) && (x > 0) == (y > 0));
         });
}

ReferenceTrajectory::ReferenceTrajectory(std::vector<LogScan> scans) : scans_(std::move(scans)) {
  std::stable_sort(scans_.begin(), scans_.end(),
                   [](const LogScan& a, const LogScan& b) { return a.scan.stamp < b.scan.stamp; });
  for (size_t i = 0; i < scans_.size(); ++i) by_readings_.emplace(readingsHash(scans_[i].scan), i);
}

const LogScan* ReferenceTrajectory::match(const LogScan& scan, ReferenceMatch how, double offset,
                                          double tolerance) {
  if (how == ReferenceMatch::kReadings) {
    const auto [first, last] = by_readings_.equal_range(readingsHash(scan.scan));
    size_t best = scans_.size(), earliest = scans_.size();
    for (auto it = first; it != last; ++it) {
      if (!sameReadings(scans_[it->second].scan, scan.scan)) continue;
      earliest = std::min(earliest, it->second);
      if (it->second >= last_match_) best = std::min(best, it->second);
    }
    if (best == scans_.size()) best = earliest;
    if (best == scans_.size()) return nullptr;
    last_match_ = best;
    return &scans_[best];
  }
  const double t = scan.scan.stamp + offset;
  const auto it = std::lower_bound(scans_.begin(), scans_.end(), t,
                                   [](const LogScan& s, double v) { return s.scan.stamp < v; });
  const LogScan* best = nullptr;
  double best_dt = tolerance;
  for (auto c : {it - (it == scans_.begin() ? 0 : 1), it}) {
    if (c == scans_.end()) continue;
    const double dt = std::abs(c->scan.stamp - t);
    if (dt <= best_dt) {
      best_dt = dt;
      best = &*c;
    }
  }
  return best;
}

PoseErrors poseErrors(const std::vector<PosePair>& pairs) {
  PoseErrors e;
  e.count = pairs.size();
  if (pairs.empty()) return e;
  double sxy = 0, sth = 0, sxy2 = 0, sth2 = 0;
  for (const PosePair& p : pairs) {
    const double d = std::hypot(p.estimate.x - p.reference.x, p.estimate.y - p.reference.y);
    const double a = std::abs(wheelchair_core::angleDifference(p.estimate.yaw, p.reference.yaw));
    sxy += d;
    sxy2 += d * d;
    sth += a;
    sth2 += a * a;
    e.position_max = std::max(e.position_max, d);
    e.heading_max = std::max(e.heading_max, a);
  }
  const double n = static_cast<double>(pairs.size());
  e.position_mean = sxy / n;
  e.position_rms = std::sqrt(sxy2 / n);
  e.heading_mean = sth / n;
  e.heading_rms = std::sqrt(sth2 / n);
  return e;
}

}  // namespace wheelchair_logs
