// PointSampler::sample_rows_changes (methods/scan/sampling/point_sampling.h): the k sample rows of
// ssaa's pixel row in one pass over the active edges must give the integer sums that
// sample_changes() gives row by row, exactly, whenever it accepts the rows, and call nothing when
// it declines. The one pass runs on ssaa's table (only the edges its sample rows meet), the rows on
// the full table.
// Checked with ssaa's own accumulation (a change at sample s adds its step times the samples
// of each pixel right of it) on seeded random scenes of dyadic values (crossing edges, several
// shapes, vertices on sample rows) and on the built-in 2-D patterns, for k = 1, 2, 3, 5; the
// rows it accepts are counted, so that the test cannot pass by always declining.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "methods/scan/sampling/point_sampling.h"
#include "methods/scan/sampling/run_sums.h"
#include "patterns/pattern.h"
#include "test_scenes.h"

namespace aabench {
namespace {

// Per pixel of one row, the sum of its k x k samples in units of the scene's dyadic unit.
using PixelSums = std::vector<std::int64_t>;

struct RowSummer {
    int k;
    int width;
    DyadicValues dyadic;
    std::vector<std::int64_t> diff;  // pixel p's sum changes by diff[p] from p - 1's
    std::int64_t first = 0;
    long calls = 0;

    void clear() {
        diff.assign(width + 1, 0);
        first = 0;
        calls = 0;
    }
    void add(std::size_t n, double before, double after) {
        const std::int64_t step = dyadic.units(after) - dyadic.units(before);
        const auto p = static_cast<std::size_t>(n) / k;
        const std::int64_t left = static_cast<std::int64_t>(n) - static_cast<std::int64_t>(p) * k;
        diff[p] += step * (k - left);
        diff[p + 1] += step * left;
        ++calls;
    }
    PixelSums sums() const {
        PixelSums out(width);
        std::int64_t sum = first;
        for (int i = 0; i < width; ++i) out[i] = sum += diff[i];
        return out;
    }
};

// Checks every pixel row of `scene` at k; returns the rows taken in one pass. The one pass
// samples from the table ssaa builds, only the edges its sample rows meet (a LineGrid with
// the rows' own steps); the row-by-row reference from the full table.
long check(const Scene& scene, int k, const std::string& what) {
    std::vector<double> xs(static_cast<std::size_t>(scene.width) * k), ys(k), offsets(k);
    for (int a = 0; a < k; ++a) offsets[a] = (a + 0.5) / k;
    for (int i = 0; i < scene.width; ++i) {
        for (int a = 0; a < k; ++a) xs[static_cast<std::size_t>(i) * k + a] = i + offsets[a];
    }
    PointSampler one_pass, by_rows(scene);
    one_pass.reset(scene, LineGrid{0.0, k, 0, scene.height - 1, offsets});
    const DyadicValues dyadic = DyadicValues::of(one_pass.table());
    EXPECT_TRUE(dyadic.exact) << what;
    RowSummer fast{k, scene.width, dyadic, {}}, slow{k, scene.width, dyadic, {}};
    long taken = 0;
    for (int j = 0; j < scene.height; ++j) {
        for (int b = 0; b < k; ++b) ys[b] = j + offsets[b];
        fast.clear();
        slow.clear();
        double start = 0.0;
        const auto add_fast = [&](std::size_t n, double before, double after) {
            fast.add(n, before, after);
        };
        const auto add_rows = [&](const std::uint32_t* n, double before, double after) {
            for (int b = 0; b < k; ++b) {
                if (n[b] < xs.size()) fast.add(n[b], before, after);
            }
        };
        if (one_pass.sample_rows_changes(ys, xs, start, add_rows)) {
            ++taken;
            fast.first = dyadic.units(start) * k * k;
        } else {
            EXPECT_EQ(fast.calls, 0) << what << " row " << j << ": declined after calling";
            for (int b = 0; b < k; ++b) {
                fast.first += dyadic.units(one_pass.sample_changes(ys[b], xs, add_fast)) * k;
            }
        }
        for (int b = 0; b < k; ++b) {
            slow.first += dyadic.units(by_rows.sample_changes(
                              ys[b], xs,
                              [&](std::size_t n, double before, double after) {
                                  slow.add(n, before, after);
                              })) *
                          k;
        }
        const PixelSums got = fast.sums(), want = slow.sums();
        for (int i = 0; i < scene.width; ++i) {
            if (got[i] != want[i]) {
                ADD_FAILURE() << fmt::format(
                    "{} k={}: pixel ({}, {}) one pass {} row by row {}\n{}", what, k, i, j, got[i],
                    want[i], testing::describe(scene));
                return taken;
            }
        }
    }
    return taken;
}

TEST(SampleRows, RandomScenesEqualRowByRow) {
    constexpr int kScenes = 80;
    long taken = 0, rows = 0;
    for (int seed = 1; seed <= kScenes; ++seed) {
        const int k = std::vector<int>{1, 2, 3, 5}[seed % 4];
        // Half snapped to the half pixel: vertices on the sample rows j + 0.5 of k = 1 and 5.
        const Scene scene = testing::with_dyadic_values(
            testing::random_scene(seed, 3 + seed % 31, 2 + seed % 19, seed % 2 == 0), seed);
        taken += check(scene, k, fmt::format("seed {}", seed));
        rows += scene.height;
        if (::testing::Test::HasFailure()) return;
    }
    // Random polygons cross a great deal, but some rows are simple.
    EXPECT_GT(taken, rows / 20) << "the one-pass rows were hardly taken: the test is weak";
}

TEST(SampleRows, PatternsEqualRowByRowAndAreTaken) {
    // The rows taken at least, in parts of the size: long bars run through every row; rings
    // and zone plates start and end chains in some rows of each ring (about half the rows are
    // taken at these sizes); the star's rays end at its centre, where most rows of a small star
    // lie (a fifth at least). Circles: equality only (their rings start and end chains in
    // most rows of a small image, and share boundaries).
    const struct {
        const char* name;
        int divisor;  // taken > size / divisor; 0: not counted
        std::vector<int> ks;
    } patterns[] = {{"grating", 4, {2, 3, 5}},   {"rings", 4, {2, 3, 5}},
                    {"zoneplate", 4, {2, 3, 5}}, {"star", 5, {2, 3, 5}},
                    {"strips", 4, {2, 3, 5}},    {"circles", 0, {3}}};
    std::mt19937_64 rng(20261126);
    for (const auto& pattern : patterns) {
        for (const int k : pattern.ks) {
            const int size = 24 + static_cast<int>(rng() % 100);
            const Scene scene = make_pattern(pattern.name, size, size);
            const long taken = check(scene, k, fmt::format("{} at {}^2", pattern.name, size));
            if (pattern.divisor > 0) {
                EXPECT_GT(taken, size / pattern.divisor)
                    << pattern.name << " at " << size << "^2, k=" << k;
            }
            if (::testing::Test::HasFailure()) return;
        }
    }
}

}  // namespace
}  // namespace aabench
