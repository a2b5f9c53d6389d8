#include <wheelchair_can/can_frame.h>

namespace wheelchair_can {

bool passesFilters(const CanFrame& frame, const std::vector<CanFilter>& filters) {
  if (filters.empty() || frame.error) return true;
  for (const CanFilter& f : filters) {
    if ((frame.id & f.mask) == (f.id & f.mask)) return true;
  }
  return false;
}

}  // namespace wheelchair_can
