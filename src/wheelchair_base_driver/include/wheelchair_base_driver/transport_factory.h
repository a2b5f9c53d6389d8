// Builds a transport from its name (socketcan | udp | fake) and options.
#pragma once

#include <wheelchair_base_driver/transport.h>

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace wheelchair_base_driver {

struct TransportOptions {
  std::string kind = "socketcan";           ///< socketcan | udp | fake
  std::string interface = "can0";           ///< SocketCAN interface
  int udp_local_port = 47110;               ///< 0 = any free port
  int udp_remote_port = 47111;              ///< 0 = learn from the first datagram
  std::string fake_bus = "wheelchair_can";  ///< process-wide fake bus name
  std::vector<CanFilter> filters;
  std::function<double()> clock;  ///< stamps received frames [s]
};

/// Throws std::invalid_argument for an unknown kind, std::runtime_error if it cannot open.
std::shared_ptr<CanTransport> makeTransport(const TransportOptions& options);

/// The receive filters of the driver: the motor controller's identifiers only.
std::vector<CanFilter> driverReceiveFilters();

}  // namespace wheelchair_base_driver
