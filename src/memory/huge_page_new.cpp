// The replacement global operator new and delete (see huge_page_new.hpp).
// Blocks from kHugeBlockBytes up are mapped 2 MiB-aligned and registered;
// delete looks a 2 MiB-aligned pointer up in the registry (a malloc block
// is never at the start of a live mapping) and unmaps it, else frees it.
// The array, nothrow and sized forms of libstdc++ call these two.
#include "memory/huge_page_new.hpp"

#include <sys/mman.h>

#include <cstdint>
#include <cstdlib>
#include <mutex>
#include <new>

#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
#define PARTET_HUGE_PAGE_NEW 0
#else
#define PARTET_HUGE_PAGE_NEW 1
#endif

namespace partet {
namespace {

#if PARTET_HUGE_PAGE_NEW

struct MappedBlock {
  void* address;
  size_t length;
};

// Fixed storage: the registry must not allocate.
std::mutex registry_mutex;
MappedBlock registry[kHugeBlockSlots];
size_t registry_size = 0;

constexpr uintptr_t kHugePage = uintptr_t{2} << 20;
constexpr size_t kPage = 4096;

// A 2 MiB-aligned mapping of `size` bytes (rounded up to pages) advised for
// huge pages, registered; nullptr when the system refuses it or the registry
// is full.
void* map_block(size_t size) {
  const size_t length = (size + kPage - 1) & ~(kPage - 1);
  void* raw = mmap(nullptr, length + kHugePage, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  if (raw == MAP_FAILED) return nullptr;
  const uintptr_t start = reinterpret_cast<uintptr_t>(raw);
  const uintptr_t aligned = (start + kHugePage - 1) & ~(kHugePage - 1);
  const uintptr_t end = start + length + kHugePage;
  if (aligned > start) munmap(raw, aligned - start);
  if (end > aligned + length) munmap(reinterpret_cast<void*>(aligned + length), end - aligned - length);
  void* block = reinterpret_cast<void*>(aligned);
  // Where the kernel has no transparent huge pages this fails and the block
  // keeps 4 KiB pages: slower, not wrong.
  madvise(block, length, MADV_HUGEPAGE);
  std::lock_guard<std::mutex> lock(registry_mutex);
  if (registry_size == kHugeBlockSlots) {
    munmap(block, length);
    return nullptr;
  }
  registry[registry_size++] = {block, length};
  return block;
}

// Unmaps `p` if it is a registered block; false if it is not one.
bool unmap_block(void* p) {
  if ((reinterpret_cast<uintptr_t>(p) & (kHugePage - 1)) != 0) return false;
  size_t length = 0;
  {
    std::lock_guard<std::mutex> lock(registry_mutex);
    size_t i = 0;
    while (i < registry_size && registry[i].address != p) ++i;
    if (i == registry_size) return false;
    length = registry[i].length;
    registry[i] = registry[--registry_size];
  }
  munmap(p, length);
  return true;
}

#endif

}  // namespace

bool huge_page_new_in_use() { return PARTET_HUGE_PAGE_NEW != 0; }

size_t huge_page_blocks_live() {
#if PARTET_HUGE_PAGE_NEW
  std::lock_guard<std::mutex> lock(registry_mutex);
  return registry_size;
#else
  return 0;
#endif
}

}  // namespace partet

#if PARTET_HUGE_PAGE_NEW

void* operator new(size_t size) {
  if (size >= partet::kHugeBlockBytes) {
    if (void* p = partet::map_block(size)) return p;
  }
  if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
  throw std::bad_alloc();
}

void operator delete(void* p) noexcept {
  if (p == nullptr || partet::unmap_block(p)) return;
  std::free(p);
}

void operator delete(void* p, size_t /*size*/) noexcept { operator delete(p); }

#endif
