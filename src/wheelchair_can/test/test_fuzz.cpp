// Seeded random fuzzing of the decoder: 10^6 random frames (wheelchair_can_testing's
// randomFrame). Invariants: no crash, and whatever is accepted re-encodes to the same bytes.
// The driver's receive path is fuzzed with the same frames in wheelchair_base_driver.
#include <wheelchair_can/protocol.h>
#include <wheelchair_can_testing/random_frames.h>

#include <gtest/gtest.h>

#include <random>

namespace wheelchair_can {
namespace {

using test::randomFrame;

TEST(Fuzz, DecoderSurvivesAMillionRandomFramesAndOnlyAcceptsWellFormedOnes) {
  std::mt19937_64 rng(20261124);
  std::uint64_t accepted = 0;
  for (int i = 0; i < 1000000; ++i) {
    const CanFrame f = randomFrame(rng);
    protocol::Message m;
    const protocol::DecodeError e = protocol::decode(f, &m);
    if (e != protocol::DecodeError::kNone) continue;
    ++accepted;
    // Whatever was accepted re-encodes to the same bytes: no field was misread.
    const CanFrame again = protocol::encode(m);
    ASSERT_EQ(again.id, f.id);
    ASSERT_EQ(again.dlc, f.dlc);
    for (int b = 0; b < f.dlc; ++b) ASSERT_EQ(again.data[b], f.data[b]) << "id " << f.id;
  }
  EXPECT_GT(accepted, 1000u);  // the valid-CRC share reaches the message decoders
}

}  // namespace
}  // namespace wheelchair_can
