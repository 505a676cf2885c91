// SubscanlineTracer::add_row (methods/scan/multiscan/subscanline.h): a pixel row's n + 1
// sub-scanlines summed change by change must give the sums that tracing them one by one gives (up
// to the order of the double additions), whenever it accepts a row, and decline (adding nothing)
// otherwise. Checked by running box-multiscan's accumulation (eq. 1-3) both ways over seeded
// random scenes (crossing edges, vertices and horizontal edges on sub-scanlines, ties), over
// scenes of disjoint polygons with holes (chains that start and end inside rows: the
// alternating rows), and over the built-in 2-D patterns at random parameters and sizes, for
// n = 1 .. 18 (past kMaxRowIntervals it must decline). The test also counts the rows the
// whole-row path took, so it cannot pass by always declining.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "methods/scan/kernel/edge_table.h"
#include "methods/scan/multiscan/subscanline.h"
#include "patterns/pattern.h"
#include "test_scenes.h"

namespace aabench {
namespace {

constexpr int kRandomScenes = 1500;
constexpr int kDisjointScenes = 1500;
// The two ways add the same terms in another order (per change instead of per line, a
// change's lines pre-summed), and a straight edge's interior x is interpolated instead of
// evaluated: the double sums differ by a few ulps of the values, and the float32 result by
// at most one rounding step. 4 float ulps of the larger magnitude (values here are <= 1;
// vertices within 1e3 px: with vertices near 1e11 px the interpolated and the evaluated x
// differ by ~1e-5 px and so do the sums, docs/methods-multiscan.md).
constexpr float kSumOrderUlps = 4.0f;

struct Rows {
    std::vector<float> pixels;
    long whole_rows = 0;
};

// box_multiscan.cpp's accumulation of a 2-D scene; `whole` lets the tracer add whole rows.
Rows box_rows(const Scene& scene, int n, bool whole) {
    EdgeTable table;
    table.reset(scene, RowBuckets::kOnDemand);
    SubscanlineTracer tracer;
    tracer.reset(table);
    LineIntegralRow current(scene.width);
    LineProfile below, above;
    Rows out;
    out.pixels.assign(static_cast<std::size_t>(scene.width) * scene.height, 0.0f);
    const double border = 0.5 / n, inner = 1.0 / n;
    tracer.trace(0.0, below, above);
    bool top_traced = true;
    for (int j = 0; j < scene.height; ++j) {
        if (whole && tracer.add_row(j, n, current)) {
            ++out.whole_rows;
            tracer.advance(j + 1.0);
            top_traced = false;
        } else {
            if (!top_traced) tracer.trace(j, below, above);
            current.add(below, border);
            for (int l = 1; l < n; ++l) {
                if (tracer.trace(j + static_cast<double>(l) / n, below, above)) {
                    current.add(below, 0.5 * inner);
                    current.add(above, 0.5 * inner);
                } else {
                    current.add(below, inner);
                }
            }
            const bool split = tracer.trace(j + 1.0, below, above);
            current.add(split ? above : below, border);
            top_traced = true;
        }
        current.resolve(out.pixels.data() + static_cast<std::size_t>(j) * scene.width);
        current.clear();
    }
    return out;
}

// The first pixel where the two differ by more than the tolerance, or -1.
long first_difference(const std::vector<float>& a, const std::vector<float>& b) {
    for (std::size_t k = 0; k < a.size(); ++k) {
        const float scale = std::max({1.0f, std::abs(a[k]), std::abs(b[k])});
        if (!(std::abs(a[k] - b[k]) <= kSumOrderUlps * FLT_EPSILON * scale)) {
            return static_cast<long>(k);
        }
    }
    return -1;
}

long check(const Scene& scene, int n, const std::string& what) {
    const Rows fast = box_rows(scene, n, true);
    const Rows slow = box_rows(scene, n, false);
    const long at = first_difference(fast.pixels, slow.pixels);
    EXPECT_EQ(at, -1) << what << " n=" << n << ": pixel (" << at % scene.width << ", "
                      << at / scene.width << ") whole rows " << (at >= 0 ? fast.pixels[at] : 0.0f)
                      << ", line by line " << (at >= 0 ? slow.pixels[at] : 0.0f);
    if (n > SubscanlineTracer::kMaxRowIntervals) {
        EXPECT_EQ(fast.whole_rows, 0) << what << " n=" << n << ": past the buffer's bound";
    }
    return fast.whole_rows;
}

// Disjoint regular polygons in a grid of cells, some with a hole (the inner contour reversed,
// or, one time in five, not: winding 2 inside, which the alternating rows must refuse), all
// of one shape: chains start and end inside rows. Some vertices snapped to the sub-scanlines
// of n so that chains start or end exactly on them.
Scene disjoint_scene(std::uint64_t seed, int n) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    Scene scene;
    const int cells_x = 1 + static_cast<int>(rng() % 5), cells_y = 1 + static_cast<int>(rng() % 5);
    const double cell = 3.0 + 9.0 * unit(rng);
    scene.width = static_cast<int>(std::ceil(cells_x * cell));
    scene.height = static_cast<int>(std::ceil(cells_y * cell));
    scene.background = 0.4 * unit(rng);
    Shape shape;
    shape.value = 0.5 + 0.5 * unit(rng);
    const bool snap = rng() % 3 == 0;
    for (int cy = 0; cy < cells_y; ++cy) {
        for (int cx = 0; cx < cells_x; ++cx) {
            if (rng() % 4 == 0) continue;
            const double r = cell * (0.15 + 0.3 * unit(rng));
            const double ox = (cx + 0.5) * cell + (unit(rng) - 0.5) * (cell - 2 * r) * 0.9;
            const double oy = (cy + 0.5) * cell + (unit(rng) - 0.5) * (cell - 2 * r) * 0.9;
            const int vertices = 3 + static_cast<int>(rng() % 40);
            const double turn = 2.0 * std::numbers::pi * unit(rng);
            const bool clockwise = rng() % 2 == 0;
            const auto polygon = [&](double radius, bool reverse) {
                Contour c;
                for (int k = 0; k < vertices; ++k) {
                    const double a = turn + 2.0 * std::numbers::pi * k / vertices;
                    Point p{ox + radius * std::cos(a), oy + radius * std::sin(a)};
                    if (snap && k % 2 == 0) p.y = std::round(p.y * n) / n;
                    c.push_back(p);
                }
                if (reverse != clockwise) std::reverse(c.begin(), c.end());
                return c;
            };
            shape.contours.push_back(polygon(r, false));
            if (rng() % 2 == 0) shape.contours.push_back(polygon(0.5 * r, rng() % 5 != 0));
        }
    }
    scene.shapes.push_back(shape);
    return scene;
}

TEST(SubscanlineRows, RandomScenesWholeRowsEqualLineByLine) {
    long whole = 0, rows = 0;
    for (std::uint64_t seed = 0; seed < kRandomScenes; ++seed) {
        std::mt19937_64 rng(seed * 104729 + 7);
        const int width = 1 + static_cast<int>(rng() % 40);
        const int height = 1 + static_cast<int>(rng() % 40);
        const int n = 1 + static_cast<int>(rng() % 18);
        const Scene scene =
            seed % 3 == 2 ? testing::random_small_scene(seed, true, {1, 24, 1, 24, 3.0, 4, 6, 8})
                          : testing::random_scene(seed, width, height, seed % 3 == 1);
        whole += check(scene, n, fmt::format("seed {}", seed));
        rows += scene.height;
        if (::testing::Test::HasFailure()) return;
    }
    // Random polygons cross a great deal, but some rows are simple.
    EXPECT_GT(whole, rows / 20) << "the whole-row path was hardly taken: the test is weak";
}

TEST(SubscanlineRows, DisjointPolygonsWithHolesWholeRowsEqualLineByLine) {
    long whole = 0, rows = 0;
    for (std::uint64_t seed = 0; seed < kDisjointScenes; ++seed) {
        const int n = 1 + static_cast<int>(seed % 18);
        const Scene scene = disjoint_scene(seed, n);
        whole += check(scene, n, fmt::format("disjoint seed {}", seed));
        rows += scene.height;
        if (::testing::Test::HasFailure()) return;
    }
    // Chains start and end in most rows here: only the alternating rows take them.
    EXPECT_GT(whole, rows / 2) << "the whole-row path was hardly taken: the test is weak";
}

TEST(SubscanlineRows, PatternsWholeRowsEqualLineByLineAndAreTaken) {
    std::mt19937_64 rng(20261124);
    for (const char* pattern : {"grating", "rings", "zoneplate", "star", "strips"}) {
        for (int trial = 0; trial < 4; ++trial) {
            const int size = 24 + static_cast<int>(rng() % 100);
            const int n = 1 + static_cast<int>(rng() % 18);
            const Scene scene = make_pattern(pattern, size, size);
            const long whole = check(scene, n, fmt::format("{} at {}^2", pattern, size));
            // Long straight bars; rings whose tops and bottoms start and end chains; the
            // star's rays meet at its centre, where rows are line by line (at 1024^2, 985 of
            // 1,024 rows are whole; a quarter at least at these sizes).
            const long taken_at_least = std::string(pattern) == "star" ? size / 4 : size / 2;
            if (n <= SubscanlineTracer::kMaxRowIntervals) {
                EXPECT_GT(whole, taken_at_least) << pattern << " at " << size << "^2, n=" << n;
            }
            if (::testing::Test::HasFailure()) return;
        }
    }
}

// LineIntegralRow::resolve_and_clear (box-multiscan's end of a row) against resolve() then
// clear(): the same floats bit for bit, and a row as empty as clear() leaves it, over widths
// around the blocks of cells and the words of flags (8 and 64 cells), with changes left of,
// inside and right of the row; a second pass on the same rows checks what the first left.
TEST(SubscanlineRows, ResolveAndClearEqualsResolveThenClear) {
    std::mt19937_64 rng(20261126);
    for (const int width : {1, 7, 8, 9, 63, 64, 65, 130, 1000}) {
        LineIntegralRow fused(width), apart(width);
        for (int pass = 0; pass < 40; ++pass) {
            // 0..24 changes at x in [-2, width + 2], values in [0, 1]: sparse rows skip blocks.
            std::uniform_real_distribution<double> x(-2.0, width + 2.0), v(0.0, 1.0);
            LineProfile line;
            line.start = v(rng);
            const int changes = static_cast<int>(rng() % 25);
            for (int c = 0; c < changes; ++c) line.changes.push_back({x(rng), v(rng)});
            std::sort(line.changes.begin(), line.changes.end(),
                      [](const ValueChange& a, const ValueChange& b) { return a.x < b.x; });
            const double weight = 1.0 / (1 + static_cast<int>(rng() % 7));
            fused.add(line, weight);
            apart.add(line, weight);
            std::vector<float> a(width), b(width);
            apart.resolve(a.data());
            apart.clear();
            fused.resolve_and_clear(b.data());
            for (int i = 0; i < width; ++i) {
                ASSERT_EQ(std::bit_cast<std::uint32_t>(a[i]), std::bit_cast<std::uint32_t>(b[i]))
                    << "width " << width << " pass " << pass << " pixel " << i;
            }
            fused.resolve(b.data());  // empty: every pixel +0.0
            for (int i = 0; i < width; ++i) {
                ASSERT_EQ(std::bit_cast<std::uint32_t>(b[i]), 0u) << "width " << width;
            }
        }
    }
}

}  // namespace
}  // namespace aabench
