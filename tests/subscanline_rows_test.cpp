// SubscanlineTracer::add_interior_lines (methods/scan/subscanline.h): a pixel row's interior
// sub-scanlines added in one pass must give the sums that tracing them one by one gives, bit
// for bit, whenever it accepts a row, and decline (adding nothing) otherwise. Checked by running
// box-multiscan's accumulation (eq. 1-3) both ways over seeded random scenes (crossing edges,
// vertices and horizontal edges on sub-scanlines, ties) and over the built-in 2-D patterns at
// random parameters and sizes, for n = 1 .. 17 (past kMaxInteriorLines it must decline). The
// test also counts the rows the one-pass path took, so it cannot pass by always declining.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "methods/scan/edge_table.h"
#include "methods/scan/subscanline.h"
#include "patterns/pattern.h"
#include "test_scenes.h"

namespace aabench {
namespace {

constexpr int kRandomScenes = 1500;

struct Rows {
    std::vector<float> pixels;
    long one_pass_rows = 0;
};

// box_multiscan.cpp's accumulation of a 2-D scene; `one_pass` lets the tracer add interior
// lines at once.
Rows box_rows(const Scene& scene, int n, bool one_pass) {
    EdgeTable table;
    table.reset(scene, RowBuckets::kOnDemand);
    SubscanlineTracer tracer;
    tracer.reset(table);
    LineIntegralRow current(scene.width), next(scene.width);
    LineProfile below, above;
    Rows out;
    out.pixels.assign(static_cast<std::size_t>(scene.width) * scene.height, 0.0f);
    const double border = 0.5 / n, inner = 1.0 / n;
    tracer.trace(0.0, below, above);
    current.add(below, border);
    for (int j = 0; j < scene.height; ++j) {
        const bool done = one_pass && tracer.add_interior_lines(j, n, inner, current);
        out.one_pass_rows += done && n > 1;
        for (int l = 1; l < n && !done; ++l) {
            if (tracer.trace(j + static_cast<double>(l) / n, below, above)) {
                current.add(below, 0.5 * inner);
                current.add(above, 0.5 * inner);
            } else {
                current.add(below, inner);
            }
        }
        const bool split = tracer.trace(j + 1.0, below, above);
        current.add(split ? above : below, border);
        next.add(below, border);
        current.resolve(out.pixels.data() + static_cast<std::size_t>(j) * scene.width);
        std::swap(current, next);
        next.clear();
    }
    return out;
}

// The first pixel that differs in its bits, or -1.
long first_difference(const std::vector<float>& a, const std::vector<float>& b) {
    for (std::size_t k = 0; k < a.size(); ++k) {
        if (std::memcmp(&a[k], &b[k], sizeof(float)) != 0) return static_cast<long>(k);
    }
    return -1;
}

long check(const Scene& scene, int n, const std::string& what) {
    const Rows fast = box_rows(scene, n, true);
    const Rows slow = box_rows(scene, n, false);
    const long at = first_difference(fast.pixels, slow.pixels);
    EXPECT_EQ(at, -1) << what << " n=" << n << ": pixel (" << at % scene.width << ", "
                      << at / scene.width << ") one pass " << fast.pixels[at] << ", line by line "
                      << slow.pixels[at];
    if (n - 1 > SubscanlineTracer::kMaxInteriorLines) {
        EXPECT_EQ(fast.one_pass_rows, 0) << what << " n=" << n << ": past the buffer's bound";
    }
    return fast.one_pass_rows;
}

TEST(SubscanlineRows, RandomScenesOnePassEqualsLineByLine) {
    long one_pass = 0, rows = 0;
    for (std::uint64_t seed = 0; seed < kRandomScenes; ++seed) {
        std::mt19937_64 rng(seed * 104729 + 7);
        const int width = 1 + static_cast<int>(rng() % 40);
        const int height = 1 + static_cast<int>(rng() % 40);
        const int n = 1 + static_cast<int>(rng() % 17);
        const Scene scene = seed % 3 == 2
                                ? testing::random_small_scene(seed, true, {1, 24, 1, 24, 3.0, 4, 6, 8})
                                : testing::random_scene(seed, width, height, seed % 3 == 1);
        one_pass += check(scene, n, fmt::format("seed {}", seed));
        rows += scene.height;
        if (::testing::Test::HasFailure()) return;
    }
    // Random polygons cross a great deal, but some rows are simple.
    EXPECT_GT(one_pass, rows / 20) << "the one-pass path was hardly taken: the test is weak";
}

TEST(SubscanlineRows, PatternsOnePassEqualsLineByLineAndIsTakenOnGratings) {
    std::mt19937_64 rng(20261124);
    for (const char* pattern : {"grating", "rings", "zoneplate", "star", "strips"}) {
        for (int trial = 0; trial < 4; ++trial) {
            const int size = 24 + static_cast<int>(rng() % 100);
            const int n = 1 + static_cast<int>(rng() % 17);
            const Scene scene = make_pattern(pattern, size, size);
            const long one_pass = check(scene, n, fmt::format("{} at {}^2", pattern, size));
            // Long straight bars: nearly every row is simple.
            if (std::string(pattern) == "grating" && n > 1 &&
                n - 1 <= SubscanlineTracer::kMaxInteriorLines) {
                EXPECT_GT(one_pass, size / 2) << "grating at " << size << "^2, n=" << n;
            }
            if (::testing::Test::HasFailure()) return;
        }
    }
}

}  // namespace
}  // namespace aabench
