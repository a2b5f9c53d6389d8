#include "bag_source.h"

#include <wheelchair_logs/bag_scans.h>

namespace wheelchair_slam {

struct BagOdometryReader::Impl {
  wheelchair_logs::BagScanReader reader;
  Impl(const std::string& path, const std::string& topic, const std::string& frame)
      : reader(path, topic, frame) {}
};

BagOdometryReader::BagOdometryReader(const std::string& path, const std::string& scan_topic,
                                     const std::string& odom_frame)
    : impl_(std::make_unique<Impl>(path, scan_topic, odom_frame)) {}

BagOdometryReader::~BagOdometryReader() = default;

bool BagOdometryReader::next(wheelchair_logs::LogScan& out) {
  if (!impl_->reader.next(out)) return false;
  out.odom_pose = out.laser_pose;
  return true;
}

const std::string& BagOdometryReader::problemsOfLastCall() const {
  return impl_->reader.problemsOfLastCall();
}
size_t BagOdometryReader::corruptLines() const { return impl_->reader.problemCount(); }
double BagOdometryReader::progress() const { return impl_->reader.progress(); }

}  // namespace wheelchair_slam
