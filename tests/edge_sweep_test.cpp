// The active edge list (methods/scan/kernel/edge_sweep.h) and what is built on it, against the
// straightforward answers they replaced, on seeded random scenes: the crossings of every line
// against EdgeTable::crossings_at (gather the row, sort it), the "endpoint on the line" flag
// against a search over every endpoint, the sub-scanline tracer's profiles against a walk of
// crossings gathered from every edge and sorted, the point sampler's run-writing centre rows
// and value runs against its per-sample walk, and the pixels a run start marks. A failure
// prints the seed, the line and the scene.
#include "methods/scan/kernel/edge_sweep.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <random>
#include <stdexcept>
#include <tuple>
#include <vector>

#include "methods/scan/kernel/edge_table.h"
#include "methods/scan/multiscan/subscanline.h"
#include "methods/scan/sampling/point_sampling.h"
#include "patterns/scene/curves.h"
#include "test_scenes.h"

namespace aabench {
namespace {

constexpr int kScenes = 1500;  // per test; each sweeps a few hundred lines

// Random scenes of several kinds: general polygons (half of them snapped to the half-pixel
// grid, so vertices and horizontal edges land on lines and crossings tie), and small snapped
// scenes with a rectangle on the quarter-pixel grid.
Scene scene_for(std::uint64_t seed) {
    std::mt19937_64 rng(seed * 7919 + 1);
    const int width = 1 + static_cast<int>(rng() % 40);
    const int height = 1 + static_cast<int>(rng() % 40);
    if (seed % 3 == 2) {
        const testing::SmallSceneShape shape{1, 24, 1, 24, 3.0, 4, 6, 8};
        return testing::random_small_scene(seed, true, shape);
    }
    return testing::random_scene(seed, width, height, seed % 3 == 1);
}

// Lines in ascending y: every sub-scanline j + l/n of a random n (integer lines included),
// plus a few random heights; some repeated.
std::vector<double> ascending_lines(std::uint64_t seed, int height) {
    std::mt19937_64 rng(seed);
    const int n = 1 + static_cast<int>(rng() % 6);
    std::vector<double> ys;
    for (int j = 0; j < height; ++j) {
        for (int l = 0; l < n; ++l) ys.push_back(j + static_cast<double>(l) / n);
    }
    std::uniform_real_distribution<double> u(0.0, height);
    for (int k = 0; k < 8; ++k) ys.push_back(u(rng));
    ys.push_back(ys[ys.size() / 2]);  // the same line twice
    std::sort(ys.begin(), ys.end());
    return ys;
}

using Key = std::tuple<double, int, int>;

std::vector<Key> keys(std::span<const Crossing> crossings) {
    std::vector<Key> out;
    for (const Crossing& c : crossings) out.emplace_back(c.x, c.shape, c.winding);
    std::sort(out.begin(), out.end());
    return out;
}

bool any_endpoint_on(const EdgeTable& table, double y) {
    for (const Edge& e : table.edges()) {
        if (e.y0 == y || e.y1 == y) return true;
    }
    return false;
}

// One line of the sweep against crossings_at; returns false (after reporting) on a mismatch.
bool check_line(const EdgeTable& reference, EdgeSweep& sweep, double y, bool exact_endpoints,
                std::uint64_t seed, const Scene& scene) {
    std::vector<Crossing> expected;
    reference.crossings_at(y, expected);
    const std::span<const Crossing> got = sweep.crossings(y);
    const std::string where = fmt::format("seed {} line y = {:.17g}", seed, y);
    bool sorted = true, ties = false;
    for (std::size_t k = 1; k < got.size(); ++k) {
        sorted = sorted && !(got[k].x < got[k - 1].x);
        ties = ties || got[k].x == got[k - 1].x;
    }
    // The same crossings (x, shape and winding), in ascending x, tied or not as the reference.
    if (!sorted || keys(got) != keys(expected) || sweep.ties() != ties) {
        ADD_FAILURE() << where
                      << fmt::format(": {} crossings, expected {}{}", got.size(), expected.size(),
                                     sorted ? "" : ", not sorted")
                      << "\n"
                      << testing::describe(scene);
        return false;
    }
    // Where the x differ, the order is crossings_at's: compare position by position.
    for (std::size_t k = 0; k < got.size(); ++k) {
        if (got[k].x != expected[k].x) {
            ADD_FAILURE() << where
                          << fmt::format(": crossing {} at x = {}, expected {}", k, got[k].x,
                                         expected[k].x);
            return false;
        }
    }
    if (exact_endpoints && sweep.endpoint_on_line() != any_endpoint_on(reference, y)) {
        ADD_FAILURE() << where << ": endpoint_on_line() " << sweep.endpoint_on_line() << "\n"
                      << testing::describe(scene);
        return false;
    }
    return true;
}

TEST(EdgeSweep, AscendingLinesMatchCrossingsAt) {
    long lines = 0, seeks = 0;
    for (std::uint64_t seed = 1; seed <= kScenes; ++seed) {
        const Scene scene = scene_for(seed);
        const EdgeTable reference(scene);
        EdgeTable table;
        table.reset(scene, RowBuckets::kOnDemand);
        EdgeSweep sweep(table);
        for (const double y : ascending_lines(seed, scene.height)) {
            if (!check_line(reference, sweep, y, true, seed, scene)) return;
            ++lines;
        }
        seeks += sweep.seeks();
        // Going down only, the sweep never needs the row buckets.
        ASSERT_FALSE(table.has_rows()) << "seed " << seed;
    }
    EXPECT_EQ(seeks, 0);
    RecordProperty("lines", static_cast<int>(lines));
}

TEST(EdgeSweep, LinesOutOfOrderSeek) {
    for (std::uint64_t seed = 1; seed <= kScenes; ++seed) {
        const Scene scene = scene_for(seed);
        const EdgeTable reference(scene);
        EdgeTable table;
        table.reset(scene, RowBuckets::kOnDemand);
        EdgeSweep sweep(table);
        std::mt19937_64 rng(seed);
        std::vector<double> ys = ascending_lines(seed, scene.height);
        // Short runs downwards, each starting above where the last one ended (the rotated
        // sample grids' order), and now and then a jump anywhere.
        for (std::size_t k = 0; k + 1 < ys.size(); k += 3) {
            if (rng() % 2) std::swap(ys[k], ys[k + 1]);
        }
        std::shuffle(ys.begin() + static_cast<std::ptrdiff_t>(ys.size() / 2), ys.end(), rng);
        double last = -1.0;
        for (const double y : ys) {
            // After a seek to y == 0 an edge wholly above the image may end on the line unseen
            // (edge_sweep.h says so): there the flag is not checked.
            const bool exact = !(y == 0.0 && y < last);
            if (!check_line(reference, sweep, y, exact, seed, scene)) return;
            last = y;
        }
    }
}

// The straightforward profile of one limit of a line: crossings of every edge met, in index
// order, sorted (what the tracer computed before the sweep), walked with the walker.
void reference_profile(const EdgeTable& table, double y, bool from_below, LineProfile& out) {
    std::vector<Crossing> crossings;
    for (const Edge& e : table.edges()) {
        const bool hit = from_below ? (e.y0 <= y && y < e.y1) : (e.y0 < y && y <= e.y1);
        if (hit) crossings.push_back({e.x_at(y), e.winding, e.shape});
    }
    std::sort(crossings.begin(), crossings.end(),
              [](const Crossing& a, const Crossing& b) { return a.x < b.x; });
    VisibilityWalker walker(table);
    out.start = walker.value();
    out.changes.clear();
    double value = out.start;
    for (const Crossing& c : crossings) {
        const double next = walker.cross(c.shape, c.winding);
        if (next != value) {
            out.changes.push_back({c.x, next});
            value = next;
        }
    }
}

bool same_profile(const LineProfile& a, const LineProfile& b) {
    if (a.start != b.start || a.changes.size() != b.changes.size()) return false;
    for (std::size_t k = 0; k < a.changes.size(); ++k) {
        if (a.changes[k].x != b.changes[k].x || a.changes[k].value != b.changes[k].value) {
            return false;
        }
    }
    return true;
}

TEST(EdgeSweep, TracerMatchesSortedWalk) {
    for (std::uint64_t seed = 1; seed <= kScenes; ++seed) {
        const Scene scene = scene_for(seed);
        const EdgeTable reference(scene);
        EdgeTable table;
        table.reset(scene, RowBuckets::kOnDemand);
        SubscanlineTracer tracer(table);
        LineProfile below, above, expected;
        // The margin lines of the Gaussian methods, then the image's lines, then past the
        // bottom: the order box- and gauss-multiscan trace in.
        std::vector<double> ys = {-1.0, -0.5, -0.25};
        for (const double y : ascending_lines(seed, scene.height)) ys.push_back(y);
        for (const double y : {1.0 * scene.height, scene.height + 0.5, scene.height + 1.0}) {
            ys.push_back(y);
        }
        for (const double y : ys) {
            const bool split = tracer.trace(y, below, above);
            const std::string where = fmt::format("seed {} line y = {:.17g}", seed, y);
            ASSERT_EQ(split, any_endpoint_on(reference, y)) << where << "\n"
                                                            << testing::describe(scene);
            reference_profile(reference, y, true, expected);
            ASSERT_TRUE(same_profile(below, expected)) << where << ": limit from below\n"
                                                       << testing::describe(scene);
            if (split) {
                reference_profile(reference, y, false, expected);
                ASSERT_TRUE(same_profile(above, expected)) << where << ": limit from above\n"
                                                           << testing::describe(scene);
            }
        }
    }
}

// box-multiscan's accumulation of rows [0, height) (methods/box_multiscan.cpp): whole rows
// where add_row() proves them, else line by line; the float image.
std::vector<float> box_rows(EdgeTable& table, int n, int width, int height) {
    SubscanlineTracer tracer(table);
    LineIntegralRow row(width);
    LineProfile below, above;
    std::vector<float> image(static_cast<std::size_t>(width) * height);
    tracer.trace(0.0, below, above);
    bool top_traced = true;
    for (int j = 0; j < height; ++j) {
        if (tracer.add_row(j, n, row)) {
            tracer.advance(j + 1.0);
            top_traced = false;
        } else {
            if (!top_traced) tracer.trace(j, below, above);
            row.add(below, 0.5 / n);
            for (int l = 1; l < n; ++l) {
                if (tracer.trace(j + static_cast<double>(l) / n, below, above)) {
                    row.add(below, 0.5 / n);
                    row.add(above, 0.5 / n);
                } else {
                    row.add(below, 1.0 / n);
                }
            }
            row.add(tracer.trace(j + 1.0, below, above) ? above : below, 0.5 / n);
            top_traced = true;
        }
        row.resolve(image.data() + static_cast<std::size_t>(j) * width);
        row.clear();
    }
    return image;
}

// A table built for a line grid (EdgeTable::reset with a LineGrid: only the edges touching a
// line, and every chain's first) against the full table: on every line of the grid the
// tracer's profiles (both limits, and whether they differ) are the same bit for bit, and
// box-multiscan's rows (whole rows and line by line) give the same floats.
TEST(EdgeSweep, LineGridTableTracesAsTheFullTable) {
    for (std::uint64_t seed = 1; seed <= kScenes / 3; ++seed) {
        const Scene scene = scene_for(seed);
        const int n = 1 + static_cast<int>(seed % 7);
        const double offset = seed % 2 == 0 ? 0.0 : 0.5;
        const LineGrid grid{offset, n, -1, scene.height};
        EdgeTable full, on_lines;
        full.reset(scene, RowBuckets::kOnDemand);
        on_lines.reset(scene, RowBuckets::kOnDemand, grid);
        ASSERT_LE(on_lines.edges().size(), full.edges().size());
        SubscanlineTracer full_tracer(full), grid_tracer(on_lines);
        LineProfile below, above, full_below, full_above;
        for (int j = grid.j_lo; j <= grid.j_hi; ++j) {
            for (int l = 0; l < n; ++l) {
                const double y = (j + offset) + static_cast<double>(l) / n;
                if (y < -SubscanlineTracer::kMarginPx ||
                    y > scene.height + SubscanlineTracer::kMarginPx) {
                    continue;
                }
                const std::string where = fmt::format("seed {} n {} line y = {:.17g}", seed, n, y);
                const bool split = grid_tracer.trace(y, below, above);
                ASSERT_EQ(split, full_tracer.trace(y, full_below, full_above)) << where;
                ASSERT_TRUE(same_profile(below, full_below)) << where << "\n"
                                                             << testing::describe(scene);
                if (split) {
                    ASSERT_TRUE(same_profile(above, full_above)) << where;
                }
            }
        }
        if (offset == 0.0 && scene.height > 0 && scene.width > 0) {
            full.reset(scene, RowBuckets::kOnDemand);
            on_lines.reset(scene, RowBuckets::kOnDemand, LineGrid{0.0, n, 0, scene.height});
            ASSERT_EQ(box_rows(on_lines, n, scene.width, scene.height),
                      box_rows(full, n, scene.width, scene.height))
                << "seed " << seed << " n " << n << "\n"
                << testing::describe(scene);
        }
    }
}

// What the grid is for: a finely polygonised ring (curves.h, sagitta 1e-7 px) keeps a few of
// its edges per line, and box-multiscan's rows are still the full table's.
TEST(EdgeSweep, LineGridTableDropsTheEdgesBetweenLines) {
    Scene scene;
    scene.width = 48;
    scene.height = 40;
    scene.shapes.push_back(ring_shape({24.5, 20.5}, 11.5, 12.5, 1.0));
    EdgeTable full, on_lines;
    full.reset(scene, RowBuckets::kOnDemand);
    on_lines.reset(scene, RowBuckets::kOnDemand, LineGrid{0.0, 3, 0, scene.height});
    // 4 chains per ring, each met by 3 lines per row over ~25 rows, plus the chains' heads:
    // a few hundred of the ~20,000 edges.
    constexpr double kMostKeptFraction = 0.05;
    EXPECT_LT(static_cast<double>(on_lines.edges().size()),
              kMostKeptFraction * static_cast<double>(full.edges().size()))
        << on_lines.edges().size() << " of " << full.edges().size();
    EXPECT_EQ(box_rows(on_lines, 3, scene.width, scene.height),
              box_rows(full, 3, scene.width, scene.height));
}

// A grid with its own steps (ssaa's sample rows j + (l + 0.5)/k): a point sampler on the
// table built for it samples every one of its lines as the sampler on the full table does,
// value for value, through both the per-sample walk and the runs (k = 1 puts the lines on the
// half-pixel grid, where half of these scenes' vertices lie).
TEST(EdgeSweep, LineGridWithOwnStepsSamplesAsTheFullTable) {
    for (std::uint64_t seed = 1; seed <= kScenes / 3; ++seed) {
        const Scene scene = scene_for(seed);
        if (scene.width <= 0 || scene.height <= 0) continue;
        const int k = 1 + static_cast<int>(seed % 6);
        std::vector<double> steps(k);
        for (int l = 0; l < k; ++l) steps[l] = (l + 0.5) / k;
        PointSampler full(scene), on_lines;
        on_lines.reset(scene, LineGrid{0.0, k, 0, scene.height - 1, steps});
        ASSERT_LE(on_lines.table().edges().size(), full.table().edges().size());
        std::vector<double> xs(static_cast<std::size_t>(scene.width) * k);
        for (int i = 0; i < scene.width; ++i) {
            for (int a = 0; a < k; ++a) xs[static_cast<std::size_t>(i) * k + a] = i + steps[a];
        }
        std::vector<double> want(xs.size()), got(xs.size());
        ValueRuns runs;
        for (int j = 0; j < scene.height; ++j) {
            for (int l = 0; l < k; ++l) {
                const double y = j + steps[l];
                full.sample_values(y, xs, want);
                on_lines.sample_values(y, xs, got);
                ASSERT_EQ(got, want) << fmt::format("seed {} k {} line y = {:.17g}\n", seed, k, y)
                                     << testing::describe(scene);
                on_lines.sample_runs(y, xs, runs);
                runs.write(got);
                ASSERT_EQ(got, want) << fmt::format("seed {} k {} runs, line {:.17g}", seed, k, y);
            }
        }
    }
}

// Steps that are not 1/n apart would put LineTouch's gaps in the wrong places: refused.
TEST(EdgeSweep, LineGridRefusesUnevenSteps) {
    const Scene scene = scene_for(1);
    EdgeTable table;
    const std::vector<double> uneven{0.1, 0.3, 0.9};
    EXPECT_THROW(table.reset(scene, RowBuckets::kOnDemand, LineGrid{0.0, 3, 0, 2, uneven}),
                 std::logic_error);
    const std::vector<double> two{0.25, 0.75};
    EXPECT_THROW(table.reset(scene, RowBuckets::kOnDemand, LineGrid{0.0, 3, 0, 2, two}),
                 std::logic_error);
    const std::vector<double> even{1.0 / 6, 0.5, 5.0 / 6};
    EXPECT_NO_THROW(table.reset(scene, RowBuckets::kOnDemand, LineGrid{0.0, 3, 0, 2, even}));
}

TEST(EdgeSweep, CentreRunsMatchSampleValues) {
    for (std::uint64_t seed = 1; seed <= kScenes; ++seed) {
        const Scene scene = scene_for(seed);
        PointSampler runs(scene), samples(scene);
        ASSERT_TRUE(runs.flat());
        std::vector<double> centres(scene.width), values(scene.width);
        for (int i = 0; i < scene.width; ++i) centres[i] = i + 0.5;
        std::vector<float> row(scene.width);
        for (int j = 0; j < scene.height; ++j) {
            runs.sample_centres(j + 0.5, row);
            samples.sample_values(j + 0.5, centres, values);
            for (int i = 0; i < scene.width; ++i) {
                // Bit for bit: both are the same double rounded once to float.
                ASSERT_EQ(row[i], static_cast<float>(values[i]))
                    << fmt::format("seed {} pixel ({}, {})\n", seed, i, j)
                    << testing::describe(scene);
            }
        }
    }
}

// sample_value_runs against the per-sample walk on the sample rows and columns of ssaa's grid
// (k = 3: x = i + (a + 0.5)/3, on and off the half-pixel grid the snapped scenes' edges lie on)
// and of nishita-d's margin lattice (lines above and below the image too): the same values bit
// for bit, and `starts` exactly the samples whose value differs from their left neighbour's.
TEST(EdgeSweep, ValueRunsMatchSampleValues) {
    for (std::uint64_t seed = 1; seed <= kScenes; ++seed) {
        const Scene scene = scene_for(seed);
        PointSampler runs(scene, 1.0), samples(scene, 1.0);
        ASSERT_TRUE(runs.flat());
        for (const int k : {1, 3}) {
            std::vector<double> xs;
            for (int q = -k; q < (scene.width + 1) * k; ++q) {
                xs.push_back(static_cast<double>(2 * q + 1) / (2.0 * k));
            }
            std::vector<double> by_runs(xs.size()), by_samples(xs.size());
            std::vector<std::uint32_t> starts;
            for (int line = -k; line < (scene.height + 1) * k; ++line) {
                const double y = static_cast<double>(2 * line + 1) / (2.0 * k);
                runs.sample_value_runs(y, xs, by_runs, starts);
                samples.sample_values(y, xs, by_samples);
                std::vector<std::uint32_t> want;
                for (std::size_t n = 1; n < xs.size(); ++n) {
                    if (by_samples[n] != by_samples[n - 1]) want.push_back(n);
                }
                ASSERT_EQ(by_runs, by_samples)
                    << fmt::format("seed {} k {} line y = {}\n", seed, k, y)
                    << testing::describe(scene);
                ASSERT_EQ(starts, want) << fmt::format("seed {} k {} line y = {}", seed, k, y);
            }
        }
    }
}

// mark_pixels_at_starts against its definition: pixel i > 0 is marked exactly when some start
// lies inside [stride (i - 1) + lo, stride i + lo + size) with both its sides read.
TEST(EdgeSweep, MarkedPixelsAreThoseAStartSplits) {
    for (const auto& [stride, lo, size] :
         {std::tuple{1, 0, 1}, std::tuple{3, 0, 3}, std::tuple{5, 0, 5}, std::tuple{3, 0, 5},
          std::tuple{2, 0, 5}, std::tuple{3, 0, 9}}) {
        const int width = 12, samples = stride * (width - 1) + lo + size;
        for (int start = 1; start < samples; ++start) {
            std::vector<char> marked(width, 0);
            const std::vector<std::uint32_t> starts = {static_cast<std::uint32_t>(start)};
            mark_pixels_at_starts(starts, stride, lo, size, marked);
            for (int i = 1; i < width; ++i) {
                const bool splits =
                    stride * (i - 1) + lo <= start - 1 && start <= stride * i + lo + size - 1;
                EXPECT_EQ(marked[i] != 0, splits)
                    << fmt::format("stride {} size {} start {} pixel {}", stride, size, start, i);
            }
        }
    }
}

}  // namespace
}  // namespace aabench
