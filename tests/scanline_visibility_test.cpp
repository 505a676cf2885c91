// The multi-scanning methods' own hidden-surface removal
// (methods/scan/multiscan/scanline_visibility.h: crossings in the paper's tie order, the NEXT
// stack, depth compared at crossings) against an independent slow evaluation: per sub-scanline, the
// exact visible spans read off the exact visibility pieces (harness/reference/visibility.h, a
// different algorithm: polygon clipping in the plane) by brute force over every piece's edges, then
// eq. 1–3. Where no two faces interpenetrate the two agree to 1e-6; where faces do interpenetrate,
// the paper's method (depth compared only at crossings) differs, and the test prints by how much
// and checks that every differing pixel lies on a pixel row whose sub-scanlines meet the screen
// overlap of an interpenetrating pair (and how many lie on the overlap itself).
#include <gtest/gtest.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include <fmt/format.h>

#include "harness/reference/visibility.h"
#include "harness/world/alloc_count.h"
#include "harness/world/frame.h"
#include "methods/method.h"
#include "methods/scan/multiscan/scanline_visibility.h"
#include "patterns/pattern.h"

namespace aabench {
namespace {

// The method rounds each pixel once to float32 (<= 6e-8 for values <= 1; the room's shaded
// values reach ~1.5); both sides sum O(100) double terms per pixel (~1e-14). 1e-6 is the
// method's bound (docs/architecture.md), a 10x margin over float32 rounding.
constexpr double kTolerance = 1e-6;
constexpr int kSubScanlines[] = {1, 2, 3, 7};
constexpr int kRandomScenes = 200;
constexpr int kWidth = 24, kHeight = 18;  // random scenes
constexpr int kPatternWidth = 64, kPatternHeight = 48;

// The integral over [x_lo, x_hi] of the visible value on the line y, from disjoint pieces: each
// piece's own crossings, nonzero winding, its covered length times its (affine: midpoint)
// value. `from_below`: an edge counts when min_y <= y < max_y, else min_y < y <= max_y.
double slow_line_integral(const Scene& pieces, double y, bool from_below, double x_lo,
                          double x_hi) {
    double covered = 0.0, sum = 0.0;
    for (const Shape& shape : pieces.shapes) {
        std::vector<std::pair<double, int>> hits;
        for (const Contour& c : shape.contours) {
            for (std::size_t k = 0; k < c.size(); ++k) {
                const Point a = c[k], b = c[(k + 1) % c.size()];
                if (a.y == b.y) continue;
                const double lo = std::min(a.y, b.y), hi = std::max(a.y, b.y);
                const bool hit = from_below ? (lo <= y && y < hi) : (lo < y && y <= hi);
                if (!hit) continue;
                const double t = (y - a.y) / (b.y - a.y);
                hits.push_back({a.x + t * (b.x - a.x), a.y < b.y ? 1 : -1});
            }
        }
        std::sort(hits.begin(), hits.end());
        int winding = 0;
        for (std::size_t k = 0; k + 1 < hits.size(); ++k) {
            winding += hits[k].second;
            if (winding == 0) continue;
            const double a = std::max(hits[k].first, x_lo), b = std::min(hits[k + 1].first, x_hi);
            if (!(b > a)) continue;
            const double v = shape.value_plane ? shape.value_plane->at(0.5 * (a + b), y) : shape.value;
            covered += b - a;
            sum += (b - a) * v;
        }
    }
    return sum + (x_hi - x_lo - covered) * pieces.background;
}

// Eq. 1–3 with box-multiscan's conventions (methods/box_multiscan.cpp): row borders take the
// limit from inside the row, interior lines the mean of both limits.
std::vector<double> slow_box_multiscan(const Scene& pieces, int n) {
    std::vector<double> out(static_cast<std::size_t>(pieces.width) * pieces.height);
    for (int j = 0; j < pieces.height; ++j) {
        for (int i = 0; i < pieces.width; ++i) {
            double sum = 0.0;
            for (int l = 0; l <= n; ++l) {
                const double y = l == n ? j + 1.0 : j + static_cast<double>(l) / n;
                double v;
                if (l == 0) {
                    v = slow_line_integral(pieces, y, true, i, i + 1.0);
                } else if (l == n) {
                    v = slow_line_integral(pieces, y, false, i, i + 1.0);
                } else {
                    v = 0.5 * (slow_line_integral(pieces, y, true, i, i + 1.0) +
                               slow_line_integral(pieces, y, false, i, i + 1.0));
                }
                sum += (l == 0 || l == n ? 0.5 / n : 1.0 / n) * v;
            }
            out[static_cast<std::size_t>(j) * pieces.width + i] = sum;
        }
    }
    return out;
}

// Sutherland–Hodgman: the convex polygon a clipped to the convex polygon b (either orientation).
Contour clip_convex(const Contour& a, const Contour& b) {
    const double orient = twice_signed_area(b) > 0 ? 1.0 : -1.0;
    Contour out = a;
    for (std::size_t k = 0; k < b.size() && !out.empty(); ++k) {
        const Point p = b[k], q = b[(k + 1) % b.size()];
        auto side = [&](Point r) {
            return orient * ((q.x - p.x) * (r.y - p.y) - (q.y - p.y) * (r.x - p.x));
        };
        Contour next;
        for (std::size_t m = 0; m < out.size(); ++m) {
            const Point r = out[m], s = out[(m + 1) % out.size()];
            const double sr = side(r), ss = side(s);
            if (sr >= 0) next.push_back(r);
            if ((sr >= 0) != (ss >= 0)) {
                const double t = sr / (sr - ss);
                next.push_back({r.x + t * (s.x - r.x), r.y + t * (s.y - r.y)});
            }
        }
        out = std::move(next);
    }
    return out;
}

// Where the paper's priority assumption fails: pairs of shapes of different faces whose depth
// planes cross strictly inside their screen overlap. On a sub-scanline that meets no such
// overlap, the depth order of any two shapes is the same all along their common span, so
// comparing at crossings is exact and the NEXT stack gives the exact visible spans. On a
// line that does meet one, `current` can be wrong from the crossing line on, and a wrong
// `current` can make later decisions on the same line wrong too (a shape compared with it),
// so the error is not confined to the pair's overlap, only to the lines through it.
// `rows` marks the pixel rows whose sub-scanlines meet such an overlap (its y-range, grown by
// 1 px); `near` the pixels of the overlaps' bounding boxes (grown by 1 px), to report how much
// of the difference lies right at the crossing faces.
int interpenetration_masks(const Scene& screen, std::vector<char>& rows, std::vector<char>& near) {
    // Relative size of a depth difference that counts as a crossing (not a touch along a shared
    // edge, where the difference is rounding, ~1e-15 relative).
    constexpr double kCrossingRelative = 1e-9;
    rows.assign(screen.height, 0);
    near.assign(static_cast<std::size_t>(screen.width) * screen.height, 0);
    int pairs = 0;
    for (std::size_t a = 0; a < screen.shapes.size(); ++a) {
        for (std::size_t b = a + 1; b < screen.shapes.size(); ++b) {
            const Shape& sa = screen.shapes[a];
            const Shape& sb = screen.shapes[b];
            if (sa.face >= 0 && sa.face == sb.face) continue;
            const Contour overlap = clip_convex(sa.contours[0], sb.contours[0]);
            if (overlap.size() < 3 || std::abs(twice_signed_area(overlap)) < 1e-12) continue;
            double lo = 0, hi = 0, scale = 0;
            for (const Point& p : overlap) {
                const double d = sa.inv_depth->at(p.x, p.y) - sb.inv_depth->at(p.x, p.y);
                lo = std::min(lo, d);
                hi = std::max(hi, d);
                scale = std::max(scale, std::abs(sa.inv_depth->at(p.x, p.y)));
            }
            if (!(lo < -kCrossingRelative * scale && hi > kCrossingRelative * scale)) continue;
            ++pairs;
            double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
            for (const Point& p : overlap) {
                x0 = std::min(x0, p.x), x1 = std::max(x1, p.x);
                y0 = std::min(y0, p.y), y1 = std::max(y1, p.y);
            }
            const int j0 = std::max(0, int(std::floor(y0)) - 1);
            const int j1 = std::min(screen.height, int(std::ceil(y1)) + 1);
            for (int j = j0; j < j1; ++j) {
                rows[j] = 1;
                for (int i = std::max(0, int(std::floor(x0)) - 1);
                     i < std::min(screen.width, int(std::ceil(x1)) + 1); ++i) {
                    near[static_cast<std::size_t>(j) * screen.width + i] = 1;
                }
            }
        }
    }
    return pairs;
}

struct Agreement {
    double worst_clean = 0.0;             // rows that meet no crossing overlap
    double worst_interpenetrating = 0.0;  // rows that do
    int pixels_differing = 0;             // in those rows, by more than kTolerance
    int differing_near = 0;               // of those, on an overlap's bounding box
    int pairs = 0;
};

Agreement compare_with_slow(const Scene& screen, int n, const std::string& what) {
    const Scene pieces = visible_pieces(screen);
    const std::vector<double> slow = slow_box_multiscan(pieces, n);
    const Image fast = render_scene(*make_method(fmt::format("box-multiscan:n={}", n)).method,
                                    screen);
    std::vector<char> rows, near;
    Agreement r;
    r.pairs = interpenetration_masks(screen, rows, near);
    for (int j = 0; j < screen.height; ++j) {
        for (int i = 0; i < screen.width; ++i) {
            const std::size_t k = static_cast<std::size_t>(j) * screen.width + i;
            const double d = std::abs(fast.data[k] - slow[k]);
            if (rows[j]) {
                r.worst_interpenetrating = std::max(r.worst_interpenetrating, d);
                const bool differs = !(d <= kTolerance);
                r.pixels_differing += differs;
                r.differing_near += differs && near[k];
            } else {
                r.worst_clean = std::max(r.worst_clean, d);
                // NaN fails: !(d <= tol).
                EXPECT_TRUE(d <= kTolerance) << what << " n=" << n << " pixel (" << i << ", " << j
                                             << "): scanline " << fast.data[k] << ", slow "
                                             << slow[k];
            }
        }
    }
    return r;
}

// A random convex polygon: k points on an ellipse at sorted random angles.
Contour random_convex(std::mt19937_64& rng, int width, int height) {
    std::uniform_real_distribution<double> u(0.0, 1.0);
    const double cx = -2.0 + u(rng) * (width + 4.0), cy = -2.0 + u(rng) * (height + 4.0);
    const double rx = 1.0 + u(rng) * width * 0.5, ry = 1.0 + u(rng) * height * 0.5;
    const int k = 3 + static_cast<int>(u(rng) * 5);
    std::vector<double> angles(k);
    for (double& a : angles) a = u(rng) * 2.0 * M_PI;
    std::sort(angles.begin(), angles.end());
    Contour c;
    for (const double a : angles) c.push_back({cx + rx * std::cos(a), cy + ry * std::sin(a)});
    if (u(rng) < 0.5) std::reverse(c.begin(), c.end());  // either orientation
    return c;
}

// A random ScreenScene of 2..6 faces. Without interpenetration each face's depth plane stays
// inside its own slab (face k: inv_depth in [k + 1.1, k + 1.9] over the whole region shapes
// reach), so no two planes cross where faces lie; with it, planes are independent and tilted.
// Some faces are cut along a chord into a face cell and a pattern or shadow cell (the same
// plane: coincident crossings in the tie order); some carry an affine value.
Scene random_screen(std::uint64_t seed, bool interpenetrate) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    Scene s;
    s.width = kWidth;
    s.height = kHeight;
    s.background = 0.25 * u(rng);
    const int faces = 2 + static_cast<int>(u(rng) * 5);
    // Shapes reach x in [-2 - W/2 - 1, W + 2 + W/2 + 1]: gradients bounded so a slab's plane
    // moves by at most 0.4 over 2 W and 2 H.
    const double gmax_x = 0.2 / (2.0 * kWidth), gmax_y = 0.2 / (2.0 * kHeight);
    for (int f = 0; f < faces; ++f) {
        AffinePlane w;
        if (interpenetrate) {
            // Tilted planes that cross each other, positive over every point shapes reach.
            w.gx = (u(rng) - 0.5) * 0.03;
            w.gy = (u(rng) - 0.5) * 0.03;
            w.c = 1.0 + u(rng) - w.gx * 0.5 * kWidth - w.gy * 0.5 * kHeight;
        } else {
            w.gx = (2 * u(rng) - 1) * gmax_x;
            w.gy = (2 * u(rng) - 1) * gmax_y;
            w.c = f + 1.5 - w.gx * 0.5 * kWidth - w.gy * 0.5 * kHeight;
        }
        Shape shape;
        shape.contours = {random_convex(rng, kWidth, kHeight)};
        shape.inv_depth = w;
        shape.face = f;
        shape.value = 0.3 + 0.7 * u(rng);
        if (u(rng) < 0.3) {
            shape.value_plane = AffinePlane{shape.value, (u(rng) - 0.5) * 0.05,
                                            (u(rng) - 0.5) * 0.05};
        }
        const Contour& c = shape.contours[0];
        if (u(rng) < 0.5 && c.size() >= 4) {
            // Cut along the chord from vertex 0 to vertex m: two cells sharing that edge.
            const std::size_t m = 2 + static_cast<std::size_t>(u(rng) * (c.size() - 3));
            Shape cell = shape;
            cell.contours = {Contour(c.begin(), c.begin() + m + 1)};
            shape.contours = {Contour(c.begin() + m, c.end())};
            shape.contours[0].push_back(c[0]);
            cell.role = u(rng) < 0.5 ? ShapeRole::kPattern : ShapeRole::kShadow;
            cell.value = 0.1 + 0.5 * u(rng);
            cell.value_plane.reset();
            s.shapes.push_back(shape);
            s.shapes.push_back(cell);
        } else {
            s.shapes.push_back(shape);
        }
    }
    // Shuffle: the priority comes from depth, not from the order.
    std::shuffle(s.shapes.begin(), s.shapes.end(), rng);
    return s;
}

TEST(ScanlineVisibility, AgreesWithSlowExactSpansOnRandomScenesWithoutInterpenetration) {
    double worst = 0.0;
    for (int seed = 1; seed <= kRandomScenes; ++seed) {
        const Scene screen = random_screen(seed, false);
        for (const int n : kSubScanlines) {
            const Agreement a = compare_with_slow(screen, n, fmt::format("seed {}", seed));
            EXPECT_EQ(a.pairs, 0) << "seed " << seed << ": the generator made faces cross";
            worst = std::max(worst, a.worst_clean);
        }
    }
    std::printf("random scenes without interpenetration: %d scenes x %zu n, worst |scanline - "
                "slow| = %.3g\n",
                kRandomScenes, std::size(kSubScanlines), worst);
}

TEST(ScanlineVisibility, InterpenetrationDiffersOnlyOnLinesThroughCrossingFaces) {
    double worst_clean = 0.0, worst_in = 0.0;
    int differing = 0, differing_near = 0, scenes_with_pairs = 0;
    for (int seed = 1; seed <= kRandomScenes; ++seed) {
        const Scene screen = random_screen(1000 + seed, true);
        const Agreement a = compare_with_slow(screen, 3, fmt::format("seed {}", 1000 + seed));
        worst_clean = std::max(worst_clean, a.worst_clean);
        worst_in = std::max(worst_in, a.worst_interpenetrating);
        differing += a.pixels_differing;
        differing_near += a.differing_near;
        scenes_with_pairs += a.pairs > 0;
    }
    std::printf("random interpenetrating scenes (n=3, %dx%d): %d scenes, %d with crossing faces; "
                "rows off their overlaps: worst %.3g; rows through them: worst %.3g, %d pixels "
                "differ by > %g, %d of them on an overlap's bounding box\n",
                kWidth, kHeight, kRandomScenes, scenes_with_pairs, worst_clean, worst_in,
                differing, kTolerance, differing_near);
    EXPECT_GT(differing, 0) << "the paper's method should differ somewhere on crossing faces";
}

TEST(ScanlineVisibility, AgreesWithSlowExactSpansOnEvery3DPattern) {
    for (const PatternInfo& info : pattern_registry()) {
        if (info.model_file) continue;  // tests/mesh_patterns_test.cpp
        const Scene scene = make_pattern(info.id, kPatternWidth, kPatternHeight);
        if (!scene.world) continue;
        const PreparedFrame world = PreparedFrame::prepare(scene);
        for (const int n : {1, 3, 6}) {
            const Agreement a = compare_with_slow(world.screen(), n, info.id);
            std::printf("%-14s %dx%d n=%d: %d interpenetrating pairs; rows off them worst %.3g; "
                        "rows through them worst %.3g (%d pixels > %g, %d on an overlap's box)\n",
                        info.id.c_str(), kPatternWidth, kPatternHeight, n, a.pairs,
                        a.worst_clean, a.worst_interpenetrating, a.pixels_differing, kTolerance,
                        a.differing_near);
        }
    }
}

// gauss-multiscan's own visibility on the ScreenScene against the same method on the exact
// visible pieces (its 2-D path): the same sub-scanlines, so the same image to float32 rounding
// where no faces interpenetrate: not on `interpenetrate`, nor on `foliage`, whose random leaves
// pierce each other (0.007 apart there at n = 3). (The lines outside the image it also walks,
// 1 px beyond, hold the same faces.)
TEST(ScanlineVisibility, GaussMultiscanOnScreenEqualsItOnTheVisiblePieces) {
    for (const PatternInfo& info : pattern_registry()) {
        if (info.model_file) continue;  // tests/mesh_patterns_test.cpp
        const Scene scene = make_pattern(info.id, kPatternWidth, kPatternHeight);
        if (!scene.world || info.id == "interpenetrate" || info.id == "foliage") continue;
        const PreparedFrame world = PreparedFrame::prepare(scene);
        for (const char* spec : {"gauss-multiscan", "gauss-multiscan:n=6,filter=cone,lut=0"}) {
            const MethodInstance m = make_method(spec);
            const Image a = render_scene(*m.method, world.screen());
            const Image b = render_scene(*m.method, world.pieces());
            double worst = 0.0;
            for (std::size_t k = 0; k < a.data.size(); ++k) {
                worst = std::max(worst, std::abs(double(a.data[k]) - b.data[k]));
            }
            EXPECT_LE(worst, kTolerance) << info.id << " / " << spec;
        }
    }
}

// On a 2-D scene the multi-scans take the priority path, unchanged. The NEXT stack with depth
// planes that encode the same priority (shape k at constant inv_depth k + 1) must give the same
// image on every 2-D pattern: the stack reproduces the priority rule exactly. Bit for bit but
// where the 2-D path sums in another order: box-multiscan's whole rows, gauss-multiscan's
// difference rows, against line-by-line or region-by-region sums, where the float results may
// differ by a rounding step (4 ulps, as tests/subscanline_rows_test.cpp's kSumOrderUlps).
constexpr float kSumOrderUlps = 4.0f;

TEST(ScanlineVisibility, DepthOrderedAsThePriorityEqualsThe2DPathBitForBit) {
    for (const PatternInfo& info : pattern_registry()) {
        if (info.model_file) continue;  // tests/mesh_patterns_test.cpp
        const Scene scene = make_pattern(info.id, 48, 40);
        if (scene.world) continue;
        Scene with_depth = scene;
        for (std::size_t k = 0; k < with_depth.shapes.size(); ++k) {
            with_depth.shapes[k].inv_depth = AffinePlane{k + 1.0, 0.0, 0.0};
        }
        for (const char* spec : {"box-multiscan:n=3", "box-multiscan:n=7", "gauss-multiscan",
                                 "gauss-multiscan:n=6,lut=0"}) {
            const MethodInstance m = make_method(spec);
            const Image a = render_scene(*m.method, scene);
            const Image b = render_scene(*m.method, with_depth);
            // box-multiscan sums a 2-D scene's simple rows change by change (the same terms
            // in another order, tests/subscanline_rows_test.cpp), the scanline visibility
            // line by line: equal up to float rounding there, bit for bit elsewhere.
            // gauss-multiscan takes every line of a 2-D scene change by change into difference
            // rows (tests/region_rows_test.cpp), the scanline visibility region by region:
            // equal up to float rounding everywhere.
            const bool whole_rows = std::string(spec).starts_with("box-multiscan") ||
                                    std::string(spec).starts_with("gauss-multiscan");
            int differ = 0;
            for (std::size_t k = 0; k < a.data.size(); ++k) {
                const float scale = std::max({1.0f, std::abs(a.data[k]), std::abs(b.data[k])});
                const float allowed = whole_rows ? kSumOrderUlps * FLT_EPSILON * scale : 0.0f;
                differ += !(std::abs(a.data[k] - b.data[k]) <= allowed);
            }
            EXPECT_EQ(differ, 0) << info.id << " / " << spec;
        }
    }
}

TEST(ScanlineVisibility, MethodsDeclareTheirOwnVisibility) {
    EXPECT_TRUE(make_method("box-multiscan").method->own_visibility());
    EXPECT_TRUE(make_method("gauss-multiscan").method->own_visibility());
    EXPECT_FALSE(make_method("cairo").method->own_visibility());
    EXPECT_FALSE(make_method("agg").method->own_visibility());
    EXPECT_FALSE(make_method("exact").method->own_visibility());
}

}  // namespace
}  // namespace aabench

namespace aabench {
namespace {

// Two rows of accumulation: the heap a box-multiscan render of a ScreenScene allocates grows
// with the width (the rows) and the edges (the active-edge list), never with width x height.
// The output image is the caller's (W x H x 4 bytes) and is not counted. Bytes allocated are
// an upper bound on the peak heap in use during the render.
TEST(ScanlineVisibility, BoxMultiscanMemoryIsTwoRowsNotTheImage) {
    const MethodInstance m = make_method("box-multiscan:n=3");
    std::vector<std::uint64_t> first_bytes;
    const int sizes[] = {256, 1024, 4096};
    // Run on a fresh thread each time so that the thread_local scratch starts empty: the bytes
    // are the cold render's, the most it ever allocates.
    for (const int size : sizes) {
        const Scene scene = make_pattern("room", size, size);
        const PreparedFrame world = PreparedFrame::prepare(scene);
        Image out(size, size);
        std::uint64_t cold = 0, warm = 0;
        std::thread([&] {
            const AllocCounts a = thread_alloc_counts();
            m.method->render(world.screen(), out);
            const AllocCounts b = thread_alloc_counts();
            m.method->render(world.screen(), out);
            const AllocCounts c = thread_alloc_counts();
            cold = b.bytes - a.bytes;
            warm = c.bytes - b.bytes;
        }).join();
        std::printf("box-multiscan:n=3 on room %dx%d (%zu shapes): %llu bytes allocated by the "
                    "first render on a thread, %llu by the second; the image is %llu bytes\n",
                    size, size, world.screen().shapes.size(),
                    static_cast<unsigned long long>(cold), static_cast<unsigned long long>(warm),
                    static_cast<unsigned long long>(4ull * size * size));
        EXPECT_EQ(warm, 0u) << "a warm render allocates nothing";
        first_bytes.push_back(cold);
    }
    // O(width): 16x the width may cost at most ~16x the bytes (plus the same edges); O(width x
    // height) would be 256x. 24 leaves room for vector growth steps.
    constexpr double kMaxGrowth = 24.0;
    EXPECT_LE(static_cast<double>(first_bytes[2]), kMaxGrowth * first_bytes[0]);
    // And far below one float image of the size.
    EXPECT_LT(first_bytes[2], 4ull * 4096 * 4096 / 100);
}

}  // namespace
}  // namespace aabench

namespace aabench {
namespace {

// Affine values (value_plane: depth images) in every method of the scanline and z-buffer
// families: a square covering the image and 5 px around it, v = 0.2 + 0.01 x + 0.02 y. Every
// one of these methods weighs samples (or line integrals) symmetrically about the pixel centre,
// and an affine function's symmetric average is its centre value: out(i, j) = v(i + 1/2,
// j + 1/2) up to float32 rounding (values <= 1.5: 1.5 * 2^-24 ~ 1e-7; 1e-6 leaves room for the
// double sums). With and without a depth plane (the z-buffer / NEXT path and the 2-D one).
TEST(ScanlineVisibility, AffineValuesGiveTheCentreValue) {
    constexpr double kAffineTolerance = 1e-6;
    for (const bool depth : {false, true}) {
        Scene scene;
        scene.width = 24;
        scene.height = 18;
        Shape square;
        square.contours = {{{-5, -5}, {29, -5}, {29, 23}, {-5, 23}}};
        square.value_plane = AffinePlane{0.2, 0.01, 0.02};
        if (depth) square.inv_depth = AffinePlane{0.5, 0.001, -0.002};
        scene.shapes.push_back(square);
        for (const char* spec : {"none", "ssaa", "ssaa:filter=gaussian", "ssaa:k=4,pattern=rgss",
                                 "nishita-d", "fast-edge", "box-multiscan", "box-multiscan:n=7",
                                 "gauss-multiscan", "gauss-multiscan:n=6,filter=cone,lut=0"}) {
            const Image out = render_scene(*make_method(spec).method, scene);
            for (int j = 0; j < scene.height; ++j) {
                for (int i = 0; i < scene.width; ++i) {
                    ASSERT_NEAR(out.at(i, j), square.value_plane->at(i + 0.5, j + 0.5),
                                kAffineTolerance)
                        << spec << (depth ? " with depth" : "") << " pixel (" << i << ", " << j
                        << ")";
                }
            }
        }
    }
}

}  // namespace
}  // namespace aabench
