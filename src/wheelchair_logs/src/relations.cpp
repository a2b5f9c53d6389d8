#include <wheelchair_logs/relations.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace wheelchair_logs {

using wheelchair_core::Pose2D;

std::vector<Relation> readRelations(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path + ": cannot open the relations file");
  std::vector<Relation> out;
  std::string line;
  size_t number = 0;
  while (std::getline(in, line)) {
    ++number;
    if (line.find_first_not_of(" \t\r") == std::string::npos || line[0] == '#') continue;
    std::istringstream s(line);
    Relation r;
    double dz, droll, dpitch;
    if (!(s >> r.t1 >> r.t2 >> r.delta.x >> r.delta.y >> dz >> droll >> dpitch >> r.delta.yaw)) {
      throw std::runtime_error(path + ":" + std::to_string(number) +
                               ": expected t1 t2 dx dy dz droll dpitch dyaw");
    }
    out.push_back(r);
  }
  return out;
}

std::vector<Relation> referenceRelations(const std::vector<TimedPose>& reference, bool all_pairs) {
  std::vector<Relation> out;
  for (size_t i = 0; i < reference.size(); ++i) {
    for (size_t j = i + 1; j < (all_pairs ? reference.size() : std::min(i + 2, reference.size()));
         ++j) {
      out.push_back({reference[i].stamp, reference[j].stamp,
                     wheelchair_core::between(reference[i].pose, reference[j].pose)});
    }
  }
  return out;
}

namespace {

/// Index of the pose nearest to `stamp` within `tolerance`, or -1.
long nearest(const std::vector<TimedPose>& trajectory, double stamp, double tolerance) {
  const auto it = std::lower_bound(trajectory.begin(), trajectory.end(), stamp,
                                   [](const TimedPose& p, double t) { return p.stamp < t; });
  long best = -1;
  double best_dt = tolerance;
  for (auto c : {it - 1, it}) {
    if (c < trajectory.begin() || c >= trajectory.end()) continue;
    const double dt = std::abs(c->stamp - stamp);
    if (dt <= best_dt) {
      best_dt = dt;
      best = c - trajectory.begin();
    }
  }
  return best;
}

}  // namespace

RelationErrors relationErrors(const std::vector<Relation>& relations,
                              const std::vector<TimedPose>& trajectory, double offset,
                              double tolerance) {
  RelationErrors out;
  out.relations = relations.size();
  for (const Relation& r : relations) {
    const long a = nearest(trajectory, r.t1 - offset, tolerance);
    const long b = nearest(trajectory, r.t2 - offset, tolerance);
    if (a < 0 || b < 0 || a == b) continue;
    const Pose2D estimate = wheelchair_core::between(trajectory[a].pose, trajectory[b].pose);
    const Pose2D error = wheelchair_core::between(r.delta, estimate);
    out.translational.push_back(std::hypot(error.x, error.y));
    out.rotational.push_back(std::abs(wheelchair_core::normalizeAngle(error.yaw)));
  }
  return out;
}

ErrorSummary summarize(const std::vector<double>& values) {
  ErrorSummary s;
  s.count = values.size();
  if (values.empty()) return s;
  double sum = 0.0;
  for (double v : values) {
    sum += v;
    s.max = std::max(s.max, v);
  }
  s.mean = sum / values.size();
  double var = 0.0;
  for (double v : values) var += (v - s.mean) * (v - s.mean);
  s.std = std::sqrt(var / values.size());
  return s;
}

}  // namespace wheelchair_logs
