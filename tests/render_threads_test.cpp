// Rendering in horizontal bands on several threads (render_in_bands, Method::render_rows;
// render --threads, compare --render-threads) gives the image of one render().
#include <gtest/gtest.h>

#include <cmath>

#include <fmt/format.h>

#include "harness/measure/compare.h"
#include "methods/method.h"
#include "patterns/pattern.h"

namespace aabench {
namespace {

// A band is a row range handed to the method's engine (Method::draw_rows), which computes
// each of its rows exactly as the whole image does: bit for bit.
constexpr double kBandTolerance = 0.0;
// agg rasterises a band with its clip box set to the band's rows: an edge crossing a band
// border gets a new vertex there, rounded to AGG's fixed-point grid (1/256 px), off the true
// edge by <= 1/512 px, and the clipped edge differs from the whole-image one along its whole
// length in the band (not only next to the border). That moves a pixel's area by
// <= 1/512 < 1/255, and the floor to 8 bits may flip one more step: two 8-bit steps (seen:
// 1.5/255 on star). (Cairo's clip rectangle of whole rows leaves its rows as they were.)
// stb-truetype draws a band into a bitmap starting at the band's first row: an edge already
// active there gets its x from its start (x0 + dxdy (y - y0), in float) where the whole image
// carries it down row by row (x += dxdy per row): float rounding, and the floor to 8 bits may
// flip a step (seen: 1/255 on star).
constexpr double kPeerBandTolerance = 2.0 / 255.0;

double band_tolerance(const std::string& id) {
    return id == "agg" || id == "stb-truetype" ? kPeerBandTolerance : kBandTolerance;
}

TEST(RenderThreads, EveryMethodInBandsGivesItsWholeImage) {
    for (const MethodInfo& info : method_registry()) {
        const MethodInstance m = make_method(info.id);
        // The circle patterns, small (every polygon method draws their polygonisation), for
        // the circle methods, which draw nothing else.
        for (const char* pattern :
             {"star", "rings", "circles:max_radius=12", "circle-radii:max_radius=13"}) {
            const Scene scene = make_pattern(pattern, 48, 37);  // 37: bands of unequal height
            if (!m.method->not_applicable(scene).empty()) continue;  // never drawn nor timed
            const Image whole = render_scene(*m.method, scene);
            for (const int threads : {2, 3}) {
                Image banded(scene.width, scene.height, -7.0f);
                render_in_bands(*m.method, scene, banded, threads);
                for (int j = 0; j < scene.height; ++j) {
                    for (int i = 0; i < scene.width; ++i) {
                        const double d = std::abs(banded.at(i, j) - whole.at(i, j));
                        ASSERT_TRUE(d <= band_tolerance(info.id))  // NaN fails
                            << fmt::format("{} on {} in {} bands, pixel ({}, {}): {} vs {}",
                                           m.spec, pattern, threads, i, j, banded.at(i, j),
                                           whole.at(i, j));
                    }
                }
            }
        }
    }
}

TEST(RenderThreads, CompareRecordsTheThreadsItTimedWith) {
    CompareOptions options;
    options.method_specs = {"exact", "exact-8bit"};
    options.pattern_specs = {"star"};
    options.width = 40;
    options.height = 32;
    options.runs = 1;
    options.symptoms = false;
    const CompareResult one = run_comparison(options);
    options.render_threads = 2;
    const CompareResult two = run_comparison(options);
    ASSERT_EQ(one.rows.size(), two.rows.size());
    for (std::size_t k = 0; k < one.rows.size(); ++k) {
        EXPECT_EQ(one.rows[k].time_threads, 1);
        EXPECT_EQ(two.rows[k].time_threads, 2);
        // Bands of `exact` are bit for bit its whole image, so the scores are equal.
        EXPECT_EQ(one.rows[k][metric::kBoxRmse], two.rows[k][metric::kBoxRmse])
            << one.rows[k].method;
    }
    options.render_threads = 0;
    EXPECT_THROW(run_comparison(options), InputError);
}

}  // namespace
}  // namespace aabench
