#include <mrpt/maps/CSimplePointsMap.h>
#include <mrpt/poses/CPosePDFGaussian.h>
#include <mrpt/slam/CICP.h>
#include <wheelchair_slam/icp_matcher.h>
#include <wheelchair_slam/point_to_line.h>
#include <Eigen/Eigenvalues>
#include <cmath>
#include <cstdint>
#include <unordered_map>

namespace wheelchair_slam {

namespace {

mrpt::maps::CSimplePointsMap toPointsMap(const Points& points) {
  mrpt::maps::CSimplePointsMap map;
  map.reserve(points.size());
  for (const Eigen::Vector2d& p : points) map.insertPointFast(p.x(), p.y(), 0.0);
  map.mark_as_modified();
  return map;
}

}  // namespace

struct ReferenceCloud::Impl {
  mrpt::maps::CSimplePointsMap map;
  Points points, normals;

  /// Each point's normal from the principal axes of its neighbours within 0.3 m.
  void computeNormals() {
    constexpr size_t kNeighbours = 8;
    constexpr float kRadius2 = 0.3f * 0.3f;
    normals.assign(points.size(), Eigen::Vector2d::Zero());
    std::vector<size_t> idx;
    std::vector<float> d2;
    for (size_t i = 0; i < points.size(); ++i) {
      map.kdTreeNClosestPoint2DIdx(static_cast<float>(points[i].x()),
                                   static_cast<float>(points[i].y()), kNeighbours, idx, d2);
      Eigen::Vector2d mean = Eigen::Vector2d::Zero();
      size_t n = 0;
      for (size_t k = 0; k < idx.size(); ++k) {
        if (d2[k] > kRadius2) continue;
        mean += points[idx[k]];
        ++n;
      }
      if (n < 4) continue;
      mean /= static_cast<double>(n);
      Eigen::Matrix2d cov = Eigen::Matrix2d::Zero();
      for (size_t k = 0; k < idx.size(); ++k) {
        if (d2[k] > kRadius2) continue;
        const Eigen::Vector2d d = points[idx[k]] - mean;
        cov += d * d.transpose();
      }
      const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(cov);
      const Eigen::Vector2d values = eig.eigenvalues();               // ascending
      if (values(1) <= 0.0 || values(0) > 0.1 * values(1)) continue;  // not a line
      normals[i] = eig.eigenvectors().col(0).normalized();
    }
  }
};

ReferenceCloud::ReferenceCloud() : impl_(std::make_unique<Impl>()) {}
ReferenceCloud::~ReferenceCloud() = default;
ReferenceCloud::ReferenceCloud(ReferenceCloud&&) noexcept = default;
ReferenceCloud& ReferenceCloud::operator=(ReferenceCloud&&) noexcept = default;
namespace {

Points voxelMeans(const Points& points, double voxel) {
  if (voxel <= 0.0) return points;
  std::unordered_map<int64_t, std::pair<Eigen::Vector2d, int>> cells;
  cells.reserve(points.size());
  std::vector<int64_t> order;
  for (const Eigen::Vector2d& p : points) {
    const int64_t key = (static_cast<int64_t>(std::floor(p.x() / voxel)) << 32) ^
                        (static_cast<int64_t>(std::floor(p.y() / voxel)) & 0xffffffff);
    auto [it, inserted] = cells.try_emplace(key, Eigen::Vector2d::Zero(), 0);
    if (inserted) order.push_back(key);
    it->second.first += p;
    ++it->second.second;
  }
  Points out;
  out.reserve(order.size());
  for (int64_t key : order) {
    const auto& [sum, n] = cells[key];
    out.push_back(sum / n);
  }
  return out;
}

}  // namespace

ReferenceCloud::ReferenceCloud(const Points& points, double voxel)
    : impl_(std::make_unique<Impl>()) {
  impl_->points = voxelMeans(points, voxel);
  impl_->map = toPointsMap(impl_->points);
  if (!impl_->points.empty()) impl_->computeNormals();
}
size_t ReferenceCloud::size() const { return impl_->points.size(); }
const Eigen::Vector2d& ReferenceCloud::point(size_t i) const { return impl_->points[i]; }
const Eigen::Vector2d& ReferenceCloud::normal(size_t i) const { return impl_->normals[i]; }
size_t ReferenceCloud::nearest(const Eigen::Vector2d& p, double& distance2) const {
  if (impl_->points.empty()) return 0;
  float d2 = 0.0f;
  const size_t i =
      impl_->map.kdTreeClosestPoint2D(static_cast<float>(p.x()), static_cast<float>(p.y()), d2);
  distance2 = d2;
  return i;
}

struct IcpMatcher::Impl {
  mrpt::slam::CICP icp;
};

IcpMatcher::IcpMatcher(const MatcherConfig& config)
    : config_(config), impl_(std::make_unique<Impl>()) {
  auto& o = impl_->icp.options;
  o.ICP_algorithm = mrpt::slam::icpClassic;
  o.ICP_covariance_method = mrpt::slam::icpCovFiniteDifferences;
  o.maxIterations = static_cast<unsigned>(config.icp_max_iterations);
  o.thresholdDist = config.icp_threshold_dist;
  o.thresholdAng = config.icp_threshold_ang;
  o.smallestThresholdDist = config.icp_smallest_dist;
  o.ALFA = config.icp_alfa;
  o.onlyUniqueRobust = false;
  o.corresponding_points_decimation = 1;
  o.covariance_varPoints = config.point_sigma * config.point_sigma;
  o.skip_cov_calculation = false;
}

IcpMatcher::~IcpMatcher() = default;

MatchResult IcpMatcher::match(const ReferenceCloud& reference, const Points& scan,
                              const wheelchair_core::Pose2D& guess, double min_goodness,
                              const Eigen::Matrix3d* prior_information) const {
  MatchResult out;
  out.pose = guess;
  if (reference.empty() || scan.size() < 3) return out;
  const mrpt::maps::CSimplePointsMap scan_map = toPointsMap(scan);
  mrpt::poses::CPosePDFGaussian initial(mrpt::poses::CPose2D(guess.x, guess.y, guess.yaw));
  mrpt::slam::CICP::TReturnInfo info;
  const auto pdf = impl_->icp.AlignPDF(&reference.impl_->map, &scan_map, initial, info);
  const auto* gauss = dynamic_cast<const mrpt::poses::CPosePDFGaussian*>(pdf.get());
  if (!gauss) return out;
  out.pose = {gauss->mean.x(), gauss->mean.y(), wheelchair_core::normalizeAngle(gauss->mean.phi())};
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) out.covariance(r, c) = gauss->cov(r, c);
  out.goodness = info.goodness;
  out.iterations = static_cast<int>(info.nIterations);
  out.accepted = info.goodness >= min_goodness && out.pose.isFinite() && out.covariance.allFinite();
  if (!out.accepted || !config_.refine) return out;
  PointToLineOptions refine;
  refine.max_distance = config_.refine_max_distance;
  refine.kernel = config_.refine_kernel;
  refine.point_sigma = config_.point_sigma;
  PosePrior prior;
  if (prior_information) {
    prior.mean = guess;
    prior.information = *prior_information;
  }
  const MatchResult fine =
      refinePointToLine(reference, scan, out.pose, refine, prior_information ? &prior : nullptr);
  if (!fine.accepted) return out;
  out.pose = fine.pose;
  out.covariance = fine.covariance;
  out.inliers = fine.inliers;
  return out;
}

}  // namespace wheelchair_slam
