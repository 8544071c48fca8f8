// The tool's large blocks on transparent huge pages. A big model's run allocates tens of MB in
// vectors (the file's bytes, the mesh, the pieces, the strokes, the paths), and with the
// kernel's THP mode "madvise" (a common default) each of them was faulted in 4 KB at a time:
// about a sixth of `plot`'s time on a 200,000-triangle torus went to page faults. Asking for huge
// pages on every block of a megabyte or more (as pipeline/host_memory.h does for the
// hidden-line arena) makes that a fault per 2 MB. Only the haloplot executable replaces the
// global operator new; the library and the tests keep the default. The allocation itself is
// still malloc's, so free() and the usual debugging tools see ordinary blocks.
#include <cstdint>
#include <cstdlib>
#include <new>

#if defined(__linux__)
#include <sys/mman.h>
#endif

#if defined(__SANITIZE_ADDRESS__)
#define HALOPLOT_HUGE_PAGES 0  // the sanitizer's allocator replaces operator new itself
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define HALOPLOT_HUGE_PAGES 0
#endif
#endif
#if !defined(HALOPLOT_HUGE_PAGES) && defined(__linux__) && defined(MADV_HUGEPAGE)
#define HALOPLOT_HUGE_PAGES 1
#endif

#if HALOPLOT_HUGE_PAGES
namespace {

constexpr size_t kLargeBlock = size_t{1} << 20;
constexpr size_t kHugePage = size_t{2} << 20;

// A large block starts on a huge page and spans whole ones (the kernel gives a huge page only
// where an aligned 2 MB lies inside the advised range), advised before anything touches it.
// aligned_alloc keeps it malloc's: free() takes it back, and a freed block's pages are reused.
void* allocate_block(size_t bytes) {
  if (bytes < kLargeBlock) return std::malloc(bytes == 0 ? 1 : bytes);
  const size_t rounded = (bytes + kHugePage - 1) & ~(kHugePage - 1);
  void* p = std::aligned_alloc(kHugePage, rounded);
  if (p != nullptr) madvise(p, rounded, MADV_HUGEPAGE);
  return p;
}

void* allocate(size_t bytes) {
  void* p = allocate_block(bytes);
  if (p == nullptr) throw std::bad_alloc();
  return p;
}

}  // namespace

void* operator new(size_t bytes) { return allocate(bytes); }
void* operator new[](size_t bytes) { return allocate(bytes); }
void* operator new(size_t bytes, const std::nothrow_t&) noexcept { return allocate_block(bytes); }
void* operator new[](size_t bytes, const std::nothrow_t& tag) noexcept {
  return operator new(bytes, tag);
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, size_t) noexcept { std::free(p); }
void operator delete[](void* p, size_t) noexcept { std::free(p); }
void operator delete(void* p, const std::nothrow_t&) noexcept { std::free(p); }
void operator delete[](void* p, const std::nothrow_t&) noexcept { std::free(p); }
#endif
