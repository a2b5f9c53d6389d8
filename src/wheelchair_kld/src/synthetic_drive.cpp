#include <mrpt/math/wrap2pi.h>
#include <mrpt/poses/CPose2D.h>
#include <mrpt/poses/CPose3D.h>
#include <mrpt/random/RandomGenerators.h>
#include <wheelchair_kld/localization_map.h>
#include <wheelchair_kld/synthetic_drive.h>

#include <cmath>
#include <stdexcept>

namespace wheelchair_kld {

using mrpt::math::TPose2D;

namespace {
struct Canvas {
  GridData g;
  Canvas(double w, double h) {
    g.resolution = 0.05;
    g.width = static_cast<int>(std::lround(w / g.resolution));
    g.height = static_cast<int>(std::lround(h / g.resolution));
    g.data.assign(static_cast<size_t>(g.width) * g.height, 0);
    box(0, 0, w, 0.1);
    box(0, h - 0.1, w, h);
    box(0, 0, 0.1, h);
    box(w - 0.1, 0, w, h);
  }
  /// Fills the axis-aligned rectangle [x0, x1] x [y0, y1] with obstacle.
  void box(double x0, double y0, double x1, double y1) {
    for (int iy = static_cast<int>(std::lround(y0 / g.resolution));
         iy < std::lround(y1 / g.resolution); ++iy)
      for (int ix = static_cast<int>(std::lround(x0 / g.resolution));
           ix < std::lround(x1 / g.resolution); ++ix)
        if (ix >= 0 && iy >= 0 && ix < g.width && iy < g.height)
          g.data[static_cast<size_t>(iy) * g.width + ix] = 100;
  }
};
}  // namespace

mrpt::maps::COccupancyGridMap2D makeBuiltinWorld(const std::string& name) {
  if (name == "flat") {  // a small apartment: hall, living room, bedroom, kitchen
    Canvas c(10, 7);
    c.box(4, 0, 4.1, 2.5);
    c.box(4, 3.5, 4.1, 7);
    c.box(0, 4, 2.5, 4.1);
    c.box(7, 3, 10, 3.1);
    c.box(6, 5, 6.6, 6.2);  // table
    c.box(1, 1, 2.2, 1.6);  // bed
    c.box(8.5, 0.1, 9.9, 0.7);
    return toMrptGrid(c.g);
  }
  if (name == "office") {  // corridor with offices of different furniture
    Canvas c(20, 12);
    c.box(0, 4, 6, 4.1);
    c.box(7, 4, 13, 4.1);
    c.box(14, 4, 20, 4.1);
    c.box(0, 7, 3, 7.1);
    c.box(4, 7, 11, 7.1);
    c.box(12, 7, 20, 7.1);
    c.box(8, 7, 8.1, 12);
    c.box(15, 7, 15.1, 12);
    c.box(10, 0, 10.1, 4);
    c.box(1, 1, 3, 2);
    c.box(12, 1.5, 12.5, 2.5);
    c.box(16, 0.5, 19, 1.2);
    c.box(2, 9.5, 2.8, 11.9);
    c.box(10, 9, 12, 10);
    c.box(17, 10, 18, 11);
    c.box(5.5, 5.3, 5.8, 5.6);
    return toMrptGrid(c.g);
  }
  if (name == "symmetric") {  // invariant under a 180 deg rotation about its centre
    Canvas c(10, 6);
    c.box(2, 1.5, 2.5, 2);
    c.box(7.5, 4, 8, 4.5);
    c.box(2, 4, 2.5, 4.5);
    c.box(7.5, 1.5, 8, 2);
    c.box(4.5, 2.9, 5.5, 3.1);
    return toMrptGrid(c.g);
  }
  throw std::invalid_argument("unknown built-in world '" + name + "'");
}

std::vector<TPose2D> builtinRoute(const std::string& name) {
  if (name == "flat")
    return {{1, 3, 0},     {3.5, 3, 0},   {5.5, 3, 0}, {5.5, 1.5, 0}, {8, 1.5, 0}, {6.5, 2, 0},
            {6.5, 4.5, 0}, {8.5, 4.5, 0}, {4.5, 3, 0}, {3, 3, 0},     {3, 5.5, 0}};
  if (name == "office")
    return {{1, 5.5, 0},    {6.5, 5.5, 0},  {6.5, 2.5, 0},  {9, 2.5, 0},    {6.6, 3, 0},
            {6.6, 5.5, 0},  {11.5, 5.5, 0}, {11.5, 8.3, 0}, {13.5, 8.5, 0}, {13.5, 11, 0},
            {11.5, 8.3, 0}, {11.5, 5.5, 0}, {18, 5.5, 0}};
  if (name == "symmetric") return {{1, 1, 0}, {4, 1, 0}, {5, 2, 0}, {9, 1, 0}};
  throw std::invalid_argument("unknown built-in route '" + name + "'");
}

LaserScan simulateScan(const mrpt::maps::COccupancyGridMap2D& grid, const TPose2D& truth,
                       const DriveParams& p, uint32_t seed) {
  mrpt::obs::CObservation2DRangeScan obs;
  obs.aperture = M_PI;
  obs.rightToLeft = true;
  obs.maxRange = static_cast<float>(p.max_range);
  obs.sensorPose =
      mrpt::poses::CPose3D(p.sensor_pose.x, p.sensor_pose.y, 0, p.sensor_pose.phi, 0, 0);
  mrpt::random::getRandomGenerator().randomize(seed);  // laserScanSimulator's noise source
  grid.laserScanSimulator(obs, mrpt::poses::CPose2D(truth), 0.4f, p.beams,
                          static_cast<float>(p.range_noise));
  return fromMrptScan(obs);
}

std::vector<DriveSample> simulateDrive(const mrpt::maps::COccupancyGridMap2D& grid,
                                       const std::vector<TPose2D>& route, const DriveParams& p) {
  mrpt::random::CRandomGenerator rng(p.seed);
  std::vector<DriveSample> out;
  TPose2D truth = route.front(), odom(0, 0, 0);
  // First leg heading.
  if (route.size() > 1) truth.phi = std::atan2(route[1].y - route[0].y, route[1].x - route[0].x);
  auto emit = [&](double dtrans, double drot) {
    // True motion: rotate then translate; odometry measures it with relative noise.
    const double mt = dtrans * (1 + rng.drawGaussian1D(0, p.odom_trans_noise));
    const double mr =
        drot + rng.drawGaussian1D(0, p.odom_rot_noise) * (std::abs(drot) + 0.1 * dtrans);
    truth.phi = mrpt::math::wrapToPi(truth.phi + drot);
    truth.x += dtrans * std::cos(truth.phi);
    truth.y += dtrans * std::sin(truth.phi);
    odom.phi = mrpt::math::wrapToPi(odom.phi + mr);
    odom.x += mt * std::cos(odom.phi);
    odom.y += mt * std::sin(odom.phi);
    out.push_back({truth, odom, simulateScan(grid, truth, p, p.seed * 7919u + out.size())});
  };
  emit(0, 0);
  for (size_t w = 1; w < route.size(); ++w) {
    const double dx = route[w].x - truth.x, dy = route[w].y - truth.y;
    const double heading = std::atan2(dy, dx);
    double turn = mrpt::math::wrapToPi(heading - truth.phi);
    while (std::abs(turn) > 1e-9) {
      const double r = std::copysign(std::min(0.1, std::abs(turn)), turn);
      emit(0, r);
      turn -= r;
    }
    const double dist = std::hypot(dx, dy);
    const int n = std::max(1, static_cast<int>(std::ceil(dist / p.step)));
    for (int i = 0; i < n; ++i) emit(dist / n, 0);
  }
  return out;
}

}  // namespace wheelchair_kld
