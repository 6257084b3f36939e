// Huge pages for the first GL context's buffers in an interpreter, where the
// CLI's restart with glibc.malloc.hugetlb (jobs/huge_pages.hpp) cannot run.
#pragma once

#include <cstddef>

namespace rollspin::python {

// Huge pages for the buffers of the first GL context, as the CLI gets them
// (jobs/huge_pages.hpp) but without its restart: an interpreter is running
// already, and glibc reads GLIBC_TUNABLES only at a process's start.
// llvmpipe allocates and zeroes its frame buffers and textures (about 75 MiB
// for a 960×540 still, four times the frame's part at 1920×1080); with
// 4 KiB pages each page is a fault, and a fresh still through Python cost
// 1.3× the CLI's (docs/python.md, "Tests and speed"). glibc's malloc
// (mallopt(3)): freeing a block it had mmapped raises its mmap threshold to
// that block's size (32 MiB at most); below the threshold blocks come from
// the heap. So: raise the threshold, take the memory the first frame will
// need from the heap in blocks under it, mark them for huge pages
// (MADV_HUGEPAGE, what glibc.malloc.hugetlb=1 does to each new heap extent),
// and free them behind a small block kept at their end, so that free() does
// not give them back to the kernel (the heap's top would be trimmed);
// llvmpipe's buffers are then carved from marked memory. Untouched, the
// reserve is address space, not memory. Nothing is done where the CLI would
// not restart either (a sanitizer's or valgrind's malloc, the kernel's mode
// is not "madvise", the user named glibc.malloc.hugetlb). Once per process;
// returns the bytes marked. The pixels are the same.
[[nodiscard]] std::size_t markHeapForHugePages(long long width, long long height);

}  // namespace rollspin::python
