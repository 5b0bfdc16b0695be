// The `cooperage` command's operator new: blocks of 4 MB and more (node,
// element and quality arrays of big meshes) are advised to the kernel as
// transparent huge pages before their first touch. On a kernel whose THP
// mode is "madvise" (Debian's default) every 4 KB page of such an array
// otherwise costs its own page fault on first write: on the 1 M-hex plate
// page faults were about a fifth of the run's CPU (issue 20; glibc's
// tunable glibc.malloc.hugetlb=1 does the same, but only when set in the
// environment before the process starts). The heap itself is advised the
// same way at start-up (HeapAdvice below). Only this executable replaces
// operator new and tunes malloc; the library and its other users keep the
// defaults.
#include "huge_pages.h"

#include "framework/pipeline/mesher.h"

#include <malloc.h>
#include <sys/mman.h>

#include <cstdint>
#include <cstdio>
#include <cstring>
#include <cstdlib>
#include <new>

namespace {

constexpr std::size_t kHugePage = std::size_t{2} << 20;
constexpr std::size_t kAdviseFrom = std::size_t{4} << 20;

void* allocate(std::size_t bytes) {
  for (;;) {
    if (void* p = std::malloc(bytes == 0 ? 1 : bytes)) {
      if (bytes >= kAdviseFrom) {
        // The whole huge pages inside the block (malloc's header precedes it).
        const auto at = reinterpret_cast<std::uintptr_t>(p);
        const std::uintptr_t first = (at + kHugePage - 1) & ~(kHugePage - 1);
        const std::uintptr_t last = (at + bytes) & ~(kHugePage - 1);
        if (last > first) madvise(reinterpret_cast<void*>(first), last - first, MADV_HUGEPAGE);
      }
      return p;
    }
    std::new_handler handler = std::get_new_handler();
    if (!handler) throw std::bad_alloc();
    handler();
  }
}

// The heap in transparent huge pages as well. Blocks under 4 MB come from
// the heap (M_MMAP_THRESHOLD), which first grows by a 64 MB pad (M_TOP_PAD,
// virtual until touched; glibc keeps the pad when it trims), and that
// range is advised once. On the 1 M-hex plate this cut page faults from
// ~15,000 to ~5,000; each 4 KB fault costs about 10 microseconds on a
// virtual machine, and the heap's pages had been a sixth of the run. Growth
// beyond the pad is a new mapping without the advice (the kernel does not
// merge it), which only loses the benefit.
struct HeapAdvice {
  HeapAdvice() {
    mallopt(M_MMAP_THRESHOLD, static_cast<int>(kAdviseFrom));
    mallopt(M_TOP_PAD, 64 << 20);
    void* volatile grow = std::malloc(std::size_t{1} << 20);  // volatile: not elided
    std::free(grow);
    FILE* maps = std::fopen("/proc/self/maps", "r");
    if (!maps) return;
    char line[512];
    while (std::fgets(line, sizeof line, maps)) {
      if (!std::strstr(line, "[heap]")) continue;
      unsigned long lo = 0, hi = 0;
      if (std::sscanf(line, "%lx-%lx", &lo, &hi) == 2) {
        const std::uintptr_t first = (lo + kHugePage - 1) & ~(kHugePage - 1);
        const std::uintptr_t last = hi & ~(kHugePage - 1);
        if (last > first) madvise(reinterpret_cast<void*>(first), last - first, MADV_HUGEPAGE);
      }
    }
    std::fclose(maps);
  }
} heap_advice;

}  // namespace

// Measured on two cores: the 0.1 M-hex plate on two threads wrote its
// export beside the quality checks in a worker's own arena, in 4 KB page
// faults (6,538 faults, 0.225 s; one arena: 3,265, 0.210 s), and the 1 M
// plate's faults fell from 8,428 to 4,876. With more threads, one arena's
// lock could cost more than the faults; that was not measured, so glibc's
// default stays. Called once the geometry is built: the decomposition's
// search judges cuts on the worker threads, which one arena's lock made
// slower on two threads than on one (gmsh_Kurbelwelle 1.33 s against
// 1.22; 1.14 s with an arena per thread); threads that took their own
// arena then keep it.
void cooperage::app::share_heap_when_few_threads(int requested) {
  if (cooperage::pipeline::limit_threads_count(requested) <= 2) mallopt(M_ARENA_MAX, 1);
}

void* operator new(std::size_t bytes) { return allocate(bytes); }
void* operator new[](std::size_t bytes) { return allocate(bytes); }
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }
