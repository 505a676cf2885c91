// A 2-D scene as SVG (harness/report/scene_svg.h).
#include "harness/report/scene_svg.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <optional>

namespace aabench {
namespace {

int code(double value) {
    return static_cast<int>(std::lround(std::clamp(value, 0.0, 1.0) * 255.0));
}

std::string grey(double value) { return fmt::format("#{0:02x}{0:02x}{0:02x}", code(value)); }

// A colour scene's fill: each channel's linear value as an 8-bit code, as grey ones are.
std::string colour(const std::optional<Rgb>& rgb, double value) {
    if (!rgb) return grey(value);
    return fmt::format("#{:02x}{:02x}{:02x}", code((*rgb)[0]), code((*rgb)[1]), code((*rgb)[2]));
}

// A shape's path data, from its exact form: a circle as arcs, Bezier segments as curves, else
// its polygon contours. {} is the shortest text that reads back to the same double.
std::string path_data(const Shape& shape) {
    std::string d;
    if (shape.circle) {  // each circle as two half-circle arcs, the hole reversed
        const Circle& c = *shape.circle;
        auto circle = [&](double r, int sweep) {
            return fmt::format("M{} {} A{} {} 0 1 {} {} {} A{} {} 0 1 {} {} {} Z", c.center.x + r,
                               c.center.y, r, r, sweep, c.center.x - r, c.center.y, r, r, sweep,
                               c.center.x + r, c.center.y);
        };
        d = circle(c.outer, 1);
        if (!c.is_disc()) d += " " + circle(c.inner, 0);
        return d;
    }
    if (!shape.outline.empty()) {
        for (const SegmentContour& contour : shape.outline) {
            d += fmt::format("{}M{} {}", d.empty() ? "" : " ", contour.front().p[0].x,
                             contour.front().p[0].y);
            const bool closing_line = contour.back().degree == 1;
            for (std::size_t k = 0; k + (closing_line ? 1 : 0) < contour.size(); ++k) {
                const Segment& seg = contour[k];
                d += seg.degree == 1 ? " L" : seg.degree == 2 ? " Q" : " C";
                for (int q = 1; q <= seg.degree; ++q) {
                    d += fmt::format("{}{} {}", q == 1 ? "" : " ", seg.p[q].x, seg.p[q].y);
                }
            }
            d += " Z";
        }
        return d;
    }
    for (const Contour& contour : shape.contours) {
        for (std::size_t k = 0; k < contour.size(); ++k) {
            d += fmt::format("{}{} {}", k == 0 ? (d.empty() ? "M" : " M") : " L", contour[k].x,
                             contour[k].y);
        }
        if (!contour.empty()) d += " Z";
    }
    return d;
}

}  // namespace

std::string scene_to_svg(const Scene& scene) {
    if (scene.world && scene.shapes.empty()) {
        throw InputError(
            "SVG: a 3-D scene is written as its visible pieces (the world stages "
            "first), not as a world");
    }
    require_window_frame(scene, "SVG");
    std::string out = fmt::format(
        "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{0}\" height=\"{1}\" "
        "viewBox=\"0 0 {0} {1}\">\n"
        "<rect x=\"0\" y=\"0\" width=\"{0}\" height=\"{1}\" fill=\"{2}\"/>\n",
        scene.width, scene.height, colour(scene.background_rgb, scene.background));
    for (std::size_t s = 0; s < scene.shapes.size(); ++s) {
        const Shape& shape = scene.shapes[s];
        if (shape.value_plane) {
            throw InputError(
                fmt::format("SVG: shapes[{}] has an affine value, which a fill "
                            "colour cannot hold",
                            s));
        }
        out += fmt::format("<path fill-rule=\"nonzero\" fill=\"{}\" d=\"{}\"/>\n",
                           colour(shape.rgb, shape.value), path_data(shape));
    }
    return out + "</svg>\n";
}

}  // namespace aabench
