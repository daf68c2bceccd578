#pragma once
// Memory the program has freed but the C library still holds. glibc's allocator keeps freed
// blocks in its arenas (one per thread that allocated: the decode workers, the lighting worker)
// for reuse, and returns only what lies at the top of an arena to the system; a window that decodes
// a 2K texture set and lets it go, again and again, fragments its arenas and its resident memory
// climbs by tens of MiB a cycle although nothing is kept (docs/benchmarks.md, "Cache budget"). The
// window asks now and then how much lies free and, above a threshold, hands the free pages back
// (malloc_trim: they stay mapped, and are zero-filled if used again).
//
// Elsewhere than glibc both are no-ops (0).

#include <cstddef>

namespace facet {

// Blocks of 1 MiB and more (decoded images, pixel buffers, mip levels) are mapped on their own
// and unmapped when freed (mallopt M_MMAP_THRESHOLD): glibc otherwise raises that threshold to the
// largest block freed so far, after which a 12 MiB texture's pixels are carved out of an arena
// and, once freed, fragment it. Process-wide; the window sets it once (ui/widgets/FreedMemoryTimer).
void mapLargeBlocksOnTheirOwn();
inline constexpr std::size_t kLargeBlockBytes = std::size_t(1) << 20;

// Bytes the allocator holds free (mallinfo2: fordblks, the free chunks of every arena).
std::size_t freedMemoryHeld();
// Returns the free pages of every arena to the system (malloc_trim(0)): whether any were. The
// free chunks stay free chunks (freedMemoryHeld() barely changes); their pages leave the resident
// set.
bool returnFreedMemory();
// The process's resident memory in bytes (/proc/self/statm), 0 where unknown.
std::size_t residentBytes();

} // namespace facet
