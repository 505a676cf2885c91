// Worlds a user could write that would make a stage compute a non-finite value: refused, in one
// line naming where, never an image with NaN or infinity in it.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "harness/reference/box_reference.h"
#include "harness/world/frame.h"
#include "methods/method.h"
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

// A square at the edge of the documented coordinate range (z = -1e100, x, y = +-1e99): its
// Newell normal reaches 4e198 per component, whose squared length overflowed and left a zero
// normal ("turns add up to 0 degrees"). Accepted, and drawn finite by a method and the
// reference: a square 8.8 px across in the view's middle (its half-angle is atan(0.1)).
TEST(HostileWorlds, ASquareAtTheEdgeOfTheCoordinateRangeIsDrawn) {
    const std::string text = R"({ "version": 2, "width": 32, "height": 32,
      "camera": { "eye": [0, 0, 0], "target": [0, 0, -1], "fov_y_deg": 40 },
      "objects": [ { "name": "far", "closed": false,
          "vertices": [[-1e99, -1e99, -1e100], [1e99, -1e99, -1e100], [1e99, 1e99, -1e100],
                       [-1e99, 1e99, -1e100]],
          "faces": [ { "loop": [0, 1, 2, 3] } ] } ] })";
    const Scene scene = parse_scene_json(text, "huge.json");
    const PreparedFrame frame = PreparedFrame::prepare(scene);
    ASSERT_EQ(frame.screen().shapes.size(), 1u);
    const Coverage reference = box_reference(frame.pieces());
    double covered = 0.0;
    for (const double v : reference.data) {
        ASSERT_TRUE(std::isfinite(v));
        covered += v;
    }
    // Half-width 16 px * 0.1 / tan(20 deg) = 4.3959 px: (8.7918 px)^2 = 77.298 px^2 (value 1
    // on background 0).
    constexpr double kExpectedAreaPx2 = 77.298;
    constexpr double kAreaTolerance = 1e-3;  // the figure above is rounded to 5 digits
    EXPECT_NEAR(covered, kExpectedAreaPx2, kAreaTolerance);
    const MethodInstance none = make_method("none");
    Image out(scene.width, scene.height);
    none.method->render(frame.input_for(*none.method), out);
    for (const float v : out.data) EXPECT_TRUE(std::isfinite(v));
}

// Past the reader (a World built in code) a face with coordinates near 1e300 makes its normal
// overflow: the projection stage stops with one line naming itself and the face instead of
// handing on a NaN frame.
TEST(HostileWorlds, EveryStageChecksItsOutputIsFinite) {
    Scene scene = parse_scene_json(floor_scene("0.5, 0, 0.25"), "floor.json");
    scene.world->lights.clear();
    for (glm::dvec3& v : scene.world->objects[0].vertices) v *= 1e300;
    try {
        PreparedFrame::prepare(scene);
        ADD_FAILURE() << "a face with an overflowing normal was projected";
    } catch (const InputError& e) {
        const std::string what = e.what();
        EXPECT_EQ(what.rfind("projection: objects[0].faces[0]: ", 0), 0u) << what;
        EXPECT_EQ(what.find('\n'), std::string::npos) << what;
    }
}

}  // namespace
}  // namespace aabench
