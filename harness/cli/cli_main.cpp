// The aabench command line. All parsing and dispatch live in harness/cli/cli.cpp.
#include <malloc.h>

#include "harness/cli/cli.h"

namespace {

// glibc returns the heap's free top to the system once it passes a threshold that adapts to the
// largest block freed so far, and maps large blocks afresh on every request: a job that frees
// and allocates buffers of tens of megabytes over and over (the GL driver batching the 100,000
// triangles of a fan: 960,000 page faults, 3.7 s of the 5.9 s in the kernel) pays a fresh page
// for every touch. Fixed thresholds keep up to 512 MiB of freed memory for reuse and serve
// blocks below 32 MiB (the largest mmap threshold glibc accepts on 64-bit) from it
// (docs/building.md, "Known traps").
constexpr int kTrimThresholdBytes = 512 << 20;
constexpr int kMmapThresholdBytes = 32 << 20;

}  // namespace

int main(int argc, char** argv) {
    mallopt(M_TRIM_THRESHOLD, kTrimThresholdBytes);
    mallopt(M_MMAP_THRESHOLD, kMmapThresholdBytes);
    return aabench::run_cli(argc, argv);
}
