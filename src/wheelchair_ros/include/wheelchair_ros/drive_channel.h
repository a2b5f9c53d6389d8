// The chair's command path inside its one process: who may move the motors and who may release
// a stop. ROS 1 has no authentication: any node may publish /wheel_torques, /safety/stop or
// /plan. Inside the chair process the nodelets that move the chair talk through this object
// instead, by direct calls (one per process, in this shared library, like the shared tf buffer):
//
//   controller --submit(DriveCommand), every control step------------> driver
//   supervisor --grant(DrivePermit), every check----------------------> driver
//   supervisor --verdict(SafetyHold), on every change-----------------> controller
//   driver     --report(DriverReport), on every change----------------> supervisor, controller
//   rider      --releaseByRider(RiderRelease)-------------------------> supervisor, driver
//   (the HMI on the rider's command; later a navigator acting on it)
//
// The driver moves the motors only with commands submitted here and a fresh permit; a latched
// stop (the supervisor's or the driver's) ends only with releaseByRider. A role is taken by one
// nodelet at a time (a second one is refused: std::logic_error); the Registration returned by
// attach*() detaches it when destroyed (the nodelet unloaded), after any call in progress. A
// call that finds no one attached does nothing and returns false. No handler may call its own
// role back; handlers must not hold their nodelet's lock while calling the channel (the driver
// and the supervisor report after unlocking).
#pragma once

#include <cmath>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <string>

namespace wheelchair_ros {

/// A torque command of the chair's own controller.
struct DriveCommand {
  double left = 0.0;   ///< [N m], positive drives the chair forward
  double right = 0.0;  ///< [N m]
  bool brake = true;
  double stamp = 0.0;          ///< [s, ROS time] when the controller computed it
  std::uint64_t sequence = 0;  ///< +1 per command of one controller
  std::uint64_t session = 0;   ///< set by submit(): which attachment of the controller sent it
};

/// The supervisor's permission to move, renewed at its check rate.
struct DrivePermit {
  std::uint64_t sequence = 0;  ///< +1 per permit of one supervisor
  double stamp = 0.0;          ///< [s, ROS time] when it was issued
  /// A stop is latched: only the controller's controlled stop may run, then the brake.
  bool stop = false;
  /// [m/s] the supervisor's speed limit now (the protective field's, /safety/speed_limit's
  /// value); +inf: none from the field. The driver holds it itself for as long as the permit is
  /// fresh (a stale permit brakes: there is no stale limit to drive by).
  double speed_limit = INFINITY;
  std::uint64_t session = 0;  ///< set by grant()
};

/// The supervisor's verdict for the controller: hold (a controlled stop, no new path) while
/// `stop`, with the rider's words.
struct SafetyHold {
  bool stop = false;
  std::string sentence;  ///< e.g. "the laser scanner is silent"
  std::string detail;    ///< for the log
};

/// The driver's state as the stack needs it: a fault (it brakes) and whether it latched (a fault
/// or a foreign command during a drive: the drive ends, only the rider's release goes on).
struct DriverReport {
  double stamp = 0.0;
  bool fault = false;
  bool latched = false;
  std::string sentence;  ///< for the rider, e.g. "another program tried to drive the chair"
  std::string detail;    ///< for the log: the driver's state, counters
};

/// The rider's own command to go on (a destination confirmed on the HMI).
struct RiderRelease {
  double stamp = 0.0;
  std::string source;  ///< who relays it, for the log: "hmi: go to kitchen_door"
};

struct DriverEndpoint {
  std::function<bool(const DriveCommand&)> on_command;  ///< false: refused (the driver says why)
  std::function<void(const DrivePermit&)> on_permit;
  std::function<void(const RiderRelease&)> on_release;
};
struct SupervisorEndpoint {
  std::function<void(const DriverReport&)> on_driver_report;
  std::function<void(const RiderRelease&)> on_release;
};
struct ControllerEndpoint {
  std::function<void(const SafetyHold&)> on_hold;
  std::function<void(const DriverReport&)> on_driver_report;
};

/// Create it with std::make_shared (driveChannel() for the process's one; tests make their own).
class DriveChannel : public std::enable_shared_from_this<DriveChannel> {
 public:
  /// While it lives its role is taken; destroyed: detached (waits for a call in progress). It
  /// keeps the channel alive.
  class Registration {
   public:
    explicit Registration(std::function<void()> detach) : detach_(std::move(detach)) {}
    ~Registration() {
      if (detach_) detach_();
    }
    Registration(const Registration&) = delete;
    Registration& operator=(const Registration&) = delete;

   private:
    std::function<void()> detach_;
  };

  /// Throws std::logic_error if the role is taken (a second driver, supervisor or controller).
  std::unique_ptr<Registration> attachDriver(DriverEndpoint endpoint);
  std::unique_ptr<Registration> attachSupervisor(SupervisorEndpoint endpoint);
  std::unique_ptr<Registration> attachController(ControllerEndpoint endpoint);

  /// Controller -> driver. False if no driver is attached or it refused the command.
  bool submit(DriveCommand command);
  /// Supervisor -> driver. False if no driver is attached.
  bool grant(DrivePermit permit);
  /// Supervisor -> controller. False if no controller is attached.
  bool hold(const SafetyHold& hold);
  /// Driver -> supervisor and controller. False if neither is attached.
  bool report(const DriverReport& report);
  /// The rider's command: releases the supervisor's and the driver's latched stops. Returns
  /// false if neither is attached (nothing to release; nothing would move either).
  bool releaseByRider(const RiderRelease& release);

  bool hasDriver() const { return driver_.attached(); }
  bool hasSupervisor() const { return supervisor_.attached(); }
  bool hasController() const { return controller_.attached(); }

 private:
  /// One role: its endpoint and the lock that serializes calls with attach / detach.
  template <typename Endpoint>
  struct Slot {
    mutable std::recursive_mutex mutex;
    std::unique_ptr<Endpoint> endpoint;
    std::uint64_t session = 0;
    bool attached() const {
      std::lock_guard<std::recursive_mutex> lock(mutex);
      return endpoint != nullptr;
    }
  };
  template <typename Endpoint>
  std::unique_ptr<Registration> attach(Slot<Endpoint>& slot, Endpoint endpoint, const char* role);

  Slot<DriverEndpoint> driver_;
  Slot<SupervisorEndpoint> supervisor_;
  Slot<ControllerEndpoint> controller_;
  std::mutex session_mutex_;
  std::uint64_t sessions_ = 0;
};

/// The process's channel. Created on the first call; kept alive by its holders (each nodelet
/// holds it for its lifetime, so that its Registration can detach).
std::shared_ptr<DriveChannel> driveChannel();

/// THE way to release a latched stop: the rider's own command to go on (a destination chosen on
/// the HMI; later the navigator acting on the rider's command). Call it in the chair process just
/// before the command it releases for (the goal): it clears the supervisor's latched stop and the
/// base driver's latched stop / e-stop of this process (a condition that still holds stops again
/// at the supervisor's next check, at once). `source` says who relays it, for the log
/// ("hmi: go to kitchen_door"). False if neither the supervisor nor the driver is in this process.
/// No topic or service releases a stop: /safety/stop is an output, ~clear_estop is refused.
bool releaseStopByRider(const std::string& source);

}  // namespace wheelchair_ros
