#include <wheelchair_base_driver/transport_factory.h>

#include <wheelchair_base_driver/fake_bus.h>
#include <wheelchair_base_driver/protocol.h>
#include <wheelchair_base_driver/socketcan_transport.h>
#include <wheelchair_base_driver/udp_transport.h>

#include <stdexcept>

namespace wheelchair_base_driver {

std::vector<CanFilter> driverReceiveFilters() {
  // The MC's identifiers, plus the driver's own (to detect a second driver on the bus).
  std::vector<CanFilter> filters;
  for (std::uint32_t id :
       {protocol::kEncoderId, protocol::kControllerStatusId, protocol::kControllerHeartbeatId,
        protocol::kTorqueCommandId, protocol::kDriverHeartbeatId}) {
    filters.push_back({id, 0x7FF});
  }
  return filters;
}

std::shared_ptr<CanTransport> makeTransport(const TransportOptions& o) {
  if (o.kind == "socketcan") {
    SocketCanTransport::Options options;
    options.interface = o.interface;
    options.filters = o.filters;
    auto transport = std::make_shared<SocketCanTransport>(options, makeLinuxSocketLayer(), o.clock);
    transport->start();
    return transport;
  }
  if (o.kind == "udp") {
    if (o.udp_local_port < 0 || o.udp_local_port > 65535 || o.udp_remote_port < 0 ||
        o.udp_remote_port > 65535) {
      throw std::invalid_argument("UDP ports must be in 0..65535");
    }
    return std::make_shared<UdpTransport>(static_cast<std::uint16_t>(o.udp_local_port),
                                          static_cast<std::uint16_t>(o.udp_remote_port), o.clock,
                                          o.filters);
  }
  if (o.kind == "fake") {
    auto bus = FakeBus::named(o.fake_bus);
    if (o.clock) bus->setClock(o.clock);
    auto endpoint = bus->connect("driver");
    endpoint->setFilters(o.filters);
    // The endpoint keeps the bus alive.
    return endpoint;
  }
  throw std::invalid_argument("unknown transport '" + o.kind + "' (socketcan | udp | fake)");
}

}  // namespace wheelchair_base_driver
