// Version-4 Bezier contours, `svg_path` and `text` shapes: reading and writing
// (scene_io_detail.h).
#include <fmt/format.h>

#include <cmath>
#include <filesystem>

#include "patterns/scene/bezier.h"
#include "patterns/scene/scene_io_detail.h"
#include "patterns/scene/svg_path.h"
#include "patterns/scene/text.h"

namespace aabench::scene_io_detail {
namespace {

// Curves' points lie within 1e9 px of the origin, as discs' centres (scene_io.cpp): the exact
// reference finds roots and crossings relative to them, to ~1e-12 px at ordinary sizes.
constexpr double kMaxBezierCoordinate = 1e9;

}  // namespace

bool has_curve_item(const Json& contours) {
    for (const Json& contour : contours) {
        if (!contour.is_array()) continue;
        for (const Json& item : contour) {
            if (item.is_object()) return true;
        }
    }
    return false;
}

void refuse_curve_items(const Json& contours, const std::string& source, const std::string& path,
                        int version) {
    for (std::size_t k = 0; k < contours.size(); ++k) {
        if (!contours[k].is_array()) continue;
        for (std::size_t p = 0; p < contours[k].size(); ++p) {
            if (contours[k][p].is_object()) {
                fail(source, child_path(child_path(path, k), p),
                     fmt::format("curve items (quad, cubic) need \"version\": 4, and this file "
                                 "is version {}",
                                 version));
            }
        }
    }
}

Shape BezierReader::polygon(const Json& contours, const std::string& path, double value) {
    std::vector<SegmentContour> outline;
    outline.reserve(contours.size());
    for (std::size_t k = 0; k < contours.size(); ++k) {
        outline.push_back(read_segment_contour(contours[k], child_path(path, k)));
    }
    return counted(std::move(outline), value, path);
}

Shape BezierReader::path(const Json& d, const std::string& d_path, double value) {
    if (!d.is_string()) {
        fail(source_, d_path, "expected a string of SVG path data, found " + describe(d));
    }
    std::vector<SegmentContour> outline;
    try {
        outline = parse_svg_path(d.get_ref<const std::string&>(), kMaxBezierCoordinate);
    } catch (const SvgPathError& e) {
        fail(source_, d_path, fmt::format("character {}: {}", e.offset() + 1, e.what()));
    }
    if (outline.empty()) {
        fail(source_, d_path,
             "the path encloses nothing (every subpath has fewer than 3 distinct points and no "
             "curve)");
    }
    return counted(std::move(outline), value, d_path);
}

Shape BezierReader::text(const Json& shape, const std::string& path, double value) {
    TextSpec spec;
    auto string_at = [&](const char* key) -> const std::string& {
        const auto it = shape.find(key);
        if (it == shape.end()) fail(source_, child_path(path, key), "required key is missing");
        if (!it->is_string()) {
            fail(source_, child_path(path, key), "expected a string, found " + describe(*it));
        }
        return it->get_ref<const std::string&>();
    };
    auto number_at = [&](const char* key, double fallback) {
        const auto it = shape.find(key);
        if (it == shape.end()) return fallback;
        if (!it->is_number() || !std::isfinite(it->get<double>())) {
            fail(source_, child_path(path, key), "expected a finite number, found " + describe(*it));
        }
        return it->get<double>();
    };
    spec.font = string_at("font");
    spec.string = string_at("string");
    if (!shape.contains("size_px")) fail(source_, child_path(path, "size_px"), "required key is missing");
    spec.size_px = number_at("size_px", 0.0);
    spec.letter_spacing_px = number_at("letter_spacing_px", 0.0);
    const std::string origin_path = child_path(path, "origin");
    const auto origin = shape.find("origin");
    if (origin == shape.end()) fail(source_, origin_path, "required key is missing");
    spec.origin = read_curve_point(*origin, origin_path);
    if (const auto kerning = shape.find("kerning"); kerning != shape.end()) {
        if (!kerning->is_boolean()) {
            fail(source_, child_path(path, "kerning"),
                 "expected true or false, found " + describe(*kerning));
        }
        spec.kerning = kerning->get<bool>();
    }
    std::vector<SegmentContour> outline;
    try {
        const std::string folder = std::filesystem::path(source_).parent_path().string();
        outline = text_outline(spec, font_file(spec.font, folder));
    } catch (const TextError& e) {
        fail(source_, child_path(path, e.field()), e.what());
    }
    for (const SegmentContour& c : outline) {
        for (const Segment& s : c) {
            for (int k = 0; k <= s.degree; ++k) {
                if (!(std::abs(s.p[k].x) <= kMaxBezierCoordinate &&
                      std::abs(s.p[k].y) <= kMaxBezierCoordinate)) {
                    fail(source_, origin_path,
                         "the text reaches beyond 1e9 px (curves' coordinates stay within it)");
                }
            }
        }
    }
    return counted(std::move(outline), value, path);
}

Shape BezierReader::counted(std::vector<SegmentContour> outline, double value,
                            const std::string& path) {
    for (const SegmentContour& c : outline) {
        for (const Segment& s : c) vertices_ += flatten_count(s, kBezierViewFlatnessPx);
    }
    if (vertices_ > kMaxSceneVertices) {
        fail(source_, path,
             fmt::format("the curves' flattening needs more than {} vertices "
                         "(docs/scene-format.md)",
                         kMaxSceneVertices));
    }
    return bezier_shape(std::move(outline), value);
}

// A version-4 contour: a start point, then items that are points (a straight edge to it),
// {"quad": [c, p]} or {"cubic": [c1, c2, p]}; closed by a straight edge back to the start
// unless the last item ends there.
SegmentContour BezierReader::read_segment_contour(const Json& value, const std::string& path) {
    if (!value.is_array()) {
        fail(source_, path,
             "expected a contour (an array of points and curve items), found " + describe(value));
    }
    if (value.empty()) fail(source_, path, "a contour needs a start point, found an empty array");
    if (!value[0].is_array()) {
        fail(source_, child_path(path, 0),
             "a contour starts with a point [x, y], found " + describe(value[0]));
    }
    SegmentContour contour;
    Point current = read_curve_point(value[0], child_path(path, 0));
    const Point start = current;
    bool curved = false;
    for (std::size_t k = 1; k < value.size(); ++k) {
        const std::string item_path = child_path(path, k);
        Segment s;
        s.p[0] = current;
        if (value[k].is_object()) {
            s = read_curve_item(value[k], item_path, current);
            curved = true;
        } else {
            s.p[1] = read_curve_point(value[k], item_path);
        }
        contour.push_back(s);
        current = s.end();
    }
    if (!curved && value.size() < 3) {
        fail(source_, path,
             fmt::format("a contour needs at least 3 points or a curve item, found {} point{}",
                         value.size(), value.size() == 1 ? "" : "s"));
    }
    if (!(current == start)) {
        Segment closing;
        closing.p[0] = current;
        closing.p[1] = start;
        contour.push_back(closing);
    }
    return contour;
}

Segment BezierReader::read_curve_item(const Json& item, const std::string& path, Point from) {
    const bool quad = item.contains("quad"), cubic = item.contains("cubic");
    if (item.size() != 1 || (!quad && !cubic)) {
        fail(source_, path,
             fmt::format("a curve item is {{\"quad\": [c, p]}} or {{\"cubic\": [c1, c2, p]}}, "
                         "found {}",
                         item.empty() ? std::string("an empty object")
                                      : "the key \"" + printable(item.begin().key()) + "\"" +
                                            (item.size() > 1 ? " among others" : "")));
    }
    const char* key = quad ? "quad" : "cubic";
    const std::size_t points = quad ? 2 : 3;
    const std::string points_path = child_path(path, key);
    const Json& list = item[key];
    if (!list.is_array() || list.size() != points) {
        fail(source_, points_path,
             fmt::format("expected {} points ({}), found {}", points,
                         quad ? "control, end" : "control 1, control 2, end", describe(list)));
    }
    Segment s;
    s.degree = quad ? 2 : 3;
    s.p[0] = from;
    for (std::size_t k = 0; k < points; ++k) {
        s.p[k + 1] = read_curve_point(list[k], child_path(points_path, k));
    }
    return s;
}

Point BezierReader::read_curve_point(const Json& point, const std::string& path) {
    const bool ok = point.is_array() && point.size() == 2 && point[0].is_number() &&
                    point[1].is_number() && std::isfinite(point[0].get<double>()) &&
                    std::isfinite(point[1].get<double>());
    if (!ok) {
        fail(source_, path,
             "expected a point [x, y] of two finite numbers, found " + describe(point));
    }
    const Point p{point[0].get<double>(), point[1].get<double>()};
    if (!(std::abs(p.x) <= kMaxBezierCoordinate && std::abs(p.y) <= kMaxBezierCoordinate)) {
        fail(source_, path,
             "a point of a shape with curves must lie within 1e9 px of the origin "
             "(docs/scene-format.md)");
    }
    return p;
}

namespace {

std::string json_number(double value, const std::string& path) {
    if (!std::isfinite(value)) {
        throw InputError(fmt::format("scene_to_json: {}: {} is not finite and JSON cannot hold it",
                                     path, value));
    }
    return Json(value).dump();
}

void append_point(std::string& out, Point p, const std::string& path) {
    out += '[' + json_number(p.x, path) + ',' + json_number(p.y, path) + ']';
}

}  // namespace

// A contour of segments as version-4 items: the start point, then a point per straight edge and
// an object per curve; the closing straight edge is left for the reader to add again.
void append_segment_contour(std::string& out, const SegmentContour& contour,
                            const std::string& path) {
    out += '[';
    append_point(out, contour.front().p[0], path);
    const std::size_t n = contour.back().degree == 1 ? contour.size() - 1 : contour.size();
    for (std::size_t k = 0; k < n; ++k) {
        const Segment& s = contour[k];
        const std::string item_path = child_path(path, k + 1);
        out += ',';
        if (s.degree == 1) {
            append_point(out, s.p[1], item_path);
            continue;
        }
        out += s.degree == 2 ? "{\"quad\": [" : "{\"cubic\": [";
        for (int q = 1; q <= s.degree; ++q) {
            if (q > 1) out += ',';
            append_point(out, s.p[q], item_path);
        }
        out += "]}";
    }
    out += ']';
}

}  // namespace aabench::scene_io_detail
