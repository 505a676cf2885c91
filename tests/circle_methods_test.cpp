// The circle methods: aa-circle against an independent, literal implementation of its source's
// pseudo-code (docs/methods-circles.md; written here, sharing no code with methods/aa_circle.cpp)
// on every radius 0..300 and on the first octant of every radius to 1024; exact eight-way
// symmetry; the table's size against the source's formula; table and on-the-fly agree; the
// midpoint circle's pixels; "not applicable" as a declared capability.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <map>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "harness/world/frame.h"
#include "methods/aa_circle.h"
#include "methods/method.h"
#include "patterns/scene/curves.h"

namespace aabench {
namespace {

constexpr int kMaxTestedRadius = 300;

// ---- The source's pseudo-code, as written, with its setPixel recorded ----

struct SourceCircle {
    static constexpr int kAlphaMax = 255;
    int radius_max;
    std::vector<std::vector<int>> D;  // D[r][y], y from 1
    mutable int reads_past_table = 0;  // levels read past their row, over all octant() calls

    explicit SourceCircle(int rmax) : radius_max(rmax), D(rmax + 1) {
        for (int r = 1; r <= radius_max; r++) {
            D[r].assign(static_cast<int>(std::ceil(r / std::sqrt(2.0))) + 1, -1);
            for (int y = 1; y <= std::ceil(r / std::sqrt(2.0)); y++) {
                double xt = std::sqrt(static_cast<double>(r * r - y * y));  // 実数型
                D[r][y] = static_cast<int>(kAlphaMax * (std::ceil(xt) - xt));  // int d
            }
        }
    }

    // setPixel calls of the octant, (x, y, alpha).
    std::vector<std::array<int, 3>> octant(int r) const {
        std::vector<std::array<int, 3>> calls;
        if (r == 0) {  // the point, as the source suggests
            calls.push_back({0, 0, kAlphaMax});
            return calls;
        }
        int x = r;
        int y = 0;
        int d = 0;
        int d_old = 0;
        calls.push_back({x, y, kAlphaMax});
        while (y < x - 1) {
            y++;
            // Past the table's row (a missed step keeps x one column out, so the loop runs past
            // ceil(r / sqrt 2): r = 804 is the first at ALPHA_MAX = 255) the source reads beyond
            // its row; the method computes that level on the fly, and so does this copy.
            if (y < static_cast<int>(D.at(r).size())) {
                d = D[r][y];
            } else {
                ++reads_past_table;
                const double xt = std::sqrt(static_cast<double>(r * r - y * y));
                d = static_cast<int>(kAlphaMax * (std::ceil(xt) - xt));
            }
            if (d < d_old) {
                x--;
            }
            calls.push_back({x, y, kAlphaMax - d});
            calls.push_back({x - 1, y, d});
            d_old = d;
        }
        return calls;
    }
};

// The circle's image: each call mirrored eight ways about the centre pixel; a pixel set twice
// keeps the larger alpha; value = alpha / ALPHA_MAX over background 0.
Image source_image(const SourceCircle& src, int r, int size, int c) {
    std::map<std::pair<int, int>, int> alpha;
    for (const auto& [x, y, a] : src.octant(r)) {
        const std::pair<int, int> images[8] = {{x, y},  {-x, y}, {x, -y}, {-x, -y},
                                               {y, x},  {-y, x}, {y, -x}, {-y, -x}};
        for (const auto& [px, py] : images) {
            int& slot = alpha[{c + px, c + py}];
            slot = std::max(slot, a);
        }
    }
    Image img(size, size, 0.0f);
    for (const auto& [p, a] : alpha) {
        img.at(p.first, p.second) = static_cast<float>(a / static_cast<double>(SourceCircle::kAlphaMax));
    }
    return img;
}

// One grid circle of radius r about the centre pixel (c, c) of a size x size scene.
Scene one_circle(int r, int size, int c) {
    Scene s;
    s.width = size;
    s.height = size;
    const Point centre{c + 0.5, c + 0.5};
    s.shapes.push_back(r == 0 ? disc_shape(centre, 0.5, 1.0) : ring_shape(centre, r - 0.5, r + 0.5, 1.0));
    return s;
}

TEST(AaCircle, MatchesTheSourcePseudoCodePixelForPixel) {
    const SourceCircle src(kMaxTestedRadius);
    const MethodInstance m = make_method("aa-circle:alpha_max=255");
    for (int r = 0; r <= kMaxTestedRadius; ++r) {
        const int size = 2 * r + 3, c = r + 1;
        const Scene scene = one_circle(r, size, c);
        ASSERT_EQ(m.method->not_applicable(scene), "") << r;
        const Image got = render_scene(*m.method, scene);
        const Image want = source_image(src, r, size, c);
        for (int j = 0; j < size; ++j) {
            for (int i = 0; i < size; ++i) {
                ASSERT_EQ(got.at(i, j), want.at(i, j))
                    << fmt::format("r={} pixel ({}, {}): method {} source {}", r, i, j, got.at(i, j), want.at(i, j));
            }
        }
    }
}

// Every radius up to radius_max (the default table's 1024, not only the full images to 300 above):
// the first octant's window of each circle (a window origin puts it there, so a radius costs
// its octant, not its whole square) against the source, and the radii whose loop reads past
// the table, which docs/claims.md reports.
TEST(AaCircle, MatchesTheSourceOnTheOctantOfEveryRadiusToRadiusMax) {
    constexpr int kRadiusMax = 1024;  // aa-circle's default radius_max
    const SourceCircle src(kRadiusMax);
    const MethodInstance m = make_method("aa-circle");
    std::vector<int> past;
    for (int r = 1; r <= kRadiusMax; ++r) {
        const int before = src.reads_past_table;
        const auto calls = src.octant(r);
        if (src.reads_past_table > before) past.push_back(r);
        // The centre pixel is (0, 0); the window holds the octant's columns x0..r + 1 (x0 two
        // short of its diagonal end, through the window origin) and rows 0..ceil(r / sqrt 2) + 1.
        const int rows = static_cast<int>(std::ceil(r / std::sqrt(2.0)));
        const int x0 = std::max(0, static_cast<int>(std::floor(r / std::sqrt(2.0))) - 2);
        const int width = r + 2 - x0, height = rows + 2;
        Scene s;
        s.width = width;
        s.height = height;
        s.origin_x = x0;
        s.shapes.push_back(ring_shape({0.5, 0.5}, r - 0.5, r + 0.5, 1.0));
        const Image got = render_scene(*m.method, window_scene(s));
        Image want(width, height, 0.0f);
        for (const auto& [x, y, a] : calls) {
            // The octant and its mirror in the diagonal: the pixels this window holds.
            for (const auto& [px, py] : {std::pair{x, y}, std::pair{y, x}}) {
                if (px < x0 || py < 0 || px - x0 >= width || py >= height) continue;
                float& slot = want.at(px - x0, py);
                slot = std::max(slot, static_cast<float>(a / static_cast<double>(SourceCircle::kAlphaMax)));
            }
        }
        ASSERT_EQ(got.data, want.data) << "r=" << r;
    }
    EXPECT_EQ(past, (std::vector<int>{804, 988, 1012}));
}

TEST(AaCircle, EightWaySymmetryIsExact) {
    for (const char* spec : {"aa-circle", "aa-circle:alpha_max=0", "aa-circle:alpha_max=65535", "wu-circle", "midpoint-circle"}) {
        const MethodInstance m = make_method(spec);
        for (int r = 0; r <= kMaxTestedRadius; r += (r < 40 ? 1 : 13)) {
            const int size = 2 * r + 3, c = r + 1;
            const Image img = render_scene(*m.method, one_circle(r, size, c));
            for (int j = 0; j < size; ++j) {
                for (int i = 0; i < size; ++i) {
                    const float v = img.at(i, j);
                    const int x = i - c, y = j - c;
                    ASSERT_EQ(v, img.at(c - x, j)) << spec << " r=" << r;          // mirror in x
                    ASSERT_EQ(v, img.at(i, c - y)) << spec << " r=" << r;          // mirror in y
                    ASSERT_EQ(v, img.at(c + y, c + x)) << spec << " r=" << r;      // the diagonal
                }
            }
        }
    }
}

TEST(AaCircle, TableSizeIsTheSourcesFormula) {
    // sum over r = 1..R of ceil(r / sqrt 2) = sqrt(2) R^2 / 4 + O(R): each ceil adds less than
    // one and the sum of r / sqrt 2 is R (R + 1) / (2 sqrt 2), so the difference is in [0, R].
    for (int R : {1, 10, 100, 300, 1024, 4096}) {
        const double formula = std::sqrt(2.0) * R * R / 4.0;
        const double entries = static_cast<double>(aa_circle_table_entries(R));
        EXPECT_GE(entries, formula) << R;
        EXPECT_LE(entries, formula + R) << R;
    }
    EXPECT_EQ(aa_circle_table_entries(0), 0u);
}

TEST(AaCircle, TableAndOnTheFlyDrawTheSame) {
    const MethodInstance table = make_method("aa-circle:radius_max=4096");
    const MethodInstance fly = make_method("aa-circle:radius_max=0");
    for (int r = 0; r <= kMaxTestedRadius; r += 7) {
        const Scene scene = one_circle(r, 2 * r + 3, r + 1);
        EXPECT_EQ(render_scene(*table.method, scene).data, render_scene(*fly.method, scene).data) << r;
    }
}

TEST(AaCircle, InkPerRowIsOneInTheOctant) {
    // The source's rule: the two pixels of a row share one unit of ink (ALPHA_MAX - d + d).
    const MethodInstance m = make_method("aa-circle:alpha_max=0");
    const int r = 100, size = 2 * r + 3, c = r + 1;
    const Image img = render_scene(*m.method, one_circle(r, size, c));
    for (int y = 1; y < 60; ++y) {  // rows well inside the octant (r / sqrt 2 = 70.7)
        double ink = 0.0;
        for (int x = c + 40; x < size; ++x) ink += img.at(x, c + y);
        EXPECT_NEAR(ink, 1.0, 1e-6) << y;  // float32 alphas: 2 ulps
    }
}

TEST(MidpointCircle, EveryPixelIsWithinHalfAPixelOfTheCircle) {
    const MethodInstance m = make_method("midpoint-circle");
    for (int r = 1; r <= 120; ++r) {
        const int size = 2 * r + 3, c = r + 1;
        const Image img = render_scene(*m.method, one_circle(r, size, c));
        int lit = 0;
        for (int j = 0; j < size; ++j) {
            for (int i = 0; i < size; ++i) {
                if (img.at(i, j) == 0.0f) continue;
                ASSERT_EQ(img.at(i, j), 1.0f);
                ++lit;
                // The midpoint rule keeps |x^2 + y^2 - r^2| <= r (within half a pixel radially).
                const double d2 = std::pow(i - c, 2) + std::pow(j - c, 2);
                ASSERT_LE(std::abs(d2 - r * r), r) << fmt::format("r={} ({}, {})", r, i, j);
            }
        }
        EXPECT_GE(lit, 4 * r) << r;  // at least one pixel per row of each of the 8 octants / 2
    }
}

TEST(CircleMethods, DeclareWhatTheyCannotDraw) {
    Scene polygon;
    polygon.width = polygon.height = 8;
    polygon.shapes.push_back({{{{1, 1}, {5, 1}, {5, 5}}}, 1.0});
    Scene off_centre = one_circle(3, 9, 4);
    off_centre.shapes[0] = ring_shape({4.25, 4.5}, 2.5, 3.5, 1.0);
    Scene wide = one_circle(3, 9, 4);
    wide.shapes[0] = ring_shape({4.5, 4.5}, 2.0, 3.5, 1.0);
    for (const char* spec : {"aa-circle", "wu-circle", "midpoint-circle"}) {
        const MethodInstance m = make_method(spec);
        for (const Scene* s : {&polygon, &off_centre, &wide}) {
            EXPECT_NE(m.method->not_applicable(*s), "") << spec;
            const Image img = render_scene(*m.method, *s);
            for (float v : img.data) ASSERT_TRUE(std::isnan(v)) << spec;  // never a silent number
        }
        EXPECT_EQ(m.method->not_applicable(one_circle(0, 3, 1)), "") << spec;
    }
    EXPECT_EQ(make_method("exact").method->not_applicable(polygon), "");
}

}  // namespace
}  // namespace aabench
