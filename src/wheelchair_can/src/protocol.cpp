#include <wheelchair_can/protocol.h>

#include <cmath>

namespace wheelchair_can::protocol {
namespace {

void putU16(std::uint8_t* p, std::uint16_t v) {
  p[0] = static_cast<std::uint8_t>(v & 0xFF);
  p[1] = static_cast<std::uint8_t>(v >> 8);
}
std::uint16_t getU16(const std::uint8_t* p) {
  return static_cast<std::uint16_t>(p[0] | (static_cast<std::uint16_t>(p[1]) << 8));
}
void putU24(std::uint8_t* p, std::uint32_t v) {
  for (int i = 0; i < 3; ++i) p[i] = static_cast<std::uint8_t>((v >> (8 * i)) & 0xFF);
}
std::uint32_t getU24(const std::uint8_t* p) {
  return static_cast<std::uint32_t>(p[0]) | (static_cast<std::uint32_t>(p[1]) << 8) |
         (static_cast<std::uint32_t>(p[2]) << 16);
}

/// A frame with identifier and length set; the CRC is appended by seal().
CanFrame makeFrame(std::uint32_t id, std::uint8_t length) {
  CanFrame frame;
  frame.id = id;
  frame.dlc = length;
  return frame;
}
CanFrame seal(CanFrame frame) {
  frame.data[frame.dlc - 1] = frameCrc(frame.id, frame.data.data(), frame.dlc - 1);
  return frame;
}

bool validControllerState(std::uint8_t v) { return v <= 3; }

/// Checks identifier-independent framing: length and CRC.
DecodeError checkFraming(const CanFrame& frame, std::uint8_t length) {
  if (frame.dlc != length) return DecodeError::kWrongLength;
  if (frameCrc(frame.id, frame.data.data(), length - 1) != frame.data[length - 1]) {
    return DecodeError::kBadCrc;
  }
  return DecodeError::kNone;
}

DecodeError decodeTorque(const CanFrame& f, Message* out) {
  if (const DecodeError e = checkFraming(f, kTorqueCommandLength); e != DecodeError::kNone) {
    return e;
  }
  const std::uint8_t flags = f.data[4];
  if ((flags & ~(kFlagEnable | kFlagBrake)) != 0) return DecodeError::kReservedBits;
  TorqueCommand m;
  m.left = rawToTorque(static_cast<std::int16_t>(getU16(&f.data[0])));
  m.right = rawToTorque(static_cast<std::int16_t>(getU16(&f.data[2])));
  m.enable = (flags & kFlagEnable) != 0;
  m.brake = (flags & kFlagBrake) != 0;
  m.sequence = f.data[6];
  m.time_tag = f.data[5];
  *out = m;
  return DecodeError::kNone;
}

DecodeError decodeEncoder(const CanFrame& f, Message* out) {
  if (const DecodeError e = checkFraming(f, kEncoderLength); e != DecodeError::kNone) return e;
  EncoderCounts m;
  m.left = getU24(&f.data[0]);
  m.right = getU24(&f.data[3]);
  m.sequence = f.data[6];
  *out = m;
  return DecodeError::kNone;
}

DecodeError decodeStatus(const CanFrame& f, Message* out) {
  if (const DecodeError e = checkFraming(f, kControllerStatusLength); e != DecodeError::kNone) {
    return e;
  }
  if (!validControllerState(f.data[0])) return DecodeError::kBadEnum;
  ControllerStatus m;
  m.state = static_cast<ControllerState>(f.data[0]);
  m.faults = getU16(&f.data[1]);
  m.sequence = f.data[3];
  *out = m;
  return DecodeError::kNone;
}

DecodeError decodeDriverHeartbeat(const CanFrame& f, Message* out) {
  if (const DecodeError e = checkFraming(f, kHeartbeatLength); e != DecodeError::kNone) return e;
  if (f.data[0] > 3) return DecodeError::kBadEnum;
  *out = DriverHeartbeat{static_cast<DriverHeartbeatState>(f.data[0]), f.data[1]};
  return DecodeError::kNone;
}

DecodeError decodeControllerHeartbeat(const CanFrame& f, Message* out) {
  if (const DecodeError e = checkFraming(f, kHeartbeatLength); e != DecodeError::kNone) return e;
  if (!validControllerState(f.data[0])) return DecodeError::kBadEnum;
  *out = ControllerHeartbeat{static_cast<ControllerState>(f.data[0]), f.data[1]};
  return DecodeError::kNone;
}

}  // namespace

std::string faultBitName(int bit) {
  static const char* const kNames[] = {
      "overcurrent_left",      "overcurrent_right", "overvoltage",   "undervoltage",
      "overtemperature",       "encoder_left",      "encoder_right", "command_timeout",
      "driver_heartbeat_lost", "bad_command",       "brake",         "hardware_estop",
      "stale_command"};
  if (bit >= 0 && bit < static_cast<int>(sizeof(kNames) / sizeof(kNames[0]))) return kNames[bit];
  return "reserved_" + std::to_string(bit);
}

std::string describeFaults(std::uint16_t faults) {
  if (faults == 0) return "none";
  std::string out;
  for (int bit = 0; bit < kFaultBitCount; ++bit) {
    if (faults & (1u << bit)) out += (out.empty() ? "" : ",") + faultBitName(bit);
  }
  return out;
}

const char* decodeErrorName(DecodeError error) {
  switch (error) {
    case DecodeError::kNone:
      return "none";
    case DecodeError::kErrorFrame:
      return "error_frame";
    case DecodeError::kNotStandardData:
      return "not_standard_data_frame";
    case DecodeError::kUnknownId:
      return "unknown_id";
    case DecodeError::kWrongLength:
      return "wrong_length";
    case DecodeError::kBadCrc:
      return "bad_crc";
    case DecodeError::kReservedBits:
      return "reserved_bits";
    case DecodeError::kBadEnum:
      return "bad_enum";
  }
  return "?";
}

std::uint8_t frameCrc(std::uint32_t id, const std::uint8_t* data, std::size_t length) {
  std::uint8_t crc = 0xFF;
  const auto feed = [&crc](std::uint8_t byte) {
    crc ^= byte;
    for (int i = 0; i < 8; ++i) {
      crc = (crc & 0x80) ? static_cast<std::uint8_t>((crc << 1) ^ 0x1D)
                         : static_cast<std::uint8_t>(crc << 1);
    }
  };
  feed(static_cast<std::uint8_t>(id & 0xFF));
  feed(static_cast<std::uint8_t>((id >> 8) & 0xFF));
  for (std::size_t i = 0; i < length; ++i) feed(data[i]);
  return static_cast<std::uint8_t>(crc ^ 0xFF);
}

std::int16_t torqueToRaw(double torque) {
  if (!std::isfinite(torque)) return std::isnan(torque) ? 0 : (torque > 0 ? 32767 : -32767);
  const double raw = std::round(torque / kTorqueLsb);
  if (raw >= 32767.0) return 32767;
  if (raw <= -32767.0) return -32767;  // symmetric range: -32768 is never sent
  return static_cast<std::int16_t>(raw);
}

double rawToTorque(std::int16_t raw) { return (raw == -32768 ? -32767 : raw) * kTorqueLsb; }

std::int32_t encoderDelta(std::uint32_t a, std::uint32_t b) {
  const std::uint32_t d = (a - b) & (kEncoderModulus - 1);
  return d >= (kEncoderModulus >> 1)
             ? static_cast<std::int32_t>(d) - static_cast<std::int32_t>(kEncoderModulus)
             : static_cast<std::int32_t>(d);
}

std::uint8_t timeTag(double time) {
  const double ticks = std::floor(time / kTimeTagTick);
  if (!std::isfinite(ticks)) return 0;
  return static_cast<std::uint8_t>(static_cast<std::int64_t>(std::fmod(ticks, 256.0) + 256.0) &
                                   0xFF);
}

double timeTagAge(std::uint8_t tag, double now) {
  const auto ticks = static_cast<std::int8_t>(static_cast<std::uint8_t>(timeTag(now) - tag));
  return ticks * kTimeTagTick;
}

CanFrame encode(const TorqueCommand& m) {
  CanFrame f = makeFrame(kTorqueCommandId, kTorqueCommandLength);
  const bool finite = std::isfinite(m.left) && std::isfinite(m.right);
  putU16(&f.data[0], static_cast<std::uint16_t>(finite ? torqueToRaw(m.left) : 0));
  putU16(&f.data[2], static_cast<std::uint16_t>(finite ? torqueToRaw(m.right) : 0));
  f.data[4] =
      finite ? static_cast<std::uint8_t>((m.enable ? kFlagEnable : 0) | (m.brake ? kFlagBrake : 0))
             : kFlagBrake;
  f.data[5] = m.time_tag;
  f.data[6] = m.sequence;
  return seal(f);
}

CanFrame encode(const EncoderCounts& m) {
  CanFrame f = makeFrame(kEncoderId, kEncoderLength);
  putU24(&f.data[0], m.left & (kEncoderModulus - 1));
  putU24(&f.data[3], m.right & (kEncoderModulus - 1));
  f.data[6] = m.sequence;
  return seal(f);
}

CanFrame encode(const ControllerStatus& m) {
  CanFrame f = makeFrame(kControllerStatusId, kControllerStatusLength);
  f.data[0] = static_cast<std::uint8_t>(m.state);
  putU16(&f.data[1], m.faults);
  f.data[3] = m.sequence;
  return seal(f);
}

CanFrame encode(const DriverHeartbeat& m) {
  CanFrame f = makeFrame(kDriverHeartbeatId, kHeartbeatLength);
  f.data[0] = static_cast<std::uint8_t>(m.state);
  f.data[1] = m.counter;
  return seal(f);
}

CanFrame encode(const ControllerHeartbeat& m) {
  CanFrame f = makeFrame(kControllerHeartbeatId, kHeartbeatLength);
  f.data[0] = static_cast<std::uint8_t>(m.state);
  f.data[1] = m.counter;
  return seal(f);
}

CanFrame encode(const Message& message) {
  return std::visit([](const auto& m) { return encode(m); }, message);
}

DecodeError decode(const CanFrame& frame, Message* out) {
  if (frame.error) return DecodeError::kErrorFrame;
  if (frame.extended || frame.remote) return DecodeError::kNotStandardData;
  switch (frame.id) {
    case kTorqueCommandId:
      return decodeTorque(frame, out);
    case kEncoderId:
      return decodeEncoder(frame, out);
    case kControllerStatusId:
      return decodeStatus(frame, out);
    case kDriverHeartbeatId:
      return decodeDriverHeartbeat(frame, out);
    case kControllerHeartbeatId:
      return decodeControllerHeartbeat(frame, out);
    default:
      return DecodeError::kUnknownId;
  }
}

}  // namespace wheelchair_can::protocol
