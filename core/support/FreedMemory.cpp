#include "core/support/FreedMemory.h"

#include <cstdio>

#include <unistd.h>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace facet {

void mapLargeBlocksOnTheirOwn()
{
#if defined(__GLIBC__)
    mallopt(M_MMAP_THRESHOLD, int(kLargeBlockBytes));
#endif
}

std::size_t freedMemoryHeld()
{
#if defined(__GLIBC__)
    return mallinfo2().fordblks;
#else
    return 0;
#endif
}

bool returnFreedMemory()
{
#if defined(__GLIBC__)
    return malloc_trim(0) != 0;
#else
    return false;
#endif
}

std::size_t residentBytes()
{
    std::FILE* file = std::fopen("/proc/self/statm", "r");
    if (!file)
        return 0;
    unsigned long long size = 0;
    unsigned long long resident = 0;
    const int read = std::fscanf(file, "%llu %llu", &size, &resident);
    std::fclose(file);
    const long page = sysconf(_SC_PAGESIZE);
    return read == 2 && page > 0 ? std::size_t(resident) * std::size_t(page) : 0;
}

} // namespace facet
