#include <wheelchair_base_driver/transport_factory.h>
#include <wheelchair_can/fake_bus.h>
#include <wheelchair_can/protocol.h>
#include <wheelchair_can/socketcan_transport.h>
#include <wheelchair_can/udp_transport.h>
#include <wheelchair_core/config.h>

#include <stdexcept>

namespace wheelchair_base_driver {

namespace can = wheelchair_can;

namespace {
bool validPort(int port) { return port >= 0 && port <= 65535; }
}  // namespace

std::string TransportOptions::validate() const {
  return wheelchair_core::ConfigChecks()
      .check(kind == "socketcan" || kind == "udp" || kind == "fake",
             "unknown transport '" + kind + "' (socketcan | udp | fake)")
      .check(!interface.empty(), "interface must not be empty")
      .check(validPort(udp_local_port) && validPort(udp_remote_port),
             "UDP ports must be in 0..65535")
      .check(!fake_bus.empty(), "fake_bus must not be empty")
      .result();
}

void readTransportOptions(wheelchair_core::ConfigReader& reader, TransportOptions& options) {
  reader.read("transport", options.kind);
  reader.read("interface", options.interface);
  reader.read("udp_local_port", options.udp_local_port);
  reader.read("udp_remote_port", options.udp_remote_port);
  reader.read("fake_bus", options.fake_bus);
}

std::vector<can::CanFilter> driverReceiveFilters() {
  // The MC's identifiers, plus the driver's own (to detect a second driver on the bus).
  std::vector<can::CanFilter> filters;
  for (std::uint32_t id : {can::protocol::kEncoderId, can::protocol::kControllerStatusId,
                           can::protocol::kControllerHeartbeatId, can::protocol::kTorqueCommandId,
                           can::protocol::kDriverHeartbeatId}) {
    filters.push_back({id, 0x7FF});
  }
  return filters;
}

std::shared_ptr<can::CanTransport> makeTransport(const TransportOptions& o) {
  const std::string problem = o.validate();
  if (!problem.empty()) throw std::invalid_argument(problem);
  if (o.kind == "socketcan") {
    can::SocketCanTransport::Options options;
    options.interface = o.interface;
    options.filters = o.filters;
    auto transport =
        std::make_shared<can::SocketCanTransport>(options, can::makeLinuxSocketLayer(), o.clock);
    transport->start();
    return transport;
  }
  if (o.kind == "udp") {
    return std::make_shared<can::UdpTransport>(static_cast<std::uint16_t>(o.udp_local_port),
                                               static_cast<std::uint16_t>(o.udp_remote_port),
                                               o.clock, o.filters);
  }
  auto bus = can::FakeBus::named(o.fake_bus);  // "fake"
  if (o.clock) bus->setClock(o.clock);
  auto endpoint = bus->connect("driver");
  endpoint->setFilters(o.filters);
  // The endpoint keeps the bus alive.
  return endpoint;
}

}  // namespace wheelchair_base_driver
