// Transparent huge pages for the C allocator: glibc's tunable glibc.malloc.hugetlb=1
// has malloc advise the kernel to back its heap and its mapped blocks with 2 MiB pages.
// glibc reads its tunables only as a process starts, so the program starts itself again
// with it, once, before anything else (app/main.cpp); GLIBC_TUNABLES set, even empty,
// is left alone. Why: on a machine whose first touch of a page is slow (this one, a
// virtual machine: 2.8 ms a MiB), a run spent a fifth of its time in page faults.
// Measured (docs/performance.md, "Huge pages, and the set-up on two ranks"): Table 1's
// row 2 0.35 -> 0.31 s, the iterative solver's set-up at 930 000 triangles 6.5 -> 2.4 s;
// the cost, 20 ms more to start and a few MB more at the peak of small runs.
#pragma once

#include <string>

namespace fsi {

// The kernel's mode, /sys/kernel/mm/transparent_hugepage/enabled, e.g. "always
// [madvise] never"; empty without the file.
std::string thp_mode();

// Whether a process whose GLIBC_TUNABLES is `tunables` (null: unset) starts again with
// the tunable, on a kernel whose /sys/kernel/mm/transparent_hugepage/enabled reads
// `thp_mode`: only where GLIBC_TUNABLES is unset (set, even empty, it is the user's
// choice; after the restart it is set) and the kernel gives huge pages to advised
// memory alone ("[madvise]"; with "[always]" every heap has them, with "[never]" none).
bool wants_huge_page_restart(const char* tunables, const std::string& thp_mode);

// Whether this process's allocator uses huge pages (summary.json's
// program.huge_pages): the kernel's mode "[always]", or "[madvise]" and the tunable set.
bool uses_huge_pages();

// Whether AddressSanitizer's allocator replaces glibc's (which then has no tunable to
// set: no restart).
bool sanitized_allocator();

// Starts this program again (/proc/self/exe, the same arguments) with the tunable
// where wants_huge_page_restart says so. Returns only if it does not, or if the new
// start failed (the run then goes on as it is).
void restart_with_huge_pages(char** argv);

}  // namespace fsi
