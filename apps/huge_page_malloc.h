#pragma once
// Transparent huge pages for the command line's heap: glibc's malloc asks the kernel for them
// (madvise) only under the tunable glibc.malloc.hugetlb=1, which it reads when a process starts.
namespace eikon::app {

// Starts this program again, once, with glibc.malloc.hugetlb=1 added to GLIBC_TUNABLES, unless
// it is there already, EIKON_NO_HUGE_PAGES is set, or the build replaces malloc (ASan); returns
// (and the program goes on as it is) when the exec fails. Call first thing in main.
void restartWithHugePageMalloc(char** argv);

}  // namespace eikon::app
