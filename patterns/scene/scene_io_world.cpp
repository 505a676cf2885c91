// The version-2 world in a scene file (docs/scene-format.md, "Version 2"): camera, ambient,
// lights, objects with faces and patterns, edges, effects. Strict like version 1: every key
// checked, every error one line naming its JSON path; defaults are world.h's member
// initialisers. The writer is exact (doubles through nlohmann's shortest round-trip text), so
// reading a written world gives it back bit for bit.
#include <cmath>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "patterns/scene/scene_io_detail.h"

namespace aabench::scene_io_detail {
namespace {

class WorldReader {
public:
    explicit WorldReader(const std::string& source) : source_(source) {}

    World read(const Json& root) {
        World w;
        w.camera = read_camera(require(root, "", "camera"));
        if (root.contains("ambient")) w.ambient = real(root["ambient"], "ambient");
        if (root.contains("lights")) {
            const Json& lights = array(root["lights"], "lights", "lights");
            for (std::size_t i = 0; i < lights.size(); ++i) {
                w.lights.push_back(read_light(lights[i], child_path("lights", i)));
            }
        }
        const Json& objects = array(root["objects"], "objects", "objects");
        for (std::size_t i = 0; i < objects.size(); ++i) {
            w.objects.push_back(read_object(objects[i], child_path("objects", i)));
        }
        if (root.contains("edges")) w.edges = read_edges(root["edges"]);
        if (root.contains("effects")) w.effects = read_effects(root["effects"]);
        return w;
    }

private:
    void keys(const Json& object, const std::string& path, const std::string& what,
              std::initializer_list<std::string_view> allowed) {
        if (!object.is_object()) fail(source_, path, "expected " + what + ", found " + describe(object));
        for (const auto& item : object.items()) {
            bool known = false;
            for (std::string_view name : allowed) known = known || item.key() == name;
            if (!known) {
                fail(source_, child_path(path, item.key()),
                     fmt::format("unknown key (expected one of: {})", fmt::join(allowed, ", ")));
            }
        }
    }
    const Json& require(const Json& object, const std::string& path, const std::string& key) {
        const auto it = object.find(key);
        if (it == object.end()) fail(source_, child_path(path, key), "required key is missing");
        return *it;
    }
    const Json& array(const Json& value, const std::string& path, const std::string& what) {
        if (!value.is_array()) fail(source_, path, "expected an array of " + what + ", found " + describe(value));
        return value;
    }
    double real(const Json& value, const std::string& path) {
        if (!value.is_number() || !std::isfinite(value.get<double>())) {
            fail(source_, path, "expected a finite number, found " + describe(value));
        }
        return value.get<double>();
    }
    bool boolean(const Json& value, const std::string& path) {
        if (!value.is_boolean()) fail(source_, path, "expected true or false, found " + describe(value));
        return value.get<bool>();
    }
    std::string choice(const Json& value, const std::string& path,
                       std::initializer_list<std::string_view> allowed) {
        if (value.is_string()) {
            for (std::string_view a : allowed) {
                if (value.get_ref<const std::string&>() == a) return std::string(a);
            }
        }
        fail(source_, path, fmt::format("expected one of \"{}\", found {}",
                                        fmt::join(allowed, "\", \""), describe(value)));
    }
    glm::dvec3 vec3(const Json& value, const std::string& path) {
        const bool ok = value.is_array() && value.size() == 3 && value[0].is_number() &&
                        value[1].is_number() && value[2].is_number();
        if (!ok) fail(source_, path, "expected a point [x, y, z] of three finite numbers, found " + describe(value));
        glm::dvec3 v;
        for (int k = 0; k < 3; ++k) v[k] = real(value[k], child_path(path, static_cast<std::size_t>(k)));
        return v;
    }

    Camera read_camera(const Json& value) {
        keys(value, "camera", "a camera object", {"eye", "target", "up", "fov_y_deg", "near"});
        Camera c;
        c.eye = vec3(require(value, "camera", "eye"), "camera.eye");
        c.target = vec3(require(value, "camera", "target"), "camera.target");
        if (value.contains("up")) c.up = vec3(value["up"], "camera.up");
        if (value.contains("fov_y_deg")) c.fov_y_deg = real(value["fov_y_deg"], "camera.fov_y_deg");
        if (value.contains("near")) c.near = real(value["near"], "camera.near");
        return c;
    }

    Light read_light(const Json& value, const std::string& path) {
        if (!value.is_object()) fail(source_, path, "expected a light object, found " + describe(value));
        Light l;
        const std::string type = choice(require(value, path, "type"), child_path(path, "type"),
                                        {"parallel", "point"});
        if (type == "parallel") {
            keys(value, path, "a light object", {"type", "direction", "intensity", "shadows"});
            l.type = LightType::kParallel;
            l.direction = vec3(require(value, path, "direction"), child_path(path, "direction"));
        } else {
            keys(value, path, "a light object", {"type", "position", "intensity", "shadows"});
            l.type = LightType::kPoint;
            l.position = vec3(require(value, path, "position"), child_path(path, "position"));
        }
        if (value.contains("intensity")) l.intensity = real(value["intensity"], child_path(path, "intensity"));
        if (value.contains("shadows")) l.shadows = boolean(value["shadows"], child_path(path, "shadows"));
        return l;
    }

    Object read_object(const Json& value, const std::string& path) {
        keys(value, path, "an object", {"name", "closed", "vertices", "faces"});
        Object o;
        if (value.contains("name")) {
            if (!value["name"].is_string()) {
                fail(source_, child_path(path, "name"), "expected a string, found " + describe(value["name"]));
            }
            o.name = value["name"].get<std::string>();
        }
        if (value.contains("closed")) o.closed = boolean(value["closed"], child_path(path, "closed"));
        const std::string vpath = child_path(path, "vertices");
        const Json& vertices = array(require(value, path, "vertices"), vpath, "points [x, y, z]");
        for (std::size_t i = 0; i < vertices.size(); ++i) {
            o.vertices.push_back(vec3(vertices[i], child_path(vpath, i)));
        }
        const std::string fpath = child_path(path, "faces");
        const Json& faces = array(require(value, path, "faces"), fpath, "faces");
        for (std::size_t i = 0; i < faces.size(); ++i) {
            o.faces.push_back(read_face(faces[i], child_path(fpath, i)));
        }
        return o;
    }

    Face read_face(const Json& value, const std::string& path) {
        keys(value, path, "a face object", {"loop", "reflectance", "mirror", "patterns"});
        Face f;
        const std::string lpath = child_path(path, "loop");
        const Json& loop = array(require(value, path, "loop"), lpath, "vertex indices");
        for (std::size_t i = 0; i < loop.size(); ++i) {
            const Json& index = loop[i];
            if (!index.is_number_integer() || index.get<long long>() < 0 ||
                index.get<long long>() > (1LL << 30)) {
                fail(source_, child_path(lpath, i), "expected a vertex index (an integer >= 0), found " + describe(index));
            }
            f.loop.push_back(index.get<int>());
        }
        if (value.contains("reflectance")) f.reflectance = real(value["reflectance"], child_path(path, "reflectance"));
        if (value.contains("mirror")) f.mirror = real(value["mirror"], child_path(path, "mirror"));
        if (value.contains("patterns")) {
            const std::string ppath = child_path(path, "patterns");
            const Json& patterns = array(value["patterns"], ppath, "patterns");
            for (std::size_t i = 0; i < patterns.size(); ++i) {
                const std::string pp = child_path(ppath, i);
                keys(patterns[i], pp, "a pattern object", {"loop", "reflectance"});
                FacePattern p;
                const Json& ploop = array(require(patterns[i], pp, "loop"), child_path(pp, "loop"), "points [x, y, z]");
                for (std::size_t k = 0; k < ploop.size(); ++k) {
                    p.loop.push_back(vec3(ploop[k], child_path(child_path(pp, "loop"), k)));
                }
                p.reflectance = real(require(patterns[i], pp, "reflectance"), child_path(pp, "reflectance"));
                f.patterns.push_back(std::move(p));
            }
        }
        return f;
    }

    EdgesSpec read_edges(const Json& value) {
        keys(value, "edges", "an edges object",
             {"contour", "crease", "kp", "kl", "style", "contour_weight", "crease_weight"});
        EdgesSpec e;
        if (value.contains("contour")) e.contour = choice(value["contour"], "edges.contour", {"sobel", "prewitt"});
        if (value.contains("crease")) {
            e.crease = choice(value["crease"], "edges.crease", {"laplacian4", "laplacian8", "none"});
        }
        if (value.contains("kp")) e.kp = real(value["kp"], "edges.kp");
        if (value.contains("kl")) e.kl = real(value["kl"], "edges.kl");
        if (value.contains("style")) e.style = choice(value["style"], "edges.style", {"black", "white-convex"});
        if (value.contains("contour_weight")) e.contour_weight = real(value["contour_weight"], "edges.contour_weight");
        if (value.contains("crease_weight")) e.crease_weight = real(value["crease_weight"], "edges.crease_weight");
        return e;
    }

    EffectSwitches read_effects(const Json& value) {
        keys(value, "effects", "an effects object", {"shadows", "patterns", "shading", "edges", "reflections"});
        EffectSwitches e;
        auto get = [&](const char* key, bool& out) {
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
};

std::string num(double v) {
    if (!std::isfinite(v)) throw InputError(fmt::format("scene_to_json: {} is not finite", v));
    return Json(v).dump();
}
std::string vec(const glm::dvec3& v) { return "[" + num(v.x) + "," + num(v.y) + "," + num(v.z) + "]"; }
std::string boolean_text(bool b) { return b ? "true" : "false"; }

std::string object_json(const Object& o) {
    std::string out = fmt::format("    {{\"name\": {}, \"closed\": {},\n     \"vertices\": [",
                                  Json(o.name).dump(), boolean_text(o.closed));
    for (std::size_t i = 0; i < o.vertices.size(); ++i) out += (i ? "," : "") + vec(o.vertices[i]);
    out += "],\n     \"faces\": [";
    for (std::size_t i = 0; i < o.faces.size(); ++i) {
        const Face& f = o.faces[i];
        out += fmt::format("{}\n      {{\"loop\": [{}], \"reflectance\": {}, \"mirror\": {}", i ? "," : "",
                           fmt::join(f.loop, ","), num(f.reflectance), num(f.mirror));
        if (!f.patterns.empty()) {
            out += ", \"patterns\": [";
            for (std::size_t k = 0; k < f.patterns.size(); ++k) {
                std::string loop;
                for (std::size_t j = 0; j < f.patterns[k].loop.size(); ++j) {
                    loop += (j ? "," : "") + vec(f.patterns[k].loop[j]);
                }
                out += fmt::format("{}{{\"loop\": [{}], \"reflectance\": {}}}", k ? ", " : "", loop,
                                   num(f.patterns[k].reflectance));
            }
            out += "]";
        }
        out += "}";
    }
    return out + "]}";
}

}  // namespace

World read_world(const Json& root, const std::string& source) {
    World w = WorldReader(source).read(root);
    check_world(w, source);
    return w;
}

std::string world_to_json(const World& w) {
    const Camera& c = w.camera;
    std::string out = fmt::format(
        "  \"camera\": {{\"eye\": {}, \"target\": {}, \"up\": {}, \"fov_y_deg\": {}, \"near\": {}}},\n",
        vec(c.eye), vec(c.target), vec(c.up), num(c.fov_y_deg), num(c.near));
    out += fmt::format("  \"ambient\": {},\n  \"lights\": [", num(w.ambient));
    for (std::size_t i = 0; i < w.lights.size(); ++i) {
        const Light& l = w.lights[i];
        out += fmt::format("{}\n    {{\"type\": \"{}\", \"{}\": {}, \"intensity\": {}, \"shadows\": {}}}",
                           i ? "," : "", l.type == LightType::kParallel ? "parallel" : "point",
                           l.type == LightType::kParallel ? "direction" : "position",
                           vec(l.type == LightType::kParallel ? l.direction : l.position),
                           num(l.intensity), boolean_text(l.shadows));
    }
    out += w.lights.empty() ? "],\n" : "\n  ],\n";
    out += "  \"objects\": [";
    for (std::size_t i = 0; i < w.objects.size(); ++i) out += (i ? ",\n" : "\n") + object_json(w.objects[i]);
    out += w.objects.empty() ? "],\n" : "\n  ],\n";
    if (w.edges) {
        const EdgesSpec& e = *w.edges;
        out += fmt::format(
            "  \"edges\": {{\"contour\": {}, \"crease\": {}, \"kp\": {}, \"kl\": {}, \"style\": {}, "
            "\"contour_weight\": {}, \"crease_weight\": {}}},\n",
            Json(e.contour).dump(), Json(e.crease).dump(), num(e.kp), num(e.kl), Json(e.style).dump(),
            num(e.contour_weight), num(e.crease_weight));
    }
    const EffectSwitches& s = w.effects;
    out += fmt::format(
        "  \"effects\": {{\"shadows\": {}, \"patterns\": {}, \"shading\": {}, \"edges\": {}, "
        "\"reflections\": {}}}\n",
        boolean_text(s.shadows), boolean_text(s.patterns), boolean_text(s.shading),
        boolean_text(s.edges), boolean_text(s.reflections));
    return out;
}

}  // namespace aabench::scene_io_detail
