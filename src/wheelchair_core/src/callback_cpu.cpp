#include <wheelchair_core/callback_cpu.h>

#include <ctime>
#include <memory>
#include <mutex>

namespace wheelchair_core {

namespace {

struct Registry {
  std::mutex mutex;
  std::map<std::string, std::unique_ptr<std::atomic<int64_t>>> totals;
};

Registry& registry() {
  static Registry r;
  return r;
}

}  // namespace

int64_t threadCpuNanoseconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<int64_t>(t.tv_sec) * 1000000000 + t.tv_nsec;
}

std::atomic<int64_t>& callbackCpuTotal(const std::string& name) {
  Registry& r = registry();
  std::lock_guard<std::mutex> lock(r.mutex);
  std::unique_ptr<std::atomic<int64_t>>& total = r.totals[name];
  if (!total) total = std::make_unique<std::atomic<int64_t>>(0);
  return *total;
}

std::map<std::string, double> callbackCpuSeconds() {
  Registry& r = registry();
  std::lock_guard<std::mutex> lock(r.mutex);
  std::map<std::string, double> out;
  for (const auto& [name, total] : r.totals) out[name] = 1e-9 * total->load();
  return out;
}

}  // namespace wheelchair_core
