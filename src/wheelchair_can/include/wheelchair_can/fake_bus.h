// An in-process CAN bus for tests, benchmarks and a simulator in the same process (like
// socketcan_interface's DummyBus): every frame sent by one endpoint is queued, stamped with the
// bus clock, at every other endpoint whose filters accept it. Deterministic: no threads, time
// injected; thread-safe so that nodelets of one manager can share a named bus.
#pragma once

#include <wheelchair_can/transport.h>

#include <deque>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

namespace wheelchair_can {

class FakeBusEndpoint;

class FakeBus : public std::enable_shared_from_this<FakeBus> {
 public:
  using Clock = std::function<double()>;
  /// `clock` stamps frames [s]; default: always 0.
  static std::shared_ptr<FakeBus> create(Clock clock = {});
  /// Process-wide bus of that name (created on first use), for nodelets sharing one manager.
  static std::shared_ptr<FakeBus> named(const std::string& name);

  /// A new node on the bus with a receive queue of at most `queue_limit` frames.
  std::shared_ptr<FakeBusEndpoint> connect(const std::string& name, std::size_t queue_limit = 4096);
  /// Puts a frame on the bus from outside every endpoint (e.g. an error frame, a foreign node).
  void inject(const CanFrame& frame);
  void setClock(Clock clock);
  /// Frames carried since creation.
  std::uint64_t framesCarried() const;

 private:
  friend class FakeBusEndpoint;
  FakeBus() = default;
  void deliver(const CanFrame& frame, const FakeBusEndpoint* sender);
  void disconnect(const FakeBusEndpoint* endpoint);

  mutable std::mutex mutex_;
  Clock clock_;
  std::vector<FakeBusEndpoint*> endpoints_;
  std::uint64_t carried_ = 0;
};

class FakeBusEndpoint : public CanTransport {
 public:
  ~FakeBusEndpoint() override;
  bool send(const CanFrame& frame) override;
  void receive(std::vector<CanFrame>& out) override;
  TransportStats stats() const override;
  std::string describe() const override;
  void setFilters(std::vector<CanFilter> filters);
  /// While down, send() fails and nothing is received (a cut cable / bus-off simulation).
  void setLinkDown(bool down);

 private:
  friend class FakeBus;
  FakeBusEndpoint(std::shared_ptr<FakeBus> bus, std::string name, std::size_t queue_limit);

  std::shared_ptr<FakeBus> bus_;
  const std::string name_;
  const std::size_t queue_limit_;
  // Guarded by bus_->mutex_.
  std::deque<CanFrame> queue_;
  std::vector<CanFilter> filters_;
  bool link_down_ = false;
  TransportStats stats_;
};

}  // namespace wheelchair_can
