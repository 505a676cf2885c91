// The kernel cell row (methods/scan/kernel/cells.h) against a plain difference array, one cell
// per pixel, summed pixel by pixel with no flags: every instantiation the engines use, on
// seeded random steps (sparse and dense, reaching the two spare cells past the row), resolved
// twice in a row to check that resolve_and_clear() leaves the row clear.
#include "methods/scan/kernel/cells.h"

#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "methods/scan/multiscan/region_rows.h"

namespace aabench {
namespace {

constexpr int kSeeds = 40;
constexpr int kMaxWidth = 300;  // several words of flags for blocks of 1, 8 and 16

struct Step {
    std::size_t cell;
    double amount;
};

// Random steps for a row of `width` pixels: cells 0..width + 1, the share of pixels stepped
// chosen per seed (a few to every other one), amounts of both signs.
std::vector<Step> random_steps(std::mt19937& rng, int width) {
    std::uniform_int_distribution<std::size_t> cell(0, static_cast<std::size_t>(width) + 1);
    std::uniform_real_distribution<double> amount(-2.0, 2.0);
    const int count = std::uniform_int_distribution<int>(0, width)(rng);
    std::vector<Step> steps;
    for (int k = 0; k < count; ++k) steps.push_back({cell(rng), amount(rng)});
    return steps;
}

// The plain in-order prefix sum the row must equal bit for bit (skipping +0.0 cells is exact).
std::vector<double> plain_prefix(const std::vector<Step>& steps, int width, double start) {
    std::vector<double> diff(static_cast<std::size_t>(width) + 2, 0.0);
    for (const Step& s : steps) diff[s.cell] += s.amount;
    std::vector<double> out(static_cast<std::size_t>(width));
    double sum = start;
    for (int i = 0; i < width; ++i) out[i] = sum += diff[i];
    return out;
}

template <class Row>
void expect_clear(Row& row, int width, double start) {
    std::vector<double> again(static_cast<std::size_t>(width));
    row.resolve_and_clear(start, again.data(), [](std::size_t, double sum) { return sum; });
    for (int i = 0; i < width; ++i) ASSERT_EQ(again[i], start) << "pixel " << i;
    for (int i = 0; i < width + 2; ++i) ASSERT_EQ(row[i], 0.0) << "cell " << i;
}

template <std::size_t kBlock>
void check_in_order(int seed) {
    std::mt19937 rng(seed);
    const int width = std::uniform_int_distribution<int>(1, kMaxWidth)(rng);
    const double start = std::uniform_real_distribution<double>(-1.0, 1.0)(rng);
    CellRow<double, kBlock> row;
    row.reset(width);
    for (int pass = 0; pass < 2; ++pass) {
        const std::vector<Step> steps = random_steps(rng, width);
        for (const Step& s : steps) row.writer().add(s.cell, s.amount);
        const std::vector<double> want = plain_prefix(steps, width, start);
        std::vector<double> got(static_cast<std::size_t>(width));
        row.resolve(start, got.data(), [](std::size_t, double sum) { return sum; });
        std::vector<double> cleared(static_cast<std::size_t>(width));
        row.resolve_and_clear(start, cleared.data(), [](std::size_t, double sum) { return sum; });
        for (int i = 0; i < width; ++i) {
            ASSERT_EQ(got[i], want[i]) << "seed " << seed << " width " << width << " pixel " << i;
            ASSERT_EQ(cleared[i], want[i]) << "seed " << seed << " pixel " << i;
        }
        expect_clear(row, width, start);
    }
}

TEST(CellRow, InOrderEqualsPlainDifferenceArray) {
    for (int seed = 0; seed < kSeeds; ++seed) {
        check_in_order<1>(seed);
        check_in_order<8>(seed);
        check_in_order<16>(seed);
    }
}

TEST(CellRow, FourWideWithinRoundingOfPlain) {
    for (int seed = 0; seed < kSeeds; ++seed) {
        std::mt19937 rng(seed);
        const int width = std::uniform_int_distribution<int>(1, kMaxWidth)(rng);
        const std::vector<Step> steps = random_steps(rng, width);
        CellRow<double, 16> row;
        row.reset(width);
        double magnitude = 1.0;  // |start| + sum of |steps|: what any partial sum is below
        for (const Step& s : steps) {
            row.writer().add(s.cell, s.amount);
            magnitude += std::abs(s.amount);
        }
        const std::vector<double> want = plain_prefix(steps, width, 1.0);
        std::vector<double> got(static_cast<std::size_t>(width));
        row.resolve_and_clear<Prefix::kFourWide>(1.0, got.data(),
                                                 [](std::size_t, double sum) { return sum; });
        // Each of the two orders rounds each of its at most width + 2 additions once, by at
        // most half an ulp of the magnitude: the rounding of a sum of k terms, twice.
        const double tolerance = 2.0 * (width + 2) * DBL_EPSILON * magnitude;
        for (int i = 0; i < width; ++i) {
            ASSERT_LE(std::abs(got[i] - want[i]), tolerance)
                << "seed " << seed << " width " << width << " pixel " << i;
        }
        expect_clear(row, width, 1.0);
    }
}

TEST(CellRow, HeldPairEqualsPlainStepsUpToRounding) {
    for (int seed = 0; seed < kSeeds; ++seed) {
        std::mt19937 rng(seed);
        const int width = std::uniform_int_distribution<int>(1, kMaxWidth)(rng);
        std::uniform_real_distribution<double> x(-3.0, width + 3.0), dv(-1.0, 1.0);
        std::vector<double> diff(static_cast<std::size_t>(width) + 2, 0.0);
        CellRow<double, 8> row;
        row.reset(width);
        double magnitude = 0.0;
        {
            CellRow<double, 8>::HeldPair held(row);
            const int count = std::uniform_int_distribution<int>(0, 2 * width)(rng);
            for (int k = 0; k < count; ++k) {
                const double at = x(rng), step = dv(rng);
                magnitude += std::abs(step);
                held.add(at, step, width);
                // The plain rule: pixel c = floor(x) gets dv (c + 1 - x), c + 1 the rest.
                if (at <= 0.0) {
                    diff[0] += step;
                } else if (at < width) {
                    const double c = std::floor(at);
                    const auto cell = static_cast<std::size_t>(c);
                    diff[cell] += step * ((c + 1.0) - at);
                    diff[cell + 1] += step * (1.0 - ((c + 1.0) - at));
                }
            }
        }
        std::vector<double> got(static_cast<std::size_t>(width));
        row.resolve_and_clear(0.0, got.data(), [](std::size_t, double sum) { return sum; });
        // The held sums add a pixel's steps before the cell: other roundings of the same
        // terms, each below an ulp of the magnitude, a few per step.
        const double tolerance = 8.0 * DBL_EPSILON * (magnitude + 1.0) * (width + 2);
        double sum = 0.0;
        for (int i = 0; i < width; ++i) {
            sum += diff[i];
            ASSERT_LE(std::abs(got[i] - sum), tolerance) << "seed " << seed << " pixel " << i;
        }
        expect_clear(row, width, 0.0);
    }
}

TEST(CellRow, PairOfRowsEqualsPlainSumOfBoth) {
    for (int seed = 0; seed < kSeeds; ++seed) {
        std::mt19937 rng(seed);
        const int width = std::uniform_int_distribution<int>(1, kMaxWidth)(rng);
        const std::vector<Step> upper = random_steps(rng, width);
        const std::vector<Step> lower = random_steps(rng, width);
        CellRow<RowPair, 8> above, here;
        above.reset(width);
        here.reset(width);
        std::vector<double> diff(static_cast<std::size_t>(width) + 2, 0.0);
        for (const Step& s : lower) {  // the row above gives its lower terms
            above[s.cell].lower += s.amount;
            above.writer().flag(s.cell);
            diff[s.cell] += s.amount;
        }
        std::vector<double> upper_diff(diff.size(), 0.0);
        for (const Step& s : upper) {
            here[s.cell].upper += s.amount;
            here.writer().flag(s.cell);
            upper_diff[s.cell] += s.amount;
        }
        const RowPair* a = above.cells();
        const RowPair* b = here.cells();
        std::vector<double> got(static_cast<std::size_t>(width));
        above.resolve_and_clear(
            0.5, got.data(), [](std::size_t, double sum) { return sum; },
            [a, b](std::size_t i) { return a[i].lower + b[i].upper; }, &here);
        double sum = 0.5;
        for (int i = 0; i < width; ++i) {
            sum += diff[i] + upper_diff[i];
            ASSERT_EQ(got[i], sum) << "seed " << seed << " width " << width << " pixel " << i;
        }
        for (int i = 0; i < width + 2; ++i) {
            ASSERT_EQ(above[i].lower, 0.0) << "cell " << i;
            ASSERT_EQ(here[i].upper, upper_diff[i]) << "the row read along is left as it was";
        }
    }
}

TEST(CellRow, IntegerCellsResolveAtFlaggedPixelsOnly) {
    for (int seed = 0; seed < kSeeds; ++seed) {
        std::mt19937 rng(seed);
        const int width = std::uniform_int_distribution<int>(1, kMaxWidth)(rng);
        std::uniform_int_distribution<std::size_t> cell(0, static_cast<std::size_t>(width));
        std::uniform_int_distribution<std::int64_t> amount(-(std::int64_t{1} << 40),
                                                           std::int64_t{1} << 40);
        CellRow<std::int64_t, 1> row;
        row.reset(width);
        std::vector<std::int64_t> diff(static_cast<std::size_t>(width) + 1, 0);
        std::vector<bool> flagged(static_cast<std::size_t>(width) + 1, false);
        flagged[0] = true;  // pixel 0 is always resolved
        const int count = std::uniform_int_distribution<int>(0, width / 2)(rng);
        for (int k = 0; k < count; ++k) {
            const std::size_t c = cell(rng);
            const std::int64_t a = k % 7 == 0 ? 0 : amount(rng);  // a step of 0 still flags
            row.writer().add(c, a);
            diff[c] += a;
            flagged[c] = true;
        }
        std::vector<int> calls;
        std::vector<std::int64_t> got(static_cast<std::size_t>(width));
        row.resolve_and_clear(std::int64_t{3}, got.data(), [&](std::size_t i, std::int64_t sum) {
            calls.push_back(static_cast<int>(i));
            return sum;
        });
        std::int64_t sum = 3;
        std::vector<int> want_calls;
        for (int i = 0; i < width; ++i) {
            sum += diff[i];
            if (flagged[i]) want_calls.push_back(i);
            ASSERT_EQ(got[i], sum) << "seed " << seed << " pixel " << i;
        }
        EXPECT_EQ(calls, want_calls) << "seed " << seed;
        for (int i = 0; i < width + 2; ++i) ASSERT_EQ(row[i], 0) << "cell " << i;
    }
}

TEST(CellRow, ValueCellsResolveEachPixelAlone) {
    for (int seed = 0; seed < kSeeds; ++seed) {
        std::mt19937 rng(seed);
        const int width = std::uniform_int_distribution<int>(1, kMaxWidth)(rng);
        std::uniform_real_distribution<double> value(-1.0, 1.0);
        CellRow<double, 8> row;
        row.reset(width);
        row.flag_all();
        std::vector<double> want(static_cast<std::size_t>(width));
        for (int i = 0; i < width; ++i) row[i] += want[i] = value(rng);
        std::vector<float> got(static_cast<std::size_t>(width));
        row.resolve_and_clear<Prefix::kNone>(
            0.0, got.data(), [](std::size_t, double v) { return static_cast<float>(v); });
        for (int i = 0; i < width; ++i) {
            ASSERT_EQ(got[i], static_cast<float>(want[i])) << "seed " << seed << " pixel " << i;
        }
        for (int i = 0; i < width + 2; ++i) ASSERT_EQ(row[i], 0.0) << "cell " << i;
    }
}

}  // namespace
}  // namespace aabench
