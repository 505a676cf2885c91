// The mesh patterns (patterns/models.cpp; docs/patterns.md, "Mesh models"): each reads its
// Debian package's model, passes check_world, frames the model, records its parameters, and is
// refused in one line naming the package where the file is missing. The suites that loop over
// every pattern leave these out (PatternInfo::model_file); this is their test.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "harness/world/frame.h"
#include "harness/world/plan.h"
#include "input_error_of.h"
#include "methods/method.h"
#include "patterns/pattern.h"
#include "patterns/scene/mesh_file.h"
#include "patterns/world_builders.h"

namespace aabench {
namespace {

struct ModelCase {
    const char* id;
    const char* file;
    const char* package;
};

constexpr ModelCase kModels[] = {
    {"bunny", "/usr/share/glmark2/models/bunny.obj", "glmark2-data"},
    {"horse", "/usr/share/glmark2/models/horse.3ds", "glmark2-data"},
    {"engine", "/usr/share/assimp/models/glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb",
     "assimp-testmodels"},
    {"truck", "/usr/share/assimp/models/glTF/CesiumMilkTruck/CesiumMilkTruck.gltf",
     "assimp-testmodels"},
};
// Every one is a real model: thousands of triangles at least.
constexpr std::size_t kMinModelTriangles = 1000;
constexpr int kWidth = 64, kHeight = 48;

bool available(const ModelCase& m) {
    return mesh_loading_available() && std::filesystem::exists(m.file);
}

TEST(MeshPatterns, AreTheModelPatternsOfTheRegistry) {
    std::vector<std::string> ids;
    for (const PatternInfo& info : pattern_registry()) {
        if (!info.model_file) continue;
        ids.push_back(info.id);
        EXPECT_FALSE(info.in_default_run) << info.id;
    }
    EXPECT_EQ(ids, (std::vector<std::string>{"bunny", "horse", "engine", "truck"}));
}

TEST(MeshPatterns, EachFramesItsModelOnTheGroundUnderOneLight) {
    int checked = 0;
    for (const ModelCase& m : kModels) {
        SCOPED_TRACE(m.id);
        if (!available(m)) {
            const std::string e = error_of([&] { make_pattern(m.id, kWidth, kHeight); });
            EXPECT_NE(e.find(m.package), std::string::npos) << e;
            continue;
        }
        const Scene scene = make_pattern(m.id, kWidth, kHeight);
        ASSERT_TRUE(scene.world.has_value());
        const World& w = *scene.world;
        EXPECT_EQ(error_of([&] { check_world(w, m.id); }), "");
        const Object& model = w.objects[0];
        EXPECT_EQ(model.mesh.file, m.file);
        EXPECT_GE(model.faces.size(), kMinModelTriangles);
        ASSERT_EQ(w.lights.size(), 1u);
        EXPECT_FALSE(w.lights[0].shadows);  // shadows=off by default: docs/patterns.md
        // Every vertex of the model above the ground (y = 0) and in view.
        int outside = 0;
        for (const glm::dvec3& v : model.vertices) {
            EXPECT_GT(v.y, 0.0);
            const glm::dvec2 p = project_point(w.camera, kWidth, kHeight, v);
            outside += p.x < 0 || p.x > kWidth || p.y < 0 || p.y > kHeight;
        }
        EXPECT_EQ(outside, 0);
        // Deterministic, every parameter recorded, and the plan names the mesh.
        EXPECT_TRUE(scene == make_pattern(m.id, kWidth, kHeight));
        for (const char* key : {"azimuth_deg", "elevation_deg", "light_azimuth_deg",
                                "light_elevation_deg", "shadows"}) {
            bool found = false;
            for (const auto& [k, v] : scene.metadata) found = found || k == key;
            EXPECT_TRUE(found) << key;
        }
        const Plan plan = make_plan(scene);
        ASSERT_EQ(plan.notes.size(), 1u);
        EXPECT_NE(plan.notes[0].find(m.file), std::string::npos) << plan.notes[0];
        EXPECT_FALSE(plan.in(Stage::kShadows));
        // With shadows the one light casts them (the plan decides from the scene alone).
        const Scene shadowed = make_pattern(fmt::format("{}:shadows=on", m.id), kWidth, kHeight);
        EXPECT_TRUE(shadowed.world->lights[0].shadows);
        EXPECT_TRUE(make_plan(shadowed).in(Stage::kShadows));
        ++checked;
    }
    if (checked == 0) GTEST_SKIP() << "no model package installed";
}

// The bunny through the world stages and `exact` at a small size: every pixel finite, the
// model hiding itself (visibility in).
TEST(MeshPatterns, TheBunnyRendersThroughTheWorldStages) {
    if (!available(kModels[0])) GTEST_SKIP() << "glmark2-data not installed";
    const Scene scene = make_pattern("bunny", 40, 32);
    const PreparedFrame frame = PreparedFrame::prepare(scene);
    const MethodInstance exact = make_method("exact");
    const Image image = render_scene(*exact.method, frame.input_for(*exact.method));
    int finite = 0;
    for (const float v : image.data) finite += std::isfinite(v);
    EXPECT_EQ(finite, 40 * 32);
    EXPECT_TRUE(frame.plan().in(Stage::kVisibility));
}

}  // namespace
}  // namespace aabench
