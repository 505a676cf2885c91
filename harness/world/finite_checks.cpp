// The finite checks after each world stage (harness/world/finite_checks.h). Each is one pass
// over what the stage produced, linear in its size: small next to the stage itself.
#include "harness/world/finite_checks.h"

#include <fmt/format.h>

#include <cmath>
#include <string>

namespace aabench {
namespace {

bool finite(const glm::dvec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

bool finite(const std::optional<AffinePlane>& p) {
    return !p || (std::isfinite(p->c) && std::isfinite(p->gx) && std::isfinite(p->gy));
}

std::string face_path(const WorldFace& f) {
    return fmt::format("objects[{}].faces[{}]", f.object, f.index);
}

[[noreturn]] void refuse(std::string_view stage, const std::string& where, std::string_view what) {
    throw InputError(
        fmt::format("{}: {}: {} is not finite (the stage's arithmetic overflowed; "
                    "docs/world.md, \"No silent non-finite value\")",
                    stage, where, what));
}

// A value past +-kMaxValue would be inf in a float32 image (patterns/scene/scene.h; the
// message spells the limit out).
static_assert(kMaxValue == 1e30);
[[noreturn]] void refuse_value(std::string_view stage, const std::string& where,
                               std::string_view what, double value) {
    throw InputError(
        fmt::format("{}: {}: {} {:g} is beyond the values an image holds, +-1e30 "
                    "(images are float32; docs/world.md, \"No silent non-finite "
                    "value\")",
                    stage, where, what, value));
}

// A value an image holds: finite and within +-kMaxValue; a colour world's each component too.
// `where` makes the path only when a value is refused.
template <class Where>
void check_value(std::string_view stage, const Where& where, std::string_view what, double value,
                 const std::optional<Rgb>& rgb) {
    if (!std::isfinite(value)) refuse(stage, where(), what);
    if (!(std::abs(value) <= kMaxValue)) refuse_value(stage, where(), what, value);
    if (!rgb) return;
    for (const double v : *rgb) {
        if (!std::isfinite(v)) refuse(stage, where(), fmt::format("{}'s colour component", what));
        if (!(std::abs(v) <= kMaxValue)) {
            refuse_value(stage, where(), fmt::format("{}'s colour component", what), v);
        }
    }
}

// The face a shape lies on, or "shape N" for a shape without one (never in a world's scenes).
std::string shape_path(const std::vector<WorldFace>& faces, const Shape& s, std::size_t k) {
    if (s.face >= 0 && static_cast<std::size_t>(s.face) < faces.size()) {
        return face_path(faces[s.face]);
    }
    return fmt::format("shape {}", k);
}

}  // namespace

void check_finite_faces(std::string_view stage, const std::vector<WorldFace>& faces) {
    for (const WorldFace& f : faces) {
        if (!f.visible) continue;
        if (!finite(f.frame.origin) || !finite(f.frame.u) || !finite(f.frame.v) ||
            !finite(f.frame.normal)) {
            refuse(stage, face_path(f), "the face's plane frame");
        }
        for (const glm::dvec3& p : f.loop) {
            if (!finite(p)) refuse(stage, face_path(f), "a vertex");
        }
    }
}

void check_finite_cells(std::string_view stage, const std::vector<WorldFace>& faces,
                        const std::vector<std::vector<Cell>>& cells) {
    for (std::size_t k = 0; k < cells.size(); ++k) {
        for (const Cell& c : cells[k]) {
            check_value(
                stage, [&] { return face_path(faces[k]); }, "a cell's value", c.value, c.value_rgb);
            if (!std::isfinite(c.reflectance)) {
                refuse(stage, face_path(faces[k]), "a cell's reflectance");
            }
            for (const glm::dvec2& q : c.loop) {
                if (!std::isfinite(q.x) || !std::isfinite(q.y)) {
                    refuse(stage, face_path(faces[k]), "a cell's vertex");
                }
            }
        }
    }
}

void check_finite_shapes(std::string_view stage, const std::vector<WorldFace>& faces,
                         const Scene& scene) {
    for (std::size_t k = 0; k < scene.shapes.size(); ++k) {
        const Shape& s = scene.shapes[k];
        check_value(
            stage, [&] { return shape_path(faces, s, k); }, "a value", s.value, s.rgb);
        if (!finite(s.value_plane)) refuse(stage, shape_path(faces, s, k), "a value plane");
        if (!finite(s.inv_depth)) {
            refuse(stage, shape_path(faces, s, k), "a depth plane (1/z_v)");
        }
        for (const Contour& c : s.contours) {
            for (const Point& p : c) {
                if (!std::isfinite(p.x) || !std::isfinite(p.y)) {
                    refuse(stage, shape_path(faces, s, k), "a vertex on screen");
                }
            }
        }
    }
}

void check_finite_image(std::string_view stage, const Image& image) {
    for (int j = 0; j < image.height; ++j) {
        for (int i = 0; i < image.width; ++i) {
            if (!std::isfinite(image.at(i, j))) {
                refuse(stage, fmt::format("pixel ({}, {})", i, j), "the value");
            }
        }
    }
}

}  // namespace aabench
