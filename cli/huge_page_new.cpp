// Large C++ allocations of the cadmedial executable are backed by transparent
// huge pages where the kernel offers them on request (THP "madvise" mode, the
// Debian default).
//
// Why: the big arrays (Delaunay cells, pair-mesh elements, output buffers) are
// written once into fresh memory, and on the VMs this project runs on a 4 KiB
// page fault costs microseconds: 14-18 % of the bottle's and the lever's
// pair-mesh CPU time was page faults (perf, 2026-12-07). One 2 MiB page per
// 512 faults removes most of that (bench/RESULTS.md, "Huge pages").
//
// How: operator new still takes its memory from malloc (so operator delete
// stays free(), and nothing else changes); for blocks of 4 MiB or more it asks
// the kernel, with madvise(MADV_HUGEPAGE), to back the whole 2 MiB pages inside
// the block with huge pages. That is what glibc does itself for every block
// under GLIBC_TUNABLES=glibc.malloc.hugetlb=1, which a process cannot set for
// itself after start-up. Advice, not a demand: where THP is off ("never") or
// no huge page is free, the kernel uses 4 KiB pages as before; the call's
// result is ignored. CADMEDIAL_HUGE_PAGES=0 in the environment turns it off.
//
// Only in the executable: a module loaded into another process (the FreeCAD
// workbench's Python module) does not replace that process's operator new.
// Over-aligned blocks (operator new with std::align_val_t) keep the library's
// allocation and get no advice; nothing large here asks for one.
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <new>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace {

constexpr std::size_t kHugePage = std::size_t(2) << 20;
// Below two huge pages a block need not hold a whole aligned one.
constexpr std::size_t kAdviseFrom = 2 * kHugePage;

bool hugePagesWanted() {
  static const bool wanted = [] {
    const char* setting = std::getenv("CADMEDIAL_HUGE_PAGES");
    return !(setting && std::strcmp(setting, "0") == 0);
  }();
  return wanted;
}

void adviseHugePages(void* block, std::size_t size) {
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  if (size < kAdviseFrom || !hugePagesWanted()) return;
  const std::uintptr_t begin = reinterpret_cast<std::uintptr_t>(block);
  const std::uintptr_t first = (begin + kHugePage - 1) & ~(kHugePage - 1);
  const std::uintptr_t last = (begin + size) & ~(kHugePage - 1);
  if (last > first) madvise(reinterpret_cast<void*>(first), last - first, MADV_HUGEPAGE);
#else
  (void)block;
  (void)size;
#endif
}

void* allocate(std::size_t size) {
  if (size == 0) size = 1;
  for (;;) {
    if (void* block = std::malloc(size)) {
      adviseHugePages(block, size);
      return block;
    }
    std::new_handler handler = std::get_new_handler();
    if (!handler) throw std::bad_alloc();
    handler();
  }
}

}  // namespace

void* operator new(std::size_t size) { return allocate(size); }
void* operator new[](std::size_t size) { return allocate(size); }
void operator delete(void* block) noexcept { std::free(block); }
void operator delete[](void* block) noexcept { std::free(block); }
void operator delete(void* block, std::size_t) noexcept { std::free(block); }
void operator delete[](void* block, std::size_t) noexcept { std::free(block); }
