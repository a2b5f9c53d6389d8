// Benchmark of the CAN path (called by bench/can/run; prints a JSON array on stdout):
//  1. frames/s through the in-process fake bus (raw, and encode+send+receive+decode);
//  2. a real-time run: torque messages at 1 kHz (a producer thread, like a ROS callback queue)
//     -> BaseDriverCore -> transport -> the chair side, which checks every torque frame for
//     lost / duplicated / reordered frames and messages and measures the latency from the
//     message's creation to the frame's stamp (fake bus: stamped when put on the bus; UDP:
//     stamped when received by the other process' socket).
#include <wheelchair_base_driver/base_driver_core.h>
#include <wheelchair_can/fake_bus.h>
#include <wheelchair_can/udp_transport.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <cstdio>
#include <cstring>
#include <deque>
#include <mutex>
#include <numeric>
#include <string>
#include <thread>
#include <vector>

using namespace wheelchair_base_driver;
using namespace wheelchair_can;
using Clock = std::chrono::steady_clock;

namespace {

const Clock::time_point kEpoch = Clock::now();
double seconds() { return std::chrono::duration<double>(Clock::now() - kEpoch).count(); }

struct Result {
  std::string c, method, metric;
  double value;
  std::string unit;
};
std::vector<Result> results;

double rawFakeBusThroughput(std::size_t frames) {
  auto bus = FakeBus::create(seconds);
  auto a = bus->connect("a", 2048), b = bus->connect("b", 2048);
  std::vector<CanFrame> rx;
  CanFrame f;
  f.id = 0x110;
  f.dlc = 8;
  const double start = seconds();
  for (std::size_t i = 0; i < frames; i += 1000) {
    for (int k = 0; k < 1000; ++k) a->send(f);
    rx.clear();
    b->receive(rx);
  }
  return static_cast<double>(frames) / (seconds() - start);
}

double protocolFakeBusThroughput(std::size_t frames) {
  auto bus = FakeBus::create(seconds);
  auto a = bus->connect("a", 2048), b = bus->connect("b", 2048);
  std::vector<CanFrame> rx;
  std::size_t decoded = 0;
  const double start = seconds();
  for (std::size_t i = 0; i < frames; i += 1000) {
    for (int k = 0; k < 1000; ++k) {
      a->send(protocol::encode(
          protocol::TorqueCommand{0.01 * k, -0.01 * k, true, false, static_cast<std::uint8_t>(k)}));
    }
    rx.clear();
    b->receive(rx);
    protocol::Message m;
    for (const CanFrame& r : rx) decoded += protocol::decode(r, &m) == protocol::DecodeError::kNone;
  }
  const double rate = static_cast<double>(frames) / (seconds() - start);
  return decoded == frames ? rate : -1.0;
}

struct RealtimeOutcome {
  std::uint64_t messages = 0, frames = 0, lost_frames = 0, duplicated = 0, reordered = 0;
  std::uint64_t lost_messages = 0, repeats = 0;
  double mean_us = 0, p99_us = 0, max_us = 0;
};

constexpr int kIndexModulus = 4000;
double indexTorque(std::uint64_t i) {
  return (static_cast<double>(i % kIndexModulus) - 2000) * 0.01;
}
int torqueIndex(double t) { return static_cast<int>(std::lround(t / 0.01)) + 2000; }

RealtimeOutcome runRealtime(CanTransport& driver_port, CanTransport& chair_port, double duration,
                            double rate) {
  DriverConfig config;
  config.geometry = {0.17, 0.275, 4096, 40};
  config.max_torque = 25;
  config.max_speed = 1.5;
  BaseDriverCore driver(config, driver_port);
  std::mutex mutex;
  std::condition_variable cv;
  std::deque<std::pair<std::uint64_t, double>> queue;  // (index, creation time)
  std::vector<double> created(static_cast<std::size_t>(duration * rate) + 16, -1.0);
  std::atomic<bool> producing{false}, done{false};
  RealtimeOutcome out;

  // The chair: healthy heartbeats/status every 10 ms; checks every torque frame.
  std::thread chair([&] {
    std::vector<CanFrame> rx;
    std::uint8_t counter = 0;
    SequenceTracker sequence;
    int expected = -1;
    std::vector<double> latencies;
    constexpr std::uint64_t kNone = ~0ull;
    std::uint64_t next_message = kNone;
    double next_heartbeat = 0;
    while (!done) {
      const double now = seconds();
      if (now >= next_heartbeat) {
        chair_port.send(protocol::encode(
            protocol::ControllerHeartbeat{protocol::ControllerState::kEnabled, counter}));
        chair_port.send(protocol::encode(
            protocol::ControllerStatus{protocol::ControllerState::kEnabled, 0, counter++}));
        next_heartbeat = now + 0.01;
      }
      rx.clear();
      chair_port.receive(rx);
      for (const CanFrame& f : rx) {
        protocol::Message m;
        if (protocol::decode(f, &m) != protocol::DecodeError::kNone) continue;
        const auto* c = std::get_if<protocol::TorqueCommand>(&m);
        if (c == nullptr || !c->enable) continue;
        ++out.frames;
        std::uint32_t lost = 0;
        const auto verdict = sequence.accept(c->sequence, &lost);
        if (verdict == SequenceTracker::Verdict::kDuplicate) ++out.duplicated;
        if (verdict == SequenceTracker::Verdict::kReordered) ++out.reordered;
        out.lost_frames += lost;
        const int index = torqueIndex(c->left);
        if (index == expected - 1 || (expected == 0 && index == kIndexModulus - 1)) {
          ++out.repeats;  // the fixed-rate repetition of the last message
          continue;
        }
        std::uint64_t gap = 0;
        if (expected >= 0 && index != expected) {
          gap = static_cast<std::uint64_t>((index - expected + kIndexModulus) % kIndexModulus);
          out.lost_messages += gap;
        }
        expected = (index + 1) % kIndexModulus;
        std::lock_guard<std::mutex> lock(mutex);
        if (next_message == kNone) {  // the first driving frame: its message number
          for (std::size_t k = 0; k < created.size(); ++k) {
            if (created[k] >= 0 && static_cast<int>(k % kIndexModulus) == index) {
              next_message = k;
              break;
            }
          }
        } else {
          next_message += gap;
        }
        if (next_message < created.size() && created[next_message] >= 0) {
          latencies.push_back((f.stamp - created[next_message]) * 1e6);
        }
        ++next_message;
      }
      std::this_thread::sleep_for(std::chrono::microseconds(50));
    }
    std::sort(latencies.begin(), latencies.end());
    if (!latencies.empty()) {
      out.mean_us = std::accumulate(latencies.begin(), latencies.end(), 0.0) / latencies.size();
      out.p99_us = latencies[static_cast<std::size_t>(0.99 * (latencies.size() - 1))];
      out.max_us = latencies.back();
    }
  });

  // The driver thread: waits for messages like a ROS callback, spins at least every 2 ms.
  std::thread driver_thread([&] {
    std::uint64_t permits = 0, commands = 0;
    while (!done) {
      driver.onPermit(++permits, 1, seconds(), false, seconds());  // the bench is the supervisor
      std::unique_lock<std::mutex> lock(mutex);
      cv.wait_for(lock, std::chrono::milliseconds(2), [&] { return !queue.empty() || done; });
      while (!queue.empty()) {
        const auto [index, t] = queue.front();
        queue.pop_front();
        lock.unlock();
        driver.onCommand({indexTorque(index), 0.0, false, t, ++commands, 1}, seconds());
        lock.lock();
      }
      lock.unlock();
      driver.spinOnce(seconds());
    }
  });

  // Wait for the driver to see the controller, then produce at `rate` Hz.
  std::this_thread::sleep_for(std::chrono::milliseconds(100));
  const std::uint64_t total = static_cast<std::uint64_t>(duration * rate);
  const auto start = Clock::now();
  for (std::uint64_t i = 0; i < total; ++i) {
    std::this_thread::sleep_until(
        start + std::chrono::nanoseconds(static_cast<std::int64_t>(i * 1e9 / rate)));
    std::lock_guard<std::mutex> lock(mutex);
    created[i] = seconds();
    queue.emplace_back(i, created[i]);
    cv.notify_one();
  }
  producing = true;
  std::this_thread::sleep_for(std::chrono::milliseconds(50));
  done = true;
  driver_thread.join();
  chair.join();
  out.messages = total;
  return out;
}

void report(const std::string& c, const std::string& method, const RealtimeOutcome& o) {
  results.push_back({c, method, "torque_messages", static_cast<double>(o.messages), "messages"});
  results.push_back({c, method, "torque_frames_received", static_cast<double>(o.frames), "frames"});
  results.push_back({c, method, "lost_frames", static_cast<double>(o.lost_frames), "frames"});
  results.push_back({c, method, "duplicated_frames", static_cast<double>(o.duplicated), "frames"});
  results.push_back({c, method, "reordered_frames", static_cast<double>(o.reordered), "frames"});
  results.push_back({c, method, "lost_messages", static_cast<double>(o.lost_messages), "messages"});
  results.push_back({c, method, "fixed_rate_repeats", static_cast<double>(o.repeats), "frames"});
  results.push_back({c, method, "latency_mean", o.mean_us, "us"});
  results.push_back({c, method, "latency_p99", o.p99_us, "us"});
  results.push_back({c, method, "latency_max", o.max_us, "us"});
}

}  // namespace

int main(int argc, char** argv) {
  double duration = 60.0, udp_duration = 10.0;
  for (int i = 1; i + 1 < argc; i += 2) {
    if (!std::strcmp(argv[i], "--duration")) duration = std::atof(argv[i + 1]);
    if (!std::strcmp(argv[i], "--udp-duration")) udp_duration = std::atof(argv[i + 1]);
  }
  results.push_back({"fake_bus_throughput", "raw_send_receive", "frames_per_second",
                     rawFakeBusThroughput(4000000), "frames/s"});
  results.push_back({"fake_bus_throughput", "encode_send_receive_decode", "frames_per_second",
                     protocolFakeBusThroughput(2000000), "frames/s"});
  {
    auto bus = FakeBus::create(seconds);
    auto driver_port = bus->connect("driver"), chair_port = bus->connect("chair", 1u << 16);
    report("fake_bus_1kHz_" + std::to_string(static_cast<int>(duration)) + "s_realtime",
           "driver_core_threads", runRealtime(*driver_port, *chair_port, duration, 1000.0));
  }
  if (udp_duration > 0) {
    UdpTransport chair_port(0, 0, seconds);
    UdpTransport driver_port(0, chair_port.localPort(), seconds);
    report("udp_loopback_1kHz_" + std::to_string(static_cast<int>(udp_duration)) + "s_realtime",
           "driver_core_threads", runRealtime(driver_port, chair_port, udp_duration, 1000.0));
  }
  std::printf("[\n");
  for (std::size_t i = 0; i < results.size(); ++i) {
    const Result& r = results[i];
    std::printf(
        "  {\"case\": \"%s\", \"method\": \"%s\", \"metric\": \"%s\", \"value\": %.6g, \"unit\": "
        "\"%s\"}%s\n",
        r.c.c_str(), r.method.c_str(), r.metric.c_str(), r.value, r.unit.c_str(),
        i + 1 < results.size() ? "," : "");
  }
  std::printf("]\n");
  return 0;
}
