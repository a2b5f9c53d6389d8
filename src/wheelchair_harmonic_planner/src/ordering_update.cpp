#include "ordering_update.h"

#include <algorithm>
#include <limits>
#include <tuple>

namespace wheelchair_harmonic_planner {

namespace {

constexpr int kNone = std::numeric_limits<int>::max();

/// A new free cell: the old position it is eliminated before, and its breadth-first distance
/// (in cells) from the old cells.
struct Added {
  int key;
  int depth;
  int unknown;
};

}  // namespace

LargeVector<int> deriveOrdering(const FactorOrdering& previous, const std::vector<uint8_t>& free,
                                const LargeVector<size_t>& cells, const LargeVector<int>& id,
                                long width, size_t max_added, size_t max_removed) {
  const std::vector<uint8_t>& old = previous.free_mask;
  if (old.size() != free.size()) return {};
  size_t added = 0, removed = 0, old_n = 0;
  for (size_t k = 0; k < free.size(); ++k) {
    added += free[k] && !old[k];
    removed += old[k] && !free[k];
    old_n += old[k] != 0;
  }
  if (added > max_added || removed > max_removed || old_n != previous.permutation.size()) {
    return {};
  }
  // The new unknown of each old one (-1: blocked now), then each kept cell's old position.
  LargeVector<int> renumber(old_n);
  for (size_t k = 0, u = 0; k < free.size(); ++k) {
    if (old[k]) renumber[u++] = free[k] ? id[k] : -1;
  }
  const int n = static_cast<int>(cells.size());
  LargeVector<int> key(n, kNone);
  for (size_t p = 0; p < old_n; ++p) {
    const int u = previous.permutation[p];
    if (u < 0 || static_cast<size_t>(u) >= old_n) return {};
    if (renumber[u] >= 0) key[renumber[u]] = static_cast<int>(p);
  }
  const long offsets[4] = {1, -1, width, -width};
  const auto isNew = [&](int v) { return v >= 0 && !old[cells[v]]; };
  // New cells next to old ones: before the earliest of those; then breadth-first through the
  // other new cells, each before the cell it was reached from.
  std::vector<Added> queue;
  queue.reserve(added);
  for (int u = 0; u < n; ++u) {
    if (!isNew(u)) continue;
    int first = kNone;
    for (const long o : offsets) {
      const int v = id[static_cast<long>(cells[u]) + o];
      if (v >= 0 && !isNew(v)) first = std::min(first, key[v]);
    }
    if (first != kNone) queue.push_back({first, 1, u});
  }
  for (const Added& a : queue) key[a.unknown] = a.key;
  for (size_t q = 0; q < queue.size(); ++q) {
    const Added a = queue[q];  // copied: push_back may reallocate
    for (const long o : offsets) {
      const int v = id[static_cast<long>(cells[a.unknown]) + o];
      if (isNew(v) && key[v] == kNone) {
        key[v] = a.key;
        queue.push_back({a.key, a.depth + 1, v});
      }
    }
  }
  std::sort(queue.begin(), queue.end(), [](const Added& a, const Added& b) {
    return std::tie(a.key, b.depth, a.unknown) < std::tie(b.key, a.depth, b.unknown);
  });
  LargeVector<int> order;
  order.reserve(n);
  size_t a = 0;
  for (size_t p = 0; p < old_n; ++p) {
    for (; a < queue.size() && queue[a].key == static_cast<int>(p); ++a) {
      order.push_back(queue[a].unknown);
    }
    const int u = renumber[previous.permutation[p]];
    if (u >= 0) order.push_back(u);
  }
  // New cells not connected to any old one (a new island): last, row by row.
  for (int u = 0; u < n; ++u) {
    if (isNew(u) && key[u] == kNone) order.push_back(u);
  }
  if (order.size() != static_cast<size_t>(n)) return {};  // not expected
  return order;
}

}  // namespace wheelchair_harmonic_planner
