#include "patterns/pattern.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include <fmt/format.h>
#include <fmt/ranges.h>

namespace aabench {

namespace {

std::vector<PatternInfo>& mutable_pattern_registry() {
    static std::vector<PatternInfo> registry = {
        star_pattern(),      strips_pattern(),  grating_pattern(),      rings_pattern(),
        zoneplate_pattern(), circles_pattern(), circle_radii_pattern(), curves_pattern(),
        crescents_pattern(), isoluminant_pattern(), text_pattern(),     text_cff_pattern(), text_page_pattern(), room_pattern(),
        colour_room_pattern(),
        blocks_pattern(),    interpenetrate_pattern(), mesh_pattern(),  terrain_pattern(),
        torus_pattern(),     checkerboard_pattern(),     terrain_edges_pattern(),  mirror_pattern(),
        foliage_pattern(),   bunny_pattern(),   horse_pattern(),  engine_pattern(),  truck_pattern(),
    };
    return registry;
}

}  // namespace

const std::vector<PatternInfo>& pattern_registry() { return mutable_pattern_registry(); }

ScopedPatternRow::ScopedPatternRow(PatternInfo row) : id_(row.id) {
    if (!row.generate) throw std::logic_error("pattern '" + id_ + "': its row has no generator");
    for (const PatternInfo& info : pattern_registry()) {
        if (info.id == id_) {
            throw InputError(fmt::format("pattern '{}' is registered already", id_));
        }
    }
    mutable_pattern_registry().push_back(std::move(row));
}

ScopedPatternRow::~ScopedPatternRow() {
    std::erase_if(mutable_pattern_registry(),
                  [this](const PatternInfo& info) { return info.id == id_; });
}

PatternInstance resolve_pattern(const std::string& spec_text) {
    const SpecString spec = parse_spec_string(spec_text);
    for (const PatternInfo& info : pattern_registry()) {
        if (info.id != spec.id) continue;
        PatternInstance instance;
        instance.info = &info;
        instance.params =
            resolve_params(fmt::format("pattern '{}'", info.id), info.params, spec.assignments);
        const std::string params = instance.params.to_string();
        instance.spec = params.empty() ? info.id : info.id + ":" + params;
        return instance;
    }
    std::vector<std::string> ids;
    for (const PatternInfo& info : pattern_registry()) ids.push_back(info.id);
    throw InputError(
        fmt::format("unknown pattern '{}'{} (valid: {})", spec.id, did_you_mean(spec.id, ids),
                    fmt::join(ids, ", ")));
}

Scene make_pattern(const std::string& spec_text, int width, int height) {
    const PatternInstance instance = resolve_pattern(spec_text);
    check_image_size(width, height, fmt::format("pattern '{}'", instance.info->id));
    return instance.info->generate(instance.params, width, height);
}

Scene begin_pattern_scene(const std::string& id, const ParamValues& values, int width,
                          int height) {
    Scene scene;
    scene.width = width;
    scene.height = height;
    scene.background = 0.0;
    scene.metadata.emplace_back("pattern", id);
    for (const auto& item : values.items()) scene.metadata.push_back(item);
    scene.metadata.emplace_back("size", fmt::format("{}x{}", width, height));
    return scene;
}

void set_focus(Scene& scene, double cx, double cy, int side_px) {
    const int side = std::max(1, std::min({side_px, scene.width, scene.height}));
    const int x = std::clamp(static_cast<int>(std::lround(cx - 0.5 * side)), 0, scene.width - side);
    const int y = std::clamp(static_cast<int>(std::lround(cy - 0.5 * side)), 0, scene.height - side);
    scene.metadata.emplace_back("focus", fmt::format("{},{},{},{}", x, y, side, side));
}

Shape concentric_annuli(double cx, double cy,
                        const std::function<std::pair<double, double>(long long)>& zone,
                        double min_zone_px, const std::string& pattern, const std::string& advice) {
    Shape shape;
    shape.value = 1.0;
    std::size_t vertices = 0;
    const auto add_circle = [&](double radius_px, bool clockwise) {
        shape.contours.push_back(circle_contour(cx, cy, radius_px, kMaxSagittaPx, clockwise));
        // Counted as generated: the total is only known by summing circle_contour's choices.
        vertices += shape.contours.back().size();
        if (vertices > kMaxPatternVertices) {
            throw InputError(fmt::format("pattern '{}': more than {} vertices; {}", pattern,
                                         kMaxPatternVertices, advice));
        }
    };
    for (long long k = 0;; ++k) {
        const auto [inner, outer] = zone(k);
        if (!(outer - inner >= min_zone_px)) break;
        add_circle(outer, /*clockwise=*/false);
        if (k > 0) add_circle(inner, /*clockwise=*/true);
    }
    return shape;
}

Contour circle_contour(double cx, double cy, double radius_px, double max_sagitta_px,
                       bool clockwise) {
    // A chord of angle 2*pi/n deviates from the arc by r*(1 - cos(pi/n)) (the sagitta):
    // choose the smallest n that keeps it under max_sagitta_px, and at least 8 vertices.
    int n = 8;
    if (radius_px > max_sagitta_px) {
        const double half_angle = std::acos(1.0 - max_sagitta_px / radius_px);
        n = std::max(8, static_cast<int>(std::ceil(std::numbers::pi / half_angle)));
    }
    Contour contour;
    contour.reserve(n);
    for (int k = 0; k < n; ++k) {
        const double a = 2.0 * std::numbers::pi * k / n * (clockwise ? -1.0 : 1.0);
        contour.push_back({cx + radius_px * std::cos(a), cy + radius_px * std::sin(a)});
    }
    return contour;
}

}  // namespace aabench
