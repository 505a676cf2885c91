// gauss-multiscan's whole region rows (SubscanlineTracer::add_region_row, methods/scan/
// region_rows.h): the method's image must be eq. 4 summed line by line, up to the order of
// the double additions, on seeded random scenes (crossing edges, vertices on the
// sub-scanlines, which decline), on disjoint polygons with holes (chains that start and end
// inside region rows: the alternating rows) and on the built-in 2-D patterns, for several n,
// both profiles and both table modes. The reference traces every line with
// SubscanlineTracer::trace (tested against brute force in edge_sweep_test.cpp) and adds each
// value change's weight right of it to every pixel, with CrossSectionTable::at: no regions,
// no difference rows. The test also drives add_region_row over the scene as the method does
// and counts the rows it takes, so that it cannot pass by always declining.
#include "methods/scan/multiscan/region_rows.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "methods/method.h"
#include "methods/scan/multiscan/subscanline.h"
#include "patterns/pattern.h"
#include "test_scenes.h"

namespace aabench {
namespace {

// The two sides add the same terms in another order (per change into difference rows, a
// change's lines pre-summed, against per line and pixel), interpolate a straight edge's
// interior x instead of evaluating it, and evaluate F at x' and 1 - x' against |x - cx|: the
// double sums differ by a few ulps of the values (<= 1 here), and the float32 results by at
// most one rounding step. 4 float ulps of the larger magnitude, as for box-multiscan's whole
// rows (subscanline_rows_test.cpp).
constexpr float kSumOrderUlps = 4.0f;

struct Setting {
    int n;
    FilterKind kind;
    int lut;
};

// The method's filter of the setting (sigma at its default, 0.5).
Filter filter_of(const Setting& s) {
    return s.kind == FilterKind::kCone ? Filter::cone(1.0) : Filter::gaussian(0.5, 1.0);
}

std::string spec_of(const Setting& s) {
    return fmt::format("gauss-multiscan:n={},filter={},lut={}", s.n,
                       s.kind == FilterKind::kCone ? "cone" : "gaussian", s.lut);
}

// Eq. 4 line by line: every line (r + 0.5) + l/n, r = -1..height-1, its two limits with weight
// 1/2 each where they differ; a change by dv at x adds dv times the part of the cross-section
// right of x to each pixel of the two rows it feeds.
std::vector<float> line_by_line(const Scene& scene, const Setting& s) {
    const Filter profile = filter_of(s);
    const CrossSectionTable table(profile, s.n, s.lut);
    EdgeTable edges;
    edges.reset(scene, RowBuckets::kOnDemand);
    SubscanlineTracer tracer(edges);
    const int width = scene.width, height = scene.height, n = s.n;
    std::vector<double> sums(static_cast<std::size_t>(width) * height, 0.0);
    // The weight right of x of the cross-section at vertical distance d/n centred on cx.
    const auto right_of = [&](int d, double x, double cx) {
        const double u = x - cx, half = table.total(d);
        if (u <= -1.0) return 2.0 * half;
        if (u >= 1.0) return 0.0;
        return u < 0.0 ? half + table.at(d, -u) : half - table.at(d, u);
    };
    const auto add_line = [&](const LineProfile& line, double weight, int row, int d) {
        if (row < 0 || row >= height || d >= n) return;
        double* out = sums.data() + static_cast<std::size_t>(row) * width;
        for (int i = 0; i < width; ++i) {
            const double cx = i + 0.5;
            double total = (line.start - scene.background) * 2.0 * table.total(d);
            double before = line.start;
            for (const ValueChange& c : line.changes) {
                total += (c.value - before) * right_of(d, c.x, cx);
                before = c.value;
            }
            out[i] += weight * total;
        }
    };
    LineProfile below, above;
    for (int r = -1; r < height; ++r) {
        for (int l = 0; l < n; ++l) {
            const double y = (r + 0.5) + static_cast<double>(l) / n;
            const bool split = tracer.trace(y, below, above);
            const double weight = split ? 0.5 : 1.0;
            add_line(below, weight, r, l);
            add_line(below, weight, r + 1, n - l);
            if (split) {
                add_line(above, weight, r, l);
                add_line(above, weight, r + 1, n - l);
            }
        }
    }
    std::vector<float> out(sums.size());
    for (std::size_t p = 0; p < sums.size(); ++p) {
        out[p] = static_cast<float>(scene.background + sums[p]);
    }
    return out;
}

// The region rows add_region_row takes, driven as gauss_multiscan.cpp drives it.
long whole_region_rows(const Scene& scene, const Setting& s) {
    const Filter profile = filter_of(s);
    const CrossSectionTable table(profile, s.n, s.lut);
    const RegionWeights weights(table);
    EdgeTable edges;
    edges.reset(scene, RowBuckets::kOnDemand);
    SubscanlineTracer tracer(edges);
    RegionCells cells;
    cells.reset(scene.width);
    LineProfile below, above;
    long taken = 0;
    for (int r = -1; r < scene.height; ++r) {
        const double y_top = r + 0.5;
        if (y_top >= 0.0) {
            tracer.advance(y_top);
            RegionRowSums sums(weights, scene.background, cells);
            if (tracer.add_region_row(y_top, s.n, sums)) {
                ++taken;
                cells.clear();
                continue;
            }
        }
        for (int l = 0; l < s.n; ++l)
            tracer.trace(y_top + static_cast<double>(l) / s.n, below, above);
    }
    return taken;
}

// Checks the method against the reference; returns the region rows taken whole.
long check(const Scene& scene, const Setting& s, const std::string& what) {
    const MethodInstance m = make_method(spec_of(s));
    const Image image = render_scene(*m.method, scene);
    const std::vector<float> want = line_by_line(scene, s);
    for (std::size_t p = 0; p < want.size(); ++p) {
        const float a = image.data[p], b = want[p];
        const float scale = std::max({1.0f, std::abs(a), std::abs(b)});
        if (!(std::abs(a - b) <= kSumOrderUlps * FLT_EPSILON * scale)) {
            ADD_FAILURE() << fmt::format("{} {}: pixel ({}, {}) whole rows {} line by line {}\n{}",
                                         what, m.spec, p % scene.width, p / scene.width, a, b,
                                         testing::describe(scene));
            return 0;
        }
    }
    return whole_region_rows(scene, s);
}

const Setting kSettings[] = {
    {1, FilterKind::kGaussian, 64},  {2, FilterKind::kCone, 64},
    {3, FilterKind::kGaussian, 64},  {3, FilterKind::kGaussian, 0},
    {4, FilterKind::kCone, 0},       {7, FilterKind::kGaussian, 64},
    {16, FilterKind::kGaussian, 64}, {17, FilterKind::kGaussian, 64},
};

TEST(RegionRows, RandomScenesEqualLineByLine) {
    constexpr int kScenes = 60;
    long whole = 0, rows = 0;
    for (int seed = 0; seed < kScenes; ++seed) {
        const Setting& s = kSettings[seed % std::size(kSettings)];
        // Snapped to the quarter pixel: vertices on the lines of n = 2 and 4.
        const Scene scene =
            seed % 2 == 0
                ? testing::random_small_scene(seed, seed % 4 == 0, {1, 24, 1, 24, 3.0, 4, 6, 8})
                : testing::random_scene(seed, 1 + seed % 29, 1 + seed % 23, seed % 3 == 0);
        whole += check(scene, s, fmt::format("seed {}", seed));
        rows += scene.height;
        if (::testing::Test::HasFailure()) return;
    }
    EXPECT_GT(whole, rows / 20) << "the whole region rows were hardly taken: the test is weak";
}

// Disjoint regular polygons of one shape, some with a hole: chains start and end inside the
// region rows (the alternating rows), and one time in three a vertex lies on a line.
Scene disjoint_polygons(std::uint64_t seed, int n) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    Scene scene;
    const int cells = 1 + static_cast<int>(rng() % 4);
    const double cell = 4.0 + 8.0 * unit(rng);
    scene.width = scene.height = static_cast<int>(std::ceil(cells * cell));
    scene.background = 0.3 * unit(rng);
    Shape shape;
    shape.value = 0.6 + 0.4 * unit(rng);
    const bool snap = rng() % 3 == 0;
    for (int cy = 0; cy < cells; ++cy) {
        for (int cx = 0; cx < cells; ++cx) {
            const double r = cell * (0.15 + 0.3 * unit(rng));
            const double ox = (cx + 0.5) * cell, oy = (cy + 0.5) * cell;
            const int vertices = 3 + static_cast<int>(rng() % 30);
            const double turn = 2.0 * std::numbers::pi * unit(rng);
            const auto polygon = [&](double radius, bool reverse) {
                Contour c;
                for (int k = 0; k < vertices; ++k) {
                    const double a = turn + 2.0 * std::numbers::pi * k / vertices;
                    Point p{ox + radius * std::cos(a), oy + radius * std::sin(a)};
                    if (snap && k % 2 == 0) p.y = std::round((p.y - 0.5) * n) / n + 0.5;
                    c.push_back(p);
                }
                if (reverse) std::reverse(c.begin(), c.end());
                return c;
            };
            shape.contours.push_back(polygon(r, false));
            if (rng() % 2 == 0) shape.contours.push_back(polygon(0.5 * r, true));
        }
    }
    scene.shapes.push_back(shape);
    return scene;
}

TEST(RegionRows, DisjointPolygonsWithHolesEqualLineByLine) {
    constexpr int kScenes = 40;
    long whole = 0, rows = 0;
    for (int seed = 0; seed < kScenes; ++seed) {
        const Setting& s = kSettings[seed % std::size(kSettings)];
        const Scene scene = disjoint_polygons(seed, s.n);
        whole += check(scene, s, fmt::format("disjoint seed {}", seed));
        rows += scene.height;
        if (::testing::Test::HasFailure()) return;
    }
    EXPECT_GT(whole, rows / 2) << "the whole region rows were hardly taken: the test is weak";
}

TEST(RegionRows, PatternsEqualLineByLineAndAreTaken) {
    std::mt19937_64 rng(20261126);
    for (const char* pattern : {"grating", "rings", "zoneplate", "star", "strips"}) {
        for (int trial = 0; trial < 2; ++trial) {
            const int size = 24 + static_cast<int>(rng() % 80);
            const Setting s = {1 + static_cast<int>(rng() % 16), FilterKind::kGaussian,
                               trial == 0 ? 64 : 0};
            const Scene scene = make_pattern(pattern, size, size);
            const long whole = check(scene, s, fmt::format("{} at {}^2", pattern, size));
            // The star's rays meet at its centre, where rows go line by line (most rows of a
            // small star: a fifth at least are whole); the others take most rows.
            const long taken_at_least = std::string(pattern) == "star" ? size / 5 : size / 2;
            EXPECT_GT(whole, taken_at_least) << pattern << " at " << size << "^2, n=" << s.n;
            if (::testing::Test::HasFailure()) return;
        }
    }
}

// RegionRowSums::resolve_and_clear reads the region row above as it clears it: the row it
// leaves must be empty (every cell and flag, the ones past the last pixel included), so that
// resolving it again against an empty row gives the background on every pixel, exactly.
// Widths around the blocks of 8 cells and the words of 8 flags; changes all over the row, the
// last regions (whose terms reach cells width and width + 1) and left of it included.
TEST(RegionRows, ResolveAndClearLeavesTheRowEmpty) {
    const Filter profile = Filter::gaussian(0.5);
    const CrossSectionTable table(profile, 3, 64);
    const RegionWeights weights(table);
    constexpr double kBackground = 0.25;
    std::mt19937_64 rng(20261126);
    for (const int width : {1, 7, 8, 9, 63, 64, 65, 130}) {
        RegionCells above, here;
        above.reset(width);
        here.reset(width);
        std::uniform_real_distribution<double> at(-1.5, width + 1.0), slant(-0.4, 0.4);
        std::vector<double> x, dv;
        for (int k = 0; k < 24; ++k) {
            const double top = k == 0 ? width - 0.1 : at(rng);
            x.push_back(top);
            x.push_back(top + slant(rng));
            dv.push_back(k % 2 == 0 ? 0.75 : -0.5);
        }
        RegionRowSums sums(weights, kBackground, above);
        sums.add_row_spans(0.5, x.data(), dv.data(), dv.size(), 3);
        std::vector<float> row(width), again(width);
        RegionRowSums::resolve_and_clear(above, here, kBackground, row.data());
        EXPECT_NE(row, std::vector<float>(width, static_cast<float>(kBackground)))
            << "width " << width << ": the changes added nothing";
        RegionRowSums::resolve_and_clear(above, here, kBackground, again.data());
        EXPECT_EQ(again, std::vector<float>(width, static_cast<float>(kBackground)))
            << "width " << width << ": the row above was not left empty";
    }
}

}  // namespace
}  // namespace aabench
