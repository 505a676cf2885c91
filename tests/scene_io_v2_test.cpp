// Scene file version 2: a rich world round-trips bit for bit, defaults fill what a file
// leaves out, the example files read, the geometry checks accept rounded geometry and refuse
// real defects, and every way a file can be wrong is one InputError naming its JSON path.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <functional>
#include <glm/gtc/matrix_transform.hpp>
#include <limits>
#include <nlohmann/json.hpp>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "input_error_of.h"
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

std::string read_text(const std::string& relative) {
    std::ifstream in(std::string(AABENCH_SOURCE_DIR) + "/" + relative, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

TEST(SceneIoV2, ReadsEveryKey) {
    const Scene s = parse(valid());
    ASSERT_TRUE(s.world.has_value());
    const World& w = *s.world;
    EXPECT_EQ(s.width, 64);
    EXPECT_EQ(s.background, 0.25);
    EXPECT_EQ(w.camera.eye, glm::dvec3(3, 2.5, 4));
    EXPECT_EQ(w.camera.fov_y_deg, 45.0);
    EXPECT_EQ(w.camera.near, 0.05);
    EXPECT_EQ(w.ambient, 0.2);
    ASSERT_EQ(w.lights.size(), 2u);
    EXPECT_EQ(w.lights[0].type, LightType::kParallel);
    EXPECT_EQ(w.lights[0].direction, glm::dvec3(-1, -2, -1.5));
    EXPECT_EQ(w.lights[0].intensity, 0.8);
    EXPECT_TRUE(w.lights[0].shadows);
    EXPECT_EQ(w.lights[1].type, LightType::kPoint);
    EXPECT_EQ(w.lights[1].position, glm::dvec3(2, 4, 3));
    ASSERT_EQ(w.objects.size(), 2u);
    EXPECT_EQ(w.objects[0].name, "cube");
    EXPECT_EQ(w.objects[0].vertices.size(), 8u);
    EXPECT_EQ(w.objects[0].faces[1].loop, (std::vector<int>{4, 5, 6, 7}));
    EXPECT_EQ(w.objects[0].faces[1].reflectance, 0.5);
    EXPECT_EQ(w.objects[0].faces[3].mirror, 0.25);
    EXPECT_FALSE(w.objects[1].closed);
    ASSERT_EQ(w.objects[1].faces[0].patterns.size(), 1u);
    EXPECT_EQ(w.objects[1].faces[0].patterns[0].loop[2], glm::dvec3(1, 0, -1));
    EXPECT_EQ(w.objects[1].faces[0].patterns[0].reflectance, 0.1);
    const EdgesSpec edges{"prewitt", "laplacian4", 8, 3, "white-convex", 0.9, 0.4};
    EXPECT_EQ(w.edges, edges);
    EXPECT_FALSE(w.effects.shadows);
    EXPECT_FALSE(w.effects.reflections);
    EXPECT_TRUE(s.shapes.empty());
}

// Every optional key left out takes world.h's member initialiser.
TEST(SceneIoV2, DefaultsFillWhatTheFileLeavesOut) {
    const Json j = Json::parse(R"({"version": 2, "width": 8, "height": 8,
        "camera": {"eye": [0, 0, 5], "target": [0, 0, 0]},
        "lights": [{"type": "parallel", "direction": [0, 0, -1]},
                   {"type": "point", "position": [0, 0, 3]}],
        "objects": [{"vertices": [[0,0,0],[1,0,0],[0,1,0]], "faces": [{"loop": [0,1,2]}]}],
        "edges": {}})");
    const Scene s = parse(j);
    const World& w = *s.world;
    const World defaults;
    EXPECT_EQ(s.background, 0.0);
    EXPECT_EQ(w.camera.up, defaults.camera.up);
    EXPECT_EQ(w.camera.fov_y_deg, defaults.camera.fov_y_deg);
    EXPECT_EQ(w.camera.near, defaults.camera.near);
    EXPECT_EQ(w.ambient, defaults.ambient);
    for (const Light& l : w.lights) {
        EXPECT_EQ(l.intensity, Light{}.intensity);
        EXPECT_EQ(l.shadows, Light{}.shadows);
    }
    EXPECT_EQ(w.objects[0].name, Object{}.name);
    EXPECT_EQ(w.objects[0].closed, Object{}.closed);
    EXPECT_EQ(w.objects[0].faces[0].reflectance, Face{}.reflectance);
    EXPECT_EQ(w.objects[0].faces[0].mirror, Face{}.mirror);
    EXPECT_TRUE(w.objects[0].faces[0].patterns.empty());
    EXPECT_EQ(w.edges, EdgesSpec{});  // present but empty: every default
    EXPECT_EQ(w.effects, EffectSwitches{});

    // No lights, no edges: none at all, not defaults.
    Json bare = j;
    bare.erase("lights");
    bare.erase("edges");
    EXPECT_TRUE(parse(bare).world->lights.empty());
    EXPECT_FALSE(parse(bare).world->edges.has_value());
}

// parse(write(s)) == s, and write(parse(write(s))) == write(s) byte for byte: the text is the
// shortest round-trip form of each double, so equal text is equal bits (-0.0 included, which
// == alone cannot tell from 0.0).
void expect_exact_round_trip(const Scene& s, const std::string& what) {
    const std::string text = scene_to_json(s);
    const Scene back = parse_scene_json(text, what);
    EXPECT_EQ(back, s) << what;
    EXPECT_EQ(scene_to_json(back), text) << what;
}

TEST(SceneIoV2, WrittenWorldsReadBackBitForBit) {
    Scene s = parse(valid());
    World& w = *s.world;
    // Doubles with no short decimal form, and a negative zero.
    w.ambient = 0.1 + 0.2;
    w.objects[0].vertices[0] = {-0.0, 0.0, -0.0};
    w.lights[1].position = {1.0 / 3.0, std::numbers::pi, 1e-300};
    w.objects[1].faces[0].patterns[0].reflectance = std::nextafter(0.1, 1.0);
    w.camera.fov_y_deg = 45.000000000000007;
    s.metadata = {{"pattern", "hand-made"}, {"note", "ünïcode"}};
    expect_exact_round_trip(s, "rich world");
    EXPECT_TRUE(
        std::signbit(parse_scene_json(scene_to_json(s), "x").world->objects[0].vertices[0].x));
    EXPECT_NE(scene_to_json(s).find("\"version\": 2"), std::string::npos);
    EXPECT_EQ(scene_to_json(s).find("\"shapes\""), std::string::npos);

    // Every built-in 3-D pattern's world passes the checks and round-trips.
    int worlds = 0;
    for (const PatternInfo& info : pattern_registry()) {
        if (info.model_file) continue;  // tests/mesh_patterns_test.cpp
        const Scene p = make_pattern(info.id, 40, 30);
        if (!p.world) continue;
        ++worlds;
        EXPECT_EQ(error_of([&] { check_world(*p.world, info.id); }), "") << info.id;
        expect_exact_round_trip(p, info.id);
    }
    EXPECT_GE(worlds, 5);
}

TEST(SceneIoV2, WriterRefusesWhatJsonCannotHoldNamingThePath) {
    Scene s = parse(valid());
    Scene bad = s;
    bad.world->objects[1].faces[0].patterns[0].loop[2].y = std::numeric_limits<double>::infinity();
    EXPECT_EQ(error_of([&] { scene_to_json(bad); }),
              "scene_to_json: objects[1].faces[0].patterns[0].loop[2][1]: inf is not finite and "
              "JSON cannot hold it");
    bad = s;
    bad.world->lights[0].intensity = std::nan("");
    EXPECT_EQ(
        error_of([&] { scene_to_json(bad); }).rfind("scene_to_json: lights[0].intensity: ", 0), 0u);
    bad = s;
    bad.world->objects[0].name = "\xff";
    EXPECT_EQ(error_of([&] { scene_to_json(bad); }).rfind("scene_to_json: objects[0].name: ", 0),
              0u);
}

TEST(SceneIoV2, ExampleFilesRead) {
    const Scene box = parse_scene_json(read_text("tests/data/one_box.json"), "one_box.json");
    ASSERT_TRUE(box.world.has_value());
    ASSERT_EQ(box.world->objects.size(), 1u);
    const Object& cube = box.world->objects[0];
    ASSERT_EQ(cube.faces.size(), 6u);
    // Counter-clockwise from outside: every face's normal points away from the centre.
    const glm::dvec3 centre(0.5);
    for (const Face& f : cube.faces) {
        EXPECT_GT(glm::dot(face_normal(cube, f), cube.vertices[f.loop[0]] - centre), 0.0);
    }
    const Scene floor =
        parse_scene_json(read_text("tests/data/floor_pattern.json"), "floor_pattern.json");
    ASSERT_TRUE(floor.world.has_value());
    EXPECT_EQ(floor.world->objects[0].faces[0].patterns.size(), 1u);
}

TEST(SceneIoV2, AVersion2FileWithoutObjectsIsA2DScene) {
    const Json j = Json::parse(R"({"version": 2, "width": 8, "height": 8,
        "shapes": [{"type": "polygon", "value": 1, "contours": [[[1,1],[5,1],[5,5]]]}]})");
    const Scene s = parse(j);
    EXPECT_FALSE(s.world.has_value());
    ASSERT_EQ(s.shapes.size(), 1u);
    EXPECT_EQ(s.shapes[0].contours[0][1], (Point{5, 1}));
}

// A version-1 file means what it meant: the same scene, the same strictness (3-D keys are
// unknown keys there, not "belongs to a 3-D scene"), written back as version 1.
TEST(SceneIoV2, Version1FilesAreUnchanged) {
    const std::string v1 = R"({"version": 1, "width": 8, "height": 4, "background": 0.5,
        "shapes": [{"type": "polygon", "value": 2, "contours": [[[1,1],[5,1],[5,3]]]}]})";
    const Scene s = parse_scene_json(v1, "v1.json");
    EXPECT_FALSE(s.world.has_value());
    EXPECT_EQ(s.shapes[0].value, 2.0);
    EXPECT_EQ(scene_to_json(s),
              "{\n  \"version\": 1,\n  \"width\": 8,\n  \"height\": 4,\n  \"background\": 0.5,\n"
              "  \"shapes\": [\n    {\"type\": \"polygon\", \"value\": 2.0, \"contours\": [\n"
              "      [[1.0,1.0],[5.0,1.0],[5.0,3.0]]\n    ]}\n  ]\n}\n");
    for (const char* key : {"camera", "objects", "lights"}) {
        Json j = Json::parse(v1);
        j[key] = Json::array();
        EXPECT_EQ(error_of([&] {
                      parse_scene_json(j.dump(), "v1.json");
                  }).rfind(std::string("v1.json: ") + key + ": unknown key", 0),
                  0u)
            << key;
    }
}

// 3-D vertices and pattern points count toward the vertex limit as they stream in: valid()
// has 8 + 4 vertices, then 4 pattern points.
TEST(SceneIoV2, VerticesAndPatternPointsCountTowardTheLimit) {
    const std::string text = valid().dump();
    EXPECT_EQ(error_of([&] { parse_scene_json(text, kSource, 16); }), "");
    EXPECT_EQ(error_of([&] { parse_scene_json(text, kSource, 12); }),
              "v2.json: objects[1].faces[0].patterns[0].loop[0]: more than 12 vertices in the "
              "scene (the limit, docs/limits.md)");
    EXPECT_EQ(error_of([&] { parse_scene_json(text, kSource, 9); }),
              "v2.json: objects[1].vertices[1]: more than 9 vertices in the scene (the limit, "
              "docs/limits.md)");
}

TEST(SceneIoV2, NumbersThatOverflowNameTheirPath) {
    Json j = valid();
    j["objects"][0]["vertices"][2][1] = 12345.5;  // a marker, replaced in the text
    std::string text = j.dump();
    text.replace(text.find("12345.5"), 7, "1e999");
    EXPECT_EQ(error_of([&] { parse_scene_json(text, kSource); }),
              "v2.json: objects[0].vertices[2][1]: number 1e999 is not a finite double");
}

// The geometry tolerances (world_check.cpp) accept a cube whose vertices carry the rounding of
// a rotation far from the origin, and refuse a bend of one vertex that is far larger than that
// rounding but still invisible.
World rotated_cube(const glm::dvec3& offset) {
    const glm::dmat4 m =
        glm::rotate(glm::rotate(glm::translate(glm::dmat4(1.0), offset), 0.7, glm::dvec3(1, 2, 3)),
                    1.1, glm::dvec3(-2, 1, 0.5));
    World w;
    w.camera.eye = offset + glm::dvec3(3, 3, 3);
    w.camera.target = offset;
    Object o;
    for (int i = 0; i < 8; ++i) {
        const glm::dvec3 corner((i & 1) ^ (i >> 1 & 1), i >> 1 & 1, i >> 2);
        o.vertices.push_back(glm::dvec3(m * glm::dvec4(corner, 1.0)));
    }
    for (std::vector<int> loop : {std::vector<int>{0, 3, 2, 1},
                                  {4, 5, 6, 7},
                                  {0, 1, 5, 4},
                                  {3, 7, 6, 2},
                                  {0, 4, 7, 3},
                                  {1, 2, 6, 5}}) {
        o.faces.push_back(Face{loop});
    }
    w.objects.push_back(o);
    return w;
}

TEST(SceneIoV2, PlanarityToleranceAcceptsRoundingAndRefusesBends) {
    // The allowance (world_check.cpp) is 1e-9 x extent + 64 eps x max|coordinate|: about
    // 1.7e-9 for this cube at the origin, 1.4e-5 at 1e9, where its vertices carry ~1e-7 of
    // rounding (a few ulps of 1e9) that a purely relative tolerance would refuse. Moving one
    // vertex by `bend` along the normal puts it about 0.75 bend off the fitted plane: 5 times
    // the allowance, still invisible.
    struct Case {
        glm::dvec3 offset;
        double bend;
    };
    for (const Case& c : {Case{glm::dvec3(0.0), 1e-8}, Case{glm::dvec3(1e9, -3e8, 5e8), 1e-4}}) {
        SCOPED_TRACE(c.offset.x);
        World w = rotated_cube(c.offset);
        EXPECT_EQ(error_of([&] { check_world(w, "cube"); }), "");
        const glm::dvec3 n = face_normal(w.objects[0], w.objects[0].faces[1]);
        w.objects[0].vertices[6] += c.bend * n;
        const std::string message = error_of([&] { check_world(w, "cube"); });
        EXPECT_EQ(message.rfind("cube: objects[0].faces[1].loop: the face is not planar", 0), 0u)
            << message;
    }
}

// A face of many vertices: convex within the tolerances however small its turns, and checked
// in O(n log n) (a repeated index found by sorting, not by comparing every pair).
TEST(SceneIoV2, ALargeRoundFaceIsConvexAndItsRepeatsAreFound) {
    constexpr int kSides = 100'000;
    World w;
    Object disc;
    Face f;
    for (int k = 0; k < kSides; ++k) {
        const double a = 2 * std::numbers::pi * k / kSides;
        disc.vertices.push_back({std::cos(a), std::sin(a), 0.0});
        f.loop.push_back(k);
    }
    disc.faces.push_back(f);
    w.objects.push_back(disc);
    EXPECT_EQ(error_of([&] { check_world(w, "disc"); }), "");
    w.objects[0].faces[0].loop[kSides - 1] = 5;
    EXPECT_EQ(error_of([&] { check_world(w, "disc"); }),
              "disc: objects[0].faces[0].loop[99999]: vertex 5 appears twice (first at loop[5])");
}

TEST(SceneIoV2, CollinearVerticesAreAllowed) {
    Json j = valid();
    j["objects"][1]["vertices"].push_back({0, 0, 3});  // on the edge 0-1
    j["objects"][1]["faces"][0]["loop"] = {0, 4, 1, 2, 3};
    EXPECT_EQ(error_of([&] { parse(j); }), "");
}

// check_world on a world no reader saw (a generator's): the numbers a file cannot hold wrong.
TEST(SceneIoV2, CheckWorldRefusesWhatAReaderWouldHave) {
    const World good = *parse(valid()).world;
    const std::vector<std::pair<std::function<void(World&)>, std::string>> cases = {
        {[](World& w) { w.objects[0].faces[2].reflectance = std::nan(""); },
         "g: objects[0].faces[2].reflectance: nan is not a finite number"},
        {[](World& w) { w.ambient = -std::numeric_limits<double>::infinity(); },
         "g: ambient: -inf is not a finite number"},
        {[](World& w) { w.objects[0].vertices[1].z = std::nan(""); },
         "g: objects[0].vertices[1][2]: nan is not a finite number within the limit of 1e100"},
        {[](World& w) { w.edges->style = "grey"; },
         "g: edges.style: expected one of \"black\", \"white-convex\", found \"grey\""},
        {[](World& w) { w.camera.near = std::numeric_limits<double>::infinity(); },
         "g: camera.near: inf is not a finite number > 0"},
    };
    for (const auto& [mutate, expected] : cases) {
        World w = good;
        mutate(w);
        EXPECT_EQ(error_of([&] { check_world(w, "g"); }), expected);
    }
}

struct Bad {
    std::string what;
    std::function<void(Json&)> mutate;
    std::string expected;  // the start of the message after "v2.json: "
};

Json& face(Json& j, int o, int f) { return j["objects"][o]["faces"][f]; }

std::vector<Bad> bad_structure() {
    return {
        {"unknown top key", [](Json& j) { j["colour"] = 1; }, "colour: unknown key"},
        {"unknown camera key", [](Json& j) { j["camera"]["zoom"] = 2; },
         "camera.zoom: unknown key (expected one of: eye, target, up, fov_y_deg, near)"},
        {"unknown light key",
         [](Json& j) {
             j["lights"][0]["position"] = {1, 2, 3};
         },
         "lights[0].position: unknown key"},
        {"unknown object key", [](Json& j) { j["objects"][0]["mass"] = 2; },
         "objects[0].mass: unknown key"},
        {"unknown face key", [](Json& j) { face(j, 0, 1)["colour"] = 2; },
         "objects[0].faces[1].colour: unknown key"},
        {"unknown pattern key", [](Json& j) { face(j, 1, 0)["patterns"][0]["alpha"] = 1; },
         "objects[1].faces[0].patterns[0].alpha: unknown key"},
        {"unknown edges key", [](Json& j) { j["edges"]["threshold"] = 1; },
         "edges.threshold: unknown key"},
        {"unknown effect", [](Json& j) { j["effects"]["fog"] = false; },
         "effects.fog: unknown key"},
        {"camera missing", [](Json& j) { j.erase("camera"); }, "camera: required key is missing"},
        {"camera not an object", [](Json& j) { j["camera"] = 1; },
         "camera: expected a camera object, found 1"},
        {"eye missing", [](Json& j) { j["camera"].erase("eye"); },
         "camera.eye: required key is missing"},
        {"objects not an array", [](Json& j) { j["objects"] = Json::object(); },
         "objects: expected an array of objects"},
        {"object not an object", [](Json& j) { j["objects"][1] = 3; },
         "objects[1]: expected an object, found 3"},
        {"vertices missing", [](Json& j) { j["objects"][0].erase("vertices"); },
         "objects[0].vertices: required key is missing"},
        {"faces missing", [](Json& j) { j["objects"][0].erase("faces"); },
         "objects[0].faces: required key is missing"},
        {"loop missing", [](Json& j) { face(j, 0, 2).erase("loop"); },
         "objects[0].faces[2].loop: required key is missing"},
        {"name not a string", [](Json& j) { j["objects"][0]["name"] = 7; },
         "objects[0].name: expected a string, found 7"},
        {"closed not a boolean", [](Json& j) { j["objects"][0]["closed"] = "yes"; },
         "objects[0].closed: expected true or false"},
        {"edges not an object", [](Json& j) { j["edges"] = true; },
         "edges: expected an edges object, found true"},
        {"effect not a boolean", [](Json& j) { j["effects"]["shading"] = 0; },
         "effects.shading: expected true or false"},
        {"objects and shapes", [](Json& j) { j["shapes"] = Json::array(); },
         "shapes: a file has objects (3-D) or shapes (2-D), not both"},
        {"3-D keys without objects", [](Json& j) { j.erase("objects"); },
         "camera: belongs to a 3-D scene"},
        {"origin on a 3-D scene",
         [](Json& j) {
             j["origin"] = {1, 2};
         },
         "origin: a 3-D scene has no window origin"},
        {"version 5", [](Json& j) { j["version"] = 5; }, "version: unsupported version 5"},
        {"a sequence in version 2",
         [](Json& j) {
             j["sequence"] = {{"motion", "still"}};
         },
         "sequence: unknown key"},
    };
}

std::vector<Bad> bad_camera_and_lights() {
    return {
        {"eye not a point",
         [](Json& j) {
             j["camera"]["eye"] = {1, 2};
         },
         "camera.eye: expected a point [x, y, z] of three finite numbers, found [1,2]"},
        {"eye a string", [](Json& j) { j["camera"]["eye"][1] = "2"; },
         "camera.eye: expected a point [x, y, z]"},
        {"eye at target",
         [](Json& j) {
             j["camera"]["eye"] = {0, 0.3, 0};
         },
         "camera.target: equals camera.eye"},
        {"up parallel to view",
         [](Json& j) {
             j["camera"]["up"] = {3, 2.2, 4};
         },
         "camera.up: is parallel to the view direction"},
        {"up zero",
         [](Json& j) {
             j["camera"]["up"] = {0, 0, 0};
         },
         "camera.up: has zero length"},
        {"fov 180", [](Json& j) { j["camera"]["fov_y_deg"] = 180; },
         "camera.fov_y_deg: 180 is outside (0, 180)"},
        {"fov 0", [](Json& j) { j["camera"]["fov_y_deg"] = 0; },
         "camera.fov_y_deg: 0 is outside (0, 180)"},
        {"fov a string", [](Json& j) { j["camera"]["fov_y_deg"] = "wide"; },
         "camera.fov_y_deg: expected a finite number"},
        {"near zero", [](Json& j) { j["camera"]["near"] = 0; },
         "camera.near: 0 is not a finite number > 0"},
        {"near negative", [](Json& j) { j["camera"]["near"] = -1; },
         "camera.near: -1 is not a finite number > 0"},
        {"ambient a string", [](Json& j) { j["ambient"] = "low"; },
         "ambient: expected a finite number"},
        {"lights not an array", [](Json& j) { j["lights"] = Json::object(); },
         "lights: expected an array of lights"},
        {"light not an object", [](Json& j) { j["lights"][0] = 1; },
         "lights[0]: expected a light object, found 1"},
        {"light type missing", [](Json& j) { j["lights"][0].erase("type"); },
         "lights[0].type: required key is missing"},
        {"unknown light type", [](Json& j) { j["lights"][1]["type"] = "spot"; },
         "lights[1].type: expected one of \"parallel\", \"point\", found the string \"spot\""},
        {"zero direction",
         [](Json& j) {
             j["lights"][0]["direction"] = {0, 0, 0};
         },
         "lights[0].direction: has zero length"},
        {"parallel light without direction", [](Json& j) { j["lights"][0].erase("direction"); },
         "lights[0].direction: required key is missing"},
        {"point light without position", [](Json& j) { j["lights"][1].erase("position"); },
         "lights[1].position: required key is missing"},
        {"intensity a string", [](Json& j) { j["lights"][1]["intensity"] = "12"; },
         "lights[1].intensity: expected a finite number"},
        {"shadows not a boolean", [](Json& j) { j["lights"][0]["shadows"] = 1; },
         "lights[0].shadows: expected true or false"},
        {"bad contour operator", [](Json& j) { j["edges"]["contour"] = "canny"; },
         "edges.contour: expected one of \"sobel\", \"prewitt\", found the string \"canny\""},
        {"bad crease operator", [](Json& j) { j["edges"]["crease"] = "log"; },
         "edges.crease: expected one of \"laplacian4\", \"laplacian8\", \"none\""},
        {"bad style", [](Json& j) { j["edges"]["style"] = "white"; },
         "edges.style: expected one of \"black\", \"white-convex\""},
        {"kp a string", [](Json& j) { j["edges"]["kp"] = "10"; }, "edges.kp: expected a finite"},
    };
}

// The five points of a regular pentagon in the plane y = 0, every second one in turn: a
// pentagram, whose turns all go one way but add up to two full turns.
Json pentagram() {
    Json points = Json::array();
    for (int k = 0; k < 5; ++k) {
        const double a = 2 * std::numbers::pi * (2 * k) / 5;
        points.push_back({std::cos(a), 0.0, -std::sin(a)});
    }
    return points;
}

std::vector<Bad> bad_geometry() {
    return {
        {"vertex not a point",
         [](Json& j) {
             j["objects"][0]["vertices"][2] = {1, 1};
         },
         "objects[0].vertices[2]: expected a point [x, y, z]"},
        // Vertices and loops are gathered outside the JSON tree while they look well formed
        // (BulkValues, scene_io_detail.h); these turn back into tree values part way through.
        {"vertex of four numbers",
         [](Json& j) {
             j["objects"][0]["vertices"][2] = {1, 1, 1, 1};
         },
         "objects[0].vertices[2]: expected a point [x, y, z]"},
        {"vertex with a string",
         [](Json& j) {
             j["objects"][0]["vertices"][2] = {1, "a", 1};
         },
         "objects[0].vertices[2]: expected a point [x, y, z]"},
        {"index a string", [](Json& j) { face(j, 0, 1)["loop"][1] = "x"; },
         "objects[0].faces[1].loop[1]: expected a vertex index (an integer >= 0), found the "
         "string \"x\""},
        {"index an array", [](Json& j) { face(j, 0, 1)["loop"][2] = {2}; },
         "objects[0].faces[1].loop[2]: expected a vertex index (an integer >= 0), found [2]"},
        {"vertex beyond the limit", [](Json& j) { j["objects"][1]["vertices"][0][0] = 1e101; },
         "objects[1].vertices[0][0]: 1e+101 is not a finite number within the limit of 1e100"},
        {"index out of range", [](Json& j) { face(j, 0, 1)["loop"][2] = 9; },
         "objects[0].faces[1].loop[2]: index 9 out of range (the object has 8 vertices)"},
        {"index past int", [](Json& j) { face(j, 0, 1)["loop"][2] = 1LL << 40; },
         "objects[0].faces[1].loop[2]: index 1099511627776 out of range (the object has 8 "
         "vertices)"},
        {"negative index", [](Json& j) { face(j, 0, 1)["loop"][0] = -1; },
         "objects[0].faces[1].loop[0]: expected a vertex index (an integer >= 0), found -1"},
        {"fractional index", [](Json& j) { face(j, 0, 1)["loop"][0] = 1.5; },
         "objects[0].faces[1].loop[0]: expected a vertex index (an integer >= 0), found 1.5"},
        {"two indices",
         [](Json& j) {
             face(j, 0, 0)["loop"] = {0, 1};
         },
         "objects[0].faces[0].loop: a face needs at least 3 vertices, found 2"},
        {"repeated index",
         [](Json& j) {
             face(j, 0, 0)["loop"] = {0, 3, 2, 3};
         },
         "objects[0].faces[0].loop[3]: vertex 3 appears twice (first at loop[1])"},
        {"the first repeat in loop order is named",
         [](Json& j) {
             face(j, 0, 0)["loop"] = {0, 1, 2, 1, 0};
         },
         "objects[0].faces[0].loop[3]: vertex 1 appears twice (first at loop[1])"},
        {"non-planar face",
         [](Json& j) {
             j["objects"][0]["vertices"][6] = {1, 1, 1.2};
         },
         "objects[0].faces[1].loop: the face is not planar"},
        {"non-planar face names its farthest point",
         [](Json& j) {
             j["objects"][1]["vertices"].push_back({0, 0.1, 3});  // lifted off y = 0
             face(j, 1, 0)["loop"] = {0, 1, 4, 2, 3};
         },
         "objects[1].faces[0].loop: the face is not planar: loop[2] lies"},
        {"non-convex face",
         [](Json& j) {
             j["objects"][1]["vertices"][1] = {-1, 0, 0};  // a reflex corner
         },
         "objects[1].faces[0].loop: the face is not convex: it turns back at loop[1]"},
        {"self-crossing face",
         [](Json& j) {
             j["objects"][1]["vertices"] = pentagram();
             face(j, 1, 0)["loop"] = {0, 1, 2, 3, 4};
         },
         "objects[1].faces[0].loop: the face is not convex: its turns add up to 720 degrees"},
        {"zero-area face",
         [](Json& j) {
             j["objects"][1]["vertices"] = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}};
         },
         "objects[1].faces[0].loop: the face has zero area"},
        {"reflectance a string", [](Json& j) { face(j, 0, 0)["reflectance"] = "0.5"; },
         "objects[0].faces[0].reflectance: expected a finite number"},
        {"patterns not an array", [](Json& j) { face(j, 1, 0)["patterns"] = 1; },
         "objects[1].faces[0].patterns: expected an array of patterns"},
        {"pattern off its plane",
         [](Json& j) {
             face(j, 1, 0)["patterns"][0]["loop"][2] = {1, 0.5, -1};
         },
         "objects[1].faces[0].patterns[0].loop[2]: lies 0.5 off its face's plane"},
        {"pattern of two points",
         [](Json& j) {
             face(j, 1, 0)["patterns"][0]["loop"] = {{0, 0, 0}, {1, 0, 0}};
         },
         "objects[1].faces[0].patterns[0].loop: a pattern needs at least 3 points, found 2"},
        {"non-convex pattern",
         [](Json& j) {
             face(j, 1, 0)["patterns"][0]["loop"] = {
                 {-1, 0, 1}, {1, 0, 1}, {0, 0, 0.5}, {1, 0, -1}, {-1, 0, -1}};
         },
         "objects[1].faces[0].patterns[0].loop: the pattern is not convex"},
        {"self-crossing pattern",
         [](Json& j) { face(j, 1, 0)["patterns"][0]["loop"] = pentagram(); },
         "objects[1].faces[0].patterns[0].loop: the pattern is not convex: its turns add up to "
         "720 degrees"},
        {"pattern without reflectance",
         [](Json& j) { face(j, 1, 0)["patterns"][0].erase("reflectance"); },
         "objects[1].faces[0].patterns[0].reflectance: required key is missing"},
    };
}

TEST(SceneIoV2, EveryErrorIsOneLineNamingItsPath) {
    std::vector<Bad> all = bad_structure();
    for (auto more : {bad_camera_and_lights(), bad_geometry()}) {
        all.insert(all.end(), more.begin(), more.end());
    }
    for (const Bad& b : all) {
        SCOPED_TRACE(b.what);
        Json j = valid();
        b.mutate(j);
        const std::string message = error_of([&] { parse(j); });
        const std::string expected = std::string(kSource) + ": " + b.expected;
        EXPECT_EQ(message.substr(0, expected.size()), expected) << message;
        EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    }
}

}  // namespace
}  // namespace aabench
