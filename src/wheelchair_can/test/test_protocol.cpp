// Encode/decode of every protocol message: round trips, limits, saturation, fault bits, CRC.
#include <wheelchair_can/protocol.h>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

namespace wheelchair_can::protocol {
namespace {

template <typename T>
T decodeAs(const CanFrame& frame) {
  Message m;
  EXPECT_EQ(decode(frame, &m), DecodeError::kNone);
  EXPECT_TRUE(std::holds_alternative<T>(m));
  return std::get<T>(m);
}

TEST(Crc, MatchesSaeJ1850CheckValue) {
  // CRC-8/SAE-J1850 of "123456789" is 0x4B; our CRC prefixes the identifier's two bytes, so
  // check the algorithm with a frame whose identifier bytes are the first two characters.
  const std::uint8_t rest[] = {'3', '4', '5', '6', '7', '8', '9'};
  EXPECT_EQ(frameCrc('1' | ('2' << 8), rest, sizeof(rest)), 0x4B);
}

TEST(Torque, RawConversionRoundsAndSaturates) {
  EXPECT_EQ(torqueToRaw(0.0), 0);
  EXPECT_EQ(torqueToRaw(1.234), 123);
  EXPECT_EQ(torqueToRaw(-1.236), -124);
  EXPECT_EQ(torqueToRaw(327.67), 32767);
  EXPECT_EQ(torqueToRaw(1e9), 32767);
  EXPECT_EQ(torqueToRaw(-1e9), -32767);
  EXPECT_EQ(torqueToRaw(std::numeric_limits<double>::infinity()), 32767);
  EXPECT_EQ(torqueToRaw(std::nan("")), 0);
  EXPECT_DOUBLE_EQ(rawToTorque(-32768), -327.67);  // never sent, read symmetric
}

TEST(Torque, EveryRawValueRoundTrips) {
  for (int raw = -32767; raw <= 32767; ++raw) {
    TorqueCommand c{rawToTorque(static_cast<std::int16_t>(raw)),
                    rawToTorque(static_cast<std::int16_t>(-raw)), true, false,
                    static_cast<std::uint8_t>(raw)};
    const TorqueCommand d = decodeAs<TorqueCommand>(encode(c));
    ASSERT_EQ(torqueToRaw(d.left), raw);
    ASSERT_EQ(torqueToRaw(d.right), -raw);
    ASSERT_EQ(d.sequence, static_cast<std::uint8_t>(raw));
  }
}

TEST(Torque, LayoutIsLittleEndianCentiNewtonMetres) {
  const CanFrame f = encode(TorqueCommand{2.56, -0.01, true, false, 7});
  EXPECT_EQ(f.id, kTorqueCommandId);
  EXPECT_EQ(f.dlc, 8);
  EXPECT_EQ(f.data[0], 0x00);  // 256 = 0x0100
  EXPECT_EQ(f.data[1], 0x01);
  EXPECT_EQ(f.data[2], 0xFF);  // -1
  EXPECT_EQ(f.data[3], 0xFF);
  EXPECT_EQ(f.data[4], kFlagEnable);
  EXPECT_EQ(f.data[5], 0);
  EXPECT_EQ(f.data[6], 7);
  EXPECT_EQ(f.data[7], frameCrc(f.id, f.data.data(), 7));
}

TEST(Torque, TheTimeTagIsByteFiveIn4msTicksModulo256) {
  const CanFrame f = encode(TorqueCommand{0, 0, true, false, 1, timeTag(1.0)});
  EXPECT_EQ(f.data[5], 250);  // 1.0 s = 250 ticks
  EXPECT_EQ(decodeAs<TorqueCommand>(f).time_tag, 250);
  EXPECT_EQ(timeTag(1.024), 0);  // 256 ticks wrap
  EXPECT_EQ(timeTag(1.0279), 0);
  EXPECT_EQ(timeTag(1.028), 1);
  EXPECT_EQ(timeTag(-0.004), 255);
  EXPECT_NEAR(timeTagAge(timeTag(10.0), 10.1), 0.1, kTimeTagTick);
  EXPECT_NEAR(timeTagAge(timeTag(10.05), 10.0), -0.05, kTimeTagTick);
  EXPECT_NEAR(timeTagAge(timeTag(9.0), 9.5), 0.5, kTimeTagTick);  // the unambiguous range
  EXPECT_EQ(faultBitName(12), "stale_command");
}

TEST(Torque, SaturatesBeyondTheEncodableRange) {
  const TorqueCommand d =
      decodeAs<TorqueCommand>(encode(TorqueCommand{500.0, -400.0, true, false, 0}));
  EXPECT_DOUBLE_EQ(d.left, kMaxEncodableTorque);
  EXPECT_DOUBLE_EQ(d.right, -kMaxEncodableTorque);
}

TEST(Torque, NonFiniteIsEncodedAsBrake) {
  for (double bad : {std::nan(""), std::numeric_limits<double>::infinity(),
                     -std::numeric_limits<double>::infinity()}) {
    const TorqueCommand d =
        decodeAs<TorqueCommand>(encode(TorqueCommand{bad, 1.0, true, false, 0}));
    EXPECT_EQ(d.left, 0.0);
    EXPECT_EQ(d.right, 0.0);
    EXPECT_FALSE(d.enable);
    EXPECT_TRUE(d.brake);
  }
}

TEST(Torque, AllFlagCombinationsRoundTrip) {
  for (bool enable : {false, true}) {
    for (bool brake : {false, true}) {
      const TorqueCommand d =
          decodeAs<TorqueCommand>(encode(TorqueCommand{1, 2, enable, brake, 3}));
      EXPECT_EQ(d.enable, enable);
      EXPECT_EQ(d.brake, brake);
    }
  }
}

TEST(Encoder, CountsRoundTripOverTheFull24BitRange) {
  for (std::uint32_t v : {0u, 1u, 0x7FFFFFu, 0x800000u, 0xFFFFFFu, 0x123456u}) {
    const EncoderCounts d = decodeAs<EncoderCounts>(encode(EncoderCounts{v, 0xFFFFFFu - v, 200}));
    EXPECT_EQ(d.left, v);
    EXPECT_EQ(d.right, 0xFFFFFFu - v);
    EXPECT_EQ(d.sequence, 200);
  }
  // Counts above 24 bits wrap.
  EXPECT_EQ(decodeAs<EncoderCounts>(encode(EncoderCounts{0x1000005u, 0, 0})).left, 5u);
}

TEST(Encoder, DeltaHandlesWrapAround) {
  EXPECT_EQ(encoderDelta(5, 3), 2);
  EXPECT_EQ(encoderDelta(3, 5), -2);
  EXPECT_EQ(encoderDelta(2, 0xFFFFFE), 4);
  EXPECT_EQ(encoderDelta(0xFFFFFE, 2), -4);
  EXPECT_EQ(encoderDelta(0x7FFFFF, 0), 0x7FFFFF);
  EXPECT_EQ(encoderDelta(0x800000, 0), -0x800000);
}

TEST(Status, EveryFaultBitRoundTripsAndHasAName) {
  for (int bit = 0; bit < kFaultBitCount; ++bit) {
    const auto faults = static_cast<std::uint16_t>(1u << bit);
    const ControllerStatus d =
        decodeAs<ControllerStatus>(encode(ControllerStatus{ControllerState::kFault, faults, 9}));
    EXPECT_EQ(d.faults, faults) << "bit " << bit;
    EXPECT_EQ(d.state, ControllerState::kFault);
    EXPECT_EQ(describeFaults(faults), faultBitName(bit));
    EXPECT_FALSE(faultBitName(bit).empty());
  }
  EXPECT_EQ(describeFaults(0), "none");
  EXPECT_EQ(describeFaults(kFaultCommandTimeout | kFaultOvercurrentLeft),
            "overcurrent_left,command_timeout");
  EXPECT_EQ(faultBitName(7), "command_timeout");
  EXPECT_EQ(faultBitName(15), "reserved_15");
}

TEST(Status, EveryStateRoundTrips) {
  for (int s = 0; s <= 3; ++s) {
    const auto state = static_cast<ControllerState>(s);
    EXPECT_EQ(decodeAs<ControllerStatus>(encode(ControllerStatus{state, 0, 1})).state, state);
    EXPECT_EQ(decodeAs<ControllerHeartbeat>(encode(ControllerHeartbeat{state, 1})).state, state);
    const auto driver = static_cast<DriverHeartbeatState>(s);
    EXPECT_EQ(decodeAs<DriverHeartbeat>(encode(DriverHeartbeat{driver, 250})).state, driver);
  }
}

TEST(Decode, RejectsEveryCorruptedByte) {
  const Message messages[] = {TorqueCommand{1.5, -2.5, true, false, 4}, EncoderCounts{10, 20, 5},
                              ControllerStatus{ControllerState::kEnabled, 0, 6},
                              DriverHeartbeat{DriverHeartbeatState::kDriving, 7},
                              ControllerHeartbeat{ControllerState::kEnabled, 8}};
  for (const Message& m : messages) {
    const CanFrame good = encode(m);
    for (int byte = 0; byte < good.dlc; ++byte) {
      for (int bit = 0; bit < 8; ++bit) {
        CanFrame bad = good;
        bad.data[byte] ^= static_cast<std::uint8_t>(1u << bit);
        Message out;
        EXPECT_NE(decode(bad, &out), DecodeError::kNone) << "id " << good.id << " byte " << byte;
      }
    }
  }
}

TEST(Decode, RejectsWrongFraming) {
  const CanFrame good = encode(EncoderCounts{1, 2, 3});
  Message out;
  for (int dlc = 0; dlc <= 15; ++dlc) {
    CanFrame f = good;
    f.dlc = static_cast<std::uint8_t>(dlc);
    EXPECT_EQ(decode(f, &out), dlc == 8 ? DecodeError::kNone : DecodeError::kWrongLength);
  }
  CanFrame f = good;
  f.extended = true;
  EXPECT_EQ(decode(f, &out), DecodeError::kNotStandardData);
  f = good;
  f.remote = true;
  EXPECT_EQ(decode(f, &out), DecodeError::kNotStandardData);
  f = good;
  f.error = true;
  EXPECT_EQ(decode(f, &out), DecodeError::kErrorFrame);
  f = good;
  f.id = 0x191;  // the status identifier with an encoder payload: wrong length
  EXPECT_NE(decode(f, &out), DecodeError::kNone);
  f.id = 0x123;
  EXPECT_EQ(decode(f, &out), DecodeError::kUnknownId);
}

TEST(Decode, RejectsReservedBitsAndUnknownStates) {
  CanFrame f = encode(TorqueCommand{0, 0, false, true, 0});
  f.data[4] |= 0x80;
  f.data[7] = frameCrc(f.id, f.data.data(), 7);
  Message out;
  EXPECT_EQ(decode(f, &out), DecodeError::kReservedBits);
  f = encode(ControllerStatus{ControllerState::kEnabled, 0, 0});
  f.data[0] = 4;
  f.data[4] = frameCrc(f.id, f.data.data(), 4);
  EXPECT_EQ(decode(f, &out), DecodeError::kBadEnum);
}

TEST(Decode, RandomMessagesRoundTrip) {
  std::mt19937 rng(42);
  std::uniform_real_distribution<double> torque(-327.67, 327.67);
  for (int i = 0; i < 10000; ++i) {
    const TorqueCommand c{torque(rng), torque(rng), (rng() & 1) != 0, (rng() & 2) != 0,
                          static_cast<std::uint8_t>(rng())};
    const TorqueCommand d = decodeAs<TorqueCommand>(encode(c));
    ASSERT_NEAR(d.left, c.left, kTorqueLsb / 2 + 1e-12);
    ASSERT_NEAR(d.right, c.right, kTorqueLsb / 2 + 1e-12);
    ASSERT_EQ(d.enable, c.enable);
    ASSERT_EQ(d.brake, c.brake);
    ASSERT_EQ(d.sequence, c.sequence);
  }
}

}  // namespace
}  // namespace wheelchair_can::protocol
