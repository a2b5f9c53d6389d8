#include <wheelchair_slam/slam_config.h>

namespace wheelchair_slam {

using wheelchair_core::ConfigChecks;

std::string MatcherConfig::validate() const {
  ConfigChecks c;
  c.positive("matcher/max_range", max_range)
      .nonNegative("matcher/point_spacing", point_spacing)
      .check(local_map_keyframes >= 1, "matcher/local_map_keyframes must be at least 1")
      .nonNegative("matcher/map_voxel", map_voxel)
      .positive("matcher/icp_threshold_dist", icp_threshold_dist)
      .nonNegative("matcher/icp_threshold_ang", icp_threshold_ang)
      .positive("matcher/icp_smallest_dist", icp_smallest_dist)
      .inRange("matcher/icp_alfa", icp_alfa, 0.05, 0.99)
      .check(icp_max_iterations >= 1, "matcher/icp_max_iterations must be at least 1")
      .inRange("matcher/min_goodness", min_goodness, 0.0, 1.0)
      .positive("matcher/point_sigma", point_sigma)
      .positive("matcher/refine_max_distance", refine_max_distance)
      .positive("matcher/refine_kernel", refine_kernel);
  return c.result();
}

std::string KeyframeConfig::validate() const {
  ConfigChecks c;
  c.nonNegative("keyframes/distance", distance).nonNegative("keyframes/angle", angle);
  return c.result();
}

std::string OdometryNoise::validate() const {
  ConfigChecks c;
  c.nonNegative("odometry/sigma_xy_per_m", sigma_xy_per_m)
      .nonNegative("odometry/sigma_yaw_per_rad", sigma_yaw_per_rad)
      .nonNegative("odometry/sigma_yaw_per_m", sigma_yaw_per_m)
      .positive("odometry/sigma_xy_floor", sigma_xy_floor)
      .positive("odometry/sigma_yaw_floor", sigma_yaw_floor);
  return c.result();
}

std::string LoopClosureConfig::validate() const {
  ConfigChecks c;
  c.positive("loops/search_radius", search_radius)
      .nonNegative("loops/min_path_gap", min_path_gap)
      .check(submap_half_width >= 0, "loops/submap_half_width must not be negative")
      .nonNegative("loops/window_xy", window_xy)
      .nonNegative("loops/window_yaw", window_yaw)
      .positive("loops/search_step_yaw", search_step_yaw)
      .positive("loops/grid_resolution", grid_resolution)
      .inRange("loops/min_score", min_score, 0.0, 1.0)
      .inRange("loops/min_goodness", min_goodness, 0.0, 1.0)
      .check(every_n_keyframes >= 1, "loops/every_n_keyframes must be at least 1")
      .positive("loops/max_chi2", max_chi2)
      .positive("loops/covariance_scale", covariance_scale)
      .positive("loops/final_radius", final_radius)
      .check(final_per_keyframe >= 0, "loops/final_per_keyframe must not be negative")
      .positive("loops/final_max_shift", final_max_shift);
  return c.result();
}

std::string SlamConfig::validate() const {
  ConfigChecks c;
  for (const std::string& p :
       {matcher.validate(), keyframes.validate(), odometry.validate(), loops.validate()}) {
    c.check(p.empty(), p);
  }
  c.positive("match_covariance_scale", match_covariance_scale)
      .check(optimizer_iterations >= 1, "optimizer_iterations must be at least 1");
  return c.result();
}

void readSlamConfig(wheelchair_core::ConfigReader& r, SlamConfig& c) {
  MatcherConfig& m = c.matcher;
  r.read("matcher/max_range", m.max_range);
  r.read("matcher/point_spacing", m.point_spacing);
  r.read("matcher/local_map_keyframes", m.local_map_keyframes);
  r.read("matcher/map_voxel", m.map_voxel);
  r.read("matcher/icp_threshold_dist", m.icp_threshold_dist);
  r.read("matcher/icp_threshold_ang", m.icp_threshold_ang);
  r.read("matcher/icp_smallest_dist", m.icp_smallest_dist);
  r.read("matcher/icp_alfa", m.icp_alfa);
  r.read("matcher/icp_max_iterations", m.icp_max_iterations);
  r.read("matcher/min_goodness", m.min_goodness);
  r.read("matcher/point_sigma", m.point_sigma);
  r.read("matcher/refine", m.refine);
  r.read("matcher/refine_max_distance", m.refine_max_distance);
  r.read("matcher/refine_kernel", m.refine_kernel);
  r.read("keyframes/distance", c.keyframes.distance);
  r.read("keyframes/angle", c.keyframes.angle);
  OdometryNoise& o = c.odometry;
  r.read("odometry/sigma_xy_per_m", o.sigma_xy_per_m);
  r.read("odometry/sigma_yaw_per_rad", o.sigma_yaw_per_rad);
  r.read("odometry/sigma_yaw_per_m", o.sigma_yaw_per_m);
  r.read("odometry/sigma_xy_floor", o.sigma_xy_floor);
  r.read("odometry/sigma_yaw_floor", o.sigma_yaw_floor);
  LoopClosureConfig& l = c.loops;
  r.read("loops/enabled", l.enabled);
  r.read("loops/search_radius", l.search_radius);
  r.read("loops/min_path_gap", l.min_path_gap);
  r.read("loops/submap_half_width", l.submap_half_width);
  r.read("loops/window_xy", l.window_xy);
  r.read("loops/window_yaw", l.window_yaw);
  r.read("loops/search_step_yaw", l.search_step_yaw);
  r.read("loops/grid_resolution", l.grid_resolution);
  r.read("loops/min_score", l.min_score);
  r.read("loops/min_goodness", l.min_goodness);
  r.read("loops/every_n_keyframes", l.every_n_keyframes);
  r.read("loops/max_chi2", l.max_chi2);
  r.read("loops/covariance_scale", l.covariance_scale);
  r.read("loops/final_pass", l.final_pass);
  r.read("loops/final_radius", l.final_radius);
  r.read("loops/final_per_keyframe", l.final_per_keyframe);
  r.read("loops/final_max_shift", l.final_max_shift);
  r.read("match_covariance_scale", c.match_covariance_scale);
  r.read("optimizer_iterations", c.optimizer_iterations);
  r.read("odometry_prior", c.odometry_prior);
}

}  // namespace wheelchair_slam
