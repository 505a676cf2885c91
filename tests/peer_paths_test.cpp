// The peers' `paths` parameter (methods/scan/kernel/peer_coverage.h): with paths=merged, cairo and
// agg give a run of consecutive shapes of one value to the library as one fill, and that agrees
// with the library filling the whole scene as one path (on star, whose spokes are one shape
// each and meet at the centre); orientations are made consistent first, so nonzero winding
// adds overlapping shapes instead of cancelling them; per-shape composites coverage where
// shapes meet (conflation), and the conflation figure compares the two.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "harness/measure/conflation.h"
#include "harness/measure/metrics.h"
#include "harness/reference/box_reference.h"
#include "methods/method.h"
#include "patterns/pattern.h"

namespace aabench {
namespace {

const char* const kPeers[] = {"cairo", "agg"};

// The star as a user draws it: every spoke's contours in one shape, turned counter-clockwise
// where a spoke's total area is negative (the same rule as the merged paths).
Scene star_as_one_path(const Scene& star) {
    Scene one = star;
    one.shapes.clear();
    Shape all;
    all.value = star.shapes.front().value;
    for (const Shape& shape : star.shapes) {
        double twice_area = 0.0;
        for (const Contour& c : shape.contours) twice_area += twice_signed_area(c);
        for (Contour c : shape.contours) {
            if (twice_area < 0.0) std::reverse(c.begin(), c.end());
            all.contours.push_back(std::move(c));
        }
    }
    one.shapes.push_back(std::move(all));
    return one;
}

double image_rmse(const Image& a, const Image& b) {
    double sum = 0.0;
    for (std::size_t k = 0; k < a.data.size(); ++k) {
        const double d = static_cast<double>(a.data[k]) - b.data[k];
        sum += d * d;
    }
    return std::sqrt(sum / static_cast<double>(a.data.size()));
}

TEST(PeerPaths, MergedAgreesWithTheLibraryFillingTheWholeStarAsOnePath) {
    const Scene star = make_pattern("star", 128, 128);
    ASSERT_GT(star.shapes.size(), 1u);  // one shape per spoke: the case merging is for
    const Scene one_path = star_as_one_path(star);
    const Coverage exact = box_reference(star);
    for (const char* peer : kPeers) {
        SCOPED_TRACE(peer);
        const std::string id = peer;
        const Image merged = render_scene(*make_method(id + ":paths=merged").method, star);
        const Image per_shape = render_scene(*make_method(id + ":paths=per-shape").method, star);
        // One fill of all spokes, the library's own answer: identical calls, identical bytes.
        const Image library =
            render_scene(*make_method(id + ":paths=per-shape").method, one_path);
        EXPECT_EQ(merged.data, library.data);
        // Per shape, the spokes' coverage is composited where they meet: a different image,
        // further from the exact one (the conflation the merged fill does not have).
        EXPECT_GT(image_rmse(merged, per_shape), 0.0);
        EXPECT_LT(compare_to_reference(merged, exact).rmse,
                  compare_to_reference(per_shape, exact).rmse);
    }
}

TEST(PeerPaths, MergedMakesOrientationsConsistentSoOverlapsDoNotCancel) {
    // Two squares of one value overlapping in [4, 6] x [4, 6], one clockwise and one
    // counter-clockwise. As one fill without reorienting, nonzero winding would cancel to 0
    // in the overlap; merged turns both the same way and fills it.
    Scene scene;
    scene.width = scene.height = 10;
    Contour a{{2, 2}, {6, 2}, {6, 6}, {2, 6}};
    Contour b{{4, 4}, {8, 4}, {8, 8}, {4, 8}};
    std::reverse(b.begin(), b.end());
    scene.shapes.push_back({{a}, 1.0});
    scene.shapes.push_back({{b}, 1.0});
    for (const char* peer : kPeers) {
        SCOPED_TRACE(peer);
        const Image merged = render_scene(*make_method(std::string(peer)).method, scene);
        EXPECT_EQ(merged.at(4, 4), 1.0f);
        EXPECT_EQ(merged.at(5, 5), 1.0f);
        EXPECT_EQ(merged.at(2, 2), 1.0f);
        EXPECT_EQ(merged.at(7, 7), 1.0f);
        EXPECT_EQ(merged.at(0, 0), 0.0f);
    }
}

TEST(PeerPaths, RunsEndWhereTheValueChanges) {
    // A square of 0.5 under a square of 1: two runs, the later one covers the earlier one.
    Scene scene;
    scene.width = scene.height = 10;
    scene.shapes.push_back({{{{2, 2}, {6, 2}, {6, 6}, {2, 6}}}, 0.5});
    scene.shapes.push_back({{{{4, 4}, {8, 4}, {8, 8}, {4, 8}}}, 1.0});
    for (const char* peer : kPeers) {
        SCOPED_TRACE(peer);
        const Image merged = render_scene(*make_method(std::string(peer)).method, scene);
        EXPECT_EQ(merged.at(3, 3), 0.5f);
        EXPECT_EQ(merged.at(5, 5), 1.0f);
    }
}

TEST(PeerPaths, MergedIsTheDefaultAndTheConflationTwinIsTheOtherChoice) {
    for (const char* peer : kPeers) {
        SCOPED_TRACE(peer);
        const MethodInstance m = make_method(peer);
        EXPECT_NE(m.spec.find("paths=merged"), std::string::npos) << m.spec;
        const auto twin_spec = conflation_twin_spec(m);
        ASSERT_TRUE(twin_spec);
        const MethodInstance twin = make_method(*twin_spec);
        EXPECT_NE(twin.spec.find("paths=per-shape"), std::string::npos) << twin.spec;
        EXPECT_EQ(conflation_twin_spec(twin), m.spec);
        // The figure on the star: the two images differ where the spokes meet.
        const Scene star = make_pattern("star", 64, 64);
        const auto figure = conflation_rmse(m, star, render_scene(*m.method, star));
        ASSERT_TRUE(figure);
        EXPECT_GT(*figure, 0.0);
    }
    EXPECT_FALSE(conflation_twin_spec(make_method("exact")));
    EXPECT_FALSE(conflation_rmse(make_method("none"), make_pattern("star", 16, 16),
                                 Image(16, 16)));
}

}  // namespace
}  // namespace aabench
