// Large blocks of memory populated at once and recycled instead of returned to the kernel (the
// direct solver's arrays and CHOLMOD's): internal header.
//
// Fresh memory is expensive on this VM: the first touch of a page costs ~4.3 ms per MB
// (measured: 100 MB mmap + memset 405-490 ms, a second memset of the same memory 5 ms;
// transparent huge pages are not granted here). Populated at mmap time (MAP_POPULATE, ~0.2 ms
// per MB) the first touch costs ~1.5 ms per MB. A cold factorization of a 1024^2 maze writes
// ~200 MB of fresh memory (the ~85 MB factor, CHOLMOD's transposes and the ordering's
// workspace, the equation and the solves' arrays), and glibc maps every block above its mmap
// threshold afresh and unmaps it on free. Here blocks of >= 1 MiB are mapped populated, and
// freed ones stay mapped for the next request (best fit): within one factorization, and for
// the next map's factorization in a running planner, they cost no page faults at all.
#pragma once

#include <cstddef>
#include <new>
#include <vector>

namespace wheelchair_harmonic_planner {

/// malloc/free for the pool: blocks of >= 1 MiB come from it, smaller ones from malloc; free
/// accepts any malloc pointer too. Thread-safe. Freed blocks stay mapped up to 1 GiB in total
/// (the largest are unmapped beyond it).
void* largeBlockAllocate(size_t bytes);
void largeBlockFree(void* block);

/// Routes SuiteSparse's allocations (CHOLMOD's) through the pool. Idempotent and thread-safe;
/// it leaves SuiteSparse's allocator alone if the process has already replaced malloc/free
/// there (then blocks allocated before keep going to free, as they must).
void recycleLargeCholmodBlocks();

/// Bytes of freed blocks currently kept for reuse (for tests and the bench).
size_t recycledLargeBlockBytes();

/// std::allocator for the solver's big vectors, from the pool.
template <class T>
struct LargeBlockAllocator {
  using value_type = T;
  LargeBlockAllocator() = default;
  template <class U>
  LargeBlockAllocator(const LargeBlockAllocator<U>&) {}
  T* allocate(size_t n) {
    void* p = largeBlockAllocate(n * sizeof(T));
    if (!p) throw std::bad_alloc();
    return static_cast<T*>(p);
  }
  void deallocate(T* p, size_t) { largeBlockFree(p); }
  template <class U>
  bool operator==(const LargeBlockAllocator<U>&) const {
    return true;
  }
  template <class U>
  bool operator!=(const LargeBlockAllocator<U>&) const {
    return false;
  }
};

template <class T>
using LargeVector = std::vector<T, LargeBlockAllocator<T>>;

}  // namespace wheelchair_harmonic_planner
