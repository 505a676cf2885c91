// agg — Anti-Grain Geometry's scanline polygon rasteriser, as a peer to the sources' methods.
//
// Computes: for each fill in order, AGG's 8-bit coverage of the fill, read back as
// a = byte / 255 and composited in float over the frame buffer, which starts as the background:
//
//     out = out + a * (value - out)       (a = 1 writes the value itself, a = 0 skips)
//
// The coverage comes from AGG's usual pipeline: rasterizer_scanline_aa (nonzero fill, gamma
// none = linear), scanline_u8, and render_scanlines_aa_solid into a pixfmt_gray8 buffer
// cleared to 0 under the fill's bounding box, drawn in opaque white (gray8(255, 255)); over
// 0, gray8's blend lerp(0, 255, cover) is the cover itself, so the buffer holds exactly the
// rasteriser's covers. Compositing is in float for the reason given in methods/cairo.cpp: the
// coverage is the library's, the values stay exact (an empty scene gives the background
// exactly; values outside [0, 1] need no clamping); AGG's own 8-bit grey compositing would add
// a rounding per shape, the 8-bit floor that docs/methods-peers.md reports separately.
//
// What AGG's coverage is (agg_rasterizer_cells_aa.h, agg_rasterizer_scanline_aa.h): vertices
// are rounded to 1/256 px (poly_subpixel_shift = 8), then the area of the polygon inside each
// pixel is accumulated exactly in those integer units (cells of cover and area, like FreeType's
// ftgrays), and turned into an 8-bit cover by cover = |area| >> 9 (a floor for one orientation,
// a ceiling for the other, as the shift rounds towards -inf before the sign is dropped), capped
// at 255. So a pixel's value is floor(256 c)/255 or ceil(256 c)/255 of its coverage c on that
// grid; on a straight edge within one byte step plus 3/256 of exact (tests/peers_test.cpp).
// The nonzero rule is applied to a pixel's summed signed area, not point by point, so pixels
// where a shape's contours overlap or cancel are not its coverage (docs/methods-peers.md).
// The pixel convention is the suite's: cell x covers [x, x+1] in pixel units, y down.
//
// Library: AGG as packaged by Debian 12 (libagg-dev 2.6.1-r134+dfsg1, libagg.pc 2.7.0; the
// headers' comments say 2.4, the code base of that snapshot; the rasteriser is header-only
// templates). The version `list` prints comes from the package at build time (build_info.h).
// Clipping: rasterizer_sl_clip_dbl clips every edge to the image in double before the conversion to
// 24.8 integers (lines left or right of the image become vertical lines on its border, keeping
// their winding), so coordinates far outside the image cannot overflow AGG's int coordinates.
//
// Parameters:
//   paths  merged|per-shape, default merged: what one fill is (methods/scan/kernel/peer_coverage.h).
//          merged: each run of consecutive shapes of one value, orientations made consistent,
//          as a user drawing the scene as one path would; per-shape: each shape alone, so
//          coverage is composited where shapes of one value meet (the star's centre). The rmse
//          between the two is the row's conflation figure (docs/metrics.md). With merged, AGG
//          sums the signed cell areas of overlapping shapes of a run and caps the cover at
//          255 (the nonzero rule on a pixel's sum, above).
// (AGG's other choices — gamma, even-odd fill, scanline_p8 vs u8 — are either outside the
// suite's conventions or give the same coverage.)
#include <agg_conv_curve.h>
#include <agg_gamma_functions.h>
#include <agg_path_storage.h>
#include <agg_pixfmt_gray.h>
#include <agg_rasterizer_scanline_aa.h>
#include <agg_renderer_base.h>
#include <agg_renderer_scanline.h>
#include <agg_rendering_buffer.h>
#include <agg_scanline_u.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <vector>

#include <fmt/format.h>

#include "build_info.h"  // generated: the AGG version of the package built against
#include "methods/cost_model.h"
#include "methods/memory_model.h"
#include "methods/method.h"
#include "methods/scan/kernel/peer_coverage.h"
#include "patterns/scene/bezier.h"

namespace aabench {
namespace {

// AGG's own double clipper (rasterizer_sl_clip_dbl) multiplies two coordinate differences,
// which overflows to NaN for coordinates near 1e300 (found by the render fuzzer: UBSan, NaN to
// int in agg_basics.h iround): contours beyond kPeerSafeCoordinate are clipped first
// (methods/scan/kernel/peer_coverage.h).
struct AggScratch {
    std::vector<std::uint8_t> coverage;
    agg::rasterizer_scanline_aa<agg::rasterizer_sl_clip_dbl> rasterizer;
    agg::scanline_u8 scanline;
};

class AggMethod : public Method {
public:
    AggMethod(PeerPaths paths, double approximation_scale)
        : paths_(paths), approximation_scale_(approximation_scale) {}

protected:
    void draw_rows(const Scene& scene, Image& out, int row_lo, int row_hi) const override {
        std::fill(out.row(row_lo), out.row(row_hi), static_cast<float>(scene.background));
        if (scene.width <= 0 || scene.shapes.empty()) return;

        const int width = scene.width, height = scene.height;
        // Per-thread buffers kept between renders (AGG's cell blocks, sorted cells and
        // scanline spans keep their capacity across reset()): no allocation once warm, and
        // one Method object may render on several threads at once (compare --jobs).
        thread_local AggScratch scratch;
        std::vector<std::uint8_t>& coverage = scratch.coverage;
        // Not cleared: every byte read is inside a shape's box, zeroed before its fill.
        coverage.resize(static_cast<std::size_t>(width) * height);
        agg::rendering_buffer buffer(coverage.data(), width, height, width);
        agg::pixfmt_gray8 pixels(buffer);
        agg::renderer_base<agg::pixfmt_gray8> renderer(pixels);
        auto& rasterizer = scratch.rasterizer;
        auto& scanline = scratch.scanline;
        rasterizer.reset();
        // A band is AGG's clip box: the rasteriser makes cells in its rows only.
        rasterizer.clip_box(0.0, row_lo, width, row_hi);
        rasterizer.filling_rule(agg::fill_non_zero);
        rasterizer.gamma(agg::gamma_none());
        const agg::gray8 opaque_white(255, 255);

        for (std::size_t first = 0; first < scene.shapes.size();) {
            const ShapeRun run = next_shape_run(scene.shapes, first, paths_);
            first = run.last;
            PixelBox box = run_pixel_box(scene.shapes, run, width, height);
            box.y0 = std::max(box.y0, row_lo);
            box.y1 = std::min(box.y1, row_hi);
            if (box.empty()) continue;
            for (int j = box.y0; j < box.y1; ++j) {
                std::memset(coverage.data() + static_cast<std::size_t>(j) * width + box.x0, 0,
                            static_cast<std::size_t>(box.x1 - box.x0));
            }
            rasterizer.reset();
            for (std::size_t k = run.first; k < run.last; ++k) {
                const Shape& shape = scene.shapes[k];
                const bool reverse = reverse_for_run(shape, paths_);
                if (draws_outline(shape)) {  // Bezier curves through AGG's own curve pipeline
                    add_outline(rasterizer, shape.outline, reverse);
                    continue;
                }
                for (const Contour& original : shape.contours) {
                    const bool clip = needs_clipping(original);
                    const Contour clipped =
                        clip ? clip_contour(original, -1.0, -1.0, width + 1.0, height + 1.0)
                             : Contour{};
                    const Contour& contour = clip ? clipped : original;
                    if (contour.empty()) continue;
                    bool first_vertex = true;
                    for_each_vertex(contour, reverse, [&](const Point& p) {
                        if (first_vertex) {
                            rasterizer.move_to_d(p.x, p.y);
                            first_vertex = false;
                        } else {
                            rasterizer.line_to_d(p.x, p.y);
                        }
                    });
                    rasterizer.close_polygon();
                }
            }
            agg::render_scanlines_aa_solid(rasterizer, scanline, renderer, opaque_white);
            const double value = scene.shapes[run.first].value;
            for (int j = box.y0; j < box.y1; ++j) {
                composite_coverage_row(
                    coverage.data() + static_cast<std::size_t>(j) * width + box.x0,
                    out.row(j) + box.x0, box.x1 - box.x0, value);
            }
        }
    }

public:
    // AGG's own flattening: conv_curve's vertices for each curved shape's outline.
    std::optional<Scene> own_flattening(const Scene& scene) const override {
        if (!has_bezier(scene)) return std::nullopt;
        Scene out = scene;
        for (Shape& shape : out.shapes) {
            if (!draws_outline(shape)) continue;
            shape.contours.clear();
            agg::path_storage path = outline_path(shape.outline, false);
            agg::conv_curve<agg::path_storage> curves(path);
            curves.approximation_scale(approximation_scale_);
            curves.rewind(0);
            Contour contour;
            double x = 0.0, y = 0.0;
            for (unsigned cmd = curves.vertex(&x, &y); !agg::is_stop(cmd); cmd = curves.vertex(&x, &y)) {
                if (agg::is_move_to(cmd) && contour.size() >= 3) {
                    shape.contours.push_back(std::move(contour));
                    contour.clear();
                } else if (agg::is_move_to(cmd)) {
                    contour.clear();
                }
                if (agg::is_vertex(cmd)) contour.push_back({x, y});
            }
            if (contour.size() >= 3) shape.contours.push_back(std::move(contour));
            shape.outline.clear();
        }
        return out;
    }

private:
    static agg::path_storage outline_path(const std::vector<SegmentContour>& outline, bool reverse) {
        agg::path_storage path;
        for (const SegmentContour& c : outline) {
            bool first = true;
            for_each_segment(c, reverse, [&](const Segment& s) {
                if (first) {
                    path.move_to(s.p[0].x, s.p[0].y);
                    first = false;
                }
                if (s.degree == 1) {
                    path.line_to(s.p[1].x, s.p[1].y);
                } else if (s.degree == 2) {
                    path.curve3(s.p[1].x, s.p[1].y, s.p[2].x, s.p[2].y);
                } else {
                    path.curve4(s.p[1].x, s.p[1].y, s.p[2].x, s.p[2].y, s.p[3].x, s.p[3].y);
                }
            });
            path.close_polygon();
        }
        return path;
    }

    // The outline as AGG's path (curve3 / curve4 vertices), flattened by conv_curve at
    // approximation_scale (AGG's curve3_div / curve4_div, angle tolerance off: their defaults).
    template <class Rasterizer>
    void add_outline(Rasterizer& rasterizer, const std::vector<SegmentContour>& outline,
                     bool reverse) const {
        agg::path_storage path = outline_path(outline, reverse);
        agg::conv_curve<agg::path_storage> curves(path);
        curves.approximation_scale(approximation_scale_);
        rasterizer.add_path(curves);
    }

    PeerPaths paths_;
    double approximation_scale_;
};

}  // namespace

// What the harness knows of `agg` (methods/method_traits.h).
MethodTraits agg_traits() {
    MethodTraits t;
    t.curves = "natively: path_storage curve3 / curve4 through conv_curve at `approximation_scale`";
    t.working_bytes = [](const ParamValues&, const SceneSize& s) {
        // An 8-bit coverage plane (Cairo pads rows to 4 bytes) and the rasteriser's cells.
        return 1.0 * (s.width + 3) * s.height +
               memory_model::kPeerCellBytes * (s.edge_columns + s.edge_rows);
    };
    t.time_ms = [](const ParamValues&, const SceneSize& s) {
        return cost_model::linear_ms(cost_model::kAgg, s.pixels(), s.vertices);
    };
    t.hard_cases.properties = {
        {Invariant::kContinuity, CaseSet::kAll, DocumentedBound::kLocalChanges,
         "vertices rounded to 1/256 px and coverage to 8 bits: steps, not a continuum"},
        {Invariant::kArea, CaseSet::kAll, DocumentedBound::kQuantisedArea,
         "8-bit coverage (floor or ceil of 256 c) on a 1/256 px vertex grid"},
    };
    t.hard_cases.figures = [](const ParamValues&) {
        // Coverage quantisation per edge pixel (docs/hardcases.md, "area"): the cover is
        // floor or ceil of 256 c over 255, within 2/255 of c.
        // Vertices rounded to 1/256 px: each edge moves by at most 2^-9 px in x and in y,
        // which changes the area by at most (edge length) x 2^-9 x sqrt(2) < (edge length) x
        // 2^-8.
        return BoundFigures{.coverage_step = 2.0 / 255.0, .vertex_grid_px = 0x1p-8};
    };
    return t;
}

MethodInfo agg_method() {
    return {"agg",
            fmt::format("AGG {} rasterizer_scanline_aa (nonzero, linear gamma, gray8 coverage / "
                        "255), composited in float",
                        build_info::kAggVersion),
            {{"paths", ParamKind::kChoice, 0, 0, 0, {"merged", "per-shape"},
              "merged: each run of consecutive shapes of one value is one fill (orientations "
              "made consistent), as a user drawing the scene as one path; per-shape: one fill "
              "per shape, composited where shapes meet"},
             {"approximation_scale", ParamKind::kReal, 1, 0.01, 100, {},
              "conv_curve's approximation_scale: curves are flattened to a distance of about "
              "0.5 / scale px; 1 is AGG's default. Polygons do not depend on it"}},
            [](const ParamValues& p) {
                return std::make_unique<AggMethod>(peer_paths_from_name(p.get_choice("paths")),
                                                   p.get_real("approximation_scale"));
            },
            // The accuracy-time curve of its flattening, on scenes with curves.
            "approximation_scale",
            {0.3, 3, 10},
            {},
            /*sweep_on_curves_only=*/true};
}

}  // namespace aabench
