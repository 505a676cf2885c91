// The HTML report's edge figures (html_parts.h): for a scene with `edges`, the edge stage on the
// exact depth image (Saito & Takahashi's Fig. 3: depth, contour image p, crease image e, both
// compositing styles) beside the ground-truth line drawing (docs/edges.md).
//
// Display transforms, stated on the page:
// - depth z_s divided by its largest value (nearer is brighter, the background black), then the
//   sRGB view like every other image;
// - p (in [0, 1]) and the "black" line image (darkness in [0, 1]) as 1 - value: black lines on
//   white paper;
// - e (signed, > 0 convex) and the "white-convex" line image (W - D in [-1, 1]) on the error
//   maps' diverging log scale: red convex / light, blue concave / dark;
// - the composites as they are.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "harness/report/html_parts.h"
#include "harness/report/image_io.h"

namespace aabench::html_parts {
namespace {

namespace fs = std::filesystem;

// Images narrower than this are shown at an integer zoom (as in html_figures.cpp).
constexpr int kThumbnailPx = 256;
// A signed map needs a scale when the image is all zero.
constexpr double kMinSignedScale = 1e-6;

Image mapped(const Image& in, float (*f)(float)) {
    Image out(in.width, in.height);
    for (std::size_t k = 0; k < in.data.size(); ++k) out.data[k] = f(in.data[k]);
    return out;
}

float inverted(float v) { return 1.0f - v; }

// Largest |value| rounded up to 1, 2 or 5 x 10^k (the signed maps' full-colour level).
double signed_scale(const Image& image) {
    double largest = kMinSignedScale;
    for (float v : image.data) {
        if (std::isfinite(v)) largest = std::max(largest, static_cast<double>(std::abs(v)));
    }
    const double decade = std::pow(10.0, std::floor(std::log10(largest)));
    for (double step : {1.0, 2.0, 5.0}) {
        if (largest <= step * decade) return step * decade;
    }
    return 10.0 * decade;
}

}  // namespace

std::string edge_figure_grid(const fs::path& dir, const Section& section) {
    if (!section.figures || !section.figures->edges) return "";
    const EdgeFigures& f = *section.figures->edges;
    const int width = f.depth.width, height = f.depth.height;
    const int shown = std::max(1, kThumbnailPx / std::max(1, width));
    const int vw = width * shown, vh = height * shown;
    const std::string rel = "images/" + section.name + "/";
    const fs::path image_dir = dir / "images" / section.name;

    float largest_depth = 0.0f;
    for (float v : f.depth.data) largest_depth = std::max(largest_depth, v);
    Image depth_view = f.depth;
    for (float& v : depth_view.data) v = largest_depth > 0.0f ? v / largest_depth : 0.0f;
    const bool black = f.spec.style == "black";
    const double e_scale = signed_scale(f.e);
    const double line_scale = 1.0;  // W - D is in [-1, 1]

    struct Panel {
        std::string file, title;
        OIIO::ImageBuf view;
    };
    std::vector<Panel> panels = {
        {"edges.depth", "depth z_s = f&sup2;/z_v (exact), / its maximum", display_view(depth_view)},
        {"edges.p", "contour image p (eq. 7), shown as 1 &minus; p",
         display_view(mapped(f.p, inverted))},
        {"edges.e",
         fmt::format("crease image e (eq. 8): red convex, blue concave, full colour at "
                     "|e| &ge; {:g}",
                     e_scale),
         signed_view(f.e, e_scale)},
        {"edges.black", "every edge black (Fig. 3 h&prime;)", display_view(f.black)},
        {"edges.white-convex", "convex creases white (Fig. 3 h)", display_view(f.white_convex)},
        {"edges.lines",
         black ? "line image (black style), shown as 1 &minus; L"
               : "line image (white-convex style): W &minus; D, red light, blue dark",
         black ? display_view(mapped(f.lines, inverted)) : signed_view(f.lines, line_scale)},
        {"edges.truth",
         black ? "ground truth: the true lines as exact 1-px strips, 1 &minus; L"
               : "ground truth: the true lines as exact 1-px strips, W &minus; D",
         black ? display_view(mapped(f.truth, inverted)) : signed_view(f.truth, line_scale)},
    };
    write_image((image_dir / "edges.depth.exr").string(), f.depth);
    std::string html = fmt::format(
        "<p class=\"note\">The edge stage (contour {}, crease {}, k_p {:g}, k_l {:g}, weights {:g} "
        "/ {:g}) on the <b>exact</b> depth image and the exact shaded image; each method's "
        "own depth image is scored in the lines table. Ground truth: the visible boundary "
        "segments of the exact visibility pieces, contours and creases "
        "(docs/edges.md). <a href=\"{}edges.depth.exr\">depth EXR</a></p>\n"
        "<table class=\"figures\"><tr>",
        f.spec.contour, f.spec.crease, f.spec.kp, f.spec.kl, f.spec.contour_weight,
        f.spec.crease_weight, rel);
    for (std::size_t k = 0; k < panels.size(); ++k) {
        write_png_view(image_dir / (panels[k].file + ".png"), panels[k].view);
        if (k > 0 && k % 4 == 0) html += "</tr>\n<tr>";
        html += fmt::format("<td>{}<br><span class=\"caption\">{}</span></td>",
                            img_tag(rel + panels[k].file + ".png", vw, vh, panels[k].file),
                            panels[k].title);
    }
    html += "</tr></table>\n";
    html += fmt::format("<p>{}</p>\n", signed_colour_bar(e_scale, section.name + "-e"));
    return html;
}

}  // namespace aabench::html_parts
