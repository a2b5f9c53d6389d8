// CPU time per nodelet of a process. The threads of a nodelet manager are shared by every
// nodelet (their names say nothing), so each nodelet measures its own heavy callbacks: a
// CallbackCpuScope reads the calling thread's CPU clock (CLOCK_THREAD_CPUTIME_ID) at its start
// and end and adds the difference to the nodelet's total. One registry per process (this
// library is shared by every nodelet library); the chair's main publishes the totals
// (wheelchair_bringup: ~callback_cpu) and bench/system turns them into % of one core.
#pragma once

#include <atomic>
#include <cstdint>
#include <map>
#include <string>

namespace wheelchair_core {

/// CPU time of the calling thread so far [ns].
int64_t threadCpuNanoseconds();

/// The total of `name` (e.g. the nodelet's name, "/controller"): created on first use, never
/// moved (the reference stays valid for the life of the process).
std::atomic<int64_t>& callbackCpuTotal(const std::string& name);

/// Every total so far [s of CPU], by name.
std::map<std::string, double> callbackCpuSeconds();

/// Adds the calling thread's CPU time between construction and destruction to `total`.
class CallbackCpuScope {
 public:
  explicit CallbackCpuScope(std::atomic<int64_t>* total)
      : total_(total), start_(total ? threadCpuNanoseconds() : 0) {}
  /// For `name`'s total (looked up each time: a lock and a map lookup, ~0.1 us).
  explicit CallbackCpuScope(const std::string& name) : CallbackCpuScope(&callbackCpuTotal(name)) {}
  ~CallbackCpuScope() {
    if (total_) total_->fetch_add(threadCpuNanoseconds() - start_, std::memory_order_relaxed);
  }
  CallbackCpuScope(const CallbackCpuScope&) = delete;
  CallbackCpuScope& operator=(const CallbackCpuScope&) = delete;

 private:
  std::atomic<int64_t>* total_;
  int64_t start_;
};

}  // namespace wheelchair_core
