#include <wheelchair_can/socketcan_transport.h>

#include <linux/can.h>

#include <cerrno>
#include <cstring>

namespace wheelchair_can {

void toLinuxFrame(const CanFrame& in, struct can_frame* out) {
  std::memset(out, 0, sizeof(*out));
  out->can_id = in.extended ? ((in.id & CAN_EFF_MASK) | CAN_EFF_FLAG) : (in.id & CAN_SFF_MASK);
  if (in.remote) out->can_id |= CAN_RTR_FLAG;
  if (in.error) out->can_id = (in.id & CAN_ERR_MASK) | CAN_ERR_FLAG;
  out->can_dlc = in.dlc > 8 ? 8 : in.dlc;
  std::memcpy(out->data, in.data.data(), out->can_dlc);
}

CanFrame fromLinuxFrame(const struct can_frame& in, double stamp) {
  CanFrame f;
  f.error = (in.can_id & CAN_ERR_FLAG) != 0;
  f.extended = !f.error && (in.can_id & CAN_EFF_FLAG) != 0;
  f.remote = !f.error && (in.can_id & CAN_RTR_FLAG) != 0;
  f.id = f.error ? (in.can_id & CAN_ERR_MASK)
                 : (in.can_id & (f.extended ? CAN_EFF_MASK : CAN_SFF_MASK));
  f.dlc = in.can_dlc > 8 ? 8 : in.can_dlc;
  std::memcpy(f.data.data(), in.data, f.dlc);
  f.stamp = stamp;
  return f;
}

SocketCanTransport::SocketCanTransport(Options options, std::unique_ptr<SocketLayer> layer,
                                       Clock clock)
    : options_(std::move(options)), layer_(std::move(layer)), clock_(std::move(clock)) {}

SocketCanTransport::~SocketCanTransport() {
  stop();
  std::lock_guard<std::mutex> lock(mutex_);
  if (fd_ >= 0) layer_->close(fd_);
}

void SocketCanTransport::start() {
  if (running_.exchange(true)) return;
  thread_ = std::thread([this] {
    while (running_) pollOnce(50);
  });
}

void SocketCanTransport::stop() {
  if (!running_.exchange(false)) return;
  if (thread_.joinable()) thread_.join();
}

void SocketCanTransport::closeLocked(const std::string& why) {
  if (fd_ >= 0) layer_->close(fd_);
  fd_ = -1;
  stats_.last_error = why;
  next_open_time_ = clock_() + options_.reopen_delay;
}

void SocketCanTransport::handleError(const CanFrame& frame) {
  const CanErrorReport report = decodeErrorFrame(frame);
  ++stats_.error_frames;
  stats_.last_error = report.description;
  stats_.state = nextBusState(stats_.state, report);
  if (report.bus_off) closeLocked("bus-off on " + options_.interface + ", reopening");
  if (report.bus_off) stats_.state = BusState::kBusOff;
}

void SocketCanTransport::pollOnce(int timeout_ms) {
  int fd;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (fd_ < 0) {
      if (clock_() < next_open_time_) {
        fd = -1;
      } else {
        const int r = layer_->open(options_.interface, options_.filters);
        if (r < 0) {
          closeLocked("cannot open " + options_.interface + ": " + std::strerror(-r));
          stats_.state = stats_.state == BusState::kBusOff ? BusState::kBusOff : BusState::kClosed;
        } else {
          fd_ = r;
          ++stats_.reopens;
          stats_.state = BusState::kActive;
        }
      }
    }
    fd = fd_;
  }
  if (fd < 0) {
    // Nothing to read: wait like a read would, so the thread does not spin.
    std::this_thread::sleep_for(std::chrono::milliseconds(timeout_ms > 10 ? 10 : timeout_ms));
    return;
  }
  int wait = timeout_ms;
  for (int n = 0; n < 256; ++n, wait = 0) {
    CanFrame frame;
    const int r = layer_->read(fd, &frame, wait);
    std::lock_guard<std::mutex> lock(mutex_);
    if (r == 0) return;
    if (r < 0) {
      if (r == -EAGAIN || r == -EINTR) return;
      closeLocked("read from " + options_.interface + " failed: " + std::strerror(-r));
      stats_.state = BusState::kClosed;
      return;
    }
    frame.stamp = clock_();
    if (frame.error) handleError(frame);
    if (queue_.size() >= options_.queue_limit) {
      ++stats_.rx_dropped;
    } else {
      if (!frame.error) ++stats_.rx_frames;
      queue_.push_back(frame);
    }
    if (fd_ != fd) return;  // closed after bus-off
  }
}

bool SocketCanTransport::send(const CanFrame& frame) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (fd_ < 0 || frame.dlc > 8) {
    ++stats_.tx_failed;
    return false;
  }
  const int r = layer_->write(fd_, frame);
  if (r < 0) {
    ++stats_.tx_failed;
    stats_.last_error = std::string("write failed: ") + std::strerror(-r);
    return false;
  }
  ++stats_.tx_frames;
  return true;
}

void SocketCanTransport::receive(std::vector<CanFrame>& out) {
  std::lock_guard<std::mutex> lock(mutex_);
  out.insert(out.end(), queue_.begin(), queue_.end());
  queue_.clear();
}

TransportStats SocketCanTransport::stats() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return stats_;
}

std::string SocketCanTransport::describe() const { return "SocketCAN " + options_.interface; }

}  // namespace wheelchair_can
