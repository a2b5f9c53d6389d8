#include <wheelchair_can/can_error.h>

#include <linux/can/error.h>

namespace wheelchair_can {
namespace {

void append(std::string& s, const std::string& part) { s += (s.empty() ? "" : "; ") + part; }

std::string controllerDetail(std::uint8_t d, CanErrorReport& r) {
  std::string s;
  if (d & (CAN_ERR_CRTL_RX_OVERFLOW | CAN_ERR_CRTL_TX_OVERFLOW)) {
    r.overflow = true;
    append(s, (d & CAN_ERR_CRTL_RX_OVERFLOW) ? "rx overflow" : "tx overflow");
  }
  if (d & (CAN_ERR_CRTL_RX_WARNING | CAN_ERR_CRTL_TX_WARNING)) {
    r.error_warning = true;
    append(s, "error warning");
  }
  if (d & (CAN_ERR_CRTL_RX_PASSIVE | CAN_ERR_CRTL_TX_PASSIVE)) {
    r.error_passive = true;
    append(s, "error passive");
  }
  if (d & CAN_ERR_CRTL_ACTIVE) {
    r.back_to_active = true;
    append(s, "back to error active");
  }
  return s.empty() ? "unspecified" : s;
}

std::string protocolDetail(std::uint8_t type) {
  static const struct {
    std::uint8_t bit;
    const char* name;
  } kTypes[] = {{CAN_ERR_PROT_BIT, "bit"},
                {CAN_ERR_PROT_FORM, "form"},
                {CAN_ERR_PROT_STUFF, "stuff"},
                {CAN_ERR_PROT_BIT0, "dominant bit"},
                {CAN_ERR_PROT_BIT1, "recessive bit"},
                {CAN_ERR_PROT_OVERLOAD, "overload"},
                {CAN_ERR_PROT_ACTIVE, "active error"},
                {CAN_ERR_PROT_TX, "on transmission"}};
  std::string s;
  for (const auto& t : kTypes) {
    if (type & t.bit) append(s, t.name);
  }
  return s.empty() ? "unspecified" : s;
}

}  // namespace

CanErrorReport decodeErrorFrame(const CanFrame& frame) {
  CanErrorReport r;
  if (!frame.error) return r;
  const std::uint32_t c = frame.id;
  const auto byte = [&frame](int i) { return frame.dlc > i ? frame.data[i] : std::uint8_t{0}; };
  if (c & CAN_ERR_TX_TIMEOUT) append(r.description, "tx timeout");
  if (c & CAN_ERR_LOSTARB)
    append(r.description, "lost arbitration at bit " + std::to_string(byte(0)));
  if (c & CAN_ERR_CRTL) append(r.description, "controller: " + controllerDetail(byte(1), r));
  if (c & CAN_ERR_PROT) append(r.description, "protocol violation: " + protocolDetail(byte(2)));
  if (c & CAN_ERR_TRX) append(r.description, "transceiver fault 0x" + std::to_string(byte(4)));
  if (c & CAN_ERR_ACK) append(r.description, "no ACK");
  if (c & CAN_ERR_BUSOFF) {
    r.bus_off = true;
    append(r.description, "bus-off");
  }
  if (c & CAN_ERR_BUSERROR) append(r.description, "bus error");
  if (c & CAN_ERR_RESTARTED) {
    r.back_to_active = true;
    append(r.description, "controller restarted");
  }
  if (r.description.empty()) r.description = "unspecified error frame";
  return r;
}

BusState nextBusState(BusState current, const CanErrorReport& report) {
  if (report.bus_off) return BusState::kBusOff;
  if (report.error_passive) return BusState::kErrorPassive;
  if (report.error_warning) return BusState::kWarning;
  if (report.back_to_active) return BusState::kActive;
  return current;
}

}  // namespace wheelchair_can
