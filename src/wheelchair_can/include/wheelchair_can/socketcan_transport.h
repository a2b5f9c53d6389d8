// SocketCAN transport: a raw PF_CAN socket on a named interface (can0, vcan0) with kernel
// receive filters, error frames enabled and decoded, a dedicated receive thread with
// timestamps, non-blocking sends, and bus-off / link-loss detection with a delayed reopen.
// The socket calls sit behind SocketLayer so the logic is testable without a CAN kernel.
#pragma once

#include <wheelchair_can/can_error.h>
#include <wheelchair_can/transport.h>

#include <atomic>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

struct can_frame;

namespace wheelchair_can {

/// Conversions to and from the kernel's struct can_frame (flags in can_id's top bits).
void toLinuxFrame(const CanFrame& in, struct can_frame* out);
CanFrame fromLinuxFrame(const struct can_frame& in, double stamp);

/// The system calls the transport needs. Return values follow the kernel: >= 0 success,
/// a negative errno on failure.
class SocketLayer {
 public:
  virtual ~SocketLayer() = default;
  /// Opens a raw CAN socket bound to `interface`, non-blocking, with `filters` and every
  /// error class enabled. Returns a descriptor or -errno.
  virtual int open(const std::string& interface, const std::vector<CanFilter>& filters) = 0;
  virtual void close(int fd) = 0;
  /// Waits at most `timeout_ms` for one frame: 1 = frame read, 0 = timeout, -errno = failure.
  virtual int read(int fd, CanFrame* frame, int timeout_ms) = 0;
  /// Writes one frame without blocking: 0 = sent, -errno = failure (-EAGAIN: queue full).
  virtual int write(int fd, const CanFrame& frame) = 0;
};

/// The real Linux implementation (socket(PF_CAN, SOCK_RAW, CAN_RAW)).
std::unique_ptr<SocketLayer> makeLinuxSocketLayer();

/// True when this kernel can create a CAN socket; `why` names the reason otherwise.
bool canSocketsAvailable(std::string* why);

class SocketCanTransport : public CanTransport {
 public:
  using Clock = std::function<double()>;
  struct Options {
    std::string interface = "can0";
    std::vector<CanFilter> filters;  ///< empty = receive everything
    double reopen_delay = 0.5;       ///< [s] between a failure/bus-off and the next open attempt
    std::size_t queue_limit = 4096;  ///< receive queue between the thread and receive()
  };
  SocketCanTransport(Options options, std::unique_ptr<SocketLayer> layer, Clock clock);
  ~SocketCanTransport() override;

  /// Starts the receive thread (calls pollOnce(50) in a loop).
  void start();
  void stop();
  /// One iteration of the receive thread: (re)opens the socket when due, reads frames for at
  /// most `timeout_ms`, handles error frames and read failures. Public for tests.
  void pollOnce(int timeout_ms);

  bool send(const CanFrame& frame) override;
  void receive(std::vector<CanFrame>& out) override;
  TransportStats stats() const override;
  std::string describe() const override;

 private:
  void closeLocked(const std::string& why);
  void handleError(const CanFrame& frame);

  const Options options_;
  std::unique_ptr<SocketLayer> layer_;
  Clock clock_;
  mutable std::mutex mutex_;
  int fd_ = -1;
  double next_open_time_ = 0.0;
  std::vector<CanFrame> queue_;
  TransportStats stats_;
  std::atomic<bool> running_{false};
  std::thread thread_;
};

}  // namespace wheelchair_can
