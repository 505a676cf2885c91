// The `foliage` pattern (patterns/foliage.cpp): deterministic, its parameters checked with
// one-line errors, its leaves as documented (count, size against the count, in the box), and
// every method of the registry drawing it with finite values, shadows on and off. The geometry
// checks every 3-D pattern shares (planar convex faces, in view, no pixel-aligned edge) are in
// patterns3d_test.cpp.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include <fmt/format.h>

#include "harness/reference/box_reference.h"
#include "harness/world/frame.h"
#include "methods/method.h"
#include "patterns/pattern.h"

namespace aabench {
namespace {

// The leaf box of foliage.cpp's layout, grown by the largest leaf's half-length (0.2 world
// units at the minimum 100 leaves: 0.2 * sqrt(2) = 0.283), since a leaf's tip may poke out.
constexpr double kBoxX = 2.2 + 0.29, kBoxY = 1.6 + 0.29, kBoxZNear = 2.0 + 0.29,
                 kBoxZFar = -2.0 - 0.29;
// Rounding of a leaf's half-length computed from its vertices (~1e-16 relative).
constexpr double kLengthTolerance = 1e-12;

double half_length(const Object& leaves, const Face& face) {
    return 0.5 * glm::length(leaves.vertices[face.loop[0]] - leaves.vertices[face.loop[2]]);
}

TEST(Foliage, IsDeterministicAndTheSeedChangesTheArrangement) {
    const Scene a = make_pattern("foliage", 64, 48), b = make_pattern("foliage", 64, 48);
    EXPECT_TRUE(a == b);
    const Scene other = make_pattern("foliage:seed=2", 64, 48);
    ASSERT_TRUE(other.world.has_value());
    EXPECT_NE(a.world->objects[1].vertices, other.world->objects[1].vertices);
    // The first 100 leaves do not depend on how many follow them.
    const Scene more = make_pattern("foliage:leaves=300", 64, 48);
    const Scene fewer = make_pattern("foliage:leaves=100", 64, 48);
    for (int f = 0; f < 100; ++f) {
        const Object& m = more.world->objects[1];
        const Object& l = fewer.world->objects[1];
        // Same centre (the first draw of the leaf's stream), a scaled size.
        const glm::dvec3 cm = 0.5 * (m.vertices[4 * f] + m.vertices[4 * f + 2]);
        const glm::dvec3 cl = 0.5 * (l.vertices[4 * f] + l.vertices[4 * f + 2]);
        EXPECT_NEAR(glm::length(cm - cl), 0.0, kLengthTolerance) << f;
    }
}

TEST(Foliage, LeavesCountAndShrinkAsOneOverTheirSquareRoot) {
    for (const int count : {100, 200, 1000, 10000}) {
        const Scene scene = make_pattern(fmt::format("foliage:leaves={}", count), 32, 32);
        const World& w = *scene.world;
        ASSERT_EQ(w.objects.size(), 2u);
        EXPECT_EQ(w.objects[0].name, "backdrop");
        const Object& leaves = w.objects[1];
        EXPECT_FALSE(leaves.closed);  // two-sided: a leaf is seen from both sides
        ASSERT_EQ(leaves.faces.size(), static_cast<std::size_t>(count));
        const double expected = 0.2 * std::sqrt(200.0 / count);
        for (const Face& face : leaves.faces) {
            ASSERT_EQ(face.loop.size(), 4u);
            EXPECT_NEAR(half_length(leaves, face), expected, kLengthTolerance) << count;
            EXPECT_TRUE(face.reflectance >= 0.35 && face.reflectance < 0.85) << face.reflectance;
        }
        for (const glm::dvec3& v : leaves.vertices) {
            EXPECT_TRUE(std::abs(v.x) <= kBoxX && std::abs(v.y) <= kBoxY && v.z <= kBoxZNear &&
                        v.z >= kBoxZFar)
                << count << ": " << v.x << " " << v.y << " " << v.z;
        }
        EXPECT_NO_THROW(check_world(w, "foliage"));
    }
}

TEST(Foliage, ShadowsAreAnOption) {
    EXPECT_FALSE(make_pattern("foliage", 32, 32).world->lights.at(0).shadows);
    EXPECT_TRUE(make_pattern("foliage:shadows=on", 32, 32).world->lights.at(0).shadows);
}

TEST(Foliage, ParametersOutOfRangeAreRefusedInOneLineNamingThem) {
    for (const char* spec : {"foliage:leaves=99", "foliage:leaves=100001", "foliage:leaves=1e3x",
                             "foliage:seed=0", "foliage:shadows=yes", "foliage:leafs=200"}) {
        try {
            (void)make_pattern(spec, 32, 32);
            ADD_FAILURE() << spec << " was accepted";
        } catch (const InputError& e) {
            const std::string what = e.what();
            EXPECT_EQ(what.find('\n'), std::string::npos) << what;
            EXPECT_NE(what.find("foliage"), std::string::npos) << what;
        }
    }
}

// Every method at its defaults that applies to polygons draws the pattern (what its traits
// take: the ScreenScene, the overlay or the visible pieces) with finite values beside the
// finite reference; shadows on and off. Small, so that the whole registry runs in seconds.
TEST(Foliage, EveryMethodRendersFiniteValues) {
    // Overshoot a sharpening filter may add to values in [0, 1] (Gaussian lobes are positive,
    // but a post-process pass or a method's own filter might ring slightly).
    constexpr double kRangeSlack = 0.5;
    for (const char* spec : {"foliage:leaves=100", "foliage:leaves=300,shadows=on"}) {
        const Scene scene = make_pattern(spec, 24, 20);
        const PreparedFrame frame = PreparedFrame::prepare(scene);
        for (const double v : box_reference(frame.pieces()).data) {
            ASSERT_TRUE(std::isfinite(v)) << spec;
        }
        for (const MethodInfo& info : method_registry()) {
            const MethodInstance m = make_method(info.id);
            const SceneInput input = frame.input_for(*m.method);
            // The circle methods draw only circles; on leaves they say why not, as the
            // comparison's rows do, and draw nothing.
            if (!m.method->not_applicable(input.scene()).empty()) continue;
            Image out(scene.width, scene.height);
            m.method->render(input, out);
            for (const float v : out.data) {
                ASSERT_TRUE(std::isfinite(v)) << spec << " " << m.spec;
                ASSERT_TRUE(v >= -kRangeSlack && v <= 1.0 + kRangeSlack)
                    << spec << " " << m.spec << ": " << v;
            }
        }
    }
}

}  // namespace
}  // namespace aabench
