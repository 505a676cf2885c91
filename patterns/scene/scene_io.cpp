// Scene file reader and writer (docs/scene-format.md).
//
// Reading is two passes. nlohmann's SAX parser drives JsonBuilder, which builds an ordered_json
// tree (so metadata keeps the file's order) while keeping track of where it is, so that the
// errors the parser cannot give a JSON path for themselves — a duplicated key (nlohmann's own
// DOM parser silently keeps the last one) and a number too large for a double (nlohmann stops
// with out_of_range.406 and no position) — still name the path. Then SceneReader walks the tree
// and checks every key, type and limit, building the Scene as it goes.
//
// Writing lays the text out by hand (one line per top-level key, shape and contour) but every
// number and string goes through nlohmann's own dump(), whose doubles are the shortest text
// that reads back to the same bits, integral values keep their ".0" so they read back as
// floats, and -0.0 is written as "-0.0".
#include "patterns/scene/scene_io.h"

#include "patterns/scene/curves.h"

#include <fmt/format.h>

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

#include "patterns/scene/scene_io_detail.h"

namespace aabench {
namespace scene_io_detail {

[[noreturn]] void fail(const std::string& source, const std::string& path,
                       const std::string& problem) {
    if (path.empty()) throw InputError(fmt::format("{}: {}", source, problem));
    throw InputError(fmt::format("{}: {}: {}", source, path, problem));
}

bool is_plain_name(const std::string& key) {
    if (key.empty()) return false;
    for (char c : key) {
        const bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') ||
                        (c >= '0' && c <= '9') || c == '_' || c == '-';
        if (!ok) return false;
    }
    return true;
}

// Keeps a message to one line of printable ASCII: control and non-ASCII bytes (which may not
// even be valid UTF-8 when the error is about encoding) are shown as \xNN.
std::string printable(std::string_view text, bool escape_quotes, std::size_t max_chars) {
    std::string out;
    const bool cut = text.size() > max_chars;
    for (unsigned char c : text.substr(0, max_chars)) {
        if (escape_quotes && (c == '"' || c == '\\')) {
            out += '\\';
            out += static_cast<char>(c);
        } else if (c >= 0x20 && c < 0x7f) {
            out += static_cast<char>(c);
        } else {
            out += fmt::format("\\x{:02x}", c);
        }
    }
    if (cut) out += "...";
    return out;
}

// `shapes[3].contours`: plain keys joined by dots, anything else quoted in brackets so the path
// stays unambiguous (`metadata["a.b"]`).
std::string child_path(const std::string& path, const std::string& key) {
    if (is_plain_name(key)) return path.empty() ? key : path + "." + key;
    return path + "[\"" + printable(key, /*escape_quotes=*/true) + "\"]";
}

std::string child_path(const std::string& path, std::size_t index) {
    return fmt::format("{}[{}]", path, index);
}

std::string describe(const Json& value) {
    switch (value.type()) {
        case Json::value_t::null:
            return "null";
        case Json::value_t::boolean:
            return value.get<bool>() ? "true" : "false";
        case Json::value_t::number_integer:
        case Json::value_t::number_unsigned:
        case Json::value_t::number_float:
            return value.dump();
        case Json::value_t::string:
            return "the string \"" +
                   printable(value.get_ref<const std::string&>(), /*escape_quotes=*/true) + "\"";
        case Json::value_t::array: {
            // Small arrays are clearest shown as they are (`["1",2]`); big ones by their size.
            const std::string text = value.dump();
            if (text.size() <= kMaxQuotedChars) return printable(text);
            return fmt::format("an array of {} elements", value.size());
        }
        case Json::value_t::object:
            return "an object";
        default:
            return value.type_name();
    }
}

}  // namespace scene_io_detail

namespace {

using namespace scene_io_detail;

// A version-1 scene nests 6 levels (root, shapes, shape, contours, contour, point), a version-2
// one 9 (root, objects, object, faces, face, patterns, pattern, loop, point); anything far
// deeper is not a scene, and stopping early keeps a hostile file from building a deep tree.
// (The message keeps saying 6, the version-1 figure, so version-1 errors stay as they were.)
constexpr std::size_t kMaxNesting = 32;
// What the tree builder reserves for a new array (see JsonBuilder::start_array).
constexpr std::size_t kSmallArray = 4;

// Version 1: 2-D shapes. Version 2 adds the 3-D world (scene_io_world.cpp); a file is written
// as version 1 unless it has a world, so 2-D files stay what they were.
constexpr int kSceneVersion = 1;
constexpr int kLatestVersion = 2;
// Curves: centres within 1e9 px and radii up to 1e6 px (docs/scene-format.md: the closed-form
// area works relative to the centre, so its error grows with ulp(coordinate)).
constexpr double kMaxCurveCoordinate = 1e9;
constexpr double kMaxCurveRadius = 1e6;

// --- Pass 1: JSON text -> ordered_json tree, with paths for the parser's own errors ---

class JsonBuilder {
public:
    JsonBuilder(const std::string& source, long long max_vertices)
        : source_(source), max_vertices_(max_vertices) {}

    Json& root() { return root_; }
    const BulkValues& bulk() const { return bulk_; }

    bool null() { return put(Json(nullptr)); }
    bool boolean(bool value) { return put(Json(value)); }
    bool number_integer(Json::number_integer_t value) { return number(Json(value)); }
    bool number_unsigned(Json::number_unsigned_t value) { return number(Json(value)); }
    bool number_float(Json::number_float_t value, const std::string&) {
        return number(Json(value));
    }
    bool string(std::string& value) { return put(Json(std::move(value))); }
    bool binary(Json::binary_t&) { return put(Json(nullptr)); }  // never produced by JSON text

    bool start_object(std::size_t) { return open(Json::object()); }
    bool start_array(std::size_t) { return open(Json::array()); }
    bool end_object() { return close(); }
    bool end_array() {
        if (gather_ == Gather::kPoint && pending_count_ == 3) {
            bulk_.points.push_back(
                {pending_[0].get<double>(), pending_[1].get<double>(), pending_[2].get<double>()});
        } else if (gather_ == Gather::kLoop) {
            bulk_.loops.push_back({loop_start_, bulk_.loop_indices.size() - loop_start_});
        } else {
            materialize();  // a point of fewer than three numbers: the reader says so
            return close();
        }
        gather_ = Gather::kNone;
        return put(Json(Json::value_t::discarded));
    }

    bool key(std::string& key) {
        Frame& frame = stack_.back();
        if (frame.node->contains(key)) {
            fail(source_, child_path(container_path(), key),
                 "duplicate key (each key may appear once)");
        }
        frame.key = key;
        return true;
    }

    bool parse_error(std::size_t position, const std::string& last_token,
                     const nlohmann::json::exception& error) {
        materialize();  // so that the path names the element being read
        if (error.id == 406) {
            // out_of_range.406: a number that overflows a double (1e999). JSON has no infinity,
            // and nlohmann refuses to make one; say where it was rather than the byte.
            fail(source_, pending_path(),
                 fmt::format("number {} is not a finite double", printable(last_token)));
        }
        throw InputError(fmt::format("{}: byte {}: invalid JSON ({})", source_, position,
                                     short_reason(error.what())));
    }

private:
    struct Frame {
        Json* node;       // the open container; stable, see slot()
        std::string key;  // objects: the key whose value comes next
    };

    // Where the next value goes. A pointer into the parent stays valid while the child is open
    // because nothing else is added to the parent until the child closes.
    Json* slot() {
        if (stack_.empty()) return &root_;
        Frame& frame = stack_.back();
        if (frame.node->is_array()) {
            frame.node->push_back(nullptr);
            return &frame.node->back();
        }
        return &(*frame.node)[frame.key];
    }

    bool put(Json&& value) {
        materialize();
        *slot() = std::move(value);
        return true;
    }

    // A number goes into the point or loop being gathered when it fits there.
    bool number(Json&& value) {
        if (gather_ == Gather::kPoint && pending_count_ < 3) {
            pending_[pending_count_++] = std::move(value);
            return true;
        }
        if (gather_ == Gather::kLoop && value.is_number_unsigned() &&
            value.get<std::uint64_t>() <= static_cast<std::uint64_t>(INT_MAX)) {
            bulk_.loop_indices.push_back(value.get<int>());
            return true;
        }
        return put(std::move(value));
    }

    // The array being gathered stops being one: it becomes the tree's array, with what was
    // gathered so far, and parsing goes on as for any array.
    void materialize() {
        if (gather_ == Gather::kNone) return;
        Json array = Json::array();
        if (gather_ == Gather::kPoint) {
            for (int k = 0; k < pending_count_; ++k) array.push_back(std::move(pending_[k]));
        } else {
            for (std::size_t k = loop_start_; k < bulk_.loop_indices.size(); ++k) {
                array.push_back(Json(static_cast<Json::number_unsigned_t>(bulk_.loop_indices[k])));
            }
            bulk_.loop_indices.resize(loop_start_);
        }
        gather_ = Gather::kNone;
        Json* node = slot();
        *node = std::move(array);
        stack_.push_back({node, {}});
    }

    bool open(Json&& container) {
        materialize();
        if (stack_.size() >= kMaxNesting) {
            fail(source_, pending_path(),
                 fmt::format("nested more than {} levels deep (a scene needs 6)", kMaxNesting));
        }
        const bool point = opens_point();
        if (point && ++points_ > max_vertices_) {
            // Checked as the points stream in, so a hostile file cannot make the tree huge.
            fail(source_, pending_path(),
                 fmt::format("more than {} vertices in the scene (the limit, docs/limits.md)",
                             max_vertices_));
        }
        if (container.is_array() && point && stack_.size() == 4) {  // objects[o].vertices[v]
            gather_ = Gather::kPoint;
            pending_count_ = 0;
            return true;
        }
        if (container.is_array() && opens_face_loop()) {
            gather_ = Gather::kLoop;
            loop_start_ = bulk_.loop_indices.size();
            return true;
        }
        if (container.is_array()) {
            // Most other arrays of a scene are points of 3 numbers: room for 4 up front makes
            // one allocation where growing from empty made three.
            container.get_ref<Json::array_t&>().reserve(kSmallArray);
        }
        Json* node = slot();
        *node = std::move(container);
        stack_.push_back({node, {}});
        return true;
    }

    bool close() {
        stack_.pop_back();
        return true;
    }

    // The container about to open is a point that counts toward the vertex limit: a 2-D point
    // root.shapes[s].contours[k][p], or (version 2) a 3-D vertex root.objects[o].vertices[v] or
    // a pattern's point root.objects[o].faces[f].patterns[p].loop[k]. The parents' types are
    // checked too, so that `"shapes": {"contours": ...}` and the like do not count.
    bool opens_point() const {
        const auto key_at = [&](std::size_t level, std::string_view key) {
            return stack_[level].node->is_object() && stack_[level].key == key;
        };
        const auto array_at = [&](std::size_t level) { return stack_[level].node->is_array(); };
        switch (stack_.size()) {
            case 5:
                return key_at(0, "shapes") && array_at(1) && key_at(2, "contours") && array_at(3) &&
                       array_at(4);
            case 4:
                return key_at(0, "objects") && array_at(1) && key_at(2, "vertices") && array_at(3);
            case 8:
                return key_at(0, "objects") && array_at(1) && key_at(2, "faces") && array_at(3) &&
                       key_at(4, "patterns") && array_at(5) && key_at(6, "loop") && array_at(7);
            default:
                return false;
        }
    }

    // The container about to open is a face's loop, root.objects[o].faces[f].loop.
    bool opens_face_loop() const {
        const auto key_at = [&](std::size_t level, std::string_view key) {
            return stack_[level].node->is_object() && stack_[level].key == key;
        };
        const auto array_at = [&](std::size_t level) { return stack_[level].node->is_array(); };
        return stack_.size() == 5 && key_at(0, "objects") && array_at(1) && key_at(2, "faces") &&
               array_at(3) && key_at(4, "loop");
    }

    // Path of the innermost open container, rebuilt only when an error needs it.
    std::string container_path() const {
        std::string path;
        for (std::size_t i = 1; i < stack_.size(); ++i) {
            const Frame& parent = stack_[i - 1];
            path = parent.node->is_array() ? child_path(path, parent.node->size() - 1)
                                           : child_path(path, parent.key);
        }
        return path;
    }

    // Path of the value being parsed now (not yet stored).
    std::string pending_path() const {
        if (stack_.empty()) return "";
        const Frame& frame = stack_.back();
        return frame.node->is_array() ? child_path(container_path(), frame.node->size())
                                      : child_path(container_path(), frame.key);
    }

    // nlohmann says "[json.exception.parse_error.101] parse error at line 1, column 6: syntax
    // error while parsing value - unexpected '}'; expected '[', '{', or a literal". Keep from the
    // line onwards: it says what was expected, and the line helps in an editor.
    static std::string short_reason(std::string_view what) {
        constexpr std::string_view kPrefix = "parse error at ";
        if (const auto at = what.find(kPrefix); at != std::string_view::npos) {
            what.remove_prefix(at + kPrefix.size());
        } else if (const auto bracket = what.find("] "); bracket != std::string_view::npos) {
            what.remove_prefix(bracket + 2);
        }
        return printable(what, /*escape_quotes=*/false, std::string_view::npos);
    }

    const std::string& source_;
    Json root_;
    std::vector<Frame> stack_;
    long long max_vertices_;
    long long points_ = 0;
    // The vertex or face loop being gathered into bulk_ rather than the tree (BulkValues).
    enum class Gather { kNone, kPoint, kLoop };
    Gather gather_ = Gather::kNone;
    Json pending_[3];  // kPoint: the numbers so far, as parsed (a message shows them as written)
    int pending_count_ = 0;
    std::size_t loop_start_ = 0;  // kLoop: where its indices start in bulk_.loop_indices
    BulkValues bulk_;
};

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
        } else {
            check_keys(root, "",
                       {"version", "width", "height", "origin", "background", "metadata", "shapes",
                        "camera", "ambient", "lights", "objects", "edges", "effects"});
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
            scene.background = read_real(root["background"], "background");
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
            return scene;
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
        return scene;
    }

private:
    int read_version(const Json& value) {
        if (!value.is_number_integer()) {
            fail(source_, "version",
                 fmt::format("expected the integer 1 or {}, found {}", kLatestVersion,
                             describe(value)));
        }
        if (value != Json(1) && value != Json(kLatestVersion)) {
            fail(source_, "version",
                 fmt::format("unsupported version {} (this reader knows versions 1 and {})",
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
            return read_curve(value, path, type_name == "disc");
        }
        if (type_name != "polygon") {
            fail(source_, child_path(path, "type"),
                 fmt::format("unknown shape type \"{}\" (version {} has: {})", printable(type_name),
                             version, version >= 2 ? "polygon, disc, ring" : "polygon"));
        }
        check_keys(value, path, {"type", "value", "contours"});

        Shape shape;
        if (value.contains("value")) {
            shape.value = read_real(value["value"], child_path(path, "value"));
        }
        const std::string contours_path = child_path(path, "contours");
        const Json& contours = require(value, path, "contours");
        if (!contours.is_array()) {
            fail(source_, contours_path,
                 "expected an array of contours, found " + describe(contours));
        }
        if (contours.empty()) fail(source_, contours_path, "a shape needs at least one contour");
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
            value.contains("value") ? read_real(value["value"], child_path(path, "value")) : 1.0;
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

std::string curve_to_json(const Shape& shape, const std::string& path) {
    const Circle& c = *shape.circle;
    std::string out = fmt::format(
        "{{\"type\": \"{}\", \"value\": {}, \"center\": [{},{}], ", c.is_disc() ? "disc" : "ring",
        json_number(shape.value, child_path(path, "value")),
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
    out += fmt::format("  \"version\": {},\n",
                       scene.world || has_curves(scene) ? kLatestVersion : kSceneVersion);
    out += fmt::format("  \"width\": {},\n", scene.width);
    out += fmt::format("  \"height\": {},\n", scene.height);
    // Written only when set, so a plain scene's file stays plain; -0.0 counts as set, as the
    // round trip is bit for bit.
    if (has_origin(scene) || std::signbit(scene.origin_x) || std::signbit(scene.origin_y)) {
        out += fmt::format("  \"origin\": [{},{}],\n", json_number(scene.origin_x, "origin[0]"),
                           json_number(scene.origin_y, "origin[1]"));
    }
    out += fmt::format("  \"background\": {},\n", json_number(scene.background, "background"));
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
                           json_number(shape.value, child_path(shape_path, "value")));
        for (std::size_t k = 0; k < shape.contours.size(); ++k) {
            out += k == 0 ? "\n      " : ",\n      ";
            append_contour(out, shape.contours[k],
                           child_path(child_path(shape_path, "contours"), k));
        }
        out += "\n    ]}";
    }
    out += scene.shapes.empty() ? "]\n" : "\n  ]\n";
    out += "}\n";
    return out;
}

}  // namespace aabench
