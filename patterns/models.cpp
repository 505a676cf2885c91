// `bunny`, `horse`, `engine`, `truck`: real meshes from Debian's model packages, through the
// mesh loader (patterns/scene/mesh_file.h), on a ground plane under one shadowing light.
//
// What they provoke: what a real model has and the built-in solids do not — tens of thousands
// of small triangles sharing edges (conflation at every seam), silhouettes of every curvature,
// self-occlusion (ears, legs, engine parts: the visibility stage at depth), self-shadowing and a
// shadow of thousands of triangles on the ground.
//
//   bunny   /usr/share/glmark2/models/bunny.obj (glmark2-data): the Stanford bunny
//   horse   /usr/share/glmark2/models/horse.3ds (glmark2-data)
//   engine  /usr/share/assimp/models/glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb
//           (assimp-testmodels)
//   truck   /usr/share/assimp/models/glTF/CesiumMilkTruck/CesiumMilkTruck.gltf
//           (assimp-testmodels)
//
// Layout: the model is turned upright (y up) by a fixed rotation per model (the horse 90 degrees
// about x, the others none), then scaled and moved so that its bounding box is centred over the
// origin with a diagonal of 2 and its lowest point 0.0013 above the ground (y = 0); a face whose
// file gives no colour has reflectance 0.8. The ground is a square of 16 x 16 two-sided quads
// (tiles: each receives only the shadow triangles that reach it, which keeps the shadow stage's
// cutting per tile small) 4 diagonals across. tests/mesh_oracle_test.cpp holds `bunny` and
// `horse` to a ray caster that places the model from this paragraph. The camera looks at the
// box's centre from `azimuth_deg` (about y, from +z toward +x) and `elevation_deg`, at the
// distance where the box's bounding sphere fills the vertical field of view (40 degrees) with a
// margin. One parallel light from `light_azimuth_deg`, `light_elevation_deg` casts shadows
// (`shadows`).
//
// Parameters (defaults off the symmetry of the models and off the pixel grid):
//   azimuth_deg         30    camera azimuth
//   elevation_deg       20    camera elevation above the ground
//   light_azimuth_deg  -40    where the light comes from, about y
//   light_elevation_deg 55    its elevation
//   shadows             off   off | on: the light casts shadows (costly: docs/patterns.md)
#include <fmt/format.h>

#include <cmath>
#include <filesystem>
#include <map>
#include <memory>
#include <mutex>
#include <numbers>

#include "patterns/pattern.h"
#include "patterns/scene/mesh_file.h"
#include "patterns/world_builders.h"

namespace aabench {
namespace {

struct Model {
    const char* id;
    const char* path;
    const char* package;
    const char* summary;
    glm::dvec3 upright_deg;  // rotation that stands the model on y
};

constexpr const char* kGlmark = "/usr/share/glmark2/models/";
constexpr const char* kAssimp = "/usr/share/assimp/models/";

// Fit: the bounding box's diagonal after scaling, its lowest point above the ground.
constexpr double kModelDiagonal = 2.0;
constexpr double kGroundGap = 0.0013;  // off the ground: no face of the model lies in its plane
constexpr int kGroundTiles = 16;
constexpr double kGroundHalfSide = 2.0 * kModelDiagonal;
constexpr double kGroundReflectance = 0.55;
// The reflectance of a model's faces whose file gives no colour.
constexpr double kModelReflectance = 0.8;
constexpr double kFovDeg = 40.0;
constexpr double kFrameMargin = 1.08;  // the bounding sphere at 93% of the view's height

double radians(double deg) { return deg * (std::numbers::pi / 180.0); }

glm::dvec3 direction_from(double azimuth_deg, double elevation_deg) {
    const double az = radians(azimuth_deg), el = radians(elevation_deg);
    return {std::cos(el) * std::sin(az), std::sin(el), std::cos(el) * std::cos(az)};
}

// A model file is read once per process: the patterns are pure functions of their parameters
// and the file, which does not change under a running process.
std::shared_ptr<const LoadedMesh> load_model(const Model& m, const std::string& path) {
    static std::mutex mutex;
    static std::map<std::string, std::shared_ptr<const LoadedMesh>> cache;
    const std::lock_guard<std::mutex> lock(mutex);
    auto it = cache.find(m.id);
    if (it != cache.end()) return it->second;
    if (!mesh_loading_available()) {
        throw InputError(
            fmt::format("{}: this build has no mesh loading (Assimp was not found "
                        "when it was configured: install libassimp-dev)",
                        m.id));
    }
    if (!std::filesystem::exists(path)) {
        throw InputError(
            fmt::format("{}: needs {} from Debian's package {} (scripts/install-deps "
                        "installs it)",
                        m.id, path, m.package));
    }
    MeshTransform upright;
    upright.rotate_deg = m.upright_deg;
    try {
        auto mesh = std::make_shared<const LoadedMesh>(
            load_mesh_file(path, path, upright, kMaxMeshTriangles));
        cache.emplace(m.id, mesh);
        return mesh;
    } catch (const MeshError& e) {
        throw InputError(fmt::format("{}: {}", m.id, e.what()));
    }
}

Scene generate_model(const Model& m, const ParamValues& values, int width, int height) {
    Scene scene = begin_pattern_scene(m.id, values, width, height);
    const std::string path = std::string(m.path);
    const std::shared_ptr<const LoadedMesh> loaded = load_model(m, path);
    LoadedMesh mesh = *loaded;
    // Fit the box: centred over the origin, diagonal kModelDiagonal, lowest point at kGroundGap.
    glm::dvec3 lo(INFINITY), hi(-INFINITY);
    for (const glm::dvec3& v : mesh.vertices) {
        lo = glm::min(lo, v);
        hi = glm::max(hi, v);
    }
    const double scale = kModelDiagonal / glm::length(hi - lo);
    const glm::dvec3 centre = 0.5 * (lo + hi);
    for (glm::dvec3& v : mesh.vertices) {
        v = (v - centre) * scale + glm::dvec3(0.0, 0.5 * (hi.y - lo.y) * scale + kGroundGap, 0.0);
    }
    for (auto& r : mesh.reflectance) {
        if (!r) r = kModelReflectance;
    }
    World w;
    w.objects.push_back(mesh_object(mesh, m.id, path, std::nullopt, ClosedMode::kAuto));
    // The ground: tiles of two-sided quads at y = 0.
    const double step = 2.0 * kGroundHalfSide / kGroundTiles;
    for (int j = 0; j < kGroundTiles; ++j) {
        for (int i = 0; i < kGroundTiles; ++i) {
            const double x0 = -kGroundHalfSide + i * step, x1 = x0 + step;
            const double z0 = -kGroundHalfSide + j * step, z1 = z0 + step;
            w.objects.push_back(make_quad(fmt::format("ground {},{}", i, j), {x0, 0.0, z1},
                                          {x1, 0.0, z1}, {x1, 0.0, z0}, {x0, 0.0, z0},
                                          kGroundReflectance));
        }
    }
    const glm::dvec3 target(0.0, 0.5 * (hi.y - lo.y) * scale + kGroundGap, 0.0);
    const double radius = 0.5 * kModelDiagonal;
    const double distance = kFrameMargin * radius / std::sin(radians(0.5 * kFovDeg));
    w.camera.target = target;
    w.camera.eye = target + distance * direction_from(values.get_real("azimuth_deg"),
                                                      values.get_real("elevation_deg"));
    w.camera.fov_y_deg = kFovDeg;
    w.camera.near = 0.01;
    w.ambient = 0.25;
    Light sun;
    sun.direction = -direction_from(values.get_real("light_azimuth_deg"),
                                    values.get_real("light_elevation_deg"));
    sun.intensity = 0.75;
    sun.shadows = values.get_choice("shadows") == "on";
    w.lights.push_back(sun);
    const glm::dvec2 focus = project_point(w.camera, width, height, target);
    scene.world = std::move(w);
    set_focus(scene, focus.x, focus.y, kFocusSidePx);
    return scene;
}

std::vector<ParamSpec> model_params() {
    return {
        {"azimuth_deg",
         ParamKind::kReal,
         30,
         -360,
         360,
         {},
         "camera azimuth about the vertical axis, from +z toward +x (off the model's symmetry)"},
        {"elevation_deg",
         ParamKind::kReal,
         20,
         -5,
         89,
         {},
         "camera elevation above the ground: the model's silhouette against the ground"},
        {"light_azimuth_deg",
         ParamKind::kReal,
         -40,
         -360,
         360,
         {},
         "where the light comes from, about the vertical axis"},
        {"light_elevation_deg",
         ParamKind::kReal,
         55,
         1,
         90,
         {},
         "the light's elevation: lower throws longer shadows"},
        {"shadows",
         ParamKind::kChoice,
         0,
         0,
         0,
         {"off", "on"},
         "the light casts shadows (the model onto the ground and onto itself); off by default: "
         "on, every frame pays the shadow stage and the many cells it cuts, seconds at 256x256 "
         "for the bunny, horse and truck, minutes and 19 GB for the engine (docs/patterns.md)"},
    };
}

PatternInfo model_pattern(const Model& m) {
    PatternInfo info{m.id, m.summary, model_params(),
                     [m](const ParamValues& values, int width, int height) {
                         return generate_model(m, values, width, height);
                     }};
    info.in_default_run = false;
    info.model_file = true;
    return info;
}

const std::string glmark(const char* file) { return std::string(kGlmark) + file; }
const std::string assimp(const char* file) { return std::string(kAssimp) + file; }

}  // namespace

PatternInfo bunny_pattern() {
    static const std::string path = glmark("bunny.obj");
    return model_pattern({"bunny",
                          path.c_str(),
                          "glmark2-data",
                          "3-D mesh: the Stanford bunny (glmark2-data), on a ground plane under "
                          "a shadowing light",
                          {0.0, 0.0, 0.0}});
}

PatternInfo horse_pattern() {
    static const std::string path = glmark("horse.3ds");
    return model_pattern({"horse",
                          path.c_str(),
                          "glmark2-data",
                          "3-D mesh: a horse (glmark2-data, 3DS), on a ground plane under a "
                          "shadowing light",
                          {90.0, 0.0, 0.0}});
}

PatternInfo engine_pattern() {
    static const std::string path = assimp("glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb");
    return model_pattern({"engine",
                          path.c_str(),
                          "assimp-testmodels",
                          "3-D mesh: a two-cylinder engine (assimp-testmodels, glTF binary): "
                          "many parts hiding each other",
                          {0.0, 0.0, 0.0}});
}

PatternInfo truck_pattern() {
    static const std::string path = assimp("glTF/CesiumMilkTruck/CesiumMilkTruck.gltf");
    return model_pattern({"truck",
                          path.c_str(),
                          "assimp-testmodels",
                          "3-D mesh: Cesium's milk truck (assimp-testmodels, glTF)",
                          {0.0, 0.0, 0.0}});
}

}  // namespace aabench
