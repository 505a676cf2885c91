// The edge stage (Saito & Takahashi 1990): the operators of eq. 3–8 computed by hand here, on small
// arrays, with plain loops that share nothing with harness/world/edges.cpp (which uses OpenCV); the
// compositing styles; the exact depth image of a face parallel to the screen; and effects on
// demand: a scene without an edges block runs neither the depth nor the edge stage.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <random>
#include <thread>
#include <vector>

#include "harness/world/alloc_count.h"
#include "harness/world/edges.h"
#include "harness/world/frame.h"
#include "harness/world/plan.h"
#include "methods/method.h"
#include "patterns/world_builders.h"

namespace aabench {
namespace {

// float32 sums of nine terms of depth values up to ~1e3: a few ulps of the largest term.
constexpr double kOperatorTolerance = 1e-3;
// z_s = f d / z_v ~ 1e3 stored in float32 (relative step 6e-8) after an exact double integral.
constexpr double kDepthRelativeTolerance = 1e-6;

// The value at (x, y), past the frame continued linearly, columns first (what the stage does).
double at(const Image& im, int x, int y) {
    if (x < 0) return 2 * at(im, 0, y) - at(im, 1, y);
    if (x >= im.width) return 2 * at(im, im.width - 1, y) - at(im, im.width - 2, y);
    if (y < 0) return 2 * at(im, x, 0) - at(im, x, 1);
    if (y >= im.height) return 2 * at(im, x, im.height - 1) - at(im, x, im.height - 2);
    return im.at(x, y);
}

// g's local extremes use only the pixels that exist.
float clamped(const Image& im, int x, int y) {
    return im.at(std::clamp(x, 0, im.width - 1), std::clamp(y, 0, im.height - 1));
}

struct Neighbours {
    double A, B, C, D, X, E, F, G, H;  // Fig. 4: A B C / D X E / F G H
};

Neighbours around(const Image& im, int x, int y) {
    return {at(im, x - 1, y - 1), at(im, x, y - 1), at(im, x + 1, y - 1),
            at(im, x - 1, y),     at(im, x, y),     at(im, x + 1, y),
            at(im, x - 1, y + 1), at(im, x, y + 1), at(im, x + 1, y + 1)};
}

double sobel(const Neighbours& n) {  // eq. 3
    return (std::abs(n.A + 2 * n.B + n.C - n.F - 2 * n.G - n.H) +
            std::abs(n.C + 2 * n.E + n.H - n.A - 2 * n.D - n.F)) /
           8;
}
double prewitt(const Neighbours& n) {  // eq. 4
    return (std::abs(n.A + n.B + n.C - n.F - n.G - n.H) +
            std::abs(n.C + n.E + n.H - n.A - n.D - n.F)) /
           6;
}
double laplacian4(const Neighbours& n) { return 4 * n.X - n.B - n.D - n.E - n.G; }  // eq. 5
double laplacian8(const Neighbours& n) {                                             // eq. 6
    return (8 * n.X - n.A - n.B - n.C - n.D - n.E - n.F - n.G - n.H) / 3;
}

Image random_depth(std::mt19937& rng, int w, int h) {
    std::uniform_real_distribution<double> plane(-30.0, 30.0);
    std::uniform_real_distribution<double> base(200.0, 900.0);
    Image im(w, h);
    // Two planes meeting along a random line (a crease) and a jump to 0 (a silhouette).
    const double c0 = base(rng), gx0 = plane(rng), gy0 = plane(rng);
    const double c1 = base(rng), gx1 = plane(rng), gy1 = plane(rng);
    const int hole_x = static_cast<int>(rng() % w);
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            const double a = c0 + gx0 * x + gy0 * y, b = c1 + gx1 * x + gy1 * y;
            im.at(x, y) = x == hole_x && y > h / 2 ? 0.0f : static_cast<float>(std::min(a, b));
        }
    }
    return im;
}

// eq. 3-8 on every pixel, by hand.
void expect_operators_by_hand(const Image& depth, const EdgesSpec& spec, const EdgeImages& out,
                              unsigned seed) {
    const int w = depth.width, h = depth.height;
    Image g(w, h), l(w, h);
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            const Neighbours n = around(depth, x, y);
            g.at(x, y) = static_cast<float>(spec.contour == "sobel" ? sobel(n) : prewitt(n));
            l.at(x, y) = static_cast<float>(spec.crease == "laplacian4"   ? laplacian4(n)
                                            : spec.crease == "laplacian8" ? laplacian8(n)
                                                                          : 0.0);
        }
    }
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            double g_max = -1e300, g_min = 1e300;
            for (int dy = -1; dy <= 1; ++dy) {
                for (int dx = -1; dx <= 1; ++dx) {
                    g_max = std::max<double>(g_max, clamped(g, x + dx, y + dy));
                    g_min = std::min<double>(g_min, clamped(g, x + dx, y + dy));
                }
            }
            const double gv = g.at(x, y), lv = l.at(x, y);
            const double p = g_max - g_min >= spec.kp ? (gv - g_min) / (g_max - g_min)
                                                      : (gv - g_min) / spec.kp;  // eq. 7
            const double e = g_max <= spec.kl ? lv : lv / std::pow(g_max / spec.kl, 2);  // eq. 8
            const std::string where = "seed " + std::to_string(seed) + " pixel (" +
                                      std::to_string(x) + ", " + std::to_string(y) + ") " +
                                      spec.contour + "/" + spec.crease;
            ASSERT_NEAR(out.g.at(x, y), gv, kOperatorTolerance * std::max(1.0, gv)) << where;
            ASSERT_NEAR(out.l.at(x, y), lv, kOperatorTolerance * std::max(1.0, std::abs(lv)))
                << where;
            ASSERT_NEAR(out.p.at(x, y), p, kOperatorTolerance) << where;
            ASSERT_NEAR(out.e.at(x, y), e, kOperatorTolerance * std::max(1.0, std::abs(e)))
                << where;
        }
    }
}

TEST(Edges, OperatorsAreThePapersEquationsByHand) {
    std::mt19937 rng(20261124);
    for (unsigned seed = 0; seed < 24; ++seed) {
        rng.seed(seed);
        const Image depth = random_depth(rng, 17, 13);
        const Image shaded(17, 13, 0.5f);
        for (const char* contour : {"sobel", "prewitt"}) {
            for (const char* crease : {"laplacian4", "laplacian8", "none"}) {
                EdgesSpec spec;
                spec.contour = contour;
                spec.crease = crease;
                spec.kp = 1.0 + seed;       // both branches of eq. 7 occur
                spec.kl = 0.5 + 2.0 * seed;  // and of eq. 8
                expect_operators_by_hand(depth, spec, enhance_edges(depth, shaded, spec), seed);
            }
        }
    }
}

// Two planes at 45 degrees to the screen meeting at a right angle: the paper's |l| = 2, and
// the sign says convex (a ridge of z_s: nearer in the middle) from concave.
TEST(Edges, RightAngleCreaseGivesTwoWithTheSignOfItsConvexity) {
    constexpr int kW = 9, kH = 5;
    for (const double sign : {1.0, -1.0}) {
        Image depth(kW, kH);
        for (int y = 0; y < kH; ++y) {
            for (int x = 0; x < kW; ++x) {
                depth.at(x, y) = static_cast<float>(100.0 - sign * std::abs(x - 4));
            }
        }
        for (const char* crease : {"laplacian4", "laplacian8"}) {
            EdgesSpec spec;
            spec.crease = crease;
            spec.kl = 2.0;  // g = 1 on both planes (the slope): eq. 8 leaves l as it is
            const EdgeImages out = enhance_edges(depth, Image(kW, kH, 0.5f), spec);
            EXPECT_NEAR(out.l.at(4, 2), 2.0 * sign, kOperatorTolerance) << crease;
            EXPECT_NEAR(out.g.at(1, 2), 1.0, kOperatorTolerance) << "slope of a 45-degree plane";
            EXPECT_NEAR(out.l.at(1, 2), 0.0, kOperatorTolerance) << "a plane has no crease";
        }
    }
}

// The two styles put the lines over the shaded image as docs/edges.md says.
TEST(Edges, CompositingStyles) {
    constexpr int kW = 9, kH = 5;
    Image depth(kW, kH);
    for (int y = 0; y < kH; ++y) {
        for (int x = 0; x < kW; ++x) depth.at(x, y) = static_cast<float>(100.0 - std::abs(x - 4));
    }
    const Image shaded(kW, kH, 0.6f);
    EdgesSpec spec;
    spec.kl = 2.0;
    spec.crease_weight = 0.5;
    spec.style = "black";
    const EdgeImages black = enhance_edges(depth, shaded, spec);
    // At the ridge: e = 2 (convex), p = 0 (g is at its local minimum there).
    const double dark = std::min(1.0, spec.crease_weight * 2.0 + black.p.at(4, 2));
    EXPECT_NEAR(black.lines.at(4, 2), dark, kOperatorTolerance);
    EXPECT_NEAR(black.composite.at(4, 2), 0.6 * (1.0 - dark), kOperatorTolerance);
    EXPECT_NEAR(black.composite.at(0, 2), 0.6, kOperatorTolerance) << "no line on a plane";
    spec.style = "white-convex";
    const EdgeImages white = enhance_edges(depth, shaded, spec);
    EXPECT_GT(white.composite.at(4, 2), 0.6f) << "a convex crease is drawn white";
    EXPECT_GT(white.lines.at(4, 2), 0.0f);
    EXPECT_NEAR(white.composite.at(0, 2), 0.6, kOperatorTolerance);
    EXPECT_THROW(enhance_edges(depth, Image(kW + 1, kH), spec), InputError);
}

// The per-thread buffers (edges.h): a sequence of calls of mixed sizes and operators, written
// into one kept EdgeImages, gives bit for bit what each call gives on a thread that never ran
// the stage (fresh buffers); a repeated call of the same size keeps every output buffer and
// allocates no image on the heap.
TEST(Edges, KeptBuffersGiveBitIdenticalImages) {
    struct Call {
        int w, h;
        const char* contour;
        const char* crease;
        const char* style;
    };
    const std::vector<Call> calls = {{23, 17, "sobel", "laplacian8", "black"},
                                     {23, 17, "prewitt", "none", "white-convex"},
                                     {40, 9, "sobel", "laplacian4", "black"},
                                     {23, 17, "sobel", "laplacian8", "white-convex"},
                                     {1, 5, "prewitt", "laplacian4", "black"}};
    auto input = [](const Call& c, unsigned seed) {
        std::mt19937 rng(seed);
        return std::pair{random_depth(rng, c.w, c.h), Image(c.w, c.h, 0.25f + 0.1f * seed)};
    };
    auto spec_of = [](const Call& c) {
        EdgesSpec spec;
        spec.contour = c.contour;
        spec.crease = c.crease;
        spec.style = c.style;
        spec.kp = 4.0;
        return spec;
    };
    std::vector<EdgeImages> fresh(calls.size());
    for (std::size_t k = 0; k < calls.size(); ++k) {
        // A pair, not a structured binding: clang 14 cannot capture bindings in a lambda.
        const auto images = input(calls[k], static_cast<unsigned>(k));
        std::thread([&, k] {
            fresh[k] = enhance_edges(images.first, images.second, spec_of(calls[k]));
        }).join();
    }
    EdgeImages kept;
    for (std::size_t k = 0; k < calls.size(); ++k) {
        const auto [depth, shaded] = input(calls[k], static_cast<unsigned>(k));
        enhance_edges(depth, shaded, spec_of(calls[k]), kept);
        const std::vector<std::pair<const Image*, const Image*>> pairs = {
            {&kept.g, &fresh[k].g},         {&kept.l, &fresh[k].l},
            {&kept.p, &fresh[k].p},         {&kept.e, &fresh[k].e},
            {&kept.lines, &fresh[k].lines}, {&kept.composite, &fresh[k].composite}};
        for (std::size_t m = 0; m < pairs.size(); ++m) {
            ASSERT_EQ(pairs[m].first->width, calls[k].w) << "call " << k << " image " << m;
            // Bit for bit: memcmp, not ==, so that a NaN or a signed zero counts too.
            EXPECT_EQ(std::memcmp(pairs[m].first->data.data(), pairs[m].second->data.data(),
                                  pairs[m].first->data.size() * sizeof(float)),
                      0)
                << "call " << k << " image " << m << " (g, l, p, e, lines, composite)";
        }
    }
    // Twice at one size: the second call keeps the output buffers where they are and
    // allocates no full-size image through operator new (the kept cv::Mat buffers are
    // OpenCV's, through malloc, and would not be counted: their reuse is what the bit-identity
    // above and the benchmark show).
    const Call big{256, 256, "sobel", "laplacian8", "black"};
    const auto [depth, shaded] = input(big, 9);
    const EdgesSpec spec = spec_of(big);
    enhance_edges(depth, shaded, spec, kept);
    const float* where = kept.composite.data.data();
    const AllocCounts before = thread_alloc_counts();
    enhance_edges(depth, shaded, spec, kept);
    const AllocCounts after = thread_alloc_counts();
    EXPECT_EQ(kept.composite.data.data(), where);
    const std::uint64_t image_bytes = depth.data.size() * sizeof(float);
    // OpenCV's filter and morphology engines keep a few rows of the image in std::vectors:
    // bytes that grow with the width (45 kB at 256 wide), not with the pixel count. The bound,
    // a quarter of one image (64 kB), is above that; one full-size image made per call would
    // exceed it.
    EXPECT_LT(after.bytes - before.bytes, image_bytes / 4);
}

// A square face parallel to the image plane at view depth z: the exact method's depth image is
// f d / z on every pixel the face covers whole (the paper's eq. 2 with the screen at the target,
// d = |target - eye| = 2 here, w = d / f world units per px).
TEST(Edges, ExactDepthOfAFaceParallelToTheScreenIsFDOverZ) {
    constexpr double kZ = 5.0, kTargetDistance = 2.0;
    Scene scene;
    scene.width = 64;
    scene.height = 48;
    World w;
    w.camera.eye = {0.0, 0.0, 0.0};
    w.camera.target = {0.0, 0.0, -kTargetDistance};
    w.camera.fov_y_deg = 40.0;
    Object quad;
    quad.name = "quad";
    quad.closed = false;
    quad.vertices = {{-1.3, -0.9, -kZ}, {1.1, -0.9, -kZ}, {1.1, 0.8, -kZ}, {-1.3, 0.8, -kZ}};
    Face f;
    f.loop = {0, 1, 2, 3};
    quad.faces.push_back(f);
    w.objects.push_back(quad);
    w.edges = EdgesSpec{};
    scene.world = w;
    const Plan plan = make_plan(scene);
    ASSERT_TRUE(plan.in(Stage::kDepthImage));
    const PreparedFrame r = PreparedFrame::prepare(scene);
    const MethodInstance exact = make_method("exact");
    const Image shaded = render_scene(*exact.method, r.input_for(*exact.method));
    const AfterMethod after = r.after_method(*exact.method, exact.spec, shaded, true);
    const Image& depth = *after.depth;
    const double expected = r.focal_px() * kTargetDistance / kZ;
    int interior = 0;
    for (int y = 0; y < scene.height; ++y) {
        for (int x = 0; x < scene.width; ++x) {
            // The quad's screen rectangle, from the projection x = W/2 + f x_v / z.
            const double x0 = 32 - r.focal_px() * 1.3 / kZ, x1 = 32 + r.focal_px() * 1.1 / kZ;
            const double y0 = 24 - r.focal_px() * 0.8 / kZ, y1 = 24 + r.focal_px() * 0.9 / kZ;
            if (x >= x0 && x + 1 <= x1 && y >= y0 && y + 1 <= y1) {
                ++interior;
                ASSERT_NEAR(depth.at(x, y), expected, kDepthRelativeTolerance * expected)
                    << "pixel (" << x << ", " << y << ")";
            } else if (x + 1 <= x0 || x >= x1 || y + 1 <= y0 || y >= y1) {
                ASSERT_EQ(depth.at(x, y), 0.0f) << "background is 0 (infinitely far)";
            }
        }
    }
    EXPECT_GT(interior, 500);
    EXPECT_TRUE(r.costs()[static_cast<int>(Stage::kDepthImage)].ran);
    EXPECT_TRUE(after.depth_cost.ran);
}

// Saito & Takahashi's normalisation (eq. 2): on a plane through the camera's target the first
// derivative of the depth image, the edge stage's g (eq. 3 on the exact depth image), equals
// the plane's view-space slope (|dz_v/dx_v| + |dz_v/dy_v|, Sobel's sum) at the target's pixel,
// whatever the resolution and the field of view. (With z_s = f^2 / z_v it was the slope times
// f / d, 1,400 / 3.7 at 1024 x 768 and 30 degrees.)
TEST(Edges, DepthDerivativeAtTheTargetIsTheViewSlopeAtEveryResolutionAndFieldOfView) {
    constexpr double kTargetDistance = 3.7;
    // z_s ~ f d / z_v ~ 1.5e3 at most here, stored in float32 (ulp 1.2e-4); eq. 3 sums eight
    // such values and divides by 8: a few ulps.
    constexpr double kSlopeTolerance = 1e-3;
    struct Slope {
        double sx, sy;  // dz_v/dx_v, dz_v/dy_v
    };
    for (const Slope slope : {Slope{0.4, 0.0}, Slope{0.25, -0.3}}) {
        for (const double fov_deg : {30.0, 60.0}) {
            for (const auto& [width, height] : {std::pair{64, 48}, {256, 192}, {1024, 768}}) {
                Scene scene;
                scene.width = width;
                scene.height = height;
                World w;
                w.camera.eye = {0.0, 0.0, 0.0};
                w.camera.target = {0.0, 0.0, -kTargetDistance};
                w.camera.fov_y_deg = fov_deg;
                // z_v = d + sx x_v + sy y_v, the view looking down -z: the point (x, y) of the
                // plane lies at z = -(d + sx x + sy y). It spans the view at both angles.
                auto at = [&](double x, double y) {
                    return glm::dvec3(x, y, -(kTargetDistance + slope.sx * x + slope.sy * y));
                };
                w.objects.push_back(make_quad("plane", at(-2.5, -2.5), at(2.5, -2.5),
                                              at(2.5, 2.5), at(-2.5, 2.5), 0.8));
                w.edges = EdgesSpec{};
                scene.world = w;
                const PreparedFrame r = PreparedFrame::prepare(scene);
                const MethodInstance exact = make_method("exact");
                const Image shaded = render_scene(*exact.method, r.input_for(*exact.method));
                const AfterMethod after = r.after_method(*exact.method, exact.spec, shaded, true);
                const EdgeImages edges = enhance_edges(*after.depth, shaded, EdgesSpec{});
                // The target projects to the image centre, the corner of pixel (W/2, H/2).
                const double g = edges.g.at(width / 2, height / 2);
                EXPECT_NEAR(g, std::abs(slope.sx) + std::abs(slope.sy), kSlopeTolerance)
                    << width << " x " << height << ", fov " << fov_deg << " deg, slope ("
                    << slope.sx << ", " << slope.sy << ")";
            }
        }
    }
}

World box_world(bool with_edges) {
    World w;
    w.camera.eye = {3.1, 2.3, 4.7};
    w.camera.target = {0.01, 0.02, -0.03};
    Object o;
    o.name = "box";
    o.vertices = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                  {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
    const int loops[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
                             {3, 7, 6, 2}, {0, 4, 7, 3}, {1, 2, 6, 5}};
    for (const auto& l : loops) {
        Face f;
        f.loop = {l[0], l[1], l[2], l[3]};
        o.faces.push_back(f);
    }
    w.objects.push_back(o);
    if (with_edges) w.edges = EdgesSpec{};
    return w;
}

// Effects on demand: the depth image and the edge stage run only for a scene that asks for
// edges; without an edges block neither is called and nothing is allocated for them.
TEST(Edges, OnlyASceneWithEdgesRunsTheDepthAndEdgeStages) {
    for (const bool with_edges : {false, true}) {
        Scene scene;
        scene.width = 64;
        scene.height = 48;
        scene.world = box_world(with_edges);
        const Plan plan = make_plan(scene);
        EXPECT_EQ(plan.in(Stage::kDepthImage), with_edges);
        EXPECT_EQ(plan.in(Stage::kEdges), with_edges);
        const PreparedFrame r = PreparedFrame::prepare(scene);
        EXPECT_EQ(r.has_depth_stage(), with_edges);
        const MethodInstance exact = make_method("exact");
        const Image shaded = render_scene(*exact.method, r.pieces());
        const auto depth_cost = r.costs()[static_cast<int>(Stage::kDepthImage)];
        if (!with_edges) {
            EXPECT_FALSE(depth_cost.ran);
            EXPECT_EQ(depth_cost.bytes, 0u);
            EdgeImages none;
            EXPECT_THROW(r.edge_stage(Image(64, 48), Image(64, 48), none), std::logic_error);
            const AfterMethod after = r.after_method(*exact.method, exact.spec, shaded);
            EXPECT_FALSE(after.depth.has_value());
            EXPECT_FALSE(after.edges.has_value());
            continue;
        }
        const AfterMethod after = r.after_method(*exact.method, exact.spec, shaded);
        ASSERT_TRUE(after.edges.has_value());
        const EdgeImages& edges = *after.edges;
        const StageCost& edge_cost = after.edge_cost;
        EXPECT_TRUE(edge_cost.ran);
        EXPECT_GT(edge_cost.bytes, 0u);
        // The silhouette is drawn: some pixel next to the background is dark in the lines.
        EXPECT_GT(*std::max_element(edges.lines.data.begin(), edges.lines.data.end()), 0.5f);
    }
}

// A method that cannot draw affine values is refused a depth image, by name.
TEST(Edges, AMethodWithoutAffineValuesIsRefusedTheDepthImage) {
    Scene scene;
    scene.width = 32;
    scene.height = 24;
    scene.world = box_world(true);
    const PreparedFrame r = PreparedFrame::prepare(scene);
    for (const MethodInfo& info : method_registry()) {
        const MethodInstance m = make_method(info.id);
        if (m.method->affine_values()) continue;
        try {
            r.after_method(*m.method, m.spec, Image(32, 24));
            ADD_FAILURE() << info.id << " drew a depth image without affine values";
        } catch (const InputError& e) {
            EXPECT_NE(std::string(e.what()).find(m.spec), std::string::npos) << e.what();
            EXPECT_NE(std::string(e.what()).find("exact"), std::string::npos)
                << "the message lists the methods that can: " << e.what();
        }
    }
}

}  // namespace
}  // namespace aabench
