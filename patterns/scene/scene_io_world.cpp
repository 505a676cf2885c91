// The version-2 world in a scene file (docs/scene-format.md, "Version 2"): camera, ambient,
// lights, objects with faces and patterns, edges, effects.
//
// The reader is strict like version 1: every key checked against the keys its object may have,
// every type checked, every error one line naming its JSON path. A missing optional key takes
// world.h's member initialiser, so the defaults live in one place. The geometry (indices,
// planarity, convexity, camera) is checked afterwards by check_world (world_check.cpp), which
// generators' worlds go through too.
//
// The writer is exact: every double through nlohmann's dump() (the shortest text that reads
// back to the same bits, -0.0 kept), every key written, defaults included, so reading a
// written world gives it back bit for bit.
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <climits>
#include <cmath>
#include <initializer_list>
#include <stdexcept>
#include <string_view>

#include <filesystem>
#include <optional>

#include "patterns/scene/mesh_file.h"
#include "patterns/scene/scene_io_detail.h"

namespace aabench::scene_io_detail {
namespace {

// --- Reader ---

// Mesh objects (`"mesh"`) need this version (docs/scene-format.md, "Version 4: meshes").
constexpr int kMeshVersion = 4;

class WorldReader {
public:
    WorldReader(const std::string& source, const BulkValues& bulk, int version)
        : source_(source), bulk_(bulk), version_(version) {}

    World read(const Json& root) {
        World w;
        w.camera = read_camera(require(root, "", "camera"));
        if (root.contains("ambient"))
            grey_or_colour(root["ambient"], "ambient", w.ambient, w.ambient_rgb);
        if (root.contains("lights")) {
            const Json& lights = array(root["lights"], "lights", "lights");
            for (std::size_t i = 0; i < lights.size(); ++i) {
                w.lights.push_back(read_light(lights[i], child_path("lights", i)));
            }
        }
        const Json& objects = array(require(root, "", "objects"), "objects", "objects");
        for (std::size_t i = 0; i < objects.size(); ++i) {
            w.objects.push_back(read_object(objects[i], child_path("objects", i)));
        }
        if (root.contains("edges")) w.edges = read_edges(root["edges"]);
        if (root.contains("effects")) w.effects = read_effects(root["effects"]);
        return w;
    }

private:
    // `value` must be an object (`what` names it) with no key outside `allowed`.
    void keys(const Json& value, const LazyPath& path, const char* what,
              std::initializer_list<std::string_view> allowed) {
        if (!value.is_object()) {
            fail(source_, path.str(),
                 std::string("expected ") + what + ", found " + describe(value));
        }
        for (const auto& item : value.items()) {
            bool known = false;
            for (std::string_view name : allowed) known = known || item.key() == name;
            if (!known) {
                fail(source_, child_path(path.str(), item.key()),
                     fmt::format("unknown key (expected one of: {})", fmt::join(allowed, ", ")));
            }
        }
    }

    const Json& require(const Json& object, const LazyPath& path, const char* key) {
        const auto it = object.find(key);
        if (it == object.end()) {
            fail(source_, child_path(path.str(), std::string(key)), "required key is missing");
        }
        return *it;
    }

    const Json& array(const Json& value, const LazyPath& path, const char* what) {
        if (!value.is_array()) {
            fail(source_, path.str(),
                 std::string("expected an array of ") + what + ", found " + describe(value));
        }
        return value;
    }

    double real(const Json& value, const LazyPath& path) {
        // JSON text cannot hold inf or NaN and the builder refused overflow; a tree can: check.
        if (!value.is_number() || !std::isfinite(value.get<double>())) {
            fail(source_, path.str(), "expected a finite number, found " + describe(value));
        }
        return value.get<double>();
    }

    // A number (grey) or, in version 4, a colour [r, g, b] (docs/scene-format.md, "Version 4:
    // colour"): `grey` gets the number, or the colour's luminance with `rgb` the colour. A grey
    // number reads as before, any finite number; a colour's components are values an image
    // holds (read_rgb).
    void grey_or_colour(const Json& value, const LazyPath& path, double& grey,
                        std::optional<Rgb>& rgb) {
        if (!value.is_array()) {
            grey = real(value, path);
            return;
        }
        rgb = read_rgb(value, source_, path, version_);
        grey = luminance(*rgb);
    }

    bool boolean(const Json& value, const std::string& path) {
        if (!value.is_boolean()) {
            fail(source_, path, "expected true or false, found " + describe(value));
        }
        return value.get<bool>();
    }

    std::string choice(const Json& value, const std::string& path,
                       std::initializer_list<std::string_view> allowed) {
        if (value.is_string()) {
            for (std::string_view a : allowed) {
                if (value.get_ref<const std::string&>() == a) return std::string(a);
            }
        }
        fail(source_, path,
             fmt::format("expected one of \"{}\", found {}", fmt::join(allowed, "\", \""),
                         describe(value)));
    }

    glm::dvec3 vec3(const Json& value, const LazyPath& path) {
        const bool ok = value.is_array() && value.size() == 3 && value[0].is_number() &&
                        value[1].is_number() && value[2].is_number();
        if (!ok) {
            fail(source_, path.str(),
                 "expected a point [x, y, z] of three finite numbers, found " + describe(value));
        }
        glm::dvec3 v;
        for (std::size_t k = 0; k < 3; ++k) v[k] = real(value[k], LazyPath(path, k));
        return v;
    }

    Camera read_camera(const Json& value) {
        keys(value, "camera", "a camera object", {"eye", "target", "up", "fov_y_deg", "near"});
        Camera c;
        c.eye = vec3(require(value, "camera", "eye"), "camera.eye");
        c.target = vec3(require(value, "camera", "target"), "camera.target");
        if (value.contains("up")) c.up = vec3(value["up"], "camera.up");
        if (value.contains("fov_y_deg")) {
            c.fov_y_deg = real(value["fov_y_deg"], "camera.fov_y_deg");
        }
        if (value.contains("near")) c.near = real(value["near"], "camera.near");
        return c;
    }

    Light read_light(const Json& value, const std::string& path) {
        if (!value.is_object()) {
            fail(source_, path, "expected a light object, found " + describe(value));
        }
        // The type first: it decides which of direction and position the light may have.
        const std::string type =
            choice(require(value, path, "type"), child_path(path, "type"), {"parallel", "point"});
        Light l;
        if (type == "parallel") {
            keys(value, path, "a light object", {"type", "direction", "intensity", "shadows"});
            l.type = LightType::kParallel;
            l.direction = vec3(require(value, path, "direction"), child_path(path, "direction"));
        } else {
            keys(value, path, "a light object", {"type", "position", "intensity", "shadows"});
            l.type = LightType::kPoint;
            l.position = vec3(require(value, path, "position"), child_path(path, "position"));
        }
        if (value.contains("intensity")) {
            grey_or_colour(value["intensity"], child_path(path, "intensity"), l.intensity,
                           l.intensity_rgb);
        }
        if (value.contains("shadows")) {
            l.shadows = boolean(value["shadows"], child_path(path, "shadows"));
        }
        return l;
    }

    Object read_object(const Json& value, const std::string& path) {
        if (value.is_object() && value.contains("mesh")) return read_mesh_object(value, path);
        keys(value, path, "an object", {"name", "closed", "vertices", "faces"});
        Object o;
        if (value.contains("name")) {
            const Json& name = value["name"];
            if (!name.is_string()) {
                fail(source_, child_path(path, "name"),
                     "expected a string, found " + describe(name));
            }
            o.name = name.get<std::string>();
        }
        if (value.contains("closed"))
            o.closed = boolean(value["closed"], child_path(path, "closed"));
        const std::string vpath = child_path(path, "vertices");
        const Json& vertices = array(require(value, path, "vertices"), vpath, "points [x, y, z]");
        o.vertices.reserve(vertices.size());
        for (std::size_t i = 0; i < vertices.size(); ++i) {
            o.vertices.push_back(
                vertices[i].is_discarded() ? next_point() : vec3(vertices[i], LazyPath(vpath, i)));
        }
        const std::string fpath = child_path(path, "faces");
        const Json& faces = array(require(value, path, "faces"), fpath, "faces");
        o.faces.reserve(faces.size());
        for (std::size_t i = 0; i < faces.size(); ++i) {
            o.faces.push_back(faces[i].is_discarded()
                                  ? next_face()
                                  : read_face(faces[i], LazyPath(fpath, i), o.vertices.size()));
        }
        return o;
    }

    // A version-4 mesh object: a model file's triangles (patterns/scene/mesh_file.h), placed by
    // its transform, as faces like any object's.
    Object read_mesh_object(const Json& value, const std::string& path) {
        keys(value, path, "a mesh object", {"name", "mesh", "transform", "reflectance", "closed"});
        const std::string mpath = child_path(path, "mesh");
        if (version_ < kMeshVersion) {
            fail(source_, mpath,
                 fmt::format("a mesh object needs \"version\": {}, and this file is version {}",
                             kMeshVersion, version_));
        }
        const Json& file = value["mesh"];
        if (!file.is_string() || file.get_ref<const std::string&>().empty()) {
            fail(source_, mpath, "expected a model file's path, found " + describe(file));
        }
        std::string name;
        if (value.contains("name")) {
            const Json& n = value["name"];
            if (!n.is_string()) {
                fail(source_, child_path(path, "name"), "expected a string, found " + describe(n));
            }
            name = n.get<std::string>();
        }
        const MeshTransform transform =
            value.contains("transform") ? read_transform(value["transform"],
                                                         child_path(path, "transform"))
                                        : MeshTransform{};
        std::optional<double> reflectance;
        std::optional<Rgb> reflectance_rgb;
        if (value.contains("reflectance")) {
            grey_or_colour(value["reflectance"], child_path(path, "reflectance"),
                           reflectance.emplace(), reflectance_rgb);
        }
        ClosedMode mode = ClosedMode::kAuto;
        if (value.contains("closed")) {
            const Json& c = value["closed"];
            if (c.is_boolean()) {
                mode = c.get<bool>() ? ClosedMode::kTrue : ClosedMode::kFalse;
            } else if (!(c.is_string() && c.get_ref<const std::string&>() == "auto")) {
                fail(source_, child_path(path, "closed"),
                     "expected true, false or \"auto\", found " + describe(c));
            }
        }
        // Relative to the scene file's folder (the working directory for standard input).
        const std::string& given = file.get_ref<const std::string&>();
        const std::filesystem::path folder = std::filesystem::path(source_).parent_path();
        const std::string resolved = std::filesystem::path(given).is_absolute() || folder.empty()
                                         ? given
                                         : (folder / given).string();
        LoadedMesh mesh;
        try {
            mesh = load_mesh_file(resolved, printable(resolved, false, 400), transform,
                                  kMaxMeshTriangles - mesh_triangles_);
        } catch (const MeshError& e) {
            fail(source_, mpath, printable(e.what(), false, 400));
        }
        mesh_triangles_ += static_cast<long long>(mesh.triangles.size());
        return mesh_object(mesh, name, given, reflectance, mode, MeshColours::kColour,
                           reflectance_rgb);
    }

    MeshTransform read_transform(const Json& value, const std::string& path) {
        keys(value, path, "a transform object", {"scale", "rotate_deg", "translate"});
        MeshTransform t;
        if (value.contains("scale")) {
            const Json& s = value["scale"];
            const std::string spath = child_path(path, "scale");
            t.scale = s.is_number() ? glm::dvec3(real(s, spath)) : vec3(s, spath);
            for (int k = 0; k < 3; ++k) {
                if (t.scale[k] == 0.0) {
                    fail(source_, spath, "a zero scale flattens the mesh to no area");
                }
            }
        }
        if (value.contains("rotate_deg")) {
            t.rotate_deg = vec3(value["rotate_deg"], child_path(path, "rotate_deg"));
        }
        if (value.contains("translate")) {
            t.translate = vec3(value["translate"], child_path(path, "translate"));
        }
        return t;
    }

    Face read_face(const Json& value, const LazyPath& path, std::size_t vertex_count) {
        keys(value, path, "a face object", {"loop", "reflectance", "mirror", "patterns"});
        Face f;
        const LazyPath lpath(path, "loop");
        const Json& loop_value = require(value, path, "loop");
        if (loop_value.is_discarded()) {
            read_face_rest(value, path, next_loop(), f);
            return f;
        }
        const Json& loop = array(loop_value, lpath, "vertex indices");
        f.loop.reserve(loop.size());
        for (std::size_t i = 0; i < loop.size(); ++i) {
            const Json& index = loop[i];
            // Non-negative integers parse as unsigned; a negative one is signed.
            const bool negative = index.is_number_integer() && !index.is_number_unsigned() &&
                                  index.get<long long>() < 0;
            if (!index.is_number_integer() || negative) {
                fail(source_, LazyPath(lpath, i).str(),
                     "expected a vertex index (an integer >= 0), found " + describe(index));
            }
            // Past INT_MAX it cannot be stored in the model, and no object has that many
            // vertices; say so here, in check_world's words.
            if (index.get<unsigned long long>() > INT_MAX) {
                fail(source_, LazyPath(lpath, i).str(),
                     fmt::format("index {} out of range (the object has {} vertices)", index.dump(),
                                 vertex_count));
            }
            f.loop.push_back(index.get<int>());
        }
        read_face_rest(value, path, {}, f);
        return f;
    }

    // All of a face but its loop's indices (`loop`, when they came from the bulk values).
    void read_face_rest(const Json& value, const LazyPath& path, std::vector<int> loop, Face& f) {
        if (!loop.empty()) f.loop = std::move(loop);
        if (value.contains("reflectance")) {
            grey_or_colour(value["reflectance"], LazyPath(path, "reflectance"), f.reflectance,
                           f.reflectance_rgb);
        }
        if (value.contains("mirror")) f.mirror = real(value["mirror"], LazyPath(path, "mirror"));
        if (value.contains("patterns")) {
            const std::string ppath = child_path(path.str(), std::string("patterns"));
            const Json& patterns = array(value["patterns"], ppath, "patterns");
            for (std::size_t i = 0; i < patterns.size(); ++i) {
                f.patterns.push_back(read_pattern(patterns[i], child_path(ppath, i)));
            }
        }
    }

    // The bulk values in document order (BulkValues): the reader visits the placeholders in
    // the order the parser made them.
    glm::dvec3 next_point() {
        if (next_point_ >= bulk_.points.size()) throw std::logic_error("scene reader: points");
        return bulk_.points[next_point_++];
    }
    std::vector<int> next_loop() {
        if (next_loop_ >= bulk_.loops.size()) throw std::logic_error("scene reader: loops");
        const auto [start, count] = bulk_.loops[next_loop_++];
        const auto first = bulk_.loop_indices.begin() + static_cast<std::ptrdiff_t>(start);
        return std::vector<int>(first, first + static_cast<std::ptrdiff_t>(count));
    }
    // A face the builder checked already: its keys known, its values finite numbers.
    Face next_face() {
        if (next_face_ >= bulk_.faces.size()) throw std::logic_error("scene reader: faces");
        const BulkFace& bulk = bulk_.faces[next_face_++];
        Face f;
        f.loop = next_loop();
        if (bulk.reflectance) f.reflectance = *bulk.reflectance;
        if (bulk.mirror) f.mirror = *bulk.mirror;
        return f;
    }

    FacePattern read_pattern(const Json& value, const std::string& path) {
        keys(value, path, "a pattern object", {"loop", "reflectance"});
        FacePattern p;
        const std::string lpath = child_path(path, "loop");
        const Json& loop = array(require(value, path, "loop"), lpath, "points [x, y, z]");
        for (std::size_t k = 0; k < loop.size(); ++k) {
            p.loop.push_back(vec3(loop[k], child_path(lpath, k)));
        }
        grey_or_colour(require(value, path, "reflectance"), child_path(path, "reflectance"),
                       p.reflectance, p.reflectance_rgb);
        return p;
    }

    EdgesSpec read_edges(const Json& value) {
        keys(value, "edges", "an edges object",
             {"contour", "crease", "kp", "kl", "style", "contour_weight", "crease_weight"});
        EdgesSpec e;
        if (value.contains("contour")) {
            e.contour = choice(value["contour"], "edges.contour", {"sobel", "prewitt"});
        }
        if (value.contains("crease")) {
            e.crease =
                choice(value["crease"], "edges.crease", {"laplacian4", "laplacian8", "none"});
        }
        if (value.contains("kp")) e.kp = real(value["kp"], "edges.kp");
        if (value.contains("kl")) e.kl = real(value["kl"], "edges.kl");
        if (value.contains("style")) {
            e.style = choice(value["style"], "edges.style", {"black", "white-convex"});
        }
        if (value.contains("contour_weight")) {
            e.contour_weight = real(value["contour_weight"], "edges.contour_weight");
        }
        if (value.contains("crease_weight")) {
            e.crease_weight = real(value["crease_weight"], "edges.crease_weight");
        }
        return e;
    }

    EffectSwitches read_effects(const Json& value) {
        keys(value, "effects", "an effects object",
             {"shadows", "patterns", "shading", "edges", "reflections"});
        EffectSwitches e;
        const auto get = [&](const char* key, bool& out) {
            if (value.contains(key)) out = boolean(value[key], child_path("effects", key));
        };
        get("shadows", e.shadows);
        get("patterns", e.patterns);
        get("shading", e.shading);
        get("edges", e.edges);
        get("reflections", e.reflections);
        return e;
    }

    const std::string& source_;
    const BulkValues& bulk_;
    int version_ = 1;
    long long mesh_triangles_ = 0;  // all mesh objects' so far, against kMaxMeshTriangles
    std::size_t next_point_ = 0;
    std::size_t next_loop_ = 0;
    std::size_t next_face_ = 0;
};

// --- Writer ---

// Paths are built only when a value is refused (`path` is a callable): the writer visits every
// vertex, and a path string per coordinate would cost more than the number's text.
template <typename PathFn>
std::string number(double v, const PathFn& path) {
    if (!std::isfinite(v)) {
        throw InputError(
            fmt::format("scene_to_json: {}: {} is not finite and JSON cannot hold it", path(), v));
    }
    return Json(v).dump();
}

template <typename PathFn>
std::string point(const glm::dvec3& v, const PathFn& path) {
    std::string out = "[";
    for (std::size_t k = 0; k < 3; ++k) {
        if (k > 0) out += ',';
        out += number(v[k], [&] { return child_path(path(), k); });
    }
    return out + "]";
}

std::string text(const std::string& value, const std::string& path) {
    try {
        return Json(value).dump();
    } catch (const nlohmann::json::type_error&) {
        // type_error.316: invalid UTF-8. Replacing the bytes would break the round trip.
        throw InputError(
            fmt::format("scene_to_json: {}: \"{}\" is not valid UTF-8", path, printable(value)));
    }
}

const char* boolean_text(bool b) { return b ? "true" : "false"; }

// A grey number, or a colour [r, g, b] where the value has one.
template <typename PathFn>
std::string grey_or_colour(double grey, const std::optional<Rgb>& rgb, const PathFn& path) {
    if (!rgb) return number(grey, path);
    std::string out = "[";
    for (std::size_t k = 0; k < 3; ++k) {
        if (k > 0) out += ", ";
        out += number((*rgb)[k], [&] { return child_path(path(), k); });
    }
    return out + "]";
}

std::string pattern_json(const FacePattern& p, const std::string& path) {
    std::string loop;
    for (std::size_t j = 0; j < p.loop.size(); ++j) {
        if (j > 0) loop += ',';
        loop += point(p.loop[j], [&] { return child_path(child_path(path, "loop"), j); });
    }
    return fmt::format("{{\"loop\": [{}], \"reflectance\": {}}}", loop,
                       grey_or_colour(p.reflectance, p.reflectance_rgb,
                                      [&] { return child_path(path, "reflectance"); }));
}

std::string face_json(const Face& f, const std::string& path) {
    std::string out =
        fmt::format("{{\"loop\": [{}], \"reflectance\": {}, \"mirror\": {}", fmt::join(f.loop, ","),
                    grey_or_colour(f.reflectance, f.reflectance_rgb,
                                   [&] { return child_path(path, "reflectance"); }),
                    number(f.mirror, [&] { return child_path(path, "mirror"); }));
    if (!f.patterns.empty()) {
        out += ", \"patterns\": [";
        for (std::size_t k = 0; k < f.patterns.size(); ++k) {
            if (k > 0) out += ", ";
            out += pattern_json(f.patterns[k], child_path(child_path(path, "patterns"), k));
        }
        out += "]";
    }
    return out + "}";
}

// One line for the name, one for the vertices, one per face.
std::string object_json(const Object& o, const std::string& path) {
    std::string out = fmt::format("    {{\"name\": {}, \"closed\": {},\n     \"vertices\": [",
                                  text(o.name, child_path(path, "name")), boolean_text(o.closed));
    for (std::size_t i = 0; i < o.vertices.size(); ++i) {
        if (i > 0) out += ',';
        out += point(o.vertices[i], [&] { return child_path(child_path(path, "vertices"), i); });
    }
    out += "],\n     \"faces\": [";
    for (std::size_t i = 0; i < o.faces.size(); ++i) {
        out += i > 0 ? ",\n      " : "\n      ";
        out += face_json(o.faces[i], child_path(child_path(path, "faces"), i));
    }
    return out + "]}";
}

std::string light_json(const Light& l, const std::string& path) {
    const bool parallel = l.type == LightType::kParallel;
    const char* key = parallel ? "direction" : "position";
    return fmt::format(
        "    {{\"type\": \"{}\", \"{}\": {}, \"intensity\": {}, \"shadows\": {}}}",
        parallel ? "parallel" : "point", key,
        point(parallel ? l.direction : l.position, [&] { return child_path(path, key); }),
        grey_or_colour(l.intensity, l.intensity_rgb, [&] { return child_path(path, "intensity"); }),
        boolean_text(l.shadows));
}

std::string edges_json(const EdgesSpec& e) {
    const auto at = [](const char* key) { return [key] { return child_path("edges", key); }; };
    return fmt::format(
        "  \"edges\": {{\"contour\": {}, \"crease\": {}, \"kp\": {}, \"kl\": {}, \"style\": {}, "
        "\"contour_weight\": {}, \"crease_weight\": {}}},\n",
        text(e.contour, "edges.contour"), text(e.crease, "edges.crease"), number(e.kp, at("kp")),
        number(e.kl, at("kl")), text(e.style, "edges.style"),
        number(e.contour_weight, at("contour_weight")),
        number(e.crease_weight, at("crease_weight")));
}

}  // namespace

World read_world(const Json& root, const std::string& source, const BulkValues& bulk) {
    // The caller checked the version already.
    const int version = root.contains("version") ? root["version"].get<int>() : 1;
    World w = WorldReader(source, bulk, version).read(root);
    check_world(w, source);
    return w;
}

std::string world_to_json(const World& w) {
    const Camera& c = w.camera;
    const auto at = [](const char* key) { return [key] { return child_path("camera", key); }; };
    std::string out = fmt::format(
        "  \"camera\": {{\"eye\": {}, \"target\": {}, \"up\": {}, \"fov_y_deg\": {}, "
        "\"near\": {}}},\n",
        point(c.eye, at("eye")), point(c.target, at("target")), point(c.up, at("up")),
        number(c.fov_y_deg, at("fov_y_deg")), number(c.near, at("near")));
    out += fmt::format("  \"ambient\": {},\n", grey_or_colour(w.ambient, w.ambient_rgb, [] {
                           return std::string("ambient");
                       }));
    out += "  \"lights\": [";
    for (std::size_t i = 0; i < w.lights.size(); ++i) {
        out += i > 0 ? ",\n" : "\n";
        out += light_json(w.lights[i], child_path("lights", i));
    }
    out += w.lights.empty() ? "],\n" : "\n  ],\n";
    out += "  \"objects\": [";
    for (std::size_t i = 0; i < w.objects.size(); ++i) {
        out += i > 0 ? ",\n" : "\n";
        out += object_json(w.objects[i], child_path("objects", i));
    }
    out += w.objects.empty() ? "],\n" : "\n  ],\n";
    if (w.edges) out += edges_json(*w.edges);
    const EffectSwitches& s = w.effects;
    out += fmt::format(
        "  \"effects\": {{\"shadows\": {}, \"patterns\": {}, \"shading\": {}, \"edges\": {}, "
        "\"reflections\": {}}}\n",
        boolean_text(s.shadows), boolean_text(s.patterns), boolean_text(s.shading),
        boolean_text(s.edges), boolean_text(s.reflections));
    return out;
}

}  // namespace aabench::scene_io_detail
