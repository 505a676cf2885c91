// ssaa's Halton and listed sample positions: halton_positions is the Halton (2, 3) sequence
// from index 1; pattern=halton and positions=... are the box (and Gaussian) means of the slow
// winding sampler at exactly those points; a listed position at the centre is `none`, the
// standard 4x positions listed are pattern=msaa,k=4 bit for bit; bad lists are one-line
// InputErrors naming the item; the specs recorded before these parameters stay the same.
#include <gtest/gtest.h>

#include <array>
#include <set>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "methods/method.h"
#include "methods/scan/sampling/sample_patterns.h"
#include "patterns/pattern.h"
#include "test_scenes.h"

namespace aabench {
namespace {

// halton_pattern's integer offsets against its double positions: the offset is exact, the
// position the nearest double to the same rational, so they differ by at most an ulp of 1.
constexpr double kPositionUlp = 1e-15;

TEST(HaltonPositions, AreTheRadicalInversesInBasesTwoAndThreeFromIndexOne) {
    const std::vector<std::array<double, 2>> want = {
        {1.0 / 2, 1.0 / 3}, {1.0 / 4, 2.0 / 3}, {3.0 / 4, 1.0 / 9},
        {1.0 / 8, 4.0 / 9}, {5.0 / 8, 7.0 / 9}, {3.0 / 8, 2.0 / 9},
        {7.0 / 8, 5.0 / 9}, {1.0 / 16, 8.0 / 9}, {9.0 / 16, 1.0 / 27}};
    const std::vector<std::array<double, 2>> got = halton_positions(9);
    ASSERT_EQ(got.size(), want.size());
    for (std::size_t s = 0; s < want.size(); ++s) {
        // One division each side: the nearest double to the same rational.
        EXPECT_EQ(got[s][0], want[s][0]) << s;
        EXPECT_EQ(got[s][1], want[s][1]) << s;
    }
    // A prefix is the shorter sequence (taa takes position t mod n of halton_positions(n)).
    const std::vector<std::array<double, 2>> first_four(got.begin(), got.begin() + 4);
    EXPECT_EQ(halton_positions(4), first_four);
    EXPECT_TRUE(halton_positions(0).empty());
}

TEST(HaltonPositions, PatternHoldsTheSamePointsInsideThePixelAllDistinct) {
    for (int n : {1, 2, 7, 16, 63, kMaxHaltonSamples}) {
        const SamplePattern p = halton_pattern(n);
        const std::vector<std::array<double, 2>> positions = halton_positions(n);
        ASSERT_EQ(p.size(), static_cast<std::size_t>(n));
        std::set<std::array<int, 2>> distinct;
        for (std::size_t s = 0; s < p.size(); ++s) {
            EXPECT_EQ(p.x(s), positions[s][0]) << n << " sample " << s;
            EXPECT_EQ(p.y(s), positions[s][1]) << n << " sample " << s;
            EXPECT_TRUE(p.x(s) > 0.0 && p.x(s) < 1.0) << n << " sample " << s;
            EXPECT_TRUE(p.y(s) > 0.0 && p.y(s) < 1.0) << n << " sample " << s;
            EXPECT_NEAR(0.5 + static_cast<double>(p.offsets[s][0]) / p.denominator, p.x(s),
                        kPositionUlp);
            EXPECT_NEAR(0.5 + static_cast<double>(p.offsets[s][1]) / p.denominator, p.y(s),
                        kPositionUlp);
            distinct.insert(p.offsets[s]);
        }
        EXPECT_EQ(distinct.size(), p.size()) << n;
    }
}

// The slow reference: the winding number of every edge of every shape at the point, topmost
// shape first (the half-open rules of methods/scan/sampling/point_sampling.h).
double slow_value_at(const Scene& scene, double x, double y) {
    for (int s = static_cast<int>(scene.shapes.size()) - 1; s >= 0; --s) {
        int winding = 0;
        for (const Contour& c : scene.shapes[s].contours) {
            for (std::size_t k = 0; k < c.size(); ++k) {
                const Point a = c[k], b = c[(k + 1) % c.size()];
                if ((a.y <= y) == (b.y <= y)) continue;
                const double xc = a.x + (y - a.y) / (b.y - a.y) * (b.x - a.x);
                if (xc <= x) winding += a.y < b.y ? 1 : -1;
            }
        }
        if (winding != 0) return scene.shapes[s].value;
    }
    return scene.background;
}

// The box mean of n samples against the slow winding sampler at the same points, on random
// half-planes (0/1 values: the sum is an exact integer, divided once, so equality is the test).
void expect_box_mean_of(const std::string& spec, const std::vector<std::array<double, 2>>& points) {
    const MethodInstance m = make_method(spec);
    for (std::uint64_t seed = 1; seed <= 30; ++seed) {
        const Scene scene = testing::random_half_plane(seed, 11, 9);
        const Image out = render_scene(*m.method, scene);
        for (int j = 0; j < scene.height; ++j) {
            for (int i = 0; i < scene.width; ++i) {
                double inside = 0.0;
                for (const auto& [x, y] : points) inside += slow_value_at(scene, i + x, j + y);
                ASSERT_EQ(out.at(i, j), static_cast<float>(inside / points.size()))
                    << fmt::format("{} seed {} pixel ({}, {})", spec, seed, i, j);
            }
        }
    }
}

TEST(SsaaHalton, IsTheBoxMeanAtTheHaltonPoints) {
    for (int n : {1, 5, 16, 64}) {
        expect_box_mean_of(fmt::format("ssaa:pattern=halton,samples={}", n), halton_positions(n));
    }
}

TEST(SsaaPositions, IsTheBoxMeanAtTheListedPoints) {
    expect_box_mean_of("ssaa:positions=0.1/0.9;0.73/0.2;.5/0;0/0.25",
                       {{0.1, 0.9}, {0.73, 0.2}, {0.5, 0.0}, {0.0, 0.25}});
}

TEST(SsaaPositions, TheCentreAloneIsNoneBitForBit) {
    const MethodInstance none = make_method("none"), centre = make_method("ssaa:positions=0.5/0.5");
    for (const PatternInfo& p : pattern_registry()) {
        if (p.model_file) continue;  // tests/mesh_patterns_test.cpp
        const Scene scene = make_pattern(p.id, 40, 32);
        const Image a = render_scene(*none.method, scene), b = render_scene(*centre.method, scene);
        ASSERT_EQ(a.data, b.data) << p.id;
    }
}

// The same four points as pattern=msaa,k=4 (the standard positions in eighths): the same
// samples, the same sort, the same Gaussian weights (the same rationals, each rounded once).
TEST(SsaaPositions, TheStandardFourListedAreMsaaFourBitForBit) {
    const std::string listed = "positions=0.375/0.125;0.875/0.375;0.125/0.625;0.625/0.875";
    for (const std::string filter : {"box", "gaussian"}) {
        const MethodInstance a = make_method("ssaa:pattern=msaa,k=4,filter=" + filter);
        const MethodInstance b = make_method("ssaa:" + listed + ",filter=" + filter);
        for (const PatternInfo& p : pattern_registry()) {
            if (p.model_file) continue;  // tests/mesh_patterns_test.cpp
            const Scene scene = make_pattern(p.id, 40, 32);
            ASSERT_EQ(render_scene(*a.method, scene).data, render_scene(*b.method, scene).data)
                << p.id << " " << filter;
        }
    }
}

TEST(SsaaPositions, BadListsNameTheItem) {
    const std::vector<std::pair<std::string, std::string>> cases = {
        {"ssaa:positions=0.5", "item 1 '0.5'"},
        {"ssaa:positions=0.5/0.5;1/0.5", "item 2 '1/0.5'"},
        {"ssaa:positions=0.5/0.5;", "item 2 ''"},
        {"ssaa:positions=0.5/-0.1", "item 1"},
        {"ssaa:positions=0.123456789/0", "at most 8 digits"},
        {"ssaa:positions=0.5/0.5/0.5", "item 1"},
        {"ssaa:pattern=rgss,positions=0.5/0.5", "replaces pattern=rgss"},
        {"ssaa:pattern=halton,samples=65", "samples=65 is not an integer in 1..64"},
        {"ssaa:pattern=halton,samples=0", "samples=0 is not"},
        {"ssaa:samples=x", "samples=x is not"},
    };
    for (const auto& [spec, want] : cases) {
        try {
            make_method(spec);
            ADD_FAILURE() << spec << ": no error";
        } catch (const InputError& e) {
            const std::string message = e.what();
            EXPECT_NE(message.find(want), std::string::npos) << spec << ": " << message;
            EXPECT_EQ(message.find('\n'), std::string::npos) << message;
        }
    }
}

TEST(SsaaPositions, SpecsRecordedBeforeStayTheSame) {
    // samples and positions are left out when not given: baselines and benchmark names keep
    // the spec they were recorded under.
    EXPECT_EQ(make_method("ssaa").spec, "ssaa:k=3,filter=box,sigma=0.5,pattern=grid");
    EXPECT_EQ(make_method("ssaa:pattern=halton,samples=8").spec,
              "ssaa:k=3,filter=box,sigma=0.5,pattern=halton,samples=8");
    // A listed spec reads back as itself.
    const std::string listed = make_method("ssaa:positions=0.25/0.75;0.5/.5").spec;
    EXPECT_EQ(listed, "ssaa:k=3,filter=box,sigma=0.5,pattern=grid,positions=0.25/0.75;0.5/.5");
    EXPECT_EQ(make_method(listed).spec, listed);
}

}  // namespace
}  // namespace aabench
