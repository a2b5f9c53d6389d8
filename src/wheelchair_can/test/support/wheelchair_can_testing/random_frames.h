// Random CAN frames for the fuzz tests of the decoder (wheelchair_can) and of the driver's
// receive path (wheelchair_base_driver): random identifiers, lengths 0-8 and payloads,
// extended / remote / error frames, and frames with a valid CRC on the protocol's identifiers
// (so that the message decoders accept some of them).
#pragma once

#include <wheelchair_can/can_frame.h>

#include <random>

namespace wheelchair_can::test {

CanFrame randomFrame(std::mt19937_64& rng);

}  // namespace wheelchair_can::test
