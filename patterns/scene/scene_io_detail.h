// Internal to the scene file reader and writer (scene_io.cpp, scene_io_world.cpp,
// scene_io_sequence.cpp, world_check.cpp; the shared pieces in scene_io_detail.cpp): the
// one-line error with its JSON path, and how values are shown in it.
#pragma once

#include <cstddef>
#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "patterns/scene/scene.h"

namespace aabench::scene_io_detail {

using Json = nlohmann::ordered_json;

// Long tokens and strings are cut in messages so the message stays one readable line.
inline constexpr std::size_t kMaxQuotedChars = 40;

// Throws InputError "<source>: <path>: <problem>" (or "<source>: <problem>" at the top).
[[noreturn]] void fail(const std::string& source, const std::string& path,
                       const std::string& problem);
bool is_plain_name(const std::string& key);
// One line of printable ASCII; other bytes as \xNN; cut at max_chars with "...".
std::string printable(std::string_view text, bool escape_quotes = false,
                      std::size_t max_chars = kMaxQuotedChars);
// `shapes[3].contours`: plain keys joined by dots, anything else quoted in brackets.
std::string child_path(const std::string& path, const std::string& key);
std::string child_path(const std::string& path, std::size_t index);
// A JSON path turned into text only when an error names it. The reader visits every vertex and
// face: a path string per coordinate and per loop index (a formatted string each) cost more
// than the number it named, a third of reading a 200,000-face file. A LazyPath refers to its
// parent and to strings that outlive the call it is passed to.
class LazyPath {
public:
    LazyPath(const std::string& text) : text_(&text) {}  // NOLINT: implicit on purpose
    LazyPath(const char* text) : literal_(text) {}       // NOLINT: implicit on purpose
    LazyPath(const LazyPath& parent, std::size_t index) : parent_(&parent), index_(index) {}
    LazyPath(const LazyPath& parent, const char* key) : parent_(&parent), key_(key) {}

    std::string str() const {
        if (text_) return *text_;
        if (literal_) return literal_;
        return key_ ? child_path(parent_->str(), std::string(key_))
                    : child_path(parent_->str(), index_);
    }

private:
    const std::string* text_ = nullptr;
    const char* literal_ = nullptr;
    const LazyPath* parent_ = nullptr;
    const char* key_ = nullptr;
    std::size_t index_ = 0;
};

// A JSON value as a message shows it: `null`, `"text"`, `[1,2]`, `an object`.
std::string describe(const Json& value);

// The version that brought colours [r, g, b] (docs/scene-format.md, "Version 4: colour").
inline constexpr int kColourVersion = 4;

// A colour `[r, g, b]` (`value`, an array; `path` names it) of a file of `version`: three
// finite numbers within +-kMaxValue. Throws InputError naming the path (the component's, where
// one is wrong) when the file's version has no colours, the array's length is not 3, or a
// component is not such a number. What 2-D values and a world's values share.
Rgb read_rgb(const Json& value, const std::string& source, const LazyPath& path, int version);
// A value an image holds: a finite number within +-kMaxValue (scene.h says why; the message
// spells the limit out).
double read_image_value(const Json& value, const std::string& source, const LazyPath& path);

// ---- The version-2 world (scene_io_world.cpp) ----

// The vertices and face loops that the tree builder (scene_io.cpp, JsonBuilder) kept out of the
// JSON tree. They are the bulk of a big scene (600,000 points and 200,000 loops in a
// 200,000-triangle file), and a tree node per array, allocated and freed, cost more than
// parsing their numbers. A vertex objects[o].vertices[v] of exactly three numbers and a loop
// objects[o].faces[f].loop of integers in 0..INT_MAX are stored here in document order and
// leave a placeholder in the tree: a discarded value, which JSON text cannot produce. Anything
// else (a point of two numbers, a string in a loop) stays in the tree, for the reader to
// refuse with its path. Likewise a face objects[o].faces[f] whose keys are only "loop" (a loop
// stored here), "reflectance" and "mirror" (finite numbers), each at most once: an object in
// the tree per face cost as much again as the parse.
struct BulkFace {
    std::optional<double> reflectance;
    std::optional<double> mirror;
};
struct BulkValues {
    std::vector<glm::dvec3> points;
    std::vector<int> loop_indices;
    std::vector<std::pair<std::size_t, std::size_t>> loops;  // start and count in loop_indices
    // Each with the next loop of `loops`.
    std::vector<BulkFace> faces;
};

// Reads camera, ambient, lights, objects, edges and effects from a version-2 root object
// whose other keys the caller has checked, taking the placeholders' values from `bulk` in
// document order; then check_world(). Throws InputError.
World read_world(const Json& root, const std::string& source, const BulkValues& bulk);
// The world's keys as lines of a scene file (each line ends with ",\n" except the last).
std::string world_to_json(const World& world);

// ---- Version-4 Bezier contours and `svg_path` (scene_io_bezier.cpp) ----

// True when some contour of `contours` (a shape's "contours" array) has an object item.
bool has_curve_item(const Json& contours);
// Throws InputError at the first object item: curve items need version 4.
void refuse_curve_items(const Json& contours, const std::string& source, const std::string& path,
                        int version);

// Reads the Bezier shapes of one file, counting their flattening's vertices (`vertices`, shared
// with the file's discs and rings) against kMaxSceneVertices. Throws InputError.
class BezierReader {
public:
    BezierReader(const std::string& source, long long& vertices)
        : source_(source), vertices_(vertices) {}
    // A polygon's "contours" with curve items (`path` names the array).
    Shape polygon(const Json& contours, const std::string& path, double value);
    // A path shape's "svg_path" value (`path` names it); a path of straight edges only is the
    // plain polygon it describes.
    Shape path(const Json& d, const std::string& path, double value);
    // A text shape (`shape`, its keys checked; `path` names it): its glyphs' outlines through
    // patterns/scene/text.h, a font path taken relative to the scene file's folder.
    Shape text(const Json& shape, const std::string& path, double value);

private:
    Shape counted(std::vector<SegmentContour> outline, double value, const std::string& path);
    SegmentContour read_segment_contour(const Json& value, const std::string& path);
    Segment read_curve_item(const Json& item, const std::string& path, Point from);
    Point read_curve_point(const Json& point, const std::string& path);

    const std::string& source_;
    long long& vertices_;
};

// A contour of segments as version-4 items (start point, points and curve objects), the
// closing straight edge left out for the reader to add again.
void append_segment_contour(std::string& out, const SegmentContour& contour,
                            const std::string& path);

// ---- The version-3 sequence (scene_io_sequence.cpp) ----

// Reads "sequence" of a version-3 file whose scene (`scene`: its world, or none for a 2-D
// scene) is read already. Throws InputError naming the JSON path.
SceneSequence read_sequence(const Json& value, const std::string& source, const Scene& scene);
// The sequence as one JSON object on one line; `world`: the scene is 3-D ("pan", not
// "translate").
std::string sequence_to_json(const SceneSequence& sequence, bool world);

}  // namespace aabench::scene_io_detail
