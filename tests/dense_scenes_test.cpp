// The benchmark's dense scenes (harness/measure/dense_scenes.h): deterministic, as dense as
// documented, and scenes every engine takes: `exact` on them agrees with the box reference.
#include "harness/measure/dense_scenes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "harness/measure/metrics.h"
#include "harness/reference/box_reference.h"
#include "methods/method.h"

namespace aabench {
namespace {

// `exact` against the box reference: float32 output of double coverage, one rounding per
// pixel (2^-24 relative) on values up to 1, with room for the composited soup's sums.
constexpr double kExactAgreement = 1e-6;

TEST(DenseScenes, DeterministicAndOfTheDocumentedKinds) {
    for (const std::string& name : dense_scene_names()) {
        SCOPED_TRACE(name);
        const Scene a = make_dense_scene(name, 256), b = make_dense_scene(name, 256);
        EXPECT_EQ(a, b);
        EXPECT_EQ(a.width, 256);
        EXPECT_GT(a.edge_count(), 1000u);
    }
    EXPECT_THROW(make_dense_scene("sparse", 256), std::invalid_argument);
}

TEST(DenseScenes, RingsAreThe085PxRingsAt17PxPitch) {
    // A 1024^2 ring pattern of pitch 1.7 px: about 0.95 * 512 / 1.7 = 286 annuli of two
    // circles each, within 0.01 px: some 190,000 edges.
    const Scene rings = make_dense_scene("dense-rings", 1024);
    EXPECT_GT(rings.edge_count(), 150000u);
    EXPECT_LT(rings.edge_count(), 250000u);
}

TEST(DenseScenes, SoupOverlapsWithBothOrientationsAndGlyphsAreMany) {
    const Scene soup = make_dense_scene("soup", 256);
    int clockwise = 0, counter = 0;
    for (const Shape& s : soup.shapes) {
        (twice_signed_area(s.contours.front()) > 0.0 ? clockwise : counter) += 1;
    }
    EXPECT_GT(clockwise, 10);
    EXPECT_GT(counter, 10);
    const Scene glyphs = make_dense_scene("glyphs", 256);
    EXPECT_GT(glyphs.shapes.size(), 200u);
}

TEST(DenseScenes, ExactAgreesWithTheBoxReference) {
    const MethodInstance exact = make_method("exact");
    for (const std::string& name : {std::string("soup"), std::string("glyphs")}) {
        SCOPED_TRACE(name);
        const Scene scene = make_dense_scene(name, 128);
        const ErrorStats s = compare_to_reference(render_scene(*exact.method, scene),
                                                  box_reference(scene));
        EXPECT_LT(s.max_abs, kExactAgreement);
    }
}

}  // namespace
}  // namespace aabench
