// Graph SLAM live on the chair (the mapping mode): the front end (scan matching, keyframes;
// GraphSlam::addScan) runs in the caller's thread, one scan at a time; the back end (loop
// closure, optimization) and the map (the Elfes grid at the current poses) run on a worker
// thread of this class, so a scan never waits for a loop search, an optimization or a grid
// rebuild. The back end works on a copy of the keyframe graph and its result is merged back
// (GraphSlam::mergeBackEnd). The map grows incrementally (new scans inserted) and is rebuilt from
// every scan only when a closure moved the poses; at most once per `map_period`.
#pragma once

#include <wheelchair_core/occupancy_map.h>
#include <wheelchair_core/pose2d.h>
#include <wheelchair_mapping/bayes_mapper.h>
#include <wheelchair_mapping/mapper_config.h>
#include <wheelchair_slam/graph_slam.h>
#include <wheelchair_slam/slam_session.h>

#include <chrono>
#include <condition_variable>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

namespace wheelchair_slam {

class LiveSlam {
 public:
  /// Called on the worker thread with each new map (at most once per map period).
  using MapCallback = std::function<void(const wheelchair_core::OccupancyMap&)>;

  /// A new map. Throws wheelchair_core::ConfigError for an invalid configuration.
  LiveSlam(const SlamConfig& slam, const wheelchair_mapping::MapperConfig& map, double map_period,
           MapCallback on_map);
  /// Continues a saved map (slam_session.h); the first scan is located in it near
  /// `start` (the sensor's pose in the map frame), or, without one, where the
  /// saved drive's map -> odom puts it.
  LiveSlam(const SlamConfig& slam, const wheelchair_mapping::MapperConfig& map, double map_period,
           MapCallback on_map, SavedSlam saved,
           const std::optional<wheelchair_core::Pose2D>& start);
  /// Stops the worker (a back-end pass under way is finished first).
  ~LiveSlam();
  LiveSlam(const LiveSlam&) = delete;
  LiveSlam& operator=(const LiveSlam&) = delete;

  /// Adds a scan with the sensor's odometry pose at its stamp; returns its pose in the map
  /// frame, or nullopt when it was not used (a continued map not yet located, a stamp older
  /// than the last scan's of the same drive, non-finite odometry).
  std::optional<wheelchair_core::Pose2D> addScan(const wheelchair_core::LaserScan2D& scan,
                                                 const wheelchair_core::Pose2D& odometry);
  /// map -> odometry frame (identity before the first scan).
  wheelchair_core::Pose2D mapToOdom() const;
  size_t scans() const;
  /// The current pose of every scan used, in order (the sensor's, map frame).
  std::vector<wheelchair_core::Pose2D> trajectory() const;
  SlamStats stats() const;
  /// The current map (every scan at its current pose), built now.
  wheelchair_core::OccupancyMap buildMapNow() const;
  /// Writes DIR/map.yaml + map.pgm, trajectory.csv (stamp,x,y,yaw of the sensor), graph.graph
  /// and graph.scans (what a continued map needs). DIR must exist. Throws std::runtime_error /
  /// wheelchair_core::MapFileError naming the file.
  void save(const std::string& dir) const;
  /// Blocks until the back end has no loop request pending and the map has every scan
  /// (for tests and a final save); false after `timeout`.
  bool waitIdle(std::chrono::milliseconds timeout);

 private:
  void work();
  bool backEndPass(std::unique_lock<std::mutex>& lock);
  void mapPass(std::unique_lock<std::mutex>& lock);

  wheelchair_mapping::MapperConfig map_config_;
  std::chrono::duration<double> map_period_;
  MapCallback on_map_;
  mutable std::mutex mutex_;  ///< guards slam_, scans_, requests_, poses_moved_
  std::condition_variable wake_, idle_;
  GraphSlam slam_;
  LoopCloser closer_;  ///< the back end's own (GraphSlam's is the front end's)
  std::vector<std::shared_ptr<const wheelchair_core::LaserScan2D>> scans_;
  std::vector<size_t> requests_;
  bool poses_moved_ = false;
  bool busy_ = false;                                      ///< the worker is in a pass
  size_t mapped_ = 0;                                      ///< scans in the worker's grid
  std::unique_ptr<wheelchair_mapping::BayesMapper> grid_;  ///< the worker's
  std::chrono::steady_clock::time_point last_map_{};
  bool stop_ = false;
  std::thread worker_;
};

}  // namespace wheelchair_slam
