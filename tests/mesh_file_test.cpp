// Mesh objects (scene file version 4, "mesh"; patterns/scene/mesh_file.h): small OBJ, PLY and
// STL files written here load to the expected triangles, placed by the transform in its order,
// coloured by their material, found closed or not, degenerate triangles dropped and counted;
// a mesh cube renders as the same cube written as a version-2 object; and every bad input is
// one line naming the JSON path and the file, exit code 2, nothing written.
#include "patterns/scene/mesh_file.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>

#include "cli_runner.h"
#include "harness/world/frame.h"
#include "harness/world/plan.h"
#include "input_error_of.h"
#include "methods/method.h"
#include "patterns/scene/scene_io.h"

namespace aabench {
namespace {

namespace fs = std::filesystem;

// Rotations by multiples of 90 degrees leave cos(pi/2) = 6e-17 in the matrix: coordinates of
// magnitude ~30 come out a few 1e-15 off their exact places.
constexpr double kRotationRounding = 1e-12;
// The same cube drawn as 12 triangles and as 6 quads: the exact coverage of two halves of a
// quad against the whole, each summed in double and stored as float32 (rounding of ~6e-8 at
// values <= 1), with room for the ties along the shared diagonal.
constexpr double kSameCubeTolerance = 1e-6;

// The unit cube [0, 1]^3: 8 corners, 6 quads counter-clockwise seen from outside.
constexpr const char* kCubeVertices = R"(v 0 0 0
v 1 0 0
v 1 1 0
v 0 1 0
v 0 0 1
v 1 0 1
v 1 1 1
v 0 1 1
)";
constexpr const char* kCubeFaces[6] = {"f 1 4 3 2", "f 5 6 7 8", "f 1 2 6 5",
                                       "f 4 8 7 3", "f 1 5 8 4", "f 2 3 7 6"};
// The same loops, 0-based, for the version-2 object.
constexpr int kCubeLoops[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
                                  {3, 7, 6, 2}, {0, 4, 7, 3}, {1, 2, 6, 5}};

class MeshFile : public CliRunner {
protected:
    MeshFile() : CliRunner("mesh_file") {}
    void SetUp() override {
        CliRunner::SetUp();
        if (!mesh_loading_available()) GTEST_SKIP() << "built without Assimp";
    }
    void write(const std::string& name, const std::string& text) const {
        std::ofstream(path(name), std::ios::binary) << text;
    }
    // The cube as OBJ, faces `skip` left out and `flip` reversed (-1: none).
    std::string cube_obj(int skip = -1, int flip = -1, const std::string& head = "") const {
        std::string out = head + kCubeVertices;
        for (int f = 0; f < 6; ++f) {
            if (f == skip) continue;
            if (f == flip) {
                out += fmt::format("f {} {} {} {}\n", kCubeLoops[f][3] + 1, kCubeLoops[f][2] + 1,
                                   kCubeLoops[f][1] + 1, kCubeLoops[f][0] + 1);
            } else {
                out += std::string(kCubeFaces[f]) + "\n";
            }
        }
        return out;
    }
    // A version-4 scene of one mesh object (`object`: its JSON) seen from a corner.
    std::string scene_with(const std::string& object) const {
        return fmt::format(
            R"({{"version": 4, "width": 48, "height": 40, "background": 0.1,
  "camera": {{"eye": [3.1, 2.3, 4.2], "target": [0.5, 0.45, 0.5], "fov_y_deg": 35}},
  "ambient": 0.2, "lights": [{{"type": "parallel", "direction": [-0.3, -1, -0.6], "intensity": 0.7}}],
  "objects": [{}]}})",
            object);
    }
    Scene read(const std::string& object, const std::string& name = "s.json") const {
        write(name, scene_with(object));
        return read_scene_file(path(name));
    }
};

struct Box {
    glm::dvec3 lo{INFINITY}, hi{-INFINITY};
};
Box bounds(const Object& o) {
    Box b;
    for (const glm::dvec3& v : o.vertices) {
        b.lo = glm::min(b.lo, v);
        b.hi = glm::max(b.hi, v);
    }
    return b;
}

void expect_near3(const glm::dvec3& a, const glm::dvec3& b, const char* what) {
    for (int k = 0; k < 3; ++k)
        EXPECT_NEAR(a[k], b[k], kRotationRounding) << what << "[" << k << "]";
}

TEST_F(MeshFile, ObjPlyAndStlLoadToTheirTriangles) {
    write("cube.obj", cube_obj());
    write("tetra.ply", R"(ply
format ascii 1.0
element vertex 4
property float x
property float y
property float z
element face 4
property list uchar int vertex_indices
end_header
0 0 0
1 0 0
0 1 0
0 0 1
3 0 2 1
3 0 1 3
3 0 3 2
3 1 2 3
)");
    // STL repeats every corner per triangle: joined by position, it is the 8-corner cube.
    std::string stl = "solid cube\n";
    const double corner[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                                 {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
    for (const auto& loop : kCubeLoops) {
        for (const int t : {1, 2}) {
            stl += " facet normal 0 0 0\n  outer loop\n";
            for (const int v : {loop[0], loop[t], loop[t + 1]}) {
                stl +=
                    fmt::format("   vertex {} {} {}\n", corner[v][0], corner[v][1], corner[v][2]);
            }
            stl += "  endloop\n endfacet\n";
        }
    }
    write("cube.stl", stl + "endsolid cube\n");

    const Scene obj = read(R"({"mesh": "cube.obj"})");
    ASSERT_EQ(obj.world->objects.size(), 1u);
    EXPECT_EQ(obj.world->objects[0].faces.size(), 12u);
    EXPECT_EQ(obj.world->objects[0].vertices.size(), 8u);
    const Scene ply = read(R"({"mesh": "tetra.ply"})");
    EXPECT_EQ(ply.world->objects[0].faces.size(), 4u);
    EXPECT_EQ(ply.world->objects[0].vertices.size(), 4u);
    EXPECT_TRUE(ply.world->objects[0].closed) << ply.world->objects[0].mesh.closure;
    const Scene stl_scene = read(R"({"mesh": "cube.stl"})");
    EXPECT_EQ(stl_scene.world->objects[0].faces.size(), 12u);
    EXPECT_EQ(stl_scene.world->objects[0].vertices.size(), 8u);
    EXPECT_TRUE(stl_scene.world->objects[0].closed) << stl_scene.world->objects[0].mesh.closure;
    // Every face a triangle of the file's orientation: counter-clockwise from outside.
    const Object& cube = obj.world->objects[0];
    for (const Face& f : cube.faces) {
        ASSERT_EQ(f.loop.size(), 3u);
        const glm::dvec3 c =
            (cube.vertices[f.loop[0]] + cube.vertices[f.loop[1]] + cube.vertices[f.loop[2]]) / 3.0;
        EXPECT_GT(glm::dot(face_normal(cube, f), c - glm::dvec3(0.5)), 0.0);
    }
}

// p' = R_z R_y R_x S p + t: the unit cube scaled to [0,2]x[0,3]x[0,1], turned 90 degrees about
// x (to [0,2]x[-1,0]x[0,3]), then about y (to [0,3]x[-1,0]x[-2,0]), then moved by (10, 20, 30).
// Turned about y first and x second, it would be [0,1]x[0,2]x[0,3] before the move.
TEST_F(MeshFile, TheTransformScalesThenTurnsAboutXThenYThenZThenMoves) {
    write("cube.obj", cube_obj());
    const Object o = read(R"({"mesh": "cube.obj", "transform": {"scale": [2, 3, 1],
        "rotate_deg": [90, 90, 0], "translate": [10, 20, 30]}})")
                         .world->objects[0];
    const Box b = bounds(o);
    expect_near3(b.lo, {10, 19, 28}, "lo");
    expect_near3(b.hi, {13, 20, 30}, "hi");
    // Then z: (x, y) -> (-y, x) after the two above.
    const Object z = read(R"({"mesh": "cube.obj", "transform": {"scale": [2, 3, 1],
        "rotate_deg": [90, 90, 90]}})")
                         .world->objects[0];
    expect_near3(bounds(z).lo, {0, 0, -2}, "lo z");
    expect_near3(bounds(z).hi, {1, 3, 0}, "hi z");
    // A uniform scale as one number; a mirror (one negative axis) keeps the faces outward.
    const Object m =
        read(R"({"mesh": "cube.obj", "transform": {"scale": [-1.5, 1.5, 1.5]}})").world->objects[0];
    expect_near3(bounds(m).lo, {-1.5, 0, 0}, "lo mirrored");
    const glm::dvec3 centre(-0.75, 0.75, 0.75);
    for (const Face& f : m.faces) {
        EXPECT_GT(glm::dot(face_normal(m, f), m.vertices[f.loop[0]] - centre), 0.0);
    }
    EXPECT_TRUE(m.closed) << m.mesh.closure;
    const Object u = read(R"({"mesh": "cube.obj", "transform": {"scale": 0.5}})").world->objects[0];
    expect_near3(bounds(u).hi, {0.5, 0.5, 0.5}, "hi uniform");
}

TEST_F(MeshFile, ReflectanceIsTheFilesDiffuseColourWithItsLuminance) {
    write("grey.mtl", "newmtl paint\nKd 0.2 0.5 0.8\n");
    write("cube.obj", cube_obj(-1, -1, "mtllib grey.mtl\nusemtl paint\n"));
    const double y = 0.2126 * 0.2 + 0.7152 * 0.5 + 0.0722 * 0.8;
    // The colour is a float in the file: its luminance to float rounding.
    constexpr double kFloatColour = 1e-7;
    // Each scene held by name: a range-for over a member of a temporary would dangle.
    const Scene coloured = read(R"({"mesh": "cube.obj"})");
    EXPECT_EQ(coloured.channels, 3);  // a colour world
    for (const Face& f : coloured.world->objects[0].faces) {
        EXPECT_NEAR(f.reflectance, y, kFloatColour);
        ASSERT_TRUE(f.reflectance_rgb.has_value());
        EXPECT_NEAR((*f.reflectance_rgb)[0], 0.2, kFloatColour);
        EXPECT_NEAR((*f.reflectance_rgb)[1], 0.5, kFloatColour);
        EXPECT_NEAR((*f.reflectance_rgb)[2], 0.8, kFloatColour);
    }
    const Scene given = read(R"({"mesh": "cube.obj", "reflectance": 0.25})");
    EXPECT_EQ(given.channels, 1);
    for (const Face& f : given.world->objects[0].faces) {
        EXPECT_EQ(f.reflectance, 0.25);
        EXPECT_FALSE(f.reflectance_rgb.has_value());
    }
    const Scene given_colour = read(R"({"mesh": "cube.obj", "reflectance": [0.25, 0.5, 1]})");
    for (const Face& f : given_colour.world->objects[0].faces) {
        EXPECT_EQ(f.reflectance_rgb, (Rgb{0.25, 0.5, 1.0}));
    }
    // A grey diffuse colour is its number: the world stays grey.
    write("white.mtl", "newmtl paint\nKd 0.6 0.6 0.6\n");
    write("white.obj", cube_obj(-1, -1, "mtllib white.mtl\nusemtl paint\n"));
    const Scene white = read(R"({"mesh": "white.obj"})");
    EXPECT_EQ(white.channels, 1);
    for (const Face& f : white.world->objects[0].faces) {
        EXPECT_FALSE(f.reflectance_rgb.has_value());
    }
    // No material in the file: Face's default.
    write("plain.obj", cube_obj());
    const Scene plain = read(R"({"mesh": "plain.obj"})");
    for (const Face& f : plain.world->objects[0].faces) {
        EXPECT_EQ(f.reflectance, 1.0);
    }
}

TEST_F(MeshFile, ClosedAutoCullsOnlyAWatertightConsistentlyOrientedMesh) {
    write("cube.obj", cube_obj());
    write("open.obj", cube_obj(/*skip=*/2));
    write("flipped.obj", cube_obj(-1, /*flip=*/4));
    const Object cube = read(R"({"mesh": "cube.obj"})").world->objects[0];
    EXPECT_TRUE(cube.closed);
    EXPECT_EQ(cube.mesh.closure, "watertight and consistently oriented");
    const Object open = read(R"({"mesh": "open.obj", "closed": "auto"})").world->objects[0];
    EXPECT_FALSE(open.closed);
    EXPECT_EQ(open.mesh.closure.rfind("open: edge ", 0), 0u) << open.mesh.closure;
    const Object flipped = read(R"({"mesh": "flipped.obj"})").world->objects[0];
    EXPECT_FALSE(flipped.closed);
    EXPECT_EQ(flipped.mesh.closure.rfind("not consistently oriented: edge ", 0), 0u)
        << flipped.mesh.closure;
    // Forced either way, and the finding still recorded.
    EXPECT_TRUE(read(R"({"mesh": "open.obj", "closed": true})").world->objects[0].closed);
    EXPECT_FALSE(read(R"({"mesh": "cube.obj", "closed": false})").world->objects[0].closed);
    // The plan says what it found.
    const Plan plan = make_plan(read(R"({"name": "lid", "mesh": "open.obj"})"));
    ASSERT_EQ(plan.notes.size(), 1u);
    EXPECT_NE(plan.notes[0].find("'lid': open.obj, 10 triangles"), std::string::npos)
        << plan.notes[0];
    EXPECT_NE(plan.notes[0].find("closed: auto, open: edge"), std::string::npos) << plan.notes[0];
    EXPECT_NE(plan.notes[0].find("two-sided faces"), std::string::npos) << plan.notes[0];
}

TEST_F(MeshFile, DegenerateTrianglesAreDroppedAndCounted) {
    // A tetrahedron, a triangle with a repeated corner and one with three collinear corners
    // (vertex 5 is the midpoint of vertices 1 and 2).
    write("tetra.obj",
          "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nv 0.5 0 0\n"
          "f 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\nf 1 1 2\nf 1 5 2\n");
    const Scene s = read(R"({"mesh": "tetra.obj"})");
    const Object& o = s.world->objects[0];
    EXPECT_EQ(o.faces.size(), 4u);
    EXPECT_EQ(o.mesh.degenerate_dropped, 2u);
    EXPECT_EQ(o.vertices.size(), 4u);  // the midpoint is used by no triangle kept
    EXPECT_TRUE(o.closed) << o.mesh.closure;
    const std::string plan = format_plan(make_plan(s));
    EXPECT_NE(plan.find("4 triangles, 2 degenerate left out"), std::string::npos) << plan;
}

// Done when: a world with a mesh cube renders (to rounding) as the same cube written as a
// version-2 object with its vertices.
TEST_F(MeshFile, AMeshCubeRendersAsTheSameCubeWrittenAsAVersion2Object) {
    write("cube.obj", cube_obj());
    const Scene mesh = read(R"({"mesh": "cube.obj", "reflectance": 0.8})");
    std::string faces;
    for (const auto& loop : kCubeLoops) {
        faces += fmt::format("{}{{\"loop\": [{}, {}, {}, {}], \"reflectance\": 0.8}}",
                             faces.empty() ? "" : ", ", loop[0], loop[1], loop[2], loop[3]);
    }
    const std::string v2 = fmt::format(
        R"({{"version": 2, "width": 48, "height": 40, "background": 0.1,
  "camera": {{"eye": [3.1, 2.3, 4.2], "target": [0.5, 0.45, 0.5], "fov_y_deg": 35}},
  "ambient": 0.2, "lights": [{{"type": "parallel", "direction": [-0.3, -1, -0.6], "intensity": 0.7}}],
  "objects": [{{"vertices": [[0,0,0],[1,0,0],[1,1,0],[0,1,0],[0,0,1],[1,0,1],[1,1,1],[0,1,1]],
                "faces": [{}]}}]}})",
        faces);
    const Scene quads = parse_scene_json(v2, "v2.json");
    int compared = 0;
    for (const char* id : {"exact", "box-multiscan", "none"}) {
        const MethodInstance m = make_method(id);
        const PreparedFrame a = PreparedFrame::prepare(mesh);
        const PreparedFrame b = PreparedFrame::prepare(quads);
        const Image ia = render_scene(*m.method, a.input_for(*m.method));
        const Image ib = render_scene(*m.method, b.input_for(*m.method));
        ASSERT_EQ(ia.data.size(), ib.data.size());
        double worst = 0.0;
        std::size_t cube_pixels = 0;  // off the background 0.1 by more than its lit faces' least
        for (std::size_t k = 0; k < ia.data.size(); ++k) {
            worst = std::max(worst, static_cast<double>(std::abs(ia.data[k] - ib.data[k])));
            cube_pixels += std::abs(ib.data[k] - 0.1f) > 0.05f;
        }
        EXPECT_LE(worst, kSameCubeTolerance) << id;
        EXPECT_GT(cube_pixels, ib.data.size() / 10) << id;  // the cube is in view
        ++compared;
    }
    EXPECT_EQ(compared, 3);
}

// Export writes a mesh scene as version 2 with the triangles inlined (after the transform),
// which reads back as the same world without the file.
TEST_F(MeshFile, ExportWritesTheTrianglesInline) {
    write("cube.obj", cube_obj());
    write("s.json",
          scene_with(R"({"mesh": "cube.obj", "transform": {"translate": [0.25, 0, 0]}})"));
    ASSERT_EQ(
        run(fmt::format("export --scene {} --out {}", path("s.json"), path("out.json"))).exit_code,
        0);
    fs::remove(path("cube.obj"));
    const Scene again = read_scene_file(path("out.json"));
    ASSERT_TRUE(again.world.has_value());
    const Object& o = again.world->objects[0];
    EXPECT_EQ(o.faces.size(), 12u);
    EXPECT_TRUE(o.mesh.file.empty());
    expect_near3(bounds(o).lo, {0.25, 0, 0}, "lo");
    expect_near3(bounds(o).hi, {1.25, 1, 1}, "hi");
}

// Every bad mesh is one line naming the JSON path and the file; through the CLI, exit code 2
// and nothing written.
TEST_F(MeshFile, EveryBadMeshIsOneLineNamingItsPathAndFile) {
    write("cube.obj", cube_obj());
    write("notes.txt", "These are notes, not a model.\nA second line.\n");
    write("notes.obj", "These are notes, not a model.\nA second line.\n");
    write("junk.xyz1", std::string("\x01\x02\x03 binary junk \xff\xfe"));
    write("points.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n");
    write("empty.obj", "");
    write("inf.obj", "v 1e39 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    // Files on which Assimp 5.2.5 aborts or never returns, refused before it runs
    // (patterns/scene/mesh_file.cpp): the fuzz target's regression inputs.
    const auto corpus = [](const char* file) {
        std::ifstream in(std::string(AABENCH_SOURCE_DIR) + "/tests/fuzz/corpus/mesh_fuzz/" + file,
                         std::ios::binary);
        return std::string(std::istreambuf_iterator<char>(in), {});
    };
    write("empty-faces.ply", corpus("regression-ply-empty-faces.ply"));
    write("no-end.ply", corpus("regression-ply-no-end-header.ply"));
    write("nul-end.ply", corpus("regression-ply-nul-end-header.ply"));
    write("bad-normal.stl", corpus("regression-stl-normal-mismatch.stl"));
    fs::create_directories(path("folder.obj"));
    struct Case {
        std::string object;
        std::vector<std::string> parts;  // each in the one line, in order
    };
    const std::string dir = dir_.string();
    const std::vector<Case> cases = {
        {R"({"mesh": "missing.obj"})",
         {"s.json: objects[0].mesh: ",
          dir + "/missing.obj: cannot open: No such file or directory"}},
        {R"({"mesh": "folder.obj"})",
         {"objects[0].mesh: ", "folder.obj: cannot read: Is a directory"}},
        {R"({"mesh": "empty.obj"})", {"objects[0].mesh: ", "empty.obj: empty file"}},
        {R"({"mesh": "notes.txt"})", {"objects[0].mesh: ", "notes.txt: Assimp cannot read it: "}},
        {R"({"mesh": "junk.xyz1"})", {"objects[0].mesh: ", "junk.xyz1: Assimp cannot read it: "}},
        {R"({"mesh": "points.obj"})", {"objects[0].mesh: ", "points.obj: "}},
        {R"({"mesh": "inf.obj"})", {"objects[0].mesh: ", "inf.obj: ", "not finite"}},
        {R"({"mesh": "empty-faces.ply"})",
         {"objects[0].mesh: ", "empty-faces.ply: mesh 0 face ", " has no vertex indices"}},
        {R"({"mesh": "no-end.ply"})",
         {"objects[0].mesh: ", "no-end.ply: a PLY header without end_header"}},
        {R"({"mesh": "nul-end.ply"})",
         {"objects[0].mesh: ", "nul-end.ply: a PLY header without end_header"}},
        {R"({"mesh": "bad-normal.stl"})",
         {"objects[0].mesh: ", "bad-normal.stl: Assimp cannot read it: Normal buffer size"}},
        {R"({"mesh": "cube.obj", "transform": {"scale": [1, 0, 1]}})",
         {"objects[0].transform.scale: a zero scale flattens the mesh to no area"}},
        {R"({"mesh": "cube.obj", "transform": {"scale": 0}})",
         {"objects[0].transform.scale: a zero scale"}},
        {R"({"mesh": "cube.obj", "transform": {"rotate": [1, 0, 1]}})",
         {"objects[0].transform.rotate: unknown key (expected one of: scale, rotate_deg, "
          "translate)"}},
        {R"({"mesh": "cube.obj", "closed": "yes"})",
         {"objects[0].closed: expected true, false or \"auto\", found the string \"yes\""}},
        {R"({"mesh": 3})", {"objects[0].mesh: expected a model file's path, found 3"}},
        {R"({"mesh": "cube.obj", "faces": []})",
         {"objects[0].faces: unknown key (expected one of: name, mesh, transform, reflectance, "
          "closed)"}},
    };
    for (const Case& c : cases) {
        write("s.json", scene_with(c.object));
        const std::string e = error_of([&] { read_scene_file(path("s.json")); });
        std::size_t at = 0;
        for (const std::string& part : c.parts) {
            const std::size_t found = e.find(part, at);
            EXPECT_NE(found, std::string::npos) << c.object << "\n" << e << "\nlacks: " << part;
            if (found != std::string::npos) at = found + part.size();
        }
        EXPECT_EQ(e.find('\n'), std::string::npos) << e;
        // The CLI: exit code 2, one line, nothing written.
        const CliOutput out = run(fmt::format("render --scene {} --method exact --out {}",
                                              path("s.json"), path("o.exr")));
        EXPECT_EQ(out.exit_code, 2) << c.object;
        EXPECT_FALSE(fs::exists(path("o.exr"))) << c.object;
        EXPECT_NE(out.err.find(c.parts.back()), std::string::npos) << out.err;
    }
    // "mesh" needs version 4.
    std::string v2 = scene_with(R"({"mesh": "cube.obj"})");
    v2.replace(v2.find("\"version\": 4"), 12, "\"version\": 2");
    write("v2.json", v2);
    EXPECT_EQ(error_of([&] { read_scene_file(path("v2.json")); }),
              path("v2.json") +
                  ": objects[0].mesh: a mesh object needs \"version\": 4, and this "
                  "file is version 2");
}

// More triangles than the limit are refused on the file's face count, before any face is made
// (the limit is a parameter of the loader, so a 12-triangle cube reaches it here).
TEST_F(MeshFile, MoreTrianglesThanTheLimitAreRefused) {
    write("cube.obj", cube_obj());
    try {
        load_mesh_file(path("cube.obj"), "cube.obj", {}, 11);
        ADD_FAILURE() << "no MeshError";
    } catch (const MeshError& e) {
        EXPECT_EQ(std::string(e.what()),
                  "cube.obj: 12 faces, more than the limit of 11 triangles per scene "
                  "(docs/limits.md)");
    }
    EXPECT_EQ(load_mesh_file(path("cube.obj"), "cube.obj", {}, 12).triangles.size(), 12u);
}

}  // namespace
}  // namespace aabench
