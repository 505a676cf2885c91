// The visibility rule is one (methods/scan/kernel/visibility_rule.h): every engine that decides
// which shape is seen decides a z-fighting overlap by the one depth tie, kDepthTieRelative. Two
// squares on nearly equal depth planes, the later one moved in front of or behind the earlier
// one by a fraction or by a multiple of the tie: inside the tie every engine shows the later
// square, beyond it every engine shows the nearer one. An engine with a tie of its own
// (`==`, another tolerance) disagrees on one of the two sides.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include <fmt/format.h>

#include "harness/reference/visibility.h"
#include "methods/method.h"
#include "methods/scan/kernel/visibility_rule.h"
#include "methods/scan/sampling/point_sampling.h"

namespace aabench {
namespace {

constexpr int kSide = 16;
constexpr double kEarlierValue = 0.25, kLaterValue = 0.75;
// 1/z_v of the earlier square; the later one's is this times (1 + offset * kDepthTieRelative).
// Both planes are constant, so the tie at any point is kDepthTieRelative of the larger.
constexpr double kInvDepth = 0.5;
// The filtering methods (ssaa, nishita-d) average samples of one value with weights summing to
// one in double: the float output may be off the value by rounding, far below the 0.5 between
// the two squares' values.
constexpr double kAveragingTolerance = 1e-6;
// A pixel well inside the overlap [6, 10]^2 (its box and every sample in it inside).
constexpr int kOverlapI = 7, kOverlapJ = 7;

Shape square(double x0, double y0, double x1, double y1, double value, double inv_depth) {
    Shape s;
    s.contours = {{{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}};
    s.value = value;
    s.inv_depth = AffinePlane{inv_depth, 0.0, 0.0};
    return s;
}

// The later square's depth offset from the earlier one, in units of the tie (> 0: nearer).
Scene z_fighting_squares(double offset_in_ties) {
    Scene scene;
    scene.width = kSide;
    scene.height = kSide;
    scene.shapes = {
        square(2, 2, 10, 10, kEarlierValue, kInvDepth),
        square(6, 6, 14, 14, kLaterValue,
               kInvDepth * (1.0 + offset_in_ties * kDepthTieRelative)),
    };
    return scene;
}

struct Case {
    double offset_in_ties;
    double seen_value;  // the value every engine shows inside the overlap
};

// Inside the tie the later square is seen whichever way the planes differ; beyond it, the
// nearer one.
const std::vector<Case> kCases = {
    {0.5, kLaterValue},
    {-0.5, kLaterValue},
    {2.0, kLaterValue},
    {-2.0, kEarlierValue},
};

double rendered(const std::string& spec, const Scene& scene) {
    const MethodInstance m = make_method(spec);
    return render_scene(*m.method, scene).at(kOverlapI, kOverlapJ);
}

TEST(VisibilityRule, EveryEngineDecidesAZFightingOverlapByTheOneTie) {
    for (const Case& c : kCases) {
        const Scene scene = z_fighting_squares(c.offset_in_ties);
        const std::string where = fmt::format("later square {} ties nearer", c.offset_in_ties);
        const double x = kOverlapI + 0.5, y = kOverlapJ + 0.5;
        const bool later_seen = c.seen_value == kLaterValue;
        // The rule itself.
        const std::vector<AffinePlane> planes = {*scene.shapes[0].inv_depth,
                                                 *scene.shapes[1].inv_depth};
        EXPECT_EQ(seen_over(1, 0, planes, x, y), later_seen) << where;
        // The point sampler (none, ssaa, nishita-d, fast-edge's fill).
        PointSampler sampler(scene);
        const std::vector<double> xs = {x};
        std::vector<int> top(1);
        sampler.sample_top(y, xs, top);
        EXPECT_EQ(top[0], later_seen ? 1 : 0) << where << ": point sampler";
        // Methods on the ScreenScene: their own visibility (point samples, scanline NEXT).
        for (const char* spec : {"none", "ssaa", "nishita-d", "fast-edge", "box-multiscan"}) {
            EXPECT_NEAR(rendered(spec, scene), c.seen_value, kAveragingTolerance)
                << where << ": " << spec;
        }
        // The reference: exact visible pieces, drawn by the exact engine.
        EXPECT_EQ(rendered("exact", visible_pieces(scene)), static_cast<float>(c.seen_value))
            << where << ": reference visibility";
    }
}

// Fast-edge's z-test (no z-write): the earlier square's right edge (x = 10) runs through the
// later square, and with inset 1/2 blends pixel column 9 with alpha 1 towards the earlier
// value, unless the later square there is nearer beyond the tie.
TEST(VisibilityRule, FastEdgeZTestPassesATieAndBlocksBeyondIt) {
    constexpr int kEdgeI = 9;  // the column left of x = 10, inside the overlap
    for (const auto& [offset_in_ties, expected] :
         std::vector<std::pair<double, double>>{{0.5, kEarlierValue}, {2.0, kLaterValue}}) {
        const MethodInstance m = make_method("fast-edge:inset=0.5");
        const Image out = render_scene(*m.method, z_fighting_squares(offset_in_ties));
        EXPECT_EQ(out.at(kEdgeI, kOverlapJ), static_cast<float>(expected))
            << "later square " << offset_in_ties << " ties nearer";
    }
}

// The tie's three outcomes at one point, and its scale: relative to the planes' terms there.
TEST(VisibilityRule, DepthOrderIsRelativeToTheTermsOfThePlanes) {
    const AffinePlane near{1.0, 0.0, 0.0};
    EXPECT_EQ(depth_order(near, AffinePlane{1.0 - 0.5 * kDepthTieRelative, 0.0, 0.0}, 0.0, 0.0),
              DepthOrder::kTie);
    EXPECT_EQ(depth_order(near, AffinePlane{1.0 - 2.0 * kDepthTieRelative, 0.0, 0.0}, 0.0, 0.0),
              DepthOrder::kFirstNearer);
    EXPECT_EQ(depth_order(AffinePlane{1.0 - 2.0 * kDepthTieRelative, 0.0, 0.0}, near, 0.0, 0.0),
              DepthOrder::kSecondNearer);
    // Far from the origin the terms gx x are large, and so is the tie: 1e3 px with gx = 1e-3
    // doubles the size of the terms.
    const AffinePlane sloped{1.0, 1e-3, 0.0};
    const AffinePlane shifted{1.0 - 1.5 * kDepthTieRelative, 1e-3, 0.0};
    EXPECT_EQ(depth_order(sloped, shifted, 0.0, 0.0), DepthOrder::kFirstNearer);
    EXPECT_EQ(depth_order(sloped, shifted, 1e3, 0.0), DepthOrder::kTie);
    // A tie at the point: the plane nearer just right of it, then the later shape.
    const std::vector<AffinePlane> crossing = {{1.0, -1e-3, 0.0}, {1.0, 1e-3, 0.0}};
    EXPECT_TRUE(seen_over(1, 0, crossing, 0.0, 0.0));
    EXPECT_FALSE(seen_over(0, 1, crossing, 0.0, 0.0));
    const std::vector<AffinePlane> coplanar = {near, near};
    EXPECT_TRUE(seen_over(1, 0, coplanar, 0.0, 0.0));
    EXPECT_FALSE(seen_over(0, 1, coplanar, 0.0, 0.0));
}

// The one-shape walk (OneShapeWalk: CoverWalk's shortcut, and the engines' walks in registers)
// against CoverWalk's general bookkeeping, made to run by a second shape that is never
// crossed: the same shape seen after every crossing of a walk whose winding number goes
// through 0, +-1 and +-2 (nested and opposite contours).
TEST(VisibilityRule, OneShapeWalkIsTheCoverWalksRule) {
    const std::vector<int> windings = {1, 1, -1, -1, -1, 1, 1, -1, -1, -1, 1, 1, 1, -1};
    CoverWalk general, shortcut;
    general.reset(2);  // shape 1 never crossed: the general path over shape 0 alone
    shortcut.reset(1);
    OneShapeWalk<int> by_index(0, -1);
    OneShapeWalk<> by_value(kLaterValue, kEarlierValue);
    for (std::size_t i = 0; i < windings.size(); ++i) {
        general.cross(0, windings[i]);
        shortcut.cross(0, windings[i]);
        const int seen = by_index.cross(windings[i]);
        const double value = by_value.cross(windings[i]);
        EXPECT_EQ(shortcut.top(), general.top()) << "after crossing " << i;
        EXPECT_EQ(seen, general.top()) << "after crossing " << i;
        EXPECT_EQ(value, general.top() == 0 ? kLaterValue : kEarlierValue)
            << "after crossing " << i;
    }
    // clear() forgets a walk stopped inside the shape.
    shortcut.clear();
    by_index.clear();
    EXPECT_EQ(shortcut.top(), -1);
    EXPECT_EQ(by_index.cross(1), 0);
}

}  // namespace
}  // namespace aabench
