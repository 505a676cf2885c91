// Scene file reader and writer (docs/scene-format.md).
//
// Reading is two passes. nlohmann's SAX parser drives JsonBuilder, which builds an ordered_json
// tree (so metadata keeps the file's order) while keeping track of where it is, so that the
// errors the parser cannot give a JSON path for themselves — a duplicated key (nlohmann's own
// DOM parser silently keeps the last one) and a number too large for a double (nlohmann stops
// with out_of_range.406 and no position) — still name the path. Then SceneReader walks the tree
// and checks every key, type and limit, building the Scene as it goes. A faster parser for the
// plain JSON that scene files are made of (plain_json_parser.h) drives the same JsonBuilder
// first; whenever it gives up or anything is refused, nlohmann's parser reads the text again
// and decides, so the messages and values are nlohmann's in every case.
//
// Writing lays the text out by hand (one line per top-level key, shape and contour) but every
// number and string goes through nlohmann's own dump(), whose doubles are the shortest text
// that reads back to the same bits, integral values keep their ".0" so they read back as
// floats, and -0.0 is written as "-0.0".
#include "patterns/scene/scene_io.h"

#include <fmt/format.h>
#include <sys/stat.h>

#include <cerrno>
#include <climits>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <memory>
#include <nlohmann/json.hpp>
#include <string_view>
#include <vector>

#include "patterns/scene/bezier.h"
#include "patterns/scene/curves.h"
#include "patterns/scene/json_builder.h"
#include "patterns/scene/plain_json_parser.h"
#include "patterns/scene/scene_io_detail.h"

namespace aabench {
namespace {

using namespace scene_io_detail;

// Version 1: 2-D shapes. Version 2 adds the 3-D world (scene_io_world.cpp) and exact curves,
// version 3 a sequence (scene_io_sequence.cpp), version 4 Bezier segments and `svg_path`; a
// file is written in the lowest version that holds it, so files without the newer keys stay
// what they were.
constexpr int kSceneVersion = 1;
constexpr int kWorldVersion = 2;
constexpr int kSequenceVersion = 3;
constexpr int kBezierVersion = 4;
constexpr int kLatestVersion = kBezierVersion;
// Curves: centres within 1e9 px and radii up to 1e6 px (docs/scene-format.md: the closed-form
// area works relative to the centre, so its error grows with ulp(coordinate)).
constexpr double kMaxCurveCoordinate = 1e9;
constexpr double kMaxCurveRadius = 1e6;

// --- Pass 2: the tree -> Scene, checking every key, type and limit ---

class SceneReader {
public:
    SceneReader(const std::string& source, const BulkValues& bulk) : source_(source), bulk_(bulk) {}

    Scene read(const Json& root) {
        if (!root.is_object()) {
            fail(source_, "", "expected a JSON object at the top level, found " + describe(root));
        }
        // The version first: a newer file's new keys should be reported as a newer version,
        // not as unknown keys.
        const int version = root.contains("version") ? read_version(root["version"]) : 1;
        if (version == 1) {
            check_keys(
                root, "",
                {"version", "width", "height", "origin", "background", "metadata", "shapes"});
        } else if (version == kWorldVersion) {
            check_keys(root, "",
                       {"version", "width", "height", "origin", "background", "metadata", "shapes",
                        "camera", "ambient", "lights", "objects", "edges", "effects"});
        } else {
            check_keys(root, "",
                       {"version", "width", "height", "origin", "background", "metadata", "shapes",
                        "camera", "ambient", "lights", "objects", "edges", "effects", "sequence"});
        }

        Scene scene;
        const long long width = read_side(root, "width");
        const long long height = read_side(root, "height");
        const bool width_ok = width >= 1 && width <= kMaxImageSide;
        const bool height_ok = height >= 1 && height <= kMaxImageSide;
        check_image_size(width, height,
                         fmt::format("{}: {}", source_,
                                     !width_ok    ? "width"
                                     : !height_ok ? "height"
                                                  : "width, height"));
        scene.width = static_cast<int>(width);
        scene.height = static_cast<int>(height);

        if (root.contains("origin")) {
            const Json& origin = root["origin"];
            const bool ok = origin.is_array() && origin.size() == 2 && origin[0].is_number() &&
                            origin[1].is_number() && std::isfinite(origin[0].get<double>()) &&
                            std::isfinite(origin[1].get<double>());
            if (!ok) {
                fail(source_, "origin",
                     "expected a point [x, y] of two finite numbers, found " + describe(origin));
            }
            scene.origin_x = origin[0].get<double>();
            scene.origin_y = origin[1].get<double>();
            if (!(std::abs(scene.origin_x) <= kMaxCoordinate &&
                  std::abs(scene.origin_y) <= kMaxCoordinate)) {
                fail(source_, "origin", "beyond the coordinate limit of 1e300 px (docs/limits.md)");
            }
        }
        if (root.contains("background")) {
            const ShapeValue bg = read_shape_value(root["background"], "background", version);
            scene.background = bg.value;
            scene.background_rgb = bg.rgb;
        }
        if (root.contains("metadata")) scene.metadata = read_metadata(root["metadata"]);

        if (root.contains("objects")) {
            if (root.contains("shapes")) {
                fail(source_, "shapes", "a file has objects (3-D) or shapes (2-D), not both");
            }
            if (root.contains("origin")) {
                fail(source_, "origin", "a 3-D scene has no window origin (the camera places it)");
            }
            scene.world = read_world(root, source_, bulk_);
            // A colour background or any colour in the world: a colour world, three channels.
            if (colour_ || scene.world->is_colour()) {
                scene.channels = 3;
                // The edge stage (Saito & Takahashi 1990) composites its lines over one grey
                // image; it has no colour form yet.
                if (scene.world->edges) {
                    fail(source_, "edges",
                         "a colour world has no edge stage (its lines composite over a grey "
                         "image): give grey values, or leave out \"edges\"");
                }
            }
            return with_sequence(root, std::move(scene));
        }
        for (const char* key : {"camera", "ambient", "lights", "edges", "effects"}) {
            if (root.contains(key)) {
                fail(source_, key, "belongs to a 3-D scene, and this file has no \"objects\"");
            }
        }
        const Json& shapes = require(root, "", "shapes");
        if (!shapes.is_array()) {
            fail(source_, "shapes", "expected an array of shapes, found " + describe(shapes));
        }
        scene.shapes.reserve(shapes.size());
        for (std::size_t i = 0; i < shapes.size(); ++i) {
            scene.shapes.push_back(read_shape(shapes[i], child_path("shapes", i), version));
        }
        if (colour_) scene.channels = 3;
        return with_sequence(root, std::move(scene));
    }

private:
    // Last, as the motions a sequence may have depend on the scene (2-D or 3-D, its camera).
    Scene with_sequence(const Json& root, Scene scene) {
        if (root.contains("sequence")) {
            scene.sequence = read_sequence(root["sequence"], source_, scene);
        }
        return scene;
    }

    int read_version(const Json& value) {
        if (!value.is_number_integer()) {
            fail(source_, "version",
                 fmt::format("expected the integer 1, 2, 3 or {}, found {}", kLatestVersion,
                             describe(value)));
        }
        if (value < Json(1) || value > Json(kLatestVersion)) {
            fail(source_, "version",
                 fmt::format("unsupported version {} (this reader knows versions 1 to {})",
                             value.dump(), kLatestVersion));
        }
        return value.get<int>();
    }

    void check_keys(const Json& object, const std::string& path,
                    std::initializer_list<std::string_view> allowed) {
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

    long long read_side(const Json& root, const std::string& key) {
        const Json& value = require(root, "", key);
        if (!value.is_number_integer()) {
            fail(source_, key, "expected an integer number of pixels, found " + describe(value));
        }
        if (value.is_number_unsigned() && value.get<std::uint64_t>() > LLONG_MAX) {
            // Too large for long long, so check_image_size cannot say it; say it here.
            fail(source_, key,
                 fmt::format("{} is out of range 1..{} per side", value.dump(), kMaxImageSide));
        }
        return value.get<long long>();
    }

    double read_real(const Json& value, const std::string& path) {
        // Integers are numbers too (`"value": 1`); JSON text cannot hold inf or NaN, and the
        // builder rejected overflow, but a tree can: check anyway.
        if (!value.is_number() || !std::isfinite(value.get<double>())) {
            fail(source_, path, "expected a finite number, found " + describe(value));
        }
        return value.get<double>();
    }

    double read_value(const Json& value, const std::string& path) {
        return read_image_value(value, source_, path);
    }

    // A value that may be a colour: a number, or (version 4) [r, g, b] of three numbers within
    // +-kMaxValue. A colour's shape keeps its luminance as its value (Shape::value).
    struct ShapeValue {
        double value = 1.0;
        std::optional<Rgb> rgb;
    };
    ShapeValue read_shape_value(const Json& value, const std::string& path, int version) {
        if (!value.is_array()) return {read_value(value, path), std::nullopt};
        const Rgb rgb = read_rgb(value, source_, path, version);
        colour_ = true;
        return {luminance(rgb), rgb};
    }
    ShapeValue optional_shape_value(const Json& shape, const std::string& path, int version) {
        if (!shape.contains("value")) return {};
        return read_shape_value(shape["value"], child_path(path, "value"), version);
    }

    Metadata read_metadata(const Json& value) {
        if (!value.is_object()) {
            fail(source_, "metadata",
                 "expected an object of string values, found " + describe(value));
        }
        Metadata metadata;
        for (const auto& item : value.items()) {
            if (!item.value().is_string()) {
                fail(source_, child_path("metadata", item.key()),
                     "expected a string value, found " + describe(item.value()));
            }
            metadata.emplace_back(item.key(), item.value().get<std::string>());
        }
        return metadata;
    }

    Shape read_shape(const Json& value, const std::string& path, int version) {
        if (!value.is_object())
            fail(source_, path, "expected a shape object, found " + describe(value));
        const Json& type = require(value, path, "type");
        if (!type.is_string()) {
            fail(source_, child_path(path, "type"), "expected a string, found " + describe(type));
        }
        const std::string& type_name = type.get_ref<const std::string&>();
        if (version >= 2 && (type_name == "disc" || type_name == "ring")) {
            return coloured(read_curve(value, path, type_name == "disc"),
                            optional_shape_value(value, path, version));
        }
        if (version >= kBezierVersion && type_name == "path") {
            check_keys(value, path, {"type", "value", "svg_path"});
            const ShapeValue shape_value = optional_shape_value(value, path, version);
            return coloured(BezierReader(source_, curve_vertices_)
                                .path(require(value, path, "svg_path"),
                                      child_path(path, "svg_path"), shape_value.value),
                            shape_value);
        }
        if (version >= kBezierVersion && type_name == "text") {
            check_keys(value, path,
                       {"type", "value", "font", "string", "size_px", "origin", "kerning",
                        "letter_spacing_px"});
            const ShapeValue shape_value = optional_shape_value(value, path, version);
            return coloured(
                BezierReader(source_, curve_vertices_).text(value, path, shape_value.value),
                shape_value);
        }
        if (type_name != "polygon") {
            fail(source_, child_path(path, "type"),
                 fmt::format("unknown shape type \"{}\" (version {} has: {})", printable(type_name),
                             version,
                             version >= kBezierVersion ? "polygon, disc, ring, path, text"
                             : version >= 2            ? "polygon, disc, ring"
                                                       : "polygon"));
        }
        check_keys(value, path, {"type", "value", "contours"});

        const ShapeValue shape_value = optional_shape_value(value, path, version);
        const std::string contours_path = child_path(path, "contours");
        const Json& contours = require(value, path, "contours");
        if (!contours.is_array()) {
            fail(source_, contours_path,
                 "expected an array of contours, found " + describe(contours));
        }
        if (contours.empty()) fail(source_, contours_path, "a shape needs at least one contour");
        if (version < kBezierVersion) refuse_curve_items(contours, source_, contours_path, version);
        if (version >= kBezierVersion && has_curve_item(contours)) {
            return coloured(BezierReader(source_, curve_vertices_)
                                .polygon(contours, contours_path, shape_value.value),
                            shape_value);
        }
        Shape shape;
        shape.value = shape_value.value;
        shape.rgb = shape_value.rgb;
        shape.contours.reserve(contours.size());
        for (std::size_t k = 0; k < contours.size(); ++k) {
            shape.contours.push_back(read_contour(contours[k], child_path(contours_path, k)));
        }
        return shape;
    }

    // A version-2 `disc` (center, radius) or `ring` (center, inner, outer): exact curves with
    // their polygonisation (patterns/scene/curves.h).
    Shape read_curve(const Json& value, const std::string& path, bool disc) {
        if (disc) {
            check_keys(value, path, {"type", "value", "center", "radius"});
        } else {
            check_keys(value, path, {"type", "value", "center", "inner", "outer"});
        }
        const double shape_value =
            value.contains("value") && value["value"].is_array()
                ? 1.0  // a colour: read_shape sets it
                : value.contains("value") ? read_value(value["value"], child_path(path, "value"))
                                          : 1.0;
        const std::string center_path = child_path(path, "center");
        const Json& center = require(value, path, "center");
        const bool ok = center.is_array() && center.size() == 2 && center[0].is_number() &&
                        center[1].is_number() && std::isfinite(center[0].get<double>()) &&
                        std::isfinite(center[1].get<double>());
        if (!ok) {
            fail(source_, center_path,
                 "expected a point [x, y] of two finite numbers, found " + describe(center));
        }
        const Point c{center[0].get<double>(), center[1].get<double>()};
        if (!(std::abs(c.x) <= kMaxCurveCoordinate && std::abs(c.y) <= kMaxCurveCoordinate)) {
            fail(source_, center_path,
                 "a curve's centre must lie within 1e9 px of the origin (docs/scene-format.md)");
        }
        auto radius = [&](const char* key) {
            const double r = read_real(require(value, path, key), child_path(path, key));
            if (!(r > 0.0 && r <= kMaxCurveRadius)) {
                fail(source_, child_path(path, key),
                     fmt::format("radius {} is out of range (0, {}] px", Json(r).dump(),
                                 kMaxCurveRadius));
            }
            return r;
        };
        if (disc) {
            const double r = radius("radius");
            count_curve_vertices(path, curve_segment_count(r));
            return disc_shape(c, r, shape_value);
        }
        const double inner = radius("inner");
        const double outer = radius("outer");
        if (!(inner < outer)) {
            fail(source_, child_path(path, "inner"),
                 fmt::format("inner radius {} must be less than the outer radius {}",
                             Json(inner).dump(), Json(outer).dump()));
        }
        count_curve_vertices(path, curve_segment_count(inner) + curve_segment_count(outer));
        return ring_shape(c, inner, outer, shape_value);
    }

    // `shape` with the colour it was given (its value is the colour's luminance).
    static Shape coloured(Shape shape, const ShapeValue& value) {
        shape.value = value.value;
        shape.rgb = value.rgb;
        return shape;
    }

    // The polygonisation's vertices count against the scene's vertex limit like written ones.
    void count_curve_vertices(const std::string& path, long long vertices) {
        curve_vertices_ += vertices;
        if (curve_vertices_ > kMaxSceneVertices) {
            fail(source_, path,
                 fmt::format("the curves' polygonisation needs more than {} vertices "
                             "(docs/scene-format.md)",
                             kMaxSceneVertices));
        }
    }

    Contour read_contour(const Json& value, const std::string& path) {
        if (!value.is_array()) {
            fail(source_, path,
                 "expected a contour (an array of points), found " + describe(value));
        }
        if (value.size() < 3) {
            fail(source_, path,
                 fmt::format("a contour needs at least 3 points, found {}", value.size()));
        }
        Contour contour;
        contour.reserve(value.size());
        for (std::size_t p = 0; p < value.size(); ++p) {
            const Json& point = value[p];
            const bool ok = point.is_array() && point.size() == 2 && point[0].is_number() &&
                            point[1].is_number() && std::isfinite(point[0].get<double>()) &&
                            std::isfinite(point[1].get<double>());
            if (!ok) {
                fail(source_, child_path(path, p),
                     "expected a point [x, y] of two finite numbers, found " + describe(point));
            }
            for (int axis = 0; axis < 2; ++axis) {
                const double v = point[axis].get<double>();
                if (!(std::abs(v) <= kMaxCoordinate)) {
                    fail(source_, child_path(child_path(path, p), axis),
                         fmt::format("coordinate {} is beyond the limit of 1e300 px "
                                     "(docs/limits.md)",
                                     describe(point[axis])));
                }
            }
            contour.push_back({point[0].get<double>(), point[1].get<double>()});
        }
        return contour;
    }

    const std::string& source_;
    const BulkValues& bulk_;
    long long curve_vertices_ = 0;
    bool colour_ = false;  // some value was a colour: a colour scene
};

// --- Writer ---

[[noreturn]] void fail_not_finite(const std::string& path, double value) {
    throw InputError(
        fmt::format("scene_to_json: {}: {} is not finite and JSON cannot hold it", path, value));
}

std::string json_number(double value, const std::string& path) {
    if (!std::isfinite(value)) fail_not_finite(path, value);
    return Json(value).dump();
}

std::string json_string(const std::string& value, const std::string& path) {
    try {
        return Json(value).dump();
    } catch (const nlohmann::json::type_error&) {
        // type_error.316: invalid UTF-8. Replacing the bytes would break the round trip.
        throw InputError(
            fmt::format("scene_to_json: {}: \"{}\" is not valid UTF-8", path, printable(value)));
    }
}

void append_contour(std::string& out, const Contour& contour, const std::string& path) {
    out += '[';
    for (std::size_t p = 0; p < contour.size(); ++p) {
        const Point& point = contour[p];
        // The path is built only on failure: this loop runs once per vertex.
        if (!std::isfinite(point.x)) fail_not_finite(child_path(path, p), point.x);
        if (!std::isfinite(point.y)) fail_not_finite(child_path(path, p), point.y);
        out += p == 0 ? "[" : ",[";
        out += Json(point.x).dump();
        out += ',';
        out += Json(point.y).dump();
        out += ']';
    }
    out += ']';
}

std::string json_colour(const Rgb& rgb, const std::string& path) {
    std::string out = "[";
    for (std::size_t c = 0; c < 3; ++c) {
        out += (c == 0 ? "" : ", ") + json_number(rgb[c], child_path(path, c));
    }
    return out + "]";
}

// A shape's value as the file holds it: its colour where it has one, else its number.
std::string json_shape_value(const Shape& shape, const std::string& path) {
    return shape.rgb ? json_colour(*shape.rgb, path) : json_number(shape.value, path);
}

std::string curve_to_json(const Shape& shape, const std::string& path) {
    const Circle& c = *shape.circle;
    std::string out = fmt::format("{{\"type\": \"{}\", \"value\": {}, \"center\": [{},{}], ",
                                  c.is_disc() ? "disc" : "ring",
                                  json_shape_value(shape, child_path(path, "value")),
                                  json_number(c.center.x, child_path(path, "center")),
                                  json_number(c.center.y, child_path(path, "center")));
    if (c.is_disc()) {
        out += fmt::format("\"radius\": {}}}", json_number(c.outer, child_path(path, "radius")));
    } else {
        out += fmt::format("\"inner\": {}, \"outer\": {}}}",
                           json_number(c.inner, child_path(path, "inner")),
                           json_number(c.outer, child_path(path, "outer")));
    }
    return out;
}

}  // namespace

Scene parse_scene_json(const std::string& text, const std::string& source, long long max_vertices) {
    if (text.find_first_not_of(" \t\r\n") == std::string::npos) {
        fail(source, "", "empty file (expected a JSON scene object)");
    }
    {
        // The fast path (plain_json_parser.h). When it gives up or the builder refuses what
        // it was sent, nlohmann parses the text again from the start below and decides: the
        // fast path changes no message and no value, only the time of the common case.
        JsonBuilder builder(source, max_vertices);
        bool parsed = false;
        try {
            parsed = parse_plain_json(text, builder);
        } catch (const InputError&) {
        }
        if (parsed) return SceneReader(source, builder.bulk()).read(builder.root());
    }
    JsonBuilder builder(source, max_vertices);
    // strict: trailing text after the value is an error. Every failure throws from the builder.
    Json::sax_parse(text, &builder, Json::input_format_t::json, /*strict=*/true);
    return SceneReader(source, builder.bulk()).read(builder.root());
}

Scene read_scene_file(const std::string& path) {
    const std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(path.c_str(), "rb"),
                                                               &std::fclose);
    if (!file) throw InputError(fmt::format("{}: cannot open: {}", path, std::strerror(errno)));
    std::string text;
    // Room for the whole file up front: growing the string by doubling copied a 28 MB file
    // about twice over. (A size that is wrong or unknown, as for a pipe, only costs the growth.)
    struct stat status {};
    if (fstat(fileno(file.get()), &status) == 0 && S_ISREG(status.st_mode) && status.st_size > 0) {
        text.reserve(static_cast<std::size_t>(status.st_size));
    }
    char buffer[1 << 16];
    std::size_t count = 0;
    while ((count = std::fread(buffer, 1, sizeof buffer, file.get())) > 0) {
        text.append(buffer, count);
    }
    // A directory opens fine and fails here, with errno EISDIR.
    if (std::ferror(file.get())) {
        throw InputError(fmt::format("{}: cannot read: {}", path, std::strerror(errno)));
    }
    return parse_scene_json(text, path);
}

std::string scene_to_json(const Scene& scene) {
    std::string out = "{\n";
    const bool colour = scene.channels == 3 || (scene.world && scene.world->is_colour());
    const int version = has_bezier(scene) || colour        ? kBezierVersion
                        : scene.sequence                   ? kSequenceVersion
                        : scene.world || has_curves(scene) ? kWorldVersion
                                                           : kSceneVersion;
    out += fmt::format("  \"version\": {},\n", version);
    out += fmt::format("  \"width\": {},\n", scene.width);
    out += fmt::format("  \"height\": {},\n", scene.height);
    // Written only when set, so a plain scene's file stays plain; -0.0 counts as set, as the
    // round trip is bit for bit.
    if (!is_window_frame(scene) || std::signbit(scene.origin_x) || std::signbit(scene.origin_y)) {
        out += fmt::format("  \"origin\": [{},{}],\n", json_number(scene.origin_x, "origin[0]"),
                           json_number(scene.origin_y, "origin[1]"));
    }
    // A colour scene's background is written as a colour even when grey: the array is what
    // makes the file a colour scene again.
    const Rgb grey_background{scene.background, scene.background, scene.background};
    out += fmt::format("  \"background\": {},\n",
                       colour ? json_colour(scene.background_rgb.value_or(grey_background),
                                            "background")
                              : json_number(scene.background, "background"));
    if (!scene.metadata.empty()) {
        out += "  \"metadata\": {";
        for (std::size_t i = 0; i < scene.metadata.size(); ++i) {
            const auto& [key, value] = scene.metadata[i];
            const std::string path = child_path("metadata", key);
            out += fmt::format("{}{}: {}", i == 0 ? "" : ", ", json_string(key, path),
                               json_string(value, path));
        }
        out += "},\n";
    }
    if (scene.sequence) {
        out +=
            "  \"sequence\": " + sequence_to_json(*scene.sequence, scene.world.has_value()) + ",\n";
    }
    if (scene.world) return out + world_to_json(*scene.world) + "}\n";
    out += "  \"shapes\": [";
    for (std::size_t i = 0; i < scene.shapes.size(); ++i) {
        const Shape& shape = scene.shapes[i];
        const std::string shape_path = child_path("shapes", i);
        if (shape.circle) {  // the curve itself; the reader makes the same polygonisation again
            out += (i == 0 ? "\n    " : ",\n    ") + curve_to_json(shape, shape_path);
            continue;
        }
        out += fmt::format("{}\n    {{\"type\": \"polygon\", \"value\": {}, \"contours\": [",
                           i == 0 ? "" : ",",
                           json_shape_value(shape, child_path(shape_path, "value")));
        const std::string contours_path = child_path(shape_path, "contours");
        if (has_bezier(shape)) {  // the outline; the reader makes the same flattening again
            for (std::size_t k = 0; k < shape.outline.size(); ++k) {
                out += k == 0 ? "\n      " : ",\n      ";
                append_segment_contour(out, shape.outline[k], child_path(contours_path, k));
            }
            out += "\n    ]}";
            continue;
        }
        for (std::size_t k = 0; k < shape.contours.size(); ++k) {
            out += k == 0 ? "\n      " : ",\n      ";
            append_contour(out, shape.contours[k], child_path(contours_path, k));
        }
        out += "\n    ]}";
    }
    out += scene.shapes.empty() ? "]\n" : "\n  ]\n";
    out += "}\n";
    return out;
}

}  // namespace aabench
