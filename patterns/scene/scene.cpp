#include "patterns/scene/scene.h"

#include <algorithm>
#include <stdexcept>

#include <fmt/format.h>

namespace aabench {

std::size_t Scene::edge_count() const {
    std::size_t count = 0;
    for (const Shape& shape : shapes) {
        for (const Contour& contour : shape.contours) count += contour.size();
    }
    return count;
}

double twice_signed_area(const Contour& c) {
    double sum = 0.0;
    for (std::size_t k = 1; k + 1 < c.size(); ++k) {
        const double ax = c[k].x - c[0].x, ay = c[k].y - c[0].y;
        const double bx = c[k + 1].x - c[0].x, by = c[k + 1].y - c[0].y;
        sum += ax * by - bx * ay;
    }
    return sum;
}

std::pair<double, double> Scene::value_range() const {
    double lo = background, hi = background;
    // A colour scene's planes lie within its channels' values (the luminances between them).
    auto take = [&lo, &hi](double v) {
        lo = std::min(lo, v);
        hi = std::max(hi, v);
    };
    if (background_rgb) {
        for (double v : *background_rgb) take(v);
    }
    for (const Shape& shape : shapes) {
        if (!shape.value_plane) {
            take(shape.value);
            if (shape.rgb) {
                for (double v : *shape.rgb) take(v);
            }
            continue;
        }
        // An affine value takes its extremes at the shape's vertices.
        for (const Contour& c : shape.contours) {
            for (const Point& p : c) {
                const double v = shape.value_plane->at(p.x, p.y);
                lo = std::min(lo, v);
                hi = std::max(hi, v);
            }
        }
    }
    return {lo, hi};
}

// One subtraction per coordinate, x - origin_x, correctly rounded. It is exact whenever x lies
// within a factor of two of the origin (Sterbenz's lemma: origin / 2 <= x <= 2 origin), which
// holds for every vertex near a window placed far from 0 (origin 2^30, window 65536 px wide at
// most). Otherwise it is one rounding of the window coordinate itself, |error| <= 2^-53 |x -
// origin|: the same rounding the coordinate would have had if the scene had been written in
// window coordinates to begin with. So the window frame loses nothing beyond what the scene's
// own coordinates already carry (ulp(x) / 2, 2^-23 px at 2^30), and a zero origin is left alone.
Scene without_shapes(const Scene& scene) {
    Scene out;
    out.width = scene.width;
    out.height = scene.height;
    out.origin_x = scene.origin_x;
    out.origin_y = scene.origin_y;
    out.background = scene.background;
    out.channels = scene.channels;
    out.background_rgb = scene.background_rgb;
    out.metadata = scene.metadata;
    out.thin_objects = scene.thin_objects;
    out.world = scene.world;
    out.sequence = scene.sequence;
    return out;
}

Shape without_contours(const Shape& shape) {
    Shape out;
    out.value = shape.value;
    out.rgb = shape.rgb;
    out.inv_depth = shape.inv_depth;
    out.value_plane = shape.value_plane;
    out.face = shape.face;
    out.role = shape.role;
    out.circle = shape.circle;
    return out;
}

Scene channel_scene(const Scene& scene, int c) {
    if (scene.channels == 1) return scene;
    if (c < 0 || c >= 3) throw std::logic_error("channel_scene: channel out of range");
    Scene out = scene;
    out.channels = 1;
    out.background = channel_background(scene, c);
    out.background_rgb.reset();
    auto revalue = [c](Shape& shape) {
        shape.value = channel_value(shape, c);
        shape.rgb.reset();
    };
    for (Shape& shape : out.shapes) revalue(shape);
    for (ThinObject& thin : out.thin_objects) revalue(thin.shape);
    if (out.world) *out.world = channel_world(*scene.world, c);
    return out;
}

Scene in_window_frame(const Scene& scene) {
    Scene out = scene;
    if (is_window_frame(scene)) return out;
    const double ox = scene.origin_x, oy = scene.origin_y;
    auto shift = [ox, oy](Shape& shape) {
        for (Contour& contour : shape.contours) {
            for (Point& p : contour) p = {p.x - ox, p.y - oy};
        }
        if (shape.circle) shape.circle->center = {shape.circle->center.x - ox, shape.circle->center.y - oy};
        for (SegmentContour& contour : shape.outline) {
            for (Segment& s : contour) {
                for (int k = 0; k <= s.degree; ++k) s.p[k] = {s.p[k].x - ox, s.p[k].y - oy};
            }
        }
        // A plane written in scene coordinates must give the same value at the same point:
        // c + gx * x + gy * y with x = x' + ox, so c' = c + gx * ox + gy * oy.
        for (std::optional<AffinePlane>* plane : {&shape.inv_depth, &shape.value_plane}) {
            if (*plane) (*plane)->c += (*plane)->gx * ox + (*plane)->gy * oy;
        }
    };
    for (Shape& shape : out.shapes) shift(shape);
    for (ThinObject& object : out.thin_objects) shift(object.shape);
    out.origin_x = out.origin_y = 0.0;
    return out;
}

bool has_depth_planes(const Scene& scene) {
    return std::any_of(scene.shapes.begin(), scene.shapes.end(),
                       [](const Shape& s) { return s.inv_depth.has_value(); });
}

void require_window_frame(const Scene& scene, const char* who) {
    if (is_window_frame(scene)) return;
    throw std::logic_error(fmt::format(
        "{}: the scene has a window origin ({}, {}); methods, references and metrics take it "
        "in its window frame (the prepared frame, harness/world/frame.h)",
        who, scene.origin_x, scene.origin_y));
}

void check_image_size(long long width, long long height, const std::string& where) {
    if (width < 1 || height < 1 || width > kMaxImageSide || height > kMaxImageSide) {
        // The range style of every other check ("--threads: 0 is out of range 1..256").
        throw InputError(fmt::format("{}: {}x{} is out of range 1..{} per side", where, width,
                                     height, kMaxImageSide));
    }
    if (width * height > kMaxImagePixels) {
        throw InputError(fmt::format("{}: size {}x{} has {} pixels, more than the limit of {}",
                                     where, width, height, width * height, kMaxImagePixels));
    }
}

}  // namespace aabench
