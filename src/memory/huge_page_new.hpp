// Large C++ allocations in transparent huge pages. The mesher's flat arrays
// (tets, neighbours, the Delaunay fill's and the optimizer's tables, the
// output text) are megabytes to gigabytes and short-lived: vectors double,
// steps copy them. From glibc's malloc each such block is a fresh mapping
// of 4 KiB pages, every page faults on its first touch and the mapping is
// unmapped when freed (femur r1: 50,000 page faults, a tenth of its run on
// a VM). The replacement operator new of huge_page_new.cpp maps blocks of
// kHugeBlockBytes and more at a 2 MiB boundary, advised for transparent
// huge pages (one fault per 2 MiB, fewer TLB misses) and unmapped when
// deleted as before; smaller ones go to malloc. Linked into the partet
// executable and the test programs (the library leaves the global
// allocator alone); not in sanitizer builds, whose allocator must see
// every block. docs/decisions.md, "Large blocks in huge pages".
#pragma once

#include <cstddef>

namespace partet {

// Allocations of this size and more are mapped on their own.
inline constexpr size_t kHugeBlockBytes = size_t{2} << 20;

// Mapped blocks live at once at most; past it, blocks come from malloc.
inline constexpr size_t kHugeBlockSlots = 1024;

// Whether this program's operator new is huge_page_new.cpp's (false in
// sanitizer builds, which leave the allocator to the sanitizer).
bool huge_page_new_in_use();

// Blocks mapped by operator new and not yet deleted (0 in sanitizer builds).
size_t huge_page_blocks_live();

}  // namespace partet
