// The `cooperage` command's operator new: blocks of 4 MB and more (node,
// element and quality arrays of big meshes) are advised to the kernel as
// transparent huge pages before their first touch. On a kernel whose THP
// mode is "madvise" (Debian's default) every 4 KB page of such an array
// otherwise costs its own page fault on first write: on the 1 M-hex plate
// page faults were about a fifth of the run's CPU (issue 20; glibc's
// tunable glibc.malloc.hugetlb=1 does the same, but only when set in the
// environment before the process starts). Only this executable replaces
// operator new; the library and its other users keep the default.
#include <sys/mman.h>

#include <cstdint>
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

}  // namespace

void* operator new(std::size_t bytes) { return allocate(bytes); }
void* operator new[](std::size_t bytes) { return allocate(bytes); }
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }
