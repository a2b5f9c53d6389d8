// The driver's CAN transport from its name (socketcan | udp | fake) and options
// (wheelchair_can's transports). One parameter pattern: defaults here, validate(), the keys in
// readTransportOptions.
#pragma once

#include <wheelchair_can/can_frame.h>
#include <wheelchair_can/transport.h>

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace wheelchair_core {
class ConfigReader;
}

namespace wheelchair_base_driver {

struct TransportOptions {
  std::string kind = "socketcan";           ///< socketcan | udp | fake
  std::string interface = "can0";           ///< SocketCAN interface
  int udp_local_port = 47110;               ///< 0 = any free port
  int udp_remote_port = 47111;              ///< 0 = learn from the first datagram
  std::string fake_bus = "wheelchair_can";  ///< process-wide fake bus name
  std::vector<wheelchair_can::CanFilter> filters;
  std::function<double()> clock;  ///< stamps received frames [s]

  /// "" if usable, else every problem (an unknown kind, a port outside 0..65535).
  std::string validate() const;
};

/// Keys: transport (the kind), interface, udp_local_port, udp_remote_port, fake_bus.
void readTransportOptions(wheelchair_core::ConfigReader& reader, TransportOptions& options);

/// Throws std::invalid_argument for invalid options, std::runtime_error if it cannot open.
std::shared_ptr<wheelchair_can::CanTransport> makeTransport(const TransportOptions& options);

/// The receive filters of the driver: the motor controller's identifiers only.
std::vector<wheelchair_can::CanFilter> driverReceiveFilters();

}  // namespace wheelchair_base_driver
