#include <wheelchair_kld/measurement_model.h>

#include <algorithm>
#include <cmath>

namespace wheelchair_kld {

namespace {
double gaussian(double x, double sigma) {
  return std::exp(-0.5 * x * x / (sigma * sigma)) / (sigma * std::sqrt(2 * M_PI));
}
}  // namespace

MeasurementModel::MeasurementModel(const LocalizationMap& map, const MeasurementParams& params)
    : map_(map), params_(params) {
  const double rand = params_.z_rand / params_.max_range;
  outside_log_ = std::log(rand);
  const auto& dist = map_.obstacleDistance();
  field_log_.resize(dist.size());
  // The distance transform runs between cell centres, but a beam ends where it enters the
  // first occupied cell, half a cell before its centre: measure from that surface (otherwise
  // the estimate is pulled half a cell towards what the laser sees).
  const double surface = 0.5 * map_.resolution();
  for (size_t i = 0; i < dist.size(); ++i)
    field_log_[i] = static_cast<float>(std::log(
        params_.z_hit * gaussian(std::max(0.0, dist[i] - surface), params_.sigma_hit) + rand));
}

int MeasurementModel::setScan(const wheelchair_core::LaserScan2D& scan,
                              const wheelchair_core::Pose2D& sensor_pose) {
  beams_.clear();
  sensor_pose_ = mrpt::math::TPose2D(sensor_pose.x, sensor_pose.y, sensor_pose.yaw);
  const double max_range = std::min(params_.max_range, scan.range_max);
  const int step = std::max(1, params_.beam_step);
  const double cs = std::cos(sensor_pose_.phi), sn = std::sin(sensor_pose_.phi);
  for (size_t i = 0; i < scan.ranges.size(); i += step) {
    const double r = scan.ranges[i];
    Beam b;
    switch (wheelchair_core::classifyBeam(scan.ranges[i], scan)) {
      case wheelchair_core::Beam::kReturn:
        b.max_range = r >= max_range;
        break;
      case wheelchair_core::Beam::kNoReturn:
        b.max_range = true;
        break;
      default:  // too close, erroneous, outside [range_min, range_max]: discarded
        continue;
    }
    b.angle = sensor_pose_.phi + scan.angle_min + i * scan.angle_increment;
    b.range = b.max_range ? max_range : r;
    const double lx = b.range * std::cos(scan.angle_min + i * scan.angle_increment);
    const double ly = b.range * std::sin(scan.angle_min + i * scan.angle_increment);
    b.end_x = sensor_pose_.x + cs * lx - sn * ly;
    b.end_y = sensor_pose_.y + sn * lx + cs * ly;
    beams_.push_back(b);
  }
  return beamCount();
}

double MeasurementModel::logLikelihood(const mrpt::math::TPose2D& pose) const {
  const double log_p =
      params_.type == MeasurementModelType::kBeam ? logBeamModel(pose) : logLikelihoodField(pose);
  return params_.likelihood_exponent * log_p;
}

double MeasurementModel::logLikelihoodField(const mrpt::math::TPose2D& pose) const {
  const double c = std::cos(pose.phi), s = std::sin(pose.phi);
  double sum = 0;
  for (const Beam& b : beams_) {
    if (b.max_range) continue;  // no echo carries no information in the likelihood field
    const int cell =
        map_.cellIndex(pose.x + c * b.end_x - s * b.end_y, pose.y + s * b.end_x + c * b.end_y);
    sum += cell < 0 ? outside_log_ : field_log_[cell];
  }
  return sum;
}

double MeasurementModel::inlierFraction(const mrpt::math::TPose2D& pose, double tolerance) const {
  const double c = std::cos(pose.phi), s = std::sin(pose.phi);
  int echoes = 0, inliers = 0;
  for (const Beam& b : beams_) {
    if (b.max_range) continue;
    ++echoes;
    const int cell =
        map_.cellIndex(pose.x + c * b.end_x - s * b.end_y, pose.y + s * b.end_x + c * b.end_y);
    inliers += cell >= 0 && map_.obstacleDistance()[cell] <= tolerance;
  }
  return echoes > 0 ? static_cast<double>(inliers) / echoes : 0.0;
}

MeasurementModel::FitCounts MeasurementModel::fitCounts(const mrpt::math::TPose2D& pose,
                                                        double tolerance) const {
  const double c = std::cos(pose.phi), s = std::sin(pose.phi);
  const double ox = pose.x + c * sensor_pose_.x - s * sensor_pose_.y;
  const double oy = pose.y + s * sensor_pose_.x + c * sensor_pose_.y;
  FitCounts f;
  for (const Beam& b : beams_) {
    if (b.max_range) continue;
    ++f.echoes;
    const int cell =
        map_.cellIndex(pose.x + c * b.end_x - s * b.end_y, pose.y + s * b.end_x + c * b.end_y);
    if (cell < 0) continue;
    if (map_.obstacleDistance()[cell] <= tolerance) {
      ++f.inliers;
    } else if (map_.isFree(cell)) {
      ++f.contradictions;
      if (b.range < map_.castRay(ox, oy, pose.phi + b.angle, params_.max_range) - tolerance)
        ++f.shorts;
    }
  }
  return f;
}

std::vector<double> MeasurementModel::endpointDistances(const mrpt::math::TPose2D& pose) const {
  const double c = std::cos(pose.phi), s = std::sin(pose.phi);
  std::vector<double> d;
  for (const Beam& b : beams_) {
    if (b.max_range) continue;
    const int cell =
        map_.cellIndex(pose.x + c * b.end_x - s * b.end_y, pose.y + s * b.end_x + c * b.end_y);
    if (cell >= 0) d.push_back(map_.obstacleDistance()[cell]);
  }
  return d;
}

double MeasurementModel::logBeamModel(const mrpt::math::TPose2D& pose) const {
  const double c = std::cos(pose.phi), s = std::sin(pose.phi);
  const double ox = pose.x + c * sensor_pose_.x - s * sensor_pose_.y;
  const double oy = pose.y + s * sensor_pose_.x + c * sensor_pose_.y;
  const double max_range = params_.max_range;
  double sum = 0;
  for (const Beam& b : beams_) {
    const double expected = map_.castRay(ox, oy, pose.phi + b.angle, max_range);
    double p = params_.z_rand / max_range;
    if (b.max_range) {
      p += params_.z_max;
    } else {
      p += params_.z_hit * gaussian(b.range - expected, params_.sigma_hit);
      if (b.range < expected)
        p += params_.z_short * params_.lambda_short * std::exp(-params_.lambda_short * b.range) /
             (1 - std::exp(-params_.lambda_short * expected));
    }
    sum += std::log(p);
  }
  return sum;
}

}  // namespace wheelchair_kld
