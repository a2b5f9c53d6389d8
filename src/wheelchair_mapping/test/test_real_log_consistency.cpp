// Real data (../shared/data, absent in a user's clone: skipped): a map built with the corrected
// poses of the Intel lab log, every 10th scan held back; the held-back scans' endpoints must
// land on (or next to) occupied cells.
#include <gtest/gtest.h>
#include <wheelchair_logs/carmen_log.h>
#include <wheelchair_mapping/bayes_mapper.h>
#include <wheelchair_mapping/map_consistency.h>

#include <filesystem>
#include <iostream>

namespace wheelchair_mapping {
namespace {

using wheelchair_logs::CarmenLogReader;
using wheelchair_logs::LogScan;

TEST(RealLogConsistency, IntelCorrectedHeldOutScans) {
  const std::string log = std::string(WHEELCHAIR_SHARED_DATA_DIR) + "/intel/intel-corrected.log.gz";
  if (!std::filesystem::exists(log)) GTEST_SKIP() << "no shared data at " << log;
  MapperConfig config;
  config.model.no_return_is_free = false;
  BayesMapper mapper(config);
  CarmenLogReader reader(log);
  std::vector<LogScan> held;
  size_t n = 0;
  for (LogScan s; reader.next(s);) {
    if (++n % 10 == 0) {
      held.push_back(s);
    } else {
      mapper.insert(s.scan, s.laser_pose);
    }
  }
  EXPECT_EQ(reader.corruptLines(), 0u);
  EXPECT_GT(mapper.scansInserted(), 800u);
  const wheelchair_core::OccupancyMap map = mapper.map();
  EndpointConsistency c;
  for (const auto& s : held) addEndpoints(map, s.scan, s.laser_pose, 20.0, c);
  std::cout << "intel: " << 100 * c.onFraction() << " % of " << c.endpoints
            << " held-out endpoints on occupied cells, " << 100 * c.nearFraction()
            << " % within one cell\n";
  // A map built from the true poses explains new scans; a map of a shifted or rotated log
  // does not.
  EXPECT_GT(c.nearFraction(), 0.85);
  EndpointConsistency shifted;
  for (auto s : held) {
    s.laser_pose.x += 0.25;  // 5 cells
    s.laser_pose.yaw += 0.05;
    addEndpoints(map, s.scan, s.laser_pose, 20.0, shifted);
  }
  std::cout << "intel, poses off by 0.25 m and 0.05 rad: " << 100 * shifted.nearFraction()
            << " % within one cell\n";
  EXPECT_LT(shifted.nearFraction(), 0.7 * c.nearFraction());
}

}  // namespace
}  // namespace wheelchair_mapping
