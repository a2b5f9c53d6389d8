// SocketCAN transport: kernel frame conversion, error-frame decoding, and the open / bus-off /
// reopen logic with an injected socket layer; a live test that skips without AF_CAN.
#include <wheelchair_can/socketcan_transport.h>

#include <linux/can.h>
#include <linux/can/error.h>

#include <gtest/gtest.h>

#include <cerrno>
#include <deque>

namespace wheelchair_can {
namespace {

TEST(LinuxFrame, ConversionKeepsIdFlagsAndData) {
  CanFrame f;
  f.id = 0x123;
  f.dlc = 3;
  f.data = {1, 2, 3, 4, 5, 6, 7, 8};
  struct can_frame raw;
  toLinuxFrame(f, &raw);
  EXPECT_EQ(raw.can_id, 0x123u);
  EXPECT_EQ(raw.can_dlc, 3);
  EXPECT_EQ(raw.data[2], 3);
  EXPECT_EQ(raw.data[3], 0);  // bytes beyond the length are not copied
  f.extended = true;
  f.id = 0x1ABCDEF;
  toLinuxFrame(f, &raw);
  EXPECT_EQ(raw.can_id, 0x1ABCDEFu | CAN_EFF_FLAG);
  const CanFrame back = fromLinuxFrame(raw, 4.5);
  EXPECT_TRUE(back.extended);
  EXPECT_EQ(back.id, 0x1ABCDEFu);
  EXPECT_DOUBLE_EQ(back.stamp, 4.5);
  raw.can_id = CAN_ERR_FLAG | CAN_ERR_BUSOFF;
  raw.can_dlc = 8;
  const CanFrame error = fromLinuxFrame(raw, 0);
  EXPECT_TRUE(error.error);
  EXPECT_FALSE(error.extended);
  EXPECT_EQ(error.id, static_cast<std::uint32_t>(CAN_ERR_BUSOFF));
  raw.can_id = 0x7FF | CAN_RTR_FLAG;
  EXPECT_TRUE(fromLinuxFrame(raw, 0).remote);
}

CanFrame errorFrame(std::uint32_t classes, std::uint8_t d1 = 0, std::uint8_t d2 = 0) {
  CanFrame f;
  f.error = true;
  f.id = classes;
  f.dlc = CAN_ERR_DLC;
  f.data[1] = d1;
  f.data[2] = d2;
  return f;
}

TEST(ErrorFrame, EveryClassIsDecoded) {
  const struct {
    std::uint32_t cls;
    const char* text;
  } kClasses[] = {{CAN_ERR_TX_TIMEOUT, "tx timeout"}, {CAN_ERR_LOSTARB, "lost arbitration"},
                  {CAN_ERR_CRTL, "controller"},       {CAN_ERR_PROT, "protocol violation"},
                  {CAN_ERR_TRX, "transceiver"},       {CAN_ERR_ACK, "no ACK"},
                  {CAN_ERR_BUSOFF, "bus-off"},        {CAN_ERR_BUSERROR, "bus error"},
                  {CAN_ERR_RESTARTED, "restarted"}};
  for (const auto& c : kClasses) {
    const CanErrorReport r = decodeErrorFrame(errorFrame(c.cls));
    EXPECT_NE(r.description.find(c.text), std::string::npos) << r.description;
    EXPECT_EQ(r.bus_off, c.cls == CAN_ERR_BUSOFF);
  }
  EXPECT_TRUE(decodeErrorFrame(errorFrame(0)).description.find("unspecified") != std::string::npos);
  EXPECT_TRUE(decodeErrorFrame(CanFrame{}).description.empty());  // not an error frame
}

TEST(ErrorFrame, ControllerDetailsDriveTheBusState) {
  const CanErrorReport warning =
      decodeErrorFrame(errorFrame(CAN_ERR_CRTL, CAN_ERR_CRTL_RX_WARNING));
  EXPECT_TRUE(warning.error_warning);
  EXPECT_EQ(nextBusState(BusState::kActive, warning), BusState::kWarning);
  const CanErrorReport passive =
      decodeErrorFrame(errorFrame(CAN_ERR_CRTL, CAN_ERR_CRTL_TX_PASSIVE));
  EXPECT_EQ(nextBusState(BusState::kWarning, passive), BusState::kErrorPassive);
  const CanErrorReport overflow =
      decodeErrorFrame(errorFrame(CAN_ERR_CRTL, CAN_ERR_CRTL_RX_OVERFLOW));
  EXPECT_TRUE(overflow.overflow);
  EXPECT_EQ(nextBusState(BusState::kActive, overflow), BusState::kActive);
  const CanErrorReport active = decodeErrorFrame(errorFrame(CAN_ERR_CRTL, CAN_ERR_CRTL_ACTIVE));
  EXPECT_EQ(nextBusState(BusState::kErrorPassive, active), BusState::kActive);
  const CanErrorReport prot = decodeErrorFrame(errorFrame(CAN_ERR_PROT, 0, CAN_ERR_PROT_STUFF));
  EXPECT_NE(prot.description.find("stuff"), std::string::npos);
  EXPECT_EQ(nextBusState(BusState::kActive, decodeErrorFrame(errorFrame(CAN_ERR_BUSOFF))),
            BusState::kBusOff);
}

/// A scripted socket layer: counts opens/closes, serves queued read results.
class ScriptedLayer : public SocketLayer {
 public:
  struct Read {
    int result;
    CanFrame frame;
  };
  int open(const std::string&, const std::vector<CanFilter>& filters) override {
    ++opens;
    last_filters = filters;
    return open_result;
  }
  void close(int) override { ++closes; }
  int read(int, CanFrame* frame, int) override {
    if (reads.empty()) return 0;
    const Read r = reads.front();
    reads.pop_front();
    if (r.result == 1) *frame = r.frame;
    return r.result;
  }
  int write(int, const CanFrame& frame) override {
    written.push_back(frame);
    return write_result;
  }
  int open_result = 7, write_result = 0, opens = 0, closes = 0;
  std::vector<CanFilter> last_filters;
  std::deque<Read> reads;
  std::vector<CanFrame> written;
};

struct SocketCanFixture : ::testing::Test {
  SocketCanFixture() {
    auto owned = std::make_unique<ScriptedLayer>();
    layer = owned.get();
    SocketCanTransport::Options options;
    options.interface = "can7";
    options.filters = {{0x190, 0x7F0}};
    options.reopen_delay = 0.5;
    transport =
        std::make_unique<SocketCanTransport>(options, std::move(owned), [this] { return now; });
  }
  double now = 10.0;
  ScriptedLayer* layer;
  std::unique_ptr<SocketCanTransport> transport;
};

TEST_F(SocketCanFixture, OpensWithFiltersReceivesWithTimestampsAndSends) {
  CanFrame data;
  data.id = 0x190;
  data.dlc = 1;
  layer->reads = {{1, data}, {1, data}};
  transport->pollOnce(0);
  EXPECT_EQ(layer->opens, 1);
  ASSERT_EQ(layer->last_filters.size(), 1u);
  EXPECT_EQ(layer->last_filters[0].mask, 0x7F0u);
  std::vector<CanFrame> rx;
  transport->receive(rx);
  ASSERT_EQ(rx.size(), 2u);
  EXPECT_DOUBLE_EQ(rx[0].stamp, 10.0);
  EXPECT_EQ(transport->stats().state, BusState::kActive);
  EXPECT_TRUE(transport->send(data));
  EXPECT_EQ(layer->written.size(), 1u);
  layer->write_result = -EAGAIN;
  EXPECT_FALSE(transport->send(data));
  EXPECT_EQ(transport->stats().tx_failed, 1u);
  EXPECT_EQ(transport->stats().tx_frames, 1u);
}

TEST_F(SocketCanFixture, BusOffClosesAndReopensAfterTheDelay) {
  layer->reads = {{1, errorFrame(CAN_ERR_BUSOFF)}};
  transport->pollOnce(0);
  EXPECT_EQ(layer->closes, 1);
  EXPECT_EQ(transport->stats().state, BusState::kBusOff);
  EXPECT_EQ(transport->stats().error_frames, 1u);
  EXPECT_NE(transport->stats().last_error.find("bus-off"), std::string::npos);
  std::vector<CanFrame> rx;
  transport->receive(rx);
  ASSERT_EQ(rx.size(), 1u);  // the error frame is passed on for diagnostics
  EXPECT_TRUE(rx[0].error);
  EXPECT_FALSE(transport->send(CanFrame{}));  // closed while bus-off
  now += 0.4;
  transport->pollOnce(0);
  EXPECT_EQ(layer->opens, 1);  // not yet
  now += 0.2;
  transport->pollOnce(0);
  EXPECT_EQ(layer->opens, 2);
  EXPECT_EQ(transport->stats().state, BusState::kActive);
  EXPECT_EQ(transport->stats().reopens, 2u);
}

TEST_F(SocketCanFixture, ReadFailureAndOpenFailureRetryLater) {
  layer->reads = {{-ENETDOWN, {}}};
  transport->pollOnce(0);
  EXPECT_EQ(layer->closes, 1);
  EXPECT_EQ(transport->stats().state, BusState::kClosed);
  EXPECT_NE(transport->stats().last_error.find("read from can7 failed"), std::string::npos);
  layer->open_result = -ENODEV;
  now += 1.0;
  transport->pollOnce(0);
  EXPECT_EQ(layer->opens, 2);
  EXPECT_NE(transport->stats().last_error.find("cannot open can7"), std::string::npos);
  now += 0.1;
  transport->pollOnce(0);
  EXPECT_EQ(layer->opens, 2);  // waits reopen_delay between attempts
  layer->open_result = 3;
  now += 0.5;
  transport->pollOnce(0);
  EXPECT_EQ(layer->opens, 3);
  EXPECT_EQ(transport->stats().state, BusState::kActive);
}

TEST_F(SocketCanFixture, WarningAndPassiveStatesAreReported) {
  layer->reads = {{1, errorFrame(CAN_ERR_CRTL, CAN_ERR_CRTL_TX_PASSIVE)}};
  transport->pollOnce(0);
  EXPECT_EQ(transport->stats().state, BusState::kErrorPassive);
  EXPECT_EQ(layer->closes, 0);
}

TEST(SocketCanLive, OpensVcan0WhenTheKernelHasCan) {
  std::string why;
  if (!canSocketsAvailable(&why)) {
    GTEST_SKIP() << "no SocketCAN in this kernel (" << why
                 << "); the transport logic is covered by the scripted-layer tests";
  }
  auto layer = makeLinuxSocketLayer();
  const int fd = layer->open("vcan0", {});
  if (fd < 0) GTEST_SKIP() << "no vcan0 interface (ip link add dev vcan0 type vcan)";
  CanFrame f;
  f.id = 0x123;
  f.dlc = 1;
  EXPECT_EQ(layer->write(fd, f), 0);
  layer->close(fd);
}

}  // namespace
}  // namespace wheelchair_can
