// scratch: inlier share at the reference poses, build_map map vs MRPT default insertion
#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <wheelchair_core/map_io.h>
#include <wheelchair_kld/localization_map.h>
#include <wheelchair_kld/measurement_model.h>
#include <wheelchair_logs/carmen_log.h>
#include <wheelchair_mapping/bayes_mapper.h>
#include <wheelchair_mapping/mrpt_conversions.h>
#include <algorithm>
#include <cmath>
#include <iostream>
#include <memory>
using namespace wheelchair_kld;
using wheelchair_core::LaserScan2D;
using wheelchair_core::Pose2D;
struct S {
  LaserScan2D scan;
  Pose2D pose;
};
std::vector<S> load(const std::string& p) {
  wheelchair_logs::CarmenOptions o;
  o.range_min = 0.05;
  o.range_max = 50.0;
  wheelchair_logs::CarmenLogReader r(p, o);
  std::vector<S> out;
  for (wheelchair_logs::LogScan s; r.next(s);) out.push_back({s.scan, s.laser_pose});
  return out;
}
mrpt::obs::CObservation2DRangeScan::Ptr obs(const LaserScan2D& s) {
  auto o = mrpt::obs::CObservation2DRangeScan::Create();
  o->aperture = static_cast<float>(s.angle_increment * (s.ranges.size() - 1));
  o->rightToLeft = true;
  o->maxRange = s.range_max;
  o->resizeScan(s.ranges.size());
  for (size_t i = 0; i < s.ranges.size(); ++i) {
    const bool ok = std::isfinite(s.ranges[i]) && s.ranges[i] < s.range_max;
    o->setScanRange(i, ok ? s.ranges[i] : s.range_max);
    o->setScanRangeValidity(i, ok);
  }
  return o;
}
int main(int argc, char** argv) {
  const std::string mapsrc = argv[1], maplog = argv[2], reflog = argv[3];
  const int step = std::atoi(argv[4]);
  mrpt::maps::COccupancyGridMap2D grid;
  if (mapsrc == "mrpt" || mapsrc == "mrpt_trinary") {
    grid = mrpt::maps::COccupancyGridMap2D(-10, 10, -10, 10, 0.05f);
    grid.insertionOptions.maxDistanceInsertion = 30.0f;
    for (auto& s : load(maplog))
      grid.insertObservation(*obs(s.scan),
                             mrpt::poses::CPose3D(s.pose.x, s.pose.y, 0, s.pose.yaw, 0, 0));
    if (mapsrc == "mrpt_trinary")
      grid = wheelchair_mapping::toMrptGrid(wheelchair_mapping::fromMrptGrid(grid));
  } else if (mapsrc.rfind("bayes", 0) == 0) {
    wheelchair_mapping::MapperConfig c;
    int nf = 0;
    std::sscanf(mapsrc.c_str(), "bayes:%lf:%lf:%lf:%d", &c.model.p_occ_hit, &c.model.p_occ_pass,
                &c.model.max_insertion_range, &nf);
    c.model.no_return_is_free = nf;
    wheelchair_mapping::BayesMapper mapper(c);
    for (auto& s : load(maplog)) mapper.insert(s.scan, s.pose);
    grid = wheelchair_mapping::toMrptGrid(mapper.map());
  } else {
    grid = wheelchair_mapping::toMrptGrid(wheelchair_core::loadMap(mapsrc));
  }
  KldParams kp;
  kp.measurement.beam_step = step;
  LocalizationMap map(grid, kp.measurement.max_distance);
  MeasurementModel m(map, kp.measurement);
  std::vector<double> f, fbest;
  for (auto& s : load(reflog)) {
    m.setScan(s.scan, Pose2D{0, 0, 0});
    f.push_back(m.inlierFraction({s.pose.x, s.pose.y, s.pose.yaw}, 0.15));
    double b = 0;
    for (double dx = -0.1; dx <= 0.101; dx += 0.05)
      for (double dy = -0.1; dy <= 0.101; dy += 0.05)
        for (double dt = -0.04; dt <= 0.041; dt += 0.02)
          b = std::max(b, m.inlierFraction({s.pose.x + dx, s.pose.y + dy, s.pose.yaw + dt}, 0.15));
    fbest.push_back(b);
  }
  for (auto* v : {&f, &fbest}) {
    auto x = *v;
    std::sort(x.begin(), x.end());
    double mean = 0;
    for (double a : x) mean += a;
    mean /= x.size();
    size_t lo85 = std::count_if(x.begin(), x.end(), [](double a) { return a < 0.85; });
    size_t lo7 = std::count_if(x.begin(), x.end(), [](double a) { return a < 0.7; });
    std::printf("%s n=%zu mean %.3f min %.3f p1 %.3f p5 %.3f <0.85 %.1f%% <0.7 %.1f%%\n",
                v == &f ? "at ref " : "best nb", x.size(), mean, x[0], x[x.size() / 100],
                x[x.size() / 20], 100.0 * lo85 / x.size(), 100.0 * lo7 / x.size());
  }
}
