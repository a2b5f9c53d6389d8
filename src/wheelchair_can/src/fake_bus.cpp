#include <wheelchair_can/fake_bus.h>

#include <algorithm>
#include <map>

namespace wheelchair_can {

const char* busStateName(BusState state) {
  switch (state) {
    case BusState::kClosed:
      return "closed";
    case BusState::kActive:
      return "error_active";
    case BusState::kWarning:
      return "error_warning";
    case BusState::kErrorPassive:
      return "error_passive";
    case BusState::kBusOff:
      return "bus_off";
  }
  return "?";
}

std::shared_ptr<FakeBus> FakeBus::create(Clock clock) {
  std::shared_ptr<FakeBus> bus(new FakeBus());
  bus->clock_ = std::move(clock);
  return bus;
}

std::shared_ptr<FakeBus> FakeBus::named(const std::string& name) {
  static std::mutex registry_mutex;
  static std::map<std::string, std::weak_ptr<FakeBus>> registry;
  std::lock_guard<std::mutex> lock(registry_mutex);
  std::shared_ptr<FakeBus> bus = registry[name].lock();
  if (!bus) {
    bus = create();
    registry[name] = bus;
  }
  return bus;
}

std::shared_ptr<FakeBusEndpoint> FakeBus::connect(const std::string& name,
                                                  std::size_t queue_limit) {
  std::shared_ptr<FakeBusEndpoint> endpoint(
      new FakeBusEndpoint(shared_from_this(), name, queue_limit));
  std::lock_guard<std::mutex> lock(mutex_);
  endpoints_.push_back(endpoint.get());
  endpoint->stats_.state = BusState::kActive;
  return endpoint;
}

void FakeBus::inject(const CanFrame& frame) { deliver(frame, nullptr); }

void FakeBus::setClock(Clock clock) {
  std::lock_guard<std::mutex> lock(mutex_);
  clock_ = std::move(clock);
}

std::uint64_t FakeBus::framesCarried() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return carried_;
}

void FakeBus::deliver(const CanFrame& frame, const FakeBusEndpoint* sender) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (sender != nullptr && sender->link_down_) return;
  CanFrame stamped = frame;
  stamped.stamp = clock_ ? clock_() : 0.0;
  ++carried_;
  for (FakeBusEndpoint* e : endpoints_) {
    if (e == sender || e->link_down_ || !passesFilters(stamped, e->filters_)) continue;
    if (e->queue_.size() >= e->queue_limit_) {
      ++e->stats_.rx_dropped;
      continue;
    }
    e->queue_.push_back(stamped);
  }
}

void FakeBus::disconnect(const FakeBusEndpoint* endpoint) {
  std::lock_guard<std::mutex> lock(mutex_);
  endpoints_.erase(std::remove(endpoints_.begin(), endpoints_.end(), endpoint), endpoints_.end());
}

FakeBusEndpoint::FakeBusEndpoint(std::shared_ptr<FakeBus> bus, std::string name,
                                 std::size_t queue_limit)
    : bus_(std::move(bus)), name_(std::move(name)), queue_limit_(queue_limit) {}

FakeBusEndpoint::~FakeBusEndpoint() { bus_->disconnect(this); }

bool FakeBusEndpoint::send(const CanFrame& frame) {
  {
    std::lock_guard<std::mutex> lock(bus_->mutex_);
    if (link_down_ || frame.dlc > 8) {
      ++stats_.tx_failed;
      return false;
    }
    ++stats_.tx_frames;
  }
  bus_->deliver(frame, this);
  return true;
}

void FakeBusEndpoint::receive(std::vector<CanFrame>& out) {
  std::lock_guard<std::mutex> lock(bus_->mutex_);
  for (const CanFrame& f : queue_) {
    if (f.error) {
      ++stats_.error_frames;
    } else {
      ++stats_.rx_frames;
    }
    out.push_back(f);
  }
  queue_.clear();
}

TransportStats FakeBusEndpoint::stats() const {
  std::lock_guard<std::mutex> lock(bus_->mutex_);
  return stats_;
}

std::string FakeBusEndpoint::describe() const { return "fake bus endpoint '" + name_ + "'"; }

void FakeBusEndpoint::setFilters(std::vector<CanFilter> filters) {
  std::lock_guard<std::mutex> lock(bus_->mutex_);
  filters_ = std::move(filters);
}

void FakeBusEndpoint::setLinkDown(bool down) {
  std::lock_guard<std::mutex> lock(bus_->mutex_);
  link_down_ = down;
  stats_.state = down ? BusState::kBusOff : BusState::kActive;
  if (down) queue_.clear();
}

}  // namespace wheelchair_can
