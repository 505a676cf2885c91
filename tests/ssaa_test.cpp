// ssaa: k = 1 is `none` bit for bit; k x k box sampling against the exact box reference (a
// sound bound on half-planes, a measured one on the patterns); k = 2 is exact on half-pixel
// squares; the sampling loop against a slow per-point winding count; the Gaussian variant's
// normalisation and symmetry; parameter ranges; the rgss and msaa sample patterns (positions,
// counts, coverage against the Vulkan table on half-planes, the Gaussian over them).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cfloat>
#include <cmath>
#include <numbers>
#include <random>
#include <set>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "harness/measure/compare.h"
#include "harness/measure/metrics.h"
#include "harness/reference/box_reference.h"
#include "methods/method.h"
#include "methods/scan/kernel/edge_table.h"
#include "methods/scan/sampling/run_sums.h"
#include "methods/scan/sampling/sample_patterns.h"
#include "patterns/pattern.h"
#include "test_scenes.h"

namespace aabench {
namespace {

// Output is float32 rounded once from double sums of at most a few thousand terms in [0, 1]:
// the double sums are good to ~1e-13, the float rounding to 2^-24 relative, and the exact
// reference to 1e-12. One float32 ulp at 1.0 covers all of it.
constexpr double kFloatSlack = FLT_EPSILON;
// ssaa:k=16 on the patterns at 96 x 80: the largest RMSE measured against the exact box
// reference was 0.0057 (grating, the pattern with the most edge pixels); the bound leaves
// margin for other compilers' rounding of the pattern geometry and nothing more.
constexpr double kPatternRmseBoundK16 = 0.01;

std::vector<Scene> patterns(int width, int height) {
    std::vector<Scene> scenes;
    for (const PatternInfo& p : pattern_registry()) {
        if (p.model_file) continue;  // tests/mesh_patterns_test.cpp
        scenes.push_back(make_pattern(p.id, width, height));
    }
    return scenes;
}

TEST(Ssaa, K1IsNoneBitForBit) {
    const MethodInstance none = make_method("none");
    const MethodInstance ssaa = make_method("ssaa:k=1");
    auto check = [&](const Scene& scene, const std::string& what) {
        const Image a = render_scene(*none.method, scene);
        const Image b = render_scene(*ssaa.method, scene);
        for (int j = 0; j < scene.height; ++j) {
            for (int i = 0; i < scene.width; ++i) {
                ASSERT_EQ(a.at(i, j), b.at(i, j))
                    << fmt::format("{} pixel ({}, {}): none {} ssaa:k=1 {}", what, i, j,
                                   a.at(i, j), b.at(i, j));
            }
        }
    };
    for (std::uint64_t seed = 1; seed <= 200; ++seed) {
        check(testing::random_scene(seed, 23, 17, true), fmt::format("seed {}", seed));
    }
    for (const PatternInfo& p : pattern_registry()) {
        if (p.model_file) continue;  // tests/mesh_patterns_test.cpp
        check(make_pattern(p.id, 64, 48), p.id);
    }
}

// A sound bound for a pixel crossed by one straight edge: on each sample row the covered part
// of the pixel is one interval ending at the pixel border, so the k samples count its length
// to within half a sample spacing, 1/(2k); and the covered length L(y) is monotone in y, so the
// midpoint rule over k rows errs by at most (L(1) - L(0))/(2k) <= 1/(2k). Total 1/k
// (docs/methods-sampling.md, "ssaa error bound").
TEST(Ssaa, BoxWithinOneOverKOfExactOnHalfPlanes) {
    for (int k : {3, 5, 16}) {
        const MethodInstance m = make_method(fmt::format("ssaa:k={}", k));
        const double bound = 1.0 / k + kFloatSlack;
        for (std::uint64_t seed = 1; seed <= 100; ++seed) {
            const Scene scene = testing::random_half_plane(seed, 24, 20);
            const Coverage exact = box_reference(scene);
            const Image out = render_scene(*m.method, scene);
            for (int j = 0; j < scene.height; ++j) {
                for (int i = 0; i < scene.width; ++i) {
                    const double err = std::abs(out.at(i, j) - exact.at(i, j));
                    ASSERT_TRUE(err <= bound) << fmt::format(
                        "{} seed {} pixel ({}, {}): ssaa {} exact {} (bound {})", m.spec, seed,
                        i, j, out.at(i, j), exact.at(i, j), bound);
                }
            }
        }
    }
}

TEST(Ssaa, K16CloseToExactOnPatterns) {
    const MethodInstance m = make_method("ssaa:k=16");
    for (const Scene& scene : patterns(96, 80)) {
        const ErrorStats stats =
            compare_to_reference(render_scene(*m.method, scene), box_reference(scene));
        EXPECT_TRUE(stats.rmse <= kPatternRmseBoundK16)
            << fmt::format("{} on {}: rmse {} (bound {}), max {} at ({}, {})", m.spec,
                           scene.metadata.front().second, stats.rmse, kPatternRmseBoundK16,
                           stats.max_abs, stats.max_x, stats.max_y);
    }
}

// With k = 2 the samples sit at the centres of the four half-pixel cells, so a scene of
// squares on the half-pixel grid is sampled exactly: each sample stands for the one cell it is
// the centre of, and the cell is wholly inside or outside every square.
TEST(Ssaa, K2ExactOnHalfPixelSquares) {
    const MethodInstance m = make_method("ssaa:k=2");
    for (std::uint64_t seed = 1; seed <= 50; ++seed) {
        std::mt19937_64 rng(seed);
        std::uniform_real_distribution<double> v(0.0, 1.0);
        Scene scene;
        scene.width = 16;
        scene.height = 12;
        scene.background = v(rng);
        for (int s = 0; s < 12; ++s) {
            const double x = static_cast<int>(rng() % 40) / 2.0 - 2.0;
            const double y = static_cast<int>(rng() % 32) / 2.0 - 2.0;
            const double side = (1 + static_cast<int>(rng() % 6)) / 2.0;
            scene.shapes.push_back(
                {{{{x, y}, {x + side, y}, {x + side, y + side}, {x, y + side}}}, v(rng)});
        }
        const Coverage exact = box_reference(scene);
        const Image out = render_scene(*m.method, scene);
        for (int j = 0; j < scene.height; ++j) {
            for (int i = 0; i < scene.width; ++i) {
                ASSERT_NEAR(out.at(i, j), exact.at(i, j), kFloatSlack)
                    << fmt::format("seed {} pixel ({}, {}): ssaa:k=2 {} exact {}", seed, i, j,
                                   out.at(i, j), exact.at(i, j));
            }
        }
    }
}

// Differential: the shared sampling loop (edge table, sorted crossings, incremental winding)
// against a slow count of every edge at every sample point. Vertices are not on a grid, so no
// sample lies on an edge and the tie rule plays no part.
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

TEST(Ssaa, BoxMatchesSlowPointSampling) {
    for (int k : {2, 3, 5}) {
        const MethodInstance m = make_method(fmt::format("ssaa:k={}", k));
        for (std::uint64_t seed = 1; seed <= 30; ++seed) {
            Scene scene = testing::random_scene(seed, 14, 11, true);
            for (Shape& s : scene.shapes) {
                for (Contour& c : s.contours) {
                    for (Point& p : c) p = {p.x + 1e-3 * std::sin(7.0 * seed + p.y), p.y + 1e-3};
                }
            }
            const Image out = render_scene(*m.method, scene);
            for (int j = 0; j < scene.height; ++j) {
                for (int i = 0; i < scene.width; ++i) {
                    double sum = 0.0;
                    for (int b = 0; b < k; ++b) {
                        for (int a = 0; a < k; ++a) {
                            sum += slow_value_at(scene, i + (a + 0.5) / k, j + (b + 0.5) / k);
                        }
                    }
                    const double want = sum / (k * k);
                    ASSERT_NEAR(out.at(i, j), want, kFloatSlack) << fmt::format(
                        "{} seed {} pixel ({}, {}): ssaa {} slow {}", m.spec, seed, i, j,
                        out.at(i, j), want);
                }
            }
        }
    }
}

// On a flat scene whose values are multiples of one power of two, the box on the grid is summed
// from the run ends of the sample rows (methods/scan/sampling/run_sums.h); the same scene with its
// values as constant planes is summed sample by sample, in the order the method always used. The
// two images must be the same bit for bit (the integer sums are exact, and so are those of
// doubles).
TEST(Ssaa, RunSumsEqualPerSampleSumsBitForBit) {
    std::vector<Scene> scenes;
    for (std::uint64_t seed = 1; seed <= 12; ++seed) {
        scenes.push_back(
            testing::with_dyadic_values(testing::random_scene(seed, 23, 17, true), seed));
    }
    scenes.push_back(make_pattern("star", 48, 40));
    // Rows the sampler takes in one pass (PointSampler::sample_rows_changes), most of them.
    scenes.push_back(make_pattern("grating", 40, 36));
    scenes.push_back(make_pattern("rings", 44, 44));
    for (const int k : {1, 2, 3, 5}) {
        const MethodInstance m = make_method(fmt::format("ssaa:k={}", k));
        for (std::size_t n = 0; n < scenes.size(); ++n) {
            const Image by_runs = render_scene(*m.method, scenes[n]);
            const Image by_samples =
                render_scene(*m.method, testing::with_constant_planes(scenes[n]));
            for (std::size_t p = 0; p < by_runs.data.size(); ++p) {
                ASSERT_EQ(std::bit_cast<std::uint32_t>(by_runs.data[p]),
                          std::bit_cast<std::uint32_t>(by_samples.data[p]))
                    << fmt::format("{} scene {} pixel {}: {} against {}", m.spec, n, p,
                                   by_runs.data[p], by_samples.data[p]);
            }
        }
    }
}

TEST(Ssaa, DyadicValuesAreIntegersInOneUnit) {
    auto of = [](double background, std::vector<double> values) {
        Scene scene;
        scene.width = scene.height = 4;
        scene.background = background;
        for (const double v : values) {
            Shape shape;
            shape.value = v;
            shape.contours.push_back({{0, 0}, {2, 0}, {2, 2}});
            scene.shapes.push_back(shape);
        }
        EdgeTable table;
        table.reset(scene, RowBuckets::kOnDemand);
        return DyadicValues::of(table);
    };
    const DyadicValues binary = of(0.0, {1.0});
    EXPECT_TRUE(binary.exact);
    EXPECT_EQ(binary.exponent, 0);
    EXPECT_EQ(binary.max_units, 1);
    const DyadicValues quarters = of(0.25, {3.0, -0.5});
    EXPECT_TRUE(quarters.exact);
    EXPECT_EQ(quarters.exponent, -2);
    EXPECT_EQ(quarters.max_units, 12);
    EXPECT_EQ(quarters.units(-0.5), -2);
    EXPECT_FALSE(quarters.nonnegative);
    EXPECT_FALSE(of(0.0, {0.3}).exact);                   // 53 significant bits
    EXPECT_FALSE(of(1.0, {std::ldexp(1.0, -30)}).exact);  // 2^30 units: more than 2^20
    EXPECT_FALSE(of(0.0, {NAN}).exact);
}

TEST(SsaaGaussian, ConstantSceneGivesItsValue) {
    // One shape covering the image and the one-pixel margin the filter reads.
    Scene scene;
    scene.width = 9;
    scene.height = 7;
    scene.background = 0.2;
    scene.shapes.push_back({{{{-3, -3}, {12, -3}, {12, 10}, {-3, 10}}}, 0.7});
    for (int k : {1, 2, 3, 5}) {
        for (double sigma : {0.3, 0.5, 2.0}) {
            const MethodInstance m =
                make_method(fmt::format("ssaa:k={},filter=gaussian,sigma={}", k, sigma));
            const Image out = render_scene(*m.method, scene);
            for (std::size_t n = 0; n < out.data.size(); ++n) {
                ASSERT_NEAR(out.data[n], 0.7, kFloatSlack) << m.spec << " pixel " << n;
            }
        }
    }
}

// The weights depend on the distance from the pixel centre only, and the sample lattice is
// symmetric under x -> w - x, y -> h - y and x <-> y: so is the image. Vertices off any grid
// keep samples off edges (the tie rule is not symmetric).
Scene mirrored(const Scene& scene, bool mirror_x, bool mirror_y, bool transpose) {
    Scene out = scene;
    if (transpose) std::swap(out.width, out.height);
    for (Shape& s : out.shapes) {
        for (Contour& c : s.contours) {
            for (Point& p : c) {
                if (mirror_x) p.x = scene.width - p.x;
                if (mirror_y) p.y = scene.height - p.y;
                if (transpose) std::swap(p.x, p.y);
            }
        }
    }
    return out;
}

TEST(SsaaGaussian, SymmetricUnderMirrorsAndTranspose) {
    // Different summation orders of the same weighted sum: a few double ulps, at most one
    // float32 rounding step apart.
    constexpr double kSymmetryTolerance = kFloatSlack;
    for (int k : {2, 3, 4}) {
        const MethodInstance m = make_method(fmt::format("ssaa:k={},filter=gaussian", k));
        for (std::uint64_t seed = 1; seed <= 20; ++seed) {
            Scene scene = testing::random_scene(seed, 13, 10, true);
            for (Shape& s : scene.shapes) {
                for (Contour& c : s.contours) {
                    for (Point& p : c) p = {p.x + 0.0123 * std::sin(seed + p.y), p.y + 0.0071};
                }
            }
            const Image base = render_scene(*m.method, scene);
            for (int variant = 1; variant < 8; ++variant) {
                const bool mx = variant & 1, my = variant & 2, tr = variant & 4;
                const Image img = render_scene(*m.method, mirrored(scene, mx, my, tr));
                for (int j = 0; j < scene.height; ++j) {
                    for (int i = 0; i < scene.width; ++i) {
                        int x = mx ? scene.width - 1 - i : i, y = my ? scene.height - 1 - j : j;
                        if (tr) std::swap(x, y);
                        ASSERT_NEAR(base.at(i, j), img.at(x, y), kSymmetryTolerance)
                            << fmt::format("{} seed {} variant {} pixel ({}, {}): {} vs {}",
                                           m.spec, seed, variant, i, j, base.at(i, j),
                                           img.at(x, y));
                    }
                }
            }
        }
    }
}

// One lit sample: a tiny square around the sample point (x, y) (side 0.02 < 1/k, edges through
// no sample). Each pixel then shows that sample's weight in its own window, which is computed
// here independently: exp(-r^2 / 2 sigma^2) over the sum of the same over every sample of the
// 3 x 3 pixel neighbourhood with r <= 1 (the circle itself included).
TEST(SsaaGaussian, ResponseToOneSampleIsItsNormalisedWeight) {
    const double sigma = 0.5;
    auto g = [&](double r2) { return std::exp(-r2 / (2.0 * sigma * sigma)); };
    for (int k : {1, 2, 3, 5}) {
        const std::string spec = fmt::format("ssaa:k={},filter=gaussian,sigma={}", k, sigma);
        double total = 0.0;
        for (int b = -k; b < 2 * k; ++b) {
            for (int a = -k; a < 2 * k; ++a) {
                const double dx = (a + 0.5) / k - 0.5, dy = (b + 0.5) / k - 0.5;
                // Decided in integers (units of 1/(2k)), as on the circle doubles may round.
                const long long u = 2LL * a + 1 - k, v = 2LL * b + 1 - k;
                if (u * u + v * v <= 4LL * k * k) total += g(dx * dx + dy * dy);
            }
        }
        // The sample (a, b) = (k/2, k/2) of pixel (3, 2): for odd k the pixel centre.
        const int a = k / 2, b = k / 2;
        const double x = 3 + (a + 0.5) / k, y = 2 + (b + 0.5) / k;
        Scene scene;
        scene.width = 8;
        scene.height = 6;
        scene.shapes.push_back({{{{x - 0.01, y - 0.01}, {x + 0.01, y - 0.01},
                                  {x + 0.01, y + 0.01}, {x - 0.01, y + 0.01}}},
                                1.0});
        const Image out = render_scene(*make_method(spec).method, scene);
        for (int j = 0; j < scene.height; ++j) {
            for (int i = 0; i < scene.width; ++i) {
                const double dx = x - (i + 0.5), dy = y - (j + 0.5);
                const long long u = std::llround(2.0 * k * dx), v = std::llround(2.0 * k * dy);
                const double want =
                    u * u + v * v <= 4LL * k * k ? g(dx * dx + dy * dy) / total : 0.0;
                ASSERT_NEAR(out.at(i, j), want, kFloatSlack) << fmt::format(
                    "{} pixel ({}, {}): got {} want {}", spec, i, j, out.at(i, j), want);
            }
        }
    }
}

TEST(SsaaGaussian, ReferenceFilterNamesItsGaussian) {
    EXPECT_EQ(make_method("ssaa").method->filter().text(), "box");
    EXPECT_EQ(make_method("ssaa:filter=gaussian").method->filter().text(),
              "gaussian:sigma=0.5,radius=1");
    EXPECT_EQ(make_method("ssaa:filter=gaussian,sigma=0.75").method->filter().text(),
              "gaussian:sigma=0.75,radius=1");
}

TEST(Ssaa, OutOfRangeParametersNameTheRange) {
    for (const char* spec : {"ssaa:k=0", "ssaa:k=65"}) {
        try {
            make_method(spec);
            FAIL() << spec << ": no error";
        } catch (const InputError& e) {
            EXPECT_NE(std::string(e.what()).find("1..64"), std::string::npos) << e.what();
        }
    }
    try {
        make_method("ssaa:filter=cone");
        FAIL() << "filter=cone: no error";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("box|gaussian"), std::string::npos) << e.what();
    }
    EXPECT_THROW(make_method("ssaa:sigma=0"), InputError);
    EXPECT_EQ(make_method("ssaa").spec, "ssaa:k=3,filter=box,sigma=0.5,pattern=grid");
}

// ---- Sample patterns: pattern=rgss and pattern=msaa ----

// The Vulkan specification's "Standard sample locations" table (positions from the pixel's
// top-left corner, y down), typed here from the Vulkan form so that it shares nothing with
// methods/scan/sampling/sample_patterns.cpp, which holds the Direct3D form (offsets from the centre
// in 1/16 px).
const std::vector<std::vector<std::array<double, 2>>>& vulkan_standard_locations() {
    static const std::vector<std::vector<std::array<double, 2>>> table = {
        {{0.75, 0.75}, {0.25, 0.25}},
        {{0.375, 0.125}, {0.875, 0.375}, {0.125, 0.625}, {0.625, 0.875}},
        {{0.5625, 0.3125}, {0.4375, 0.6875}, {0.8125, 0.5625}, {0.3125, 0.1875},
         {0.1875, 0.8125}, {0.0625, 0.4375}, {0.6875, 0.9375}, {0.9375, 0.0625}},
        {{0.5625, 0.5625}, {0.4375, 0.3125}, {0.3125, 0.625}, {0.75, 0.4375},
         {0.1875, 0.375}, {0.625, 0.8125}, {0.8125, 0.6875}, {0.6875, 0.1875},
         {0.375, 0.875}, {0.5, 0.0625}, {0.25, 0.125}, {0.125, 0.75},
         {0.0, 0.5}, {0.9375, 0.25}, {0.875, 0.9375}, {0.0625, 0.0}},
    };
    return table;
}

TEST(SsaaPatterns, StandardPositionsAreTheTablesInsideThePixel) {
    ASSERT_EQ(vulkan_standard_locations().size(), kStandardMsaaCounts.size());
    for (std::size_t c = 0; c < kStandardMsaaCounts.size(); ++c) {
        const int n = kStandardMsaaCounts[c];
        const SamplePattern p = standard_msaa_pattern(n);
        ASSERT_EQ(p.size(), static_cast<std::size_t>(n));
        for (std::size_t s = 0; s < p.size(); ++s) {
            // Inside the half-open pixel: 16x has samples on the left and top borders.
            EXPECT_TRUE(p.x(s) >= 0.0 && p.x(s) < 1.0) << n << " sample " << s;
            EXPECT_TRUE(p.y(s) >= 0.0 && p.y(s) < 1.0) << n << " sample " << s;
            // Multiples of 1/16: exact in double, so equality is the test.
            EXPECT_EQ(p.x(s), vulkan_standard_locations()[c][s][0]) << n << " sample " << s;
            EXPECT_EQ(p.y(s), vulkan_standard_locations()[c][s][1]) << n << " sample " << s;
        }
    }
    EXPECT_THROW(standard_msaa_pattern(3), std::invalid_argument);
}

TEST(SsaaPatterns, RotatedGridIsKSquaredRooksOnARotatedSquareGrid) {
    for (int k = 1; k <= 9; ++k) {
        const SamplePattern p = rotated_grid_pattern(k);
        ASSERT_EQ(p.size(), static_cast<std::size_t>(k * k));
        std::set<int> columns, rows;
        for (std::size_t s = 0; s < p.size(); ++s) {
            EXPECT_TRUE(p.x(s) > 0.0 && p.x(s) < 1.0) << k;
            EXPECT_TRUE(p.y(s) > 0.0 && p.y(s) < 1.0) << k;
            columns.insert(p.offsets[s][0]);
            rows.insert(p.offsets[s][1]);
        }
        // n-rooks: every sample in its own column and row of the k^2 x k^2 sub-grid.
        EXPECT_EQ(columns.size(), p.size()) << k;
        EXPECT_EQ(rows.size(), p.size()) << k;
        // A square grid: sample (a, b) is index a k + b; its steps along a and b are
        // orthogonal and of equal length.
        if (k < 2) continue;
        const auto step = [&](std::size_t from, std::size_t to) {
            return std::array<long long, 2>{p.offsets[to][0] - p.offsets[from][0],
                                            p.offsets[to][1] - p.offsets[from][1]};
        };
        const auto along_b = step(0, 1), along_a = step(0, k);
        EXPECT_EQ(along_a[0] * along_b[0] + along_a[1] * along_b[1], 0) << k;
        EXPECT_EQ(along_a[0] * along_a[0] + along_a[1] * along_a[1],
                  along_b[0] * along_b[0] + along_b[1] * along_b[1])
            << k;
    }
    // k = 2 is the classic 4x RGSS: the standard 4x positions.
    const SamplePattern rgss = rotated_grid_pattern(2), msaa = standard_msaa_pattern(4);
    ASSERT_EQ(rgss.size(), msaa.size());
    for (std::size_t s = 0; s < rgss.size(); ++s) {
        EXPECT_EQ(rgss.x(s), msaa.x(s)) << s;  // eighths and sixteenths: exact in double
        EXPECT_EQ(rgss.y(s), msaa.y(s)) << s;
    }
}

// Each standard count against the Vulkan table's positions, counted by the slow winding
// sampler on random half-planes (random lines: no sample lies on one). The output is a count
// over n, n a power of two: exact in float.
TEST(SsaaPatterns, MsaaIsTheCoverageOfTheStandardPositionsOnHalfPlanes) {
    for (std::size_t c = 0; c < kStandardMsaaCounts.size(); ++c) {
        const int n = kStandardMsaaCounts[c];
        const MethodInstance m = make_method(fmt::format("ssaa:pattern=msaa,k={}", n));
        for (std::uint64_t seed = 1; seed <= 40; ++seed) {
            const Scene scene = testing::random_half_plane(seed, 12, 10);
            const Image out = render_scene(*m.method, scene);
            for (int j = 0; j < scene.height; ++j) {
                for (int i = 0; i < scene.width; ++i) {
                    double inside = 0.0;
                    for (const auto& [x, y] : vulkan_standard_locations()[c]) {
                        inside += slow_value_at(scene, i + x, j + y);
                    }
                    ASSERT_EQ(out.at(i, j), static_cast<float>(inside / n)) << fmt::format(
                        "{} seed {} pixel ({}, {})", m.spec, seed, i, j);
                }
            }
        }
    }
}

TEST(SsaaPatterns, MsaaTakesOnlyTheStandardCounts) {
    for (const char* spec : {"ssaa:pattern=msaa,k=1", "ssaa:pattern=msaa,k=3",
                             "ssaa:pattern=msaa,k=32"}) {
        try {
            make_method(spec);
            FAIL() << spec << ": no error";
        } catch (const InputError& e) {
            EXPECT_NE(std::string(e.what()).find("2, 4, 8 or 16"), std::string::npos) << e.what();
        }
    }
    EXPECT_NO_THROW(make_method("ssaa:pattern=msaa,k=16"));
}

// The Gaussian over any pattern: against a slow weighted sum with weights computed here in
// double (r^2 <= 1 inclusive, normalised over the samples inside), on random scenes with
// vertices off the sample grid.
TEST(SsaaPatterns, GaussianOverAPatternMatchesASlowWeightedSum) {
    for (const char* spec : {"ssaa:pattern=rgss,k=3,filter=gaussian,sigma=0.6",
                             "ssaa:pattern=msaa,k=8,filter=gaussian"}) {
        const MethodInstance m = make_method(spec);
        const SamplePattern p = m.params.get_choice("pattern") == "msaa"
                                    ? standard_msaa_pattern(m.params.get_int("k"))
                                    : rotated_grid_pattern(m.params.get_int("k"));
        const double sigma = m.params.get_real("sigma");
        for (std::uint64_t seed = 1; seed <= 10; ++seed) {
            Scene scene = testing::random_scene(seed, 12, 9, true);
            for (Shape& s : scene.shapes) {
                for (Contour& c : s.contours) {
                    for (Point& q : c) q = {q.x + 1e-3 * std::sin(5.0 * seed + q.y), q.y + 1e-3};
                }
            }
            const Image out = render_scene(*m.method, scene);
            for (int j = 0; j < scene.height; ++j) {
                for (int i = 0; i < scene.width; ++i) {
                    double sum = 0.0, total = 0.0;
                    for (int dj = -1; dj <= 1; ++dj) {
                        for (int di = -1; di <= 1; ++di) {
                            for (std::size_t s = 0; s < p.size(); ++s) {
                                const double x = i + di + p.x(s), y = j + dj + p.y(s);
                                const double r2 = (x - i - 0.5) * (x - i - 0.5) +
                                                  (y - j - 0.5) * (y - j - 0.5);
                                if (r2 > 1.0) continue;
                                const double w = std::exp(-r2 / (2 * sigma * sigma));
                                sum += w * slow_value_at(scene, x, y);
                                total += w;
                            }
                        }
                    }
                    ASSERT_NEAR(out.at(i, j), sum / total, kFloatSlack) << fmt::format(
                        "{} seed {} pixel ({}, {})", spec, seed, i, j);
                }
            }
        }
    }
}

TEST(SsaaPatterns, EmptySceneAndAlignedSquareAreExact) {
    for (const char* spec : {"ssaa:pattern=rgss,k=2", "ssaa:pattern=msaa,k=16",
                             "ssaa:pattern=msaa,k=4,filter=gaussian"}) {
        const MethodInstance m = make_method(spec);
        Scene scene;
        scene.width = 9;
        scene.height = 7;
        scene.background = 0.25;
        for (float v : render_scene(*m.method, scene).data) ASSERT_EQ(v, 0.25f) << spec;
        if (m.params.get_choice("filter") == "gaussian") continue;
        // Pixels [2, 6] x [1, 4]: samples on the square's left or top border are in it, on its
        // right or bottom border out (the tie rule), so box filtering is exact.
        scene.shapes.push_back({{{{2, 1}, {6, 1}, {6, 4}, {2, 4}}}, 1.0});
        const Image out = render_scene(*m.method, scene);
        for (int j = 0; j < scene.height; ++j) {
            for (int i = 0; i < scene.width; ++i) {
                const float want = (i >= 2 && i < 6 && j >= 1 && j < 4) ? 1.0f : 0.25f;
                ASSERT_EQ(out.at(i, j), want) << fmt::format("{} pixel ({}, {})", spec, i, j);
            }
        }
    }
}

TEST(SsaaPatterns, CompareSweepOfMsaaRunsOnlyTheStandardCounts) {
    CompareOptions options;
    options.method_specs = {"ssaa:pattern=msaa,k=4", "ssaa"};
    options.pattern_specs = {"star"};
    options.width = options.height = 16;
    options.runs = 1;
    options.sweep = true;
    options.symptoms = false;
    options.keep_images = false;
    std::vector<double> msaa_k;
    int grid_rows = 0;
    for (const ResultRow& r : run_comparison(options).rows) {
        if (r.method.find("pattern=msaa") != std::string::npos) msaa_k.push_back(r.cost_value);
        grid_rows += r.method.find("pattern=grid") != std::string::npos;
    }
    std::sort(msaa_k.begin(), msaa_k.end());
    EXPECT_EQ(msaa_k, (std::vector<double>{2, 4, 8, 16}));
    EXPECT_EQ(grid_rows, 7);  // k in {1, 2, 3, 4, 5, 8, 16}, as before
}

}  // namespace
}  // namespace aabench
