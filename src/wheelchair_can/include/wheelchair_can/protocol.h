// The CAN 2.0A protocol between the base driver and the chair's motor controller (MC).
// The table in the package README is the normative description; this header implements it.
//
// All multi-byte fields are little-endian. Every frame ends with a CRC-8 (SAE J1850:
// poly 0x1D, init 0xFF, final xor 0xFF) over the 11-bit identifier (low byte, high byte)
// followed by the preceding data bytes. Decoders reject wrong identifiers, wrong lengths,
// bad CRCs, set reserved bits, remote/extended/error frames.
#pragma once

#include <wheelchair_can/can_frame.h>

#include <cstdint>
#include <string>
#include <variant>

namespace wheelchair_can::protocol {

// ---- identifiers (lower = higher bus priority) ----
constexpr std::uint32_t kTorqueCommandId = 0x110;        ///< driver -> MC, 50-100 Hz, DLC 8
constexpr std::uint32_t kEncoderId = 0x190;              ///< MC -> driver, 100 Hz, DLC 8
constexpr std::uint32_t kControllerStatusId = 0x191;     ///< MC -> driver, 100 Hz, DLC 5
constexpr std::uint32_t kDriverHeartbeatId = 0x710;      ///< driver -> MC, 20 Hz, DLC 3
constexpr std::uint32_t kControllerHeartbeatId = 0x711;  ///< MC -> driver, 20 Hz, DLC 3

constexpr std::uint8_t kTorqueCommandLength = 8;
constexpr std::uint8_t kEncoderLength = 8;
constexpr std::uint8_t kControllerStatusLength = 5;
constexpr std::uint8_t kHeartbeatLength = 3;

// ---- scaling ----
constexpr double kTorqueLsb = 0.01;  ///< N m per bit of the int16 torque fields
constexpr double kMaxEncodableTorque = 32767 * kTorqueLsb;  ///< 327.67 N m, saturates beyond
constexpr std::uint32_t kEncoderModulus = 1u << 24;         ///< counts wrap modulo 2^24
/// [s] one tick of the torque command's time tag (byte 5): its creation time on the bus clock in
/// 4 ms ticks modulo 256 (ages are unambiguous within +-0.512 s; the watchdog is 0.1 s).
constexpr double kTimeTagTick = 0.004;

// ---- torque command flags (byte 4) ----
constexpr std::uint8_t kFlagEnable = 0x01;  ///< power stage on; torques are applied
constexpr std::uint8_t kFlagBrake = 0x02;   ///< parking brakes engaged; torques ignored (zero)

// ---- MC fault bits (status bytes 1-2) ----
enum FaultBit : std::uint16_t {
  kFaultOvercurrentLeft = 1u << 0,
  kFaultOvercurrentRight = 1u << 1,
  kFaultOvervoltage = 1u << 2,
  kFaultUndervoltage = 1u << 3,
  kFaultOvertemperature = 1u << 4,
  kFaultEncoderLeft = 1u << 5,
  kFaultEncoderRight = 1u << 6,
  kFaultCommandTimeout = 1u << 7,       ///< no valid torque command for 100 ms
  kFaultDriverHeartbeatLost = 1u << 8,  ///< no driver heartbeat for 200 ms
  kFaultBadCommand = 1u << 9,           ///< a torque command failed to decode (CRC, length)
  kFaultBrake = 1u << 10,               ///< brake did not engage/release
  kFaultHardwareEstop = 1u << 11,       ///< the chair's own stop switch is pressed
  kFaultStaleCommand = 1u << 12,        ///< a drive command older than the command timeout
};
/// Reported but not braking by itself: the MC drops the bad frame and keeps the last valid
/// command (under its watchdog); the driver ends the drive with a controlled stop.
constexpr std::uint16_t kReportOnlyFaults = kFaultBadCommand;
constexpr int kFaultBitCount = 16;
/// Name of fault bit `bit` (0..15); reserved bits are named "reserved_N".
std::string faultBitName(int bit);
/// Comma-separated names of every set bit, or "none".
std::string describeFaults(std::uint16_t faults);

// ---- states ----
enum class ControllerState : std::uint8_t { kInit = 0, kDisabled = 1, kEnabled = 2, kFault = 3 };
enum class DriverHeartbeatState : std::uint8_t {
  kBraking = 0,
  kDriving = 1,
  kFault = 2,
  kEstop = 3
};

// ---- messages ----
struct TorqueCommand {
  double left = 0.0;   ///< N m, positive drives the chair forward
  double right = 0.0;  ///< N m, positive drives the chair forward
  bool enable = false;
  bool brake = true;
  std::uint8_t sequence = 0;
  std::uint8_t time_tag = 0;  ///< timeTag() of the time the command was decided
};
struct EncoderCounts {
  std::uint32_t left = 0;   ///< counts modulo 2^24, increasing when the wheel rolls forward
  std::uint32_t right = 0;  ///< counts modulo 2^24
  std::uint8_t sequence = 0;
};
struct ControllerStatus {
  ControllerState state = ControllerState::kInit;
  std::uint16_t faults = 0;
  std::uint8_t sequence = 0;
};
struct DriverHeartbeat {
  DriverHeartbeatState state = DriverHeartbeatState::kBraking;
  std::uint8_t counter = 0;
};
struct ControllerHeartbeat {
  ControllerState state = ControllerState::kInit;
  std::uint8_t counter = 0;
};
using Message = std::variant<TorqueCommand, EncoderCounts, ControllerStatus, DriverHeartbeat,
                             ControllerHeartbeat>;

enum class DecodeError {
  kNone = 0,
  kErrorFrame,
  kNotStandardData,  ///< extended or remote frame
  kUnknownId,
  kWrongLength,
  kBadCrc,
  kReservedBits,
  kBadEnum,
};
const char* decodeErrorName(DecodeError error);

/// CRC-8/SAE-J1850 of the identifier and the first `length` data bytes.
std::uint8_t frameCrc(std::uint32_t id, const std::uint8_t* data, std::size_t length);

/// Torque [N m] to the int16 field: rounded to 0.01 N m, saturated at +-327.67 N m; NaN -> 0.
std::int16_t torqueToRaw(double torque);
double rawToTorque(std::int16_t raw);

/// Signed difference a - b of two 24-bit wrapping counters, in [-2^23, 2^23).
std::int32_t encoderDelta(std::uint32_t a, std::uint32_t b);

/// The time tag of `time` [s on the bus clock]: floor(time / kTimeTagTick) modulo 256.
std::uint8_t timeTag(double time);
/// [s] how long before `now` a command tagged `tag` was decided, in [-0.512, 0.508) (a multiple
/// of the tick: +-1 tick of quantization).
double timeTagAge(std::uint8_t tag, double now);

/// Encoders. A command with non-finite torque is encoded as zero torque with the brake set.
CanFrame encode(const TorqueCommand& message);
CanFrame encode(const EncoderCounts& message);
CanFrame encode(const ControllerStatus& message);
CanFrame encode(const DriverHeartbeat& message);
CanFrame encode(const ControllerHeartbeat& message);
CanFrame encode(const Message& message);

/// Decodes any protocol frame; `out` is written only on success.
DecodeError decode(const CanFrame& frame, Message* out);

}  // namespace wheelchair_can::protocol
