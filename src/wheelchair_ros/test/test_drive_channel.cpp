// The in-process command path: one endpoint per role, calls reach who is attached, nothing
// reaches a detached one, a second driver / supervisor / controller is refused, and the rider's
// release reaches both latches.
#include <gtest/gtest.h>
#include <wheelchair_ros/drive_channel.h>

#include <atomic>
#include <thread>
#include <vector>

namespace wheelchair_ros {
namespace {

TEST(DriveChannel, CommandsAndPermitsReachTheAttachedDriverOnly) {
  auto channel = std::make_shared<DriveChannel>();
  DriveCommand command;
  command.left = 1.5;
  EXPECT_FALSE(channel->submit(command)) << "no driver: nothing to command";
  std::vector<DriveCommand> received;
  std::vector<DrivePermit> permits;
  {
    auto driver =
        channel->attachDriver({[&](const DriveCommand& c) {
                                 received.push_back(c);
                                 return true;
                               },
                               [&](const DrivePermit& p) { permits.push_back(p); }, nullptr});
    auto controller = channel->attachController({});
    EXPECT_TRUE(channel->submit(command));
    DrivePermit permit;
    permit.sequence = 7;
    EXPECT_TRUE(channel->grant(permit));
    ASSERT_EQ(received.size(), 1u);
    EXPECT_EQ(received[0].left, 1.5);
    EXPECT_NE(received[0].session, 0u) << "the channel names the controller's attachment";
    ASSERT_EQ(permits.size(), 1u);
    EXPECT_EQ(permits[0].sequence, 7u);
    EXPECT_EQ(permits[0].session, 0u) << "no supervisor attached: session 0";
  }
  EXPECT_FALSE(channel->submit(command)) << "the driver was unloaded";
  EXPECT_FALSE(channel->grant(DrivePermit()));
  EXPECT_EQ(received.size(), 1u);
}

TEST(DriveChannel, ASecondNodeletInARoleIsRefused) {
  auto channel = std::make_shared<DriveChannel>();
  auto driver = channel->attachDriver({});
  EXPECT_THROW(channel->attachDriver({}), std::logic_error);
  auto supervisor = channel->attachSupervisor({});
  EXPECT_THROW(channel->attachSupervisor({}), std::logic_error);
  auto controller = channel->attachController({});
  EXPECT_THROW(channel->attachController({}), std::logic_error);
  driver.reset();
  EXPECT_FALSE(channel->hasDriver());
  EXPECT_NO_THROW(channel->attachDriver({}));
}

TEST(DriveChannel, AReattachedControllerIsANewSession) {
  auto channel = std::make_shared<DriveChannel>();
  std::vector<std::uint64_t> sessions;
  auto driver = channel->attachDriver({[&](const DriveCommand& c) {
                                         sessions.push_back(c.session);
                                         return true;
                                       },
                                       nullptr, nullptr});
  channel->attachController({}).reset();
  auto first = channel->attachController({});
  channel->submit(DriveCommand());
  first.reset();
  auto second = channel->attachController({});
  channel->submit(DriveCommand());
  ASSERT_EQ(sessions.size(), 2u);
  EXPECT_NE(sessions[0], sessions[1]);
}

TEST(DriveChannel, TheRidersReleaseReachesTheDriverThenTheSupervisor) {
  auto channel = std::make_shared<DriveChannel>();
  EXPECT_FALSE(channel->releaseByRider({1.0, "hmi"}));
  std::vector<std::string> order;
  auto driver = channel->attachDriver(
      {nullptr, nullptr, [&](const RiderRelease& r) { order.push_back("driver " + r.source); }});
  auto supervisor = channel->attachSupervisor(
      {nullptr, [&](const RiderRelease& r) { order.push_back("supervisor " + r.source); }});
  EXPECT_TRUE(channel->releaseByRider({2.0, "hmi"}));
  EXPECT_EQ(order, (std::vector<std::string>{"driver hmi", "supervisor hmi"}));
}

TEST(DriveChannel, ReportsAndHoldsReachSupervisorAndController) {
  auto channel = std::make_shared<DriveChannel>();
  int supervisor_reports = 0, controller_reports = 0, holds = 0;
  auto supervisor =
      channel->attachSupervisor({[&](const DriverReport&) { ++supervisor_reports; }, nullptr});
  EXPECT_FALSE(channel->hold(SafetyHold()));
  auto controller =
      channel->attachController({[&](const SafetyHold& h) { holds += h.stop; },
                                 [&](const DriverReport& r) { controller_reports += r.latched; }});
  DriverReport report;
  report.latched = true;
  EXPECT_TRUE(channel->report(report));
  SafetyHold hold;
  hold.stop = true;
  EXPECT_TRUE(channel->hold(hold));
  EXPECT_EQ(supervisor_reports, 1);
  EXPECT_EQ(controller_reports, 1);
  EXPECT_EQ(holds, 1);
}

// Unloading waits for a call in progress: after the Registration is gone no handler runs, so a
// nodelet's destructor may free what its handlers use.
TEST(DriveChannel, DetachWaitsForACallInProgress) {
  auto channel = std::make_shared<DriveChannel>();
  std::atomic<bool> in_call{false}, finished{false};
  auto driver =
      channel->attachDriver({[&](const DriveCommand&) {
                               in_call = true;
                               std::this_thread::sleep_for(std::chrono::milliseconds(100));
                               finished = true;
                               return true;
                             },
                             nullptr, nullptr});
  std::thread caller([&] { channel->submit(DriveCommand()); });
  while (!in_call) std::this_thread::yield();
  driver.reset();
  EXPECT_TRUE(finished) << "detached while the driver's handler still ran";
  caller.join();
  EXPECT_FALSE(channel->submit(DriveCommand()));
}

TEST(DriveChannel, TheProcessHasOneChannel) {
  auto a = driveChannel();
  auto b = driveChannel();
  EXPECT_EQ(a.get(), b.get());
}

}  // namespace
}  // namespace wheelchair_ros
