// Worlds a user could write that would make a stage compute a non-finite value: refused, in one
// line naming where, never an image with NaN or infinity in it.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "harness/world/frame.h"
#include "patterns/scene/scene_io.h"

namespace aabench {
namespace {

// A 2 x 2 floor square lit by one point light at `light` (x y z, JSON text).
std::string floor_scene(const std::string& light) {
    return R"({ "version": 2, "width": 32, "height": 32,
      "camera": { "eye": [0, 1, 4], "target": [0, 0, 0], "up": [0, 1, 0], "fov_y_deg": 40 },
      "lights": [ { "type": "parallel", "direction": [0, -1, 0], "intensity": 0.5 },
                  { "type": "point", "position": [)" +
           light + R"(], "intensity": 5 } ],
      "objects": [ { "name": "floor", "closed": false,
          "vertices": [[-1, 0, -1], [1, 0, -1], [1, 0, 1], [-1, 0, 1]],
          "faces": [ { "loop": [3, 2, 1, 0] } ] } ] })";
}

TEST(HostileWorlds, PointLightAtAFacesCentroidIsRefusedByTheReader) {
    try {
        parse_scene_json(floor_scene("0, 0, 0"), "floor.json");
        ADD_FAILURE() << "a point light at the centroid was accepted";
    } catch (const InputError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("lights[1].position"), std::string::npos) << what;
        EXPECT_NE(what.find("objects[0].faces[0]"), std::string::npos) << what;
        EXPECT_EQ(what.find('\n'), std::string::npos) << what;
    }
    // On the face's plane but away from its centroid: the cosine is 0, the value finite.
    const Scene beside = parse_scene_json(floor_scene("0.5, 0, 0.25"), "floor.json");
    const PreparedFrame frame = PreparedFrame::prepare(beside);
    for (const Shape& s : frame.screen().shapes) EXPECT_TRUE(std::isfinite(s.value)) << s.value;
}

// A World built in code skips the reader: the shading stage itself refuses, naming the stage,
// the face and the light.
TEST(HostileWorlds, TheShadingStageRefusesANonFiniteIlluminance) {
    Scene scene = parse_scene_json(floor_scene("0.5, 0, 0.25"), "floor.json");
    scene.world->lights[1].position = {0.0, 0.0, 0.0};  // the floor's centroid
    try {
        PreparedFrame::prepare(scene);
        ADD_FAILURE() << "the shading stage accepted an infinite falloff";
    } catch (const InputError& e) {
        const std::string what = e.what();
        EXPECT_EQ(what.rfind("shading: objects[0].faces[0]: lights[1]", 0), 0u) << what;
    }
}

}  // namespace
}  // namespace aabench
