// The in-process fake bus and the UDP transport.
#include <wheelchair_can/fake_bus.h>
#include <wheelchair_can/udp_transport.h>

#include <gtest/gtest.h>

#include <chrono>
#include <thread>

namespace wheelchair_can {
namespace {

CanFrame frame(std::uint32_t id, std::uint8_t first_byte) {
  CanFrame f;
  f.id = id;
  f.dlc = 2;
  f.data[0] = first_byte;
  f.data[1] = 0xAB;
  return f;
}

TEST(FakeBus, DeliversToEveryOtherEndpointInOrderWithTheBusClock) {
  double now = 1.5;
  auto bus = FakeBus::create([&now] { return now; });
  auto a = bus->connect("a"), b = bus->connect("b"), c = bus->connect("c");
  for (int i = 0; i < 10; ++i) {
    now += 0.001;
    ASSERT_TRUE(a->send(frame(0x100, static_cast<std::uint8_t>(i))));
  }
  std::vector<CanFrame> rb, rc, ra;
  b->receive(rb);
  c->receive(rc);
  a->receive(ra);
  ASSERT_EQ(rb.size(), 10u);
  ASSERT_EQ(rc.size(), 10u);
  EXPECT_TRUE(ra.empty());  // no echo to the sender
  for (int i = 0; i < 10; ++i) {
    EXPECT_EQ(rb[i].data[0], i);
    EXPECT_NEAR(rb[i].stamp, 1.5 + 0.001 * (i + 1), 1e-12);
  }
  EXPECT_EQ(bus->framesCarried(), 10u);
  EXPECT_EQ(a->stats().tx_frames, 10u);
  EXPECT_EQ(b->stats().rx_frames, 10u);
  rb.clear();
  b->receive(rb);
  EXPECT_TRUE(rb.empty());  // drained
}

TEST(FakeBus, FiltersQueueLimitAndLinkDown) {
  auto bus = FakeBus::create();
  auto a = bus->connect("a");
  auto b = bus->connect("b", 3);
  b->setFilters({{0x190, 0x7F0}});  // 0x190..0x19F
  a->send(frame(0x110, 1));
  for (int i = 0; i < 5; ++i) a->send(frame(0x191, static_cast<std::uint8_t>(i)));
  std::vector<CanFrame> rx;
  b->receive(rx);
  ASSERT_EQ(rx.size(), 3u);
  EXPECT_EQ(rx[0].id, 0x191u);
  EXPECT_EQ(b->stats().rx_dropped, 2u);
  CanFrame error;
  error.error = true;
  error.id = 0x40;
  bus->inject(error);  // error frames pass every filter
  rx.clear();
  b->receive(rx);
  ASSERT_EQ(rx.size(), 1u);
  EXPECT_TRUE(rx[0].error);
  EXPECT_EQ(b->stats().error_frames, 1u);
  a->setLinkDown(true);
  EXPECT_FALSE(a->send(frame(0x191, 0)));
  EXPECT_EQ(a->stats().state, BusState::kBusOff);
  EXPECT_EQ(a->stats().tx_failed, 1u);
  CanFrame too_long = frame(0x191, 0);
  too_long.dlc = 9;
  a->setLinkDown(false);
  EXPECT_FALSE(a->send(too_long));
}

TEST(FakeBus, NamedBusIsSharedWhileInUse) {
  auto one = FakeBus::named("test_shared");
  auto two = FakeBus::named("test_shared");
  EXPECT_EQ(one.get(), two.get());
  EXPECT_NE(one.get(), FakeBus::named("other").get());
}

TEST(UdpFrame, PackUnpackRoundTripAndRejectsGarbage) {
  CanFrame f = frame(0x1ABCDEF, 9);
  f.extended = true;
  f.dlc = 8;
  const auto bytes = packUdpFrame(f);
  const auto back = unpackUdpFrame(bytes.data(), bytes.size());
  ASSERT_TRUE(back.has_value());
  EXPECT_EQ(back->id, f.id);
  EXPECT_TRUE(back->extended);
  EXPECT_FALSE(back->error);
  EXPECT_EQ(back->data, f.data);
  EXPECT_FALSE(unpackUdpFrame(bytes.data(), bytes.size() - 1).has_value());
  auto bad = bytes;
  bad[3] = 9;
  EXPECT_FALSE(unpackUdpFrame(bad.data(), bad.size()).has_value());
  bad = bytes;
  bad[0] = 'X';
  EXPECT_FALSE(unpackUdpFrame(bad.data(), bad.size()).has_value());
}

TEST(UdpTransport, CarriesFramesBetweenTwoSocketsAndLearnsThePeer) {
  UdpTransport motor(0, 0, [] { return 2.0; });
  UdpTransport driver(0, motor.localPort(), [] { return 3.0; });
  EXPECT_FALSE(motor.send(frame(0x190, 0)));  // peer unknown yet
  for (int i = 0; i < 100; ++i)
    ASSERT_TRUE(driver.send(frame(0x110, static_cast<std::uint8_t>(i))));
  std::vector<CanFrame> rx;
  for (int tries = 0; tries < 100 && rx.size() < 100; ++tries) {
    motor.receive(rx);
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  ASSERT_EQ(rx.size(), 100u);
  for (int i = 0; i < 100; ++i) ASSERT_EQ(rx[i].data[0], i);
  EXPECT_DOUBLE_EQ(rx[0].stamp, 2.0);
  ASSERT_TRUE(motor.send(frame(0x190, 42)));  // reply to the learnt peer
  rx.clear();
  for (int tries = 0; tries < 100 && rx.empty(); ++tries) {
    driver.receive(rx);
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  ASSERT_EQ(rx.size(), 1u);
  EXPECT_EQ(rx[0].data[0], 42);
}

}  // namespace
}  // namespace wheelchair_can
