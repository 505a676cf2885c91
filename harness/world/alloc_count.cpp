#include "harness/world/alloc_count.h"

#include <cstdlib>
#include <new>

namespace aabench {
namespace {
thread_local AllocCounts t_counts;

void* counted_alloc(std::size_t size) {
    t_counts.bytes += size;
    ++t_counts.allocations;
    // malloc(0) may return null; operator new must not.
    if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
    throw std::bad_alloc();
}

void* counted_aligned_alloc(std::size_t size, std::align_val_t align) {
    t_counts.bytes += size;
    ++t_counts.allocations;
    const std::size_t a = static_cast<std::size_t>(align);
    // aligned_alloc wants a size that is a multiple of the alignment.
    const std::size_t rounded = ((size == 0 ? 1 : size) + a - 1) / a * a;
    if (void* p = std::aligned_alloc(a, rounded)) return p;
    throw std::bad_alloc();
}
}  // namespace

AllocCounts thread_alloc_counts() { return t_counts; }

}  // namespace aabench

void* operator new(std::size_t size) { return aabench::counted_alloc(size); }
void* operator new[](std::size_t size) { return aabench::counted_alloc(size); }
void* operator new(std::size_t size, std::align_val_t a) {
    return aabench::counted_aligned_alloc(size, a);
}
void* operator new[](std::size_t size, std::align_val_t a) {
    return aabench::counted_aligned_alloc(size, a);
}
// The nothrow forms too: every form of new must come from here, or a sanitizer's own new would
// be paired with this delete (free), which AddressSanitizer reports as a mismatch.
void* operator new(std::size_t size, const std::nothrow_t&) noexcept {
    try {
        return aabench::counted_alloc(size);
    } catch (...) {
        return nullptr;
    }
}
void* operator new[](std::size_t size, const std::nothrow_t&) noexcept {
    try {
        return aabench::counted_alloc(size);
    } catch (...) {
        return nullptr;
    }
}
void* operator new(std::size_t size, std::align_val_t a, const std::nothrow_t&) noexcept {
    try {
        return aabench::counted_aligned_alloc(size, a);
    } catch (...) {
        return nullptr;
    }
}
void* operator new[](std::size_t size, std::align_val_t a, const std::nothrow_t&) noexcept {
    try {
        return aabench::counted_aligned_alloc(size, a);
    } catch (...) {
        return nullptr;
    }
}
void operator delete(void* p, const std::nothrow_t&) noexcept { std::free(p); }
void operator delete[](void* p, const std::nothrow_t&) noexcept { std::free(p); }
void operator delete(void* p, std::align_val_t, const std::nothrow_t&) noexcept { std::free(p); }
void operator delete[](void* p, std::align_val_t, const std::nothrow_t&) noexcept { std::free(p); }
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }
void operator delete(void* p, std::align_val_t) noexcept { std::free(p); }
void operator delete[](void* p, std::align_val_t) noexcept { std::free(p); }
void operator delete(void* p, std::size_t, std::align_val_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t, std::align_val_t) noexcept { std::free(p); }
