#include "synthetic_drive.h"

#include <mrpt/math/TPose2D.h>
#include <mrpt/math/wrap2pi.h>
#include <mrpt/poses/CPose2D.h>
#include <mrpt/poses/CPose3D.h>
#include <mrpt/random/RandomGenerators.h>
#include <wheelchair_core/map_io.h>
#include <wheelchair_mapping/mrpt_conversions.h>
#include <wheelchair_mapping/mrpt_scan.h>

#include <cmath>
#include <stdexcept>

namespace wheelchair_kld::test {

using mrpt::math::TPose2D;
using wheelchair_core::Pose2D;

mrpt::maps::COccupancyGridMap2D loadWorldGrid(const std::string& yaml_path) {
  return wheelchair_mapping::toMrptGrid(wheelchair_core::loadMap(yaml_path));
}

std::vector<Pose2D> worldRoute(const std::string& name) {
  if (name == "flat")  // living room -> hallway -> study -> bedroom -> guest room
    return {{3.0, 2.2, 0},  {5.1, 2.2, 0},  {5.1, 4.9, 0},  {5.1, 7.4, 0},
            {7.4, 7.4, 0},  {5.1, 7.4, 0},  {5.1, 9.35, 0}, {3.7, 9.3, 0},
            {5.1, 9.35, 0}, {5.1, 10.2, 0}, {7.5, 10.2, 0}};
  if (name == "office")  // lobby -> corridor -> office n1 -> corridor -> office s4
    return {{2.0, 11.0, 0},  {10.5, 12.0, 0},  {13.2, 12.0, 0}, {13.2, 16.0, 0},
            {13.2, 12.0, 0}, {29.35, 12.0, 0}, {29.35, 7.0, 0}};
  if (name == "symmetric")  // room a -> corridor -> room b
    return {{5.0, 5.5, 0}, {8.0, 5.0, 0}, {16.0, 5.0, 0}, {19.0, 4.5, 0}};
  throw std::invalid_argument("no route for world '" + name + "'");
}

wheelchair_core::LaserScan2D simulateScan(const mrpt::maps::COccupancyGridMap2D& grid,
                                          const Pose2D& truth, const DriveParams& p,
                                          uint32_t seed) {
  mrpt::obs::CObservation2DRangeScan obs;
  obs.aperture = M_PI;
  obs.rightToLeft = true;
  obs.maxRange = static_cast<float>(p.max_range);
  obs.sensorPose =
      mrpt::poses::CPose3D(p.sensor_pose.x, p.sensor_pose.y, 0, p.sensor_pose.yaw, 0, 0);
  mrpt::random::getRandomGenerator().randomize(seed);  // laserScanSimulator's noise source
  grid.laserScanSimulator(obs, mrpt::poses::CPose2D(truth.x, truth.y, truth.yaw), 0.4f, p.beams,
                          static_cast<float>(p.range_noise));
  wheelchair_core::LaserScan2D scan = wheelchair_mapping::laserScanFromMrpt(obs, 0.0);
  scan.range_min = p.range_min;
  return scan;
}

std::vector<DriveSample> simulateDrive(const mrpt::maps::COccupancyGridMap2D& grid,
                                       const std::vector<Pose2D>& route, const DriveParams& p) {
  mrpt::random::CRandomGenerator rng(p.seed);
  std::vector<DriveSample> out;
  TPose2D truth(route.front().x, route.front().y, route.front().yaw), odom(0, 0, 0);
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
    const Pose2D at{truth.x, truth.y, truth.phi};
    DriveSample s{at,
                  {odom.x, odom.y, odom.phi},
                  simulateScan(grid, at, p, p.seed * 7919u + out.size()),
                  p.sensor_pose};
    s.scan.stamp = static_cast<double>(out.size());
    out.push_back(std::move(s));
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

}  // namespace wheelchair_kld::test
