#include <wheelchair_core/map_io.h>
#include <wheelchair_slam/live_slam.h>
#include <wheelchair_slam/slam_map.h>
#include <wheelchair_slam/trajectory_io.h>

#include <stdexcept>
#include <utility>

namespace wheelchair_slam {

using wheelchair_core::Pose2D;

LiveSlam::LiveSlam(const SlamConfig& slam, const wheelchair_mapping::MapperConfig& map,
                   double map_period, MapCallback on_map)
    : map_config_(map),
      map_period_(map_period),
      on_map_(std::move(on_map)),
      slam_(slam),
      closer_(slam) {
  slam_.setDeferLoops(true);
  worker_ = std::thread([this] { work(); });
}

LiveSlam::LiveSlam(const SlamConfig& slam, const wheelchair_mapping::MapperConfig& map,
                   double map_period, MapCallback on_map, SavedSlam saved,
                   const std::optional<Pose2D>& start)
    : map_config_(map),
      map_period_(map_period),
      on_map_(std::move(on_map)),
      slam_(slam, std::move(saved.graph), saved.records),
      closer_(slam) {
  for (auto& s : saved.scans)
    scans_.push_back(std::make_shared<const wheelchair_core::LaserScan2D>(std::move(s)));
  slam_.setDeferLoops(true);
  if (start) slam_.startDrive(*start);
  poses_moved_ = true;  // the saved scans are mapped on the first pass
  worker_ = std::thread([this] { work(); });
}

LiveSlam::~LiveSlam() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stop_ = true;
  }
  wake_.notify_all();
  worker_.join();
}

std::optional<Pose2D> LiveSlam::addScan(const wheelchair_core::LaserScan2D& scan,
                                        const Pose2D& odometry) {
  if (!odometry.isFinite()) return std::nullopt;
  std::optional<Pose2D> pose;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    // The order is kept within a drive: a continued map's new drive may run on a clock that
    // started again (the simulator's after a restart, a chair whose clock was reset), so its
    // first scan may be older than the saved drive's last.
    if (!slam_.awaitingDriveStart() && !slam_.stamps().empty() &&
        scan.stamp < slam_.stamps().back())
      return std::nullopt;
    pose = slam_.addScan(scan, odometry);
    if (!pose) return std::nullopt;
    scans_.push_back(std::make_shared<const wheelchair_core::LaserScan2D>(scan));
    for (size_t k : slam_.takeLoopRequests()) requests_.push_back(k);
  }
  wake_.notify_all();
  return pose;
}

Pose2D LiveSlam::mapToOdom() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return slam_.scanRecords().empty() ? Pose2D{} : slam_.mapToOdom();
}

size_t LiveSlam::scans() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return scans_.size();
}

std::vector<Pose2D> LiveSlam::trajectory() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return slam_.trajectory();
}

SlamStats LiveSlam::stats() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return slam_.stats();
}

wheelchair_core::OccupancyMap LiveSlam::buildMapNow() const {
  std::vector<std::shared_ptr<const wheelchair_core::LaserScan2D>> scans;
  std::vector<Pose2D> poses;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    scans = scans_;
    poses = slam_.trajectory();
  }
  wheelchair_mapping::BayesMapper mapper(map_config_);
  for (size_t i = 0; i < scans.size() && i < poses.size(); ++i)
    insertAtPose(mapper, *scans[i], poses[i], i);
  return mapper.map();
}

void LiveSlam::save(const std::string& dir) const {
  std::vector<wheelchair_core::LaserScan2D> scans;
  std::vector<TimedPose> trajectory;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    for (const auto& s : scans_) scans.push_back(*s);
    const std::vector<Pose2D> poses = slam_.trajectory();
    for (size_t i = 0; i < poses.size(); ++i) trajectory.push_back({slam_.stamps()[i], poses[i]});
    saveSlam(dir, slam_, scans);
  }
  writeTrajectoryCsv(dir + "/trajectory.csv", trajectory);
  wheelchair_mapping::BayesMapper mapper(map_config_);
  for (size_t i = 0; i < scans.size() && i < trajectory.size(); ++i)
    insertAtPose(mapper, scans[i], trajectory[i].pose, i);
  wheelchair_core::saveMap(mapper.map(), dir + "/map.yaml");
}

bool LiveSlam::waitIdle(std::chrono::milliseconds timeout) {
  std::unique_lock<std::mutex> lock(mutex_);
  wake_.notify_all();
  return idle_.wait_for(lock, timeout, [this] {
    return !busy_ && requests_.empty() && !poses_moved_ && mapped_ == scans_.size();
  });
}

bool LiveSlam::backEndPass(std::unique_lock<std::mutex>& lock) {
  std::vector<size_t> requests;
  requests.swap(requests_);
  KeyframeGraph worked = slam_.keyframeGraph();  // the keyframes' points are shared, not copied
  const size_t nodes = worked.graph.size(), edges = worked.graph.edges().size();
  lock.unlock();
  SlamStats stats;
  bool closed = false;
  for (size_t k : requests)
    if (k < worked.keyframes.size()) closed = closer_.closeLoop(worked, k, stats) || closed;
  lock.lock();
  slam_.mergeBackEnd(std::move(worked), nodes, edges, stats);
  return closed;
}

void LiveSlam::mapPass(std::unique_lock<std::mutex>& lock) {
  const bool rebuild = poses_moved_ || !grid_;
  poses_moved_ = false;
  const size_t first = rebuild ? 0 : mapped_;
  std::vector<std::shared_ptr<const wheelchair_core::LaserScan2D>> scans(scans_.begin() + first,
                                                                         scans_.end());
  std::vector<Pose2D> poses = slam_.trajectory();
  lock.unlock();
  if (rebuild) grid_ = std::make_unique<wheelchair_mapping::BayesMapper>(map_config_);
  for (size_t i = 0; i < scans.size() && first + i < poses.size(); ++i)
    insertAtPose(*grid_, *scans[i], poses[first + i], first + i);
  const wheelchair_core::OccupancyMap map = grid_->map();
  if (on_map_) on_map_(map);
  lock.lock();
  mapped_ = first + scans.size();
}

void LiveSlam::work() {
  std::unique_lock<std::mutex> lock(mutex_);
  while (!stop_) {
    const auto now = std::chrono::steady_clock::now();
    const auto map_due =
        last_map_ + std::chrono::duration_cast<std::chrono::steady_clock::duration>(map_period_);
    const bool map_wanted = poses_moved_ || mapped_ < scans_.size();
    if (!requests_.empty()) {
      busy_ = true;
      if (backEndPass(lock)) poses_moved_ = true;
      busy_ = false;
    } else if (map_wanted && now >= map_due) {
      busy_ = true;
      last_map_ = now;
      mapPass(lock);
      busy_ = false;
    } else {
      idle_.notify_all();
      if (map_wanted)
        wake_.wait_until(lock, map_due);
      else
        wake_.wait(lock);
    }
  }
  idle_.notify_all();
}

}  // namespace wheelchair_slam
