// The properties every post-process row must have (methods/post_process.h), over every registry
// row with traits.post_process: it changes nothing on a constant image, nor on smooth random
// images whose local contrast stays below its edge threshold; it does change an aliased edge;
// it is deterministic; the same image comes out in bands as in one piece; its pass allocates
// nothing when warm.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "harness/world/alloc_count.h"
#include "methods/method.h"
#include "methods/post_process.h"
#include "patterns/pattern.h"

namespace aabench {
namespace {

constexpr int kSide = 96;
// The smooth images' largest luma range over a pixel and its 4 neighbours, sRGB-encoded or not:
// below every row's default threshold (FXAA's absolute minimum 0.0833; MLAA's 0.1; SMAA's
// presets 0.05 .. 0.15), so each pass must leave them exactly as they are.
constexpr float kSmoothLocalContrast = 0.04f;
// The smooth images: bilinear interpolation of random values in [kSmoothLo, kSmoothHi] on a
// grid of kSmoothCellPx cells, steep enough to be more than flat, below kSmoothLocalContrast
// in luma (checked below, not assumed).
constexpr int kSmoothCellPx = 24;
constexpr float kSmoothLo = 0.3f, kSmoothHi = 0.7f;
constexpr int kSmoothImages = 8;

struct PassRow {
    std::string spec;
    MethodInstance instance;
    const PostProcessMethod* pass = nullptr;
};

std::vector<PassRow> post_process_rows() {
    std::vector<PassRow> rows;
    for (const MethodInfo& info : method_registry()) {
        if (!info.traits->post_process) continue;
        PassRow row;
        row.spec = info.id;
        row.instance = make_method(info.id);
        row.pass = dynamic_cast<const PostProcessMethod*>(row.instance.method.get());
        rows.push_back(std::move(row));
    }
    return rows;
}

Image smooth_random_image(unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> value(kSmoothLo, kSmoothHi);
    const int cells = kSide / kSmoothCellPx + 2;
    std::vector<float> grid(static_cast<std::size_t>(cells) * cells);
    for (float& g : grid) g = value(rng);
    Image img(kSide, kSide);
    for (int y = 0; y < kSide; ++y) {
        for (int x = 0; x < kSide; ++x) {
            const float gx = (x + 0.5f) / kSmoothCellPx, gy = (y + 0.5f) / kSmoothCellPx;
            const int i = static_cast<int>(gx), j = static_cast<int>(gy);
            const float tx = gx - i, ty = gy - j;
            const auto g = [&](int a, int b) {
                return grid[static_cast<std::size_t>(b) * cells + a];
            };
            img.at(x, y) = (1 - ty) * ((1 - tx) * g(i, j) + tx * g(i + 1, j)) +
                           ty * ((1 - tx) * g(i, j + 1) + tx * g(i + 1, j + 1));
        }
    }
    return img;
}

// The largest range of `luma` over a pixel and its 4 neighbours.
float local_contrast(const Image& img, bool srgb) {
    float worst = 0.0f;
    const auto l = [&](int x, int y) {
        const float v = img.at(std::clamp(x, 0, kSide - 1), std::clamp(y, 0, kSide - 1));
        return srgb ? srgb_encode(v) : v;
    };
    for (int y = 0; y < kSide; ++y) {
        for (int x = 0; x < kSide; ++x) {
            const float v[] = {l(x, y), l(x - 1, y), l(x + 1, y), l(x, y - 1), l(x, y + 1)};
            worst = std::max(worst, *std::max_element(v, v + 5) - *std::min_element(v, v + 5));
        }
    }
    return worst;
}

bool same_pixels(const Image& a, const Image& b) { return a.data == b.data; }

TEST(PostProcess, ThereAreRowsToCheck) { EXPECT_GE(post_process_rows().size(), 2u); }

TEST(PostProcess, EveryRowIsAPassOverItsBase) {
    for (const PassRow& row : post_process_rows()) {
        ASSERT_NE(row.pass, nullptr) << row.spec;
        EXPECT_EQ(row.instance.params.get_choice("base"), "none") << row.spec;
    }
}

TEST(PostProcess, ConstantImagesComeOutUnchanged) {
    for (const PassRow& row : post_process_rows()) {
        for (const float v : {0.0f, 0.18f, 0.5f, 1.0f}) {
            const Image in(kSide, kSide, v);
            Image out(kSide, kSide, -1.0f);
            row.pass->pass(in, out);
            EXPECT_TRUE(same_pixels(in, out)) << row.spec << " on the constant " << v;
        }
    }
}

TEST(PostProcess, SmoothImagesBelowTheThresholdComeOutUnchanged) {
    for (unsigned seed = 1; seed <= kSmoothImages; ++seed) {
        const Image in = smooth_random_image(seed);
        ASSERT_LT(local_contrast(in, true), kSmoothLocalContrast) << "seed " << seed;
        ASSERT_LT(local_contrast(in, false), kSmoothLocalContrast) << "seed " << seed;
        const auto [lo, hi] = std::minmax_element(in.data.begin(), in.data.end());
        ASSERT_GT(*hi - *lo, 4 * kSmoothLocalContrast) << "seed " << seed << ": not smooth, flat";
        for (const PassRow& row : post_process_rows()) {
            Image out(kSide, kSide, -1.0f);
            row.pass->pass(in, out);
            EXPECT_TRUE(same_pixels(in, out)) << row.spec << " on smooth image " << seed;
        }
    }
}

TEST(PostProcess, AnAliasedEdgeIsChanged) {
    // The properties above hold for a pass that does nothing: each must also soften the
    // star's point-sampled edges, and bring it nearer the exact image.
    const Scene star = make_pattern("star", kSide, kSide);
    const Image aliased = render_scene(*make_method("none").method, star);
    const Image exact = render_scene(*make_method("exact").method, star);
    const auto rmse = [&](const Image& img) {
        double sum = 0.0;
        for (std::size_t k = 0; k < img.data.size(); ++k) {
            sum += (img.data[k] - exact.data[k]) * (img.data[k] - exact.data[k]);
        }
        return std::sqrt(sum / static_cast<double>(img.data.size()));
    };
    for (const PassRow& row : post_process_rows()) {
        const Image out = render_scene(*row.instance.method, star);
        EXPECT_FALSE(same_pixels(out, aliased)) << row.spec;
        EXPECT_LT(rmse(out), rmse(aliased)) << row.spec;
    }
}

TEST(PostProcess, DeterministicAndTheSameInBands) {
    const Scene star = make_pattern("star", kSide, kSide);
    for (const PassRow& row : post_process_rows()) {
        const Image once = render_scene(*row.instance.method, star);
        const Image again = render_scene(*make_method(row.spec).method, star);
        EXPECT_TRUE(same_pixels(once, again)) << row.spec;
        for (const int threads : {2, 3, 7}) {
            Image banded(kSide, kSide, -1.0f);
            render_in_bands(*row.instance.method, star, banded, threads);
            EXPECT_TRUE(same_pixels(once, banded)) << row.spec << " in " << threads << " bands";
        }
    }
}

TEST(PostProcess, AWarmPassAllocatesNothing) {
    const Scene star = make_pattern("star", kSide, kSide);
    const Image base = render_scene(*make_method("none").method, star);
    for (const PassRow& row : post_process_rows()) {
        Image out(kSide, kSide);
        row.pass->pass(base, out);  // warm-up: per-thread scratch grows here
        const AllocCounts before = thread_alloc_counts();
        row.pass->pass(base, out);
        const AllocCounts after = thread_alloc_counts();
        EXPECT_EQ(after.allocations - before.allocations, 0u) << row.spec;
    }
}

}  // namespace
}  // namespace aabench
