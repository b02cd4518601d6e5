// The contactbench command: parses arguments and hands over to the app library.
#include <malloc.h>

#include "contactbench/app/cli.hpp"

int main(int argc, char** argv) {
  // Large arrays (a 1024^2 grid's fields are 8 MB each) from the heap, and freed memory kept: glibc maps
  // each allocation above its threshold afresh (every page faulted and zeroed again by the kernel) and
  // returns it on free, so that the stages and loads of one command would pay the page faults of their work
  // arrays again and again (issue 42: a fifth of a 1024^2 command's time was in the kernel). A command runs
  // once and ends; its peak memory is unchanged.
  mallopt(M_MMAP_THRESHOLD, 1 << 30);
  mallopt(M_TRIM_THRESHOLD, 1 << 30);
  return contactbench::run_cli(argc, argv);
}
