// The real SocketCAN system calls behind SocketLayer.
#include <wheelchair_can/socketcan_transport.h>

#include <linux/can.h>
#include <linux/can/error.h>
#include <linux/can/raw.h>
#include <net/if.h>
#include <poll.h>
#include <sys/ioctl.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace wheelchair_can {
namespace {

class LinuxSocketLayer : public SocketLayer {
 public:
  int open(const std::string& interface, const std::vector<CanFilter>& filters) override {
    const int fd = ::socket(PF_CAN, SOCK_RAW | SOCK_NONBLOCK | SOCK_CLOEXEC, CAN_RAW);
    if (fd < 0) return -errno;
    const int r = configure(fd, interface, filters);
    if (r < 0) ::close(fd);
    return r < 0 ? r : fd;
  }

  void close(int fd) override { ::close(fd); }

  int read(int fd, CanFrame* frame, int timeout_ms) override {
    pollfd p{fd, POLLIN, 0};
    const int ready = ::poll(&p, 1, timeout_ms);
    if (ready < 0) return -errno;
    if (ready == 0) return 0;
    if (p.revents & (POLLERR | POLLHUP | POLLNVAL)) return -ENETDOWN;
    struct can_frame raw;
    const ssize_t n = ::recv(fd, &raw, sizeof(raw), MSG_DONTWAIT);
    if (n < 0) return errno == EAGAIN ? 0 : -errno;
    if (n != static_cast<ssize_t>(sizeof(raw))) return -EPROTO;
    *frame = fromLinuxFrame(raw, 0.0);
    return 1;
  }

  int write(int fd, const CanFrame& frame) override {
    struct can_frame raw;
    toLinuxFrame(frame, &raw);
    const ssize_t n = ::send(fd, &raw, sizeof(raw), MSG_DONTWAIT);
    if (n < 0) return -errno;
    return n == static_cast<ssize_t>(sizeof(raw)) ? 0 : -EIO;
  }

 private:
  static int configure(int fd, const std::string& interface,
                       const std::vector<CanFilter>& filters) {
    ifreq ifr{};
    if (interface.size() >= IFNAMSIZ) return -ENAMETOOLONG;
    std::strncpy(ifr.ifr_name, interface.c_str(), IFNAMSIZ - 1);
    if (::ioctl(fd, SIOCGIFINDEX, &ifr) < 0) return -errno;
    std::vector<can_filter> kernel_filters;
    for (const CanFilter& f : filters) kernel_filters.push_back({f.id, f.mask});
    if (!kernel_filters.empty() &&
        ::setsockopt(fd, SOL_CAN_RAW, CAN_RAW_FILTER, kernel_filters.data(),
                     static_cast<socklen_t>(kernel_filters.size() * sizeof(can_filter))) < 0) {
      return -errno;
    }
    const can_err_mask_t errors = CAN_ERR_MASK;
    if (::setsockopt(fd, SOL_CAN_RAW, CAN_RAW_ERR_FILTER, &errors, sizeof(errors)) < 0) {
      return -errno;
    }
    sockaddr_can addr{};
    addr.can_family = AF_CAN;
    addr.can_ifindex = ifr.ifr_ifindex;
    if (::bind(fd, reinterpret_cast<sockaddr*>(&addr), sizeof(addr)) < 0) return -errno;
    return 0;
  }
};

}  // namespace

std::unique_ptr<SocketLayer> makeLinuxSocketLayer() { return std::make_unique<LinuxSocketLayer>(); }

bool canSocketsAvailable(std::string* why) {
  const int fd = ::socket(PF_CAN, SOCK_RAW, CAN_RAW);
  if (fd < 0) {
    if (why)
      *why = std::string("socket(AF_CAN, SOCK_RAW, CAN_RAW) failed: ") + std::strerror(errno);
    return false;
  }
  ::close(fd);
  return true;
}

}  // namespace wheelchair_can
