#include <wheelchair_ros/drive_channel.h>

#include <ros/time.h>

#include <stdexcept>

namespace wheelchair_ros {

template <typename Endpoint>
std::unique_ptr<DriveChannel::Registration> DriveChannel::attach(Slot<Endpoint>& slot,
                                                                 Endpoint endpoint,
                                                                 const char* role) {
  std::uint64_t session = 0;
  {
    std::lock_guard<std::mutex> lock(session_mutex_);
    session = ++sessions_;
  }
  std::lock_guard<std::recursive_mutex> lock(slot.mutex);
  if (slot.endpoint)
    throw std::logic_error(std::string("drive channel: a ") + role +
                           " is already attached in this process");
  slot.endpoint = std::make_unique<Endpoint>(std::move(endpoint));
  slot.session = session;
  Slot<Endpoint>* target = &slot;
  return std::make_unique<Registration>([self = shared_from_this(), target, session] {
    (void)self;  // the slot lives in the channel: keep it alive until detached
    std::lock_guard<std::recursive_mutex> lock(target->mutex);  // after a call in progress
    if (target->session == session) target->endpoint.reset();
  });
}

std::unique_ptr<DriveChannel::Registration> DriveChannel::attachDriver(DriverEndpoint endpoint) {
  return attach(driver_, std::move(endpoint), "driver");
}

std::unique_ptr<DriveChannel::Registration> DriveChannel::attachSupervisor(
    SupervisorEndpoint endpoint) {
  return attach(supervisor_, std::move(endpoint), "supervisor");
}

std::unique_ptr<DriveChannel::Registration> DriveChannel::attachController(
    ControllerEndpoint endpoint) {
  return attach(controller_, std::move(endpoint), "controller");
}

bool DriveChannel::submit(DriveCommand command) {
  {
    std::lock_guard<std::recursive_mutex> lock(controller_.mutex);
    command.session = controller_.endpoint ? controller_.session : 0;
  }
  std::lock_guard<std::recursive_mutex> lock(driver_.mutex);
  if (!driver_.endpoint || !driver_.endpoint->on_command) return false;
  return driver_.endpoint->on_command(command);
}

bool DriveChannel::grant(DrivePermit permit) {
  {
    std::lock_guard<std::recursive_mutex> lock(supervisor_.mutex);
    permit.session = supervisor_.endpoint ? supervisor_.session : 0;
  }
  std::lock_guard<std::recursive_mutex> lock(driver_.mutex);
  if (!driver_.endpoint || !driver_.endpoint->on_permit) return false;
  driver_.endpoint->on_permit(permit);
  return true;
}

bool DriveChannel::hold(const SafetyHold& hold) {
  std::lock_guard<std::recursive_mutex> lock(controller_.mutex);
  if (!controller_.endpoint || !controller_.endpoint->on_hold) return false;
  controller_.endpoint->on_hold(hold);
  return true;
}

bool DriveChannel::report(const DriverReport& report) {
  bool delivered = false;
  {
    std::lock_guard<std::recursive_mutex> lock(supervisor_.mutex);
    if (supervisor_.endpoint && supervisor_.endpoint->on_driver_report) {
      supervisor_.endpoint->on_driver_report(report);
      delivered = true;
    }
  }
  std::lock_guard<std::recursive_mutex> lock(controller_.mutex);
  if (controller_.endpoint && controller_.endpoint->on_driver_report) {
    controller_.endpoint->on_driver_report(report);
    delivered = true;
  }
  return delivered;
}

bool DriveChannel::releaseByRider(const RiderRelease& release) {
  bool delivered = false;
  {
    // The driver first: when the supervisor's release lifts its hold, nothing of the driver's
    // latch is left to stop the drive the rider asked for.
    std::lock_guard<std::recursive_mutex> lock(driver_.mutex);
    if (driver_.endpoint && driver_.endpoint->on_release) {
      driver_.endpoint->on_release(release);
      delivered = true;
    }
  }
  std::lock_guard<std::recursive_mutex> lock(supervisor_.mutex);
  if (supervisor_.endpoint && supervisor_.endpoint->on_release) {
    supervisor_.endpoint->on_release(release);
    delivered = true;
  }
  return delivered;
}

std::shared_ptr<DriveChannel> driveChannel() {
  static std::mutex mutex;
  static std::weak_ptr<DriveChannel> shared;
  std::lock_guard<std::mutex> lock(mutex);
  std::shared_ptr<DriveChannel> channel = shared.lock();
  if (!channel) {
    channel = std::make_shared<DriveChannel>();
    shared = channel;
  }
  return channel;
}

bool releaseStopByRider(const std::string& source) {
  RiderRelease release;
  release.stamp = ros::Time::isValid() ? ros::Time::now().toSec() : 0.0;
  release.source = source;
  return driveChannel()->releaseByRider(release);
}

}  // namespace wheelchair_ros
