#include <wheelchair_can/udp_transport.h>

#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>

namespace wheelchair_can {
namespace {
constexpr std::uint8_t kMagic0 = 'W', kMagic1 = 'C';
constexpr std::uint8_t kExtended = 1, kRemote = 2, kError = 4;

sockaddr_in loopback(std::uint16_t port) {
  sockaddr_in a{};
  a.sin_family = AF_INET;
  a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  a.sin_port = htons(port);
  return a;
}
}  // namespace

std::array<std::uint8_t, kUdpFrameSize> packUdpFrame(const CanFrame& f) {
  std::array<std::uint8_t, kUdpFrameSize> b{};
  b[0] = kMagic0;
  b[1] = kMagic1;
  b[2] = static_cast<std::uint8_t>((f.extended ? kExtended : 0) | (f.remote ? kRemote : 0) |
                                   (f.error ? kError : 0));
  b[3] = f.dlc;
  for (int i = 0; i < 4; ++i) b[4 + i] = static_cast<std::uint8_t>((f.id >> (8 * i)) & 0xFF);
  std::memcpy(&b[8], f.data.data(), 8);
  return b;
}

std::optional<CanFrame> unpackUdpFrame(const std::uint8_t* b, std::size_t size) {
  if (size != kUdpFrameSize || b[0] != kMagic0 || b[1] != kMagic1 || b[3] > 8 ||
      (b[2] & ~(kExtended | kRemote | kError)) != 0) {
    return std::nullopt;
  }
  CanFrame f;
  f.extended = b[2] & kExtended;
  f.remote = b[2] & kRemote;
  f.error = b[2] & kError;
  f.dlc = b[3];
  for (int i = 0; i < 4; ++i) f.id |= static_cast<std::uint32_t>(b[4 + i]) << (8 * i);
  std::memcpy(f.data.data(), &b[8], 8);
  return f;
}

UdpTransport::UdpTransport(std::uint16_t local_port, std::uint16_t remote_port, Clock clock,
                           std::vector<CanFilter> filters)
    : clock_(std::move(clock)), filters_(std::move(filters)), remote_port_(remote_port) {
  fd_ = ::socket(AF_INET, SOCK_DGRAM | SOCK_NONBLOCK | SOCK_CLOEXEC, 0);
  if (fd_ < 0) throw std::runtime_error(std::string("UDP socket: ") + std::strerror(errno));
  sockaddr_in a = loopback(local_port);
  socklen_t len = sizeof(a);
  if (::bind(fd_, reinterpret_cast<sockaddr*>(&a), sizeof(a)) < 0 ||
      ::getsockname(fd_, reinterpret_cast<sockaddr*>(&a), &len) < 0) {
    const std::string why = std::strerror(errno);
    ::close(fd_);
    throw std::runtime_error("UDP bind 127.0.0.1:" + std::to_string(local_port) + ": " + why);
  }
  const int buffer = 1 << 20;
  ::setsockopt(fd_, SOL_SOCKET, SO_RCVBUF, &buffer, sizeof(buffer));
  local_port_ = ntohs(a.sin_port);
  stats_.state = BusState::kActive;
}

UdpTransport::~UdpTransport() { ::close(fd_); }

bool UdpTransport::send(const CanFrame& frame) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (remote_port_ == 0 || frame.dlc > 8) {
    ++stats_.tx_failed;
    return false;
  }
  const auto bytes = packUdpFrame(frame);
  const sockaddr_in to = loopback(remote_port_);
  if (::sendto(fd_, bytes.data(), bytes.size(), MSG_DONTWAIT,
               reinterpret_cast<const sockaddr*>(&to),
               sizeof(to)) != static_cast<ssize_t>(bytes.size())) {
    ++stats_.tx_failed;
    stats_.last_error = std::string("sendto: ") + std::strerror(errno);
    return false;
  }
  ++stats_.tx_frames;
  return true;
}

void UdpTransport::receive(std::vector<CanFrame>& out) {
  std::lock_guard<std::mutex> lock(mutex_);
  std::uint8_t buffer[64];
  for (;;) {
    sockaddr_in from{};
    socklen_t len = sizeof(from);
    const ssize_t n = ::recvfrom(fd_, buffer, sizeof(buffer), MSG_DONTWAIT,
                                 reinterpret_cast<sockaddr*>(&from), &len);
    if (n < 0) break;
    std::optional<CanFrame> frame = unpackUdpFrame(buffer, static_cast<std::size_t>(n));
    if (!frame) {
      ++stats_.rx_dropped;
      stats_.last_error = "malformed UDP datagram";
      continue;
    }
    if (remote_port_ == 0) remote_port_ = ntohs(from.sin_port);
    if (!passesFilters(*frame, filters_)) continue;
    frame->stamp = clock_ ? clock_() : 0.0;
    ++(frame->error ? stats_.error_frames : stats_.rx_frames);
    out.push_back(*frame);
  }
}

TransportStats UdpTransport::stats() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return stats_;
}

std::string UdpTransport::describe() const {
  return "UDP 127.0.0.1:" + std::to_string(local_port_) + " -> " + std::to_string(remote_port_);
}

}  // namespace wheelchair_can
