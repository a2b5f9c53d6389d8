#include <wheelchair_logs/splice.h>

#include <algorithm>
#include <stdexcept>

namespace wheelchair_logs {

std::vector<LogScan> spliceKidnapping(const std::vector<LogScan>& scans, long at, long from) {
  if (at < 0 || from < 0 || static_cast<size_t>(std::max(at, from)) >= scans.size())
    throw std::invalid_argument("kidnapping splice outside the log's scans");
  std::vector<LogScan> out(scans.begin(), scans.begin() + at + 1);
  const wheelchair_core::Pose2D anchor = scans[at].odom_pose, source = scans[from].odom_pose;
  const double dt = scans[at].scan.stamp + 0.2 - scans[from].scan.stamp;
  for (size_t i = from; i < scans.size(); ++i) {
    LogScan s = scans[i];
    s.odom_pose =
        wheelchair_core::compose(anchor, wheelchair_core::between(source, scans[i].odom_pose));
    s.scan.stamp += dt;
    out.push_back(std::move(s));
  }
  return out;
}

}  // namespace wheelchair_logs
