// Scene file version 2: a rich world round-trips bit for bit, defaults fill what a file
// leaves out, and every way a file can be wrong is one InputError naming its JSON path.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "patterns/pattern.h"
#include "patterns/scene/scene_io.h"

namespace aabench {
namespace {

using Json = nlohmann::ordered_json;
constexpr const char* kSource = "v2.json";

// A unit cube (closed, faces counter-clockwise from outside), a floor quad with a pattern,
// both light types, edges and effects.
Json valid() {
    return Json::parse(R"({
      "version": 2, "width": 64, "height": 48, "background": 0.25,
      "camera": {"eye": [3, 2.5, 4], "target": [0, 0.3, 0], "up": [0, 1, 0], "fov_y_deg": 45,
                 "near": 0.05},
      "ambient": 0.2,
      "lights": [{"type": "parallel", "direction": [-1, -2, -1.5], "intensity": 0.8,
                  "shadows": true},
                 {"type": "point", "position": [2, 4, 3], "intensity": 12}],
      "objects": [
        {"name": "cube", "closed": true,
         "vertices": [[0,0,0],[1,0,0],[1,1,0],[0,1,0],[0,0,1],[1,0,1],[1,1,1],[0,1,1]],
         "faces": [{"loop": [0,3,2,1]}, {"loop": [4,5,6,7], "reflectance": 0.5},
                   {"loop": [0,1,5,4]}, {"loop": [3,7,6,2], "mirror": 0.25},
                   {"loop": [0,4,7,3]}, {"loop": [1,2,6,5]}]},
        {"name": "floor", "closed": false,
         "vertices": [[-3,0,3],[3,0,3],[3,0,-3],[-3,0,-3]],
         "faces": [{"loop": [0,1,2,3], "reflectance": 0.7,
                    "patterns": [{"loop": [[-1,0,1],[1,0,1],[1,0,-1],[-1,0,-1]],
                                  "reflectance": 0.1}]}]}
      ],
      "edges": {"contour": "prewitt", "crease": "laplacian4", "kp": 8, "kl": 3,
                "style": "white-convex", "contour_weight": 0.9, "crease_weight": 0.4},
      "effects": {"shadows": false, "reflections": false}
    })");
}

Scene parse(const Json& j) { return parse_scene_json(j.dump(), kSource); }

TEST(SceneIoV2, ReadsEveryKey) {
    const Scene s = parse(valid());
    ASSERT_TRUE(s.world.has_value());
    const World& w = *s.world;
    EXPECT_EQ(w.camera.fov_y_deg, 45.0);
    EXPECT_EQ(w.camera.near, 0.05);
    ASSERT_EQ(w.lights.size(), 2u);
    EXPECT_EQ(w.lights[0].type, LightType::kParallel);
    EXPECT_TRUE(w.lights[0].shadows);
    EXPECT_EQ(w.lights[1].type, LightType::kPoint);
    EXPECT_FALSE(w.lights[1].shadows);  // default
    EXPECT_EQ(w.lights[1].position, glm::dvec3(2, 4, 3));
    ASSERT_EQ(w.objects.size(), 2u);
    EXPECT_EQ(w.objects[0].faces[0].reflectance, 1.0);  // default
    EXPECT_EQ(w.objects[0].faces[3].mirror, 0.25);
    EXPECT_FALSE(w.objects[1].closed);
    ASSERT_EQ(w.objects[1].faces[0].patterns.size(), 1u);
    ASSERT_TRUE(w.edges.has_value());
    EXPECT_EQ(w.edges->contour, "prewitt");
    EXPECT_EQ(w.edges->style, "white-convex");
    EXPECT_FALSE(w.effects.shadows);
    EXPECT_TRUE(w.effects.patterns);  // default
    EXPECT_TRUE(s.shapes.empty());
}

TEST(SceneIoV2, DefaultsFillWhatTheFileLeavesOut) {
    Json j = valid();
    j["camera"].erase("up");
    j["camera"].erase("fov_y_deg");
    j["camera"].erase("near");
    j.erase("ambient");
    j.erase("lights");
    j.erase("edges");
    j.erase("effects");
    const World w = *parse(j).world;
    const World defaults;
    EXPECT_EQ(w.camera.up, defaults.camera.up);
    EXPECT_EQ(w.camera.fov_y_deg, defaults.camera.fov_y_deg);
    EXPECT_EQ(w.camera.near, defaults.camera.near);
    EXPECT_EQ(w.ambient, 0.0);
    EXPECT_TRUE(w.lights.empty());
    EXPECT_FALSE(w.edges.has_value());
    EXPECT_EQ(w.effects, EffectSwitches{});
}

TEST(SceneIoV2, WrittenWorldsReadBackBitForBit) {
    const Scene s = parse(valid());
    EXPECT_EQ(parse_scene_json(scene_to_json(s), kSource), s);
    for (const char* id : {"room", "blocks", "interpenetrate", "mesh", "terrain"}) {
        const Scene p = make_pattern(id, 40, 30);
        const Scene back = parse_scene_json(scene_to_json(p), id);
        EXPECT_EQ(back, p) << id;
    }
    // A 2-D scene is still written as version 1.
    EXPECT_NE(scene_to_json(make_pattern("star", 16, 16)).find("\"version\": 1"),
              std::string::npos);
}

TEST(SceneIoV2, AVersion2FileWithoutObjectsIsA2DScene) {
    const Json j = Json::parse(R"({"version": 2, "width": 8, "height": 8,
        "shapes": [{"type": "polygon", "value": 1, "contours": [[[1,1],[5,1],[5,5]]]}]})");
    const Scene s = parse(j);
    EXPECT_FALSE(s.world.has_value());
    EXPECT_EQ(s.shapes.size(), 1u);
}

struct Bad {
    std::string what;
    std::function<void(Json&)> mutate;
    std::string expected;  // the message after "v2.json: "
};

std::vector<Bad> bad_files() {
    auto face = [](Json& j, int o, int f) -> Json& { return j["objects"][o]["faces"][f]; };
    return {
        {"unknown top key", [](Json& j) { j["colour"] = 1; }, "colour: unknown key"},
        {"unknown camera key", [](Json& j) { j["camera"]["zoom"] = 2; }, "camera.zoom: unknown key"},
        {"unknown object key", [](Json& j) { j["objects"][0]["mass"] = 2; },
         "objects[0].mass: unknown key"},
        {"unknown face key", [&](Json& j) { face(j, 0, 1)["colour"] = 2; },
         "objects[0].faces[1].colour: unknown key"},
        {"unknown light key", [](Json& j) { j["lights"][0]["position"] = {1, 2, 3}; },
         "lights[0].position: unknown key"},
        {"camera missing", [](Json& j) { j.erase("camera"); }, "camera: required key is missing"},
        {"eye not a point", [](Json& j) { j["camera"]["eye"] = {1, 2}; },
         "camera.eye: expected a point [x, y, z]"},
        {"eye a string", [](Json& j) { j["camera"]["eye"][1] = "2"; },
         "camera.eye: expected a point [x, y, z]"},
        {"eye at target", [](Json& j) { j["camera"]["eye"] = {0, 0.3, 0}; },
         "camera.target: equals camera.eye"},
        {"up parallel to view", [](Json& j) { j["camera"]["up"] = {3, 2.2, 4}; },
         "camera.up: is parallel to the view direction"},
        {"up zero", [](Json& j) { j["camera"]["up"] = {0, 0, 0}; }, "camera.up: has zero length"},
        {"fov out of range", [](Json& j) { j["camera"]["fov_y_deg"] = 180; },
         "camera.fov_y_deg: 180 is outside (0, 180)"},
        {"near not positive", [](Json& j) { j["camera"]["near"] = 0; },
         "camera.near: 0 is not > 0"},
        {"ambient a string", [](Json& j) { j["ambient"] = "low"; },
         "ambient: expected a finite number"},
        {"lights not an array", [](Json& j) { j["lights"] = Json::object(); },
         "lights: expected an array of lights"},
        {"unknown light type", [](Json& j) { j["lights"][1]["type"] = "spot"; },
         "lights[1].type: expected one of \"parallel\", \"point\""},
        {"zero direction", [](Json& j) { j["lights"][0]["direction"] = {0, 0, 0}; },
         "lights[0].direction: has zero length"},
        {"point light without position", [](Json& j) { j["lights"][1].erase("position"); },
         "lights[1].position: required key is missing"},
        {"shadows not a boolean", [](Json& j) { j["lights"][0]["shadows"] = 1; },
         "lights[0].shadows: expected true or false"},
        {"index out of range", [&](Json& j) { face(j, 0, 1)["loop"][2] = 9; },
         "objects[0].faces[1].loop[2]: index 9 out of range (the object has 8 vertices)"},
        {"negative index", [&](Json& j) { face(j, 0, 1)["loop"][0] = -1; },
         "objects[0].faces[1].loop[0]: expected a vertex index"},
        {"two indices", [&](Json& j) { face(j, 0, 0)["loop"] = {0, 1}; },
         "objects[0].faces[0].loop: a face needs at least 3 vertices, found 2"},
        {"repeated index", [&](Json& j) { face(j, 0, 0)["loop"] = {0, 3, 2, 3}; },
         "objects[0].faces[0].loop[3]: vertex 3 appears twice"},
        {"non-planar face", [](Json& j) { j["objects"][0]["vertices"][6] = {1, 1, 1.2}; },
         "objects[0].faces[1].loop: the face is not planar"},
        {"non-convex face",
         [](Json& j) {
             j["objects"][1]["vertices"][1] = {-1, 0, 0};  // pulled inside: a reflex corner
         },
         "objects[1].faces[0].loop: the face is not convex"},
        {"zero-area face", [](Json& j) { j["objects"][1]["vertices"] = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}}; },
         "objects[1].faces[0].loop: the face has zero area"},
        {"pattern off its plane",
         [&](Json& j) { face(j, 1, 0)["patterns"][0]["loop"][2] = {1, 0.5, -1}; },
         "objects[1].faces[0].patterns[0].loop[2]: lies"},
        {"non-convex pattern",
         [&](Json& j) {
             face(j, 1, 0)["patterns"][0]["loop"] = {{-1, 0, 1}, {1, 0, 1}, {0, 0, 0.5}, {1, 0, -1}, {-1, 0, -1}};
         },
         "objects[1].faces[0].patterns[0].loop: the pattern is not convex"},
        {"pattern without reflectance", [&](Json& j) { face(j, 1, 0)["patterns"][0].erase("reflectance"); },
         "objects[1].faces[0].patterns[0].reflectance: required key is missing"},
        {"vertex not finite-shaped", [](Json& j) { j["objects"][0]["vertices"][2] = {1, 1}; },
         "objects[0].vertices[2]: expected a point [x, y, z]"},
        {"objects and shapes", [](Json& j) { j["shapes"] = Json::array(); },
         "shapes: a file has objects (3-D) or shapes (2-D), not both"},
        {"3-D keys without objects", [](Json& j) { j.erase("objects"); },
         "camera: belongs to a 3-D scene"},
        {"bad contour operator", [](Json& j) { j["edges"]["contour"] = "canny"; },
         "edges.contour: expected one of \"sobel\", \"prewitt\""},
        {"bad crease operator", [](Json& j) { j["edges"]["crease"] = "log"; },
         "edges.crease: expected one of"},
        {"bad style", [](Json& j) { j["edges"]["style"] = "white"; }, "edges.style: expected one of"},
        {"unknown effect", [](Json& j) { j["effects"]["fog"] = false; }, "effects.fog: unknown key"},
        {"effect not a boolean", [](Json& j) { j["effects"]["shading"] = 0; },
         "effects.shading: expected true or false"},
        {"origin on a 3-D scene", [](Json& j) { j["origin"] = {1, 2}; },
         "origin: a 3-D scene has no window origin"},
        {"version 3", [](Json& j) { j["version"] = 3; }, "version: unsupported version 3"},
    };
}

TEST(SceneIoV2, EveryErrorIsOneLineNamingItsPath) {
    for (const Bad& b : bad_files()) {
        SCOPED_TRACE(b.what);
        Json j = valid();
        b.mutate(j);
        try {
            parse(j);
            ADD_FAILURE() << "accepted";
        } catch (const InputError& e) {
            const std::string message = e.what();
            const std::string expected = std::string(kSource) + ": " + b.expected;
            EXPECT_EQ(message.substr(0, expected.size()), expected) << message;
            EXPECT_EQ(message.find('\n'), std::string::npos) << message;
        }
    }
}

}  // namespace
}  // namespace aabench
