// Counts heap allocations made by the current thread, so that a stage's (or a render's) bytes
// allocated can be measured, and a stage the plan leaves out can be shown to allocate nothing.
// alloc_count.cpp replaces the global operator new/delete of every program that links it
// (the replacement forwards to malloc/free and adds two thread-local increments).
#pragma once

#include <cstdint>

namespace aabench {

struct AllocCounts {
    std::uint64_t bytes = 0;
    std::uint64_t allocations = 0;
};

// Totals for the calling thread since it started.
AllocCounts thread_alloc_counts();

}  // namespace aabench
