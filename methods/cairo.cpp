// cairo — the Cairo graphics library's polygon fill, as a peer to the sources' methods.
//
// Computes: for each fill in order, Cairo's 8-bit coverage of the fill (cairo_fill of its
// contours, nonzero winding rule, into a CAIRO_FORMAT_A8 image surface cleared to 0 under the
// fill's bounding box), read back as a = byte / 255, and composited in float over the frame
// buffer, which starts as the background:
//
//     out = out + a * (value - out)       (a = 1 writes the value itself, a = 0 skips)
//
// That is Cairo's own OVER operator with a solid source of the shape's value, carried out in
// float instead of in 8 bits: the coverage is what the library computes, the values are kept
// exact. So an empty scene gives the background exactly, values outside [0, 1] need no
// clamping, and the only quantisation is Cairo's coverage (its 8-bit step and its
// rasteriser's sub-pixel grid) — which is what this row of the tables is meant to measure.
// Compositing the 8-bit grey values inside Cairo (ARGB32, OVER) would add a rounding to 8 bits
// per shape on top; that floor is reported separately (the exact image rounded to 8 bits,
// docs/methods-peers.md).
//
// Library: Cairo, image backend (pixman), as found at run time (Debian 12: libcairo2 1.16.0);
// the method's summary prints cairo_version_string(). The pixel convention is the suite's:
// with the identity matrix, pixel (i, j) of the surface covers [i, i+1] x [j, j+1], y down.
// Geometry reaches Cairo as 24.8 fixed point (vertices rounded to 1/256 px). Cairo's fixed
// point wraps beyond +-2^23 px, so a contour with a coordinate beyond +-2^20 px is first
// clipped (Sutherland–Hodgman, which keeps the winding number of every point inside the
// window) to the image grown by one pixel; ordinary contours reach Cairo untouched.
//
// Parameters:
//   antialias  default|none|gray|fast|good|best, default `default` (Cairo's own default, what
//              a user who sets nothing gets). In Cairo 1.16's image backend a fill takes one of
//              three scan converters (cairo-spans-compositor.c, composite_polygon):
//                default, gray, good, best  "tor" (glitter-paths): 1/256 px in x, 15
//                      sub-scanlines per pixel row (rows without edge events in one step),
//                      coverage rounded to a byte;
//                fast  "tor22", a 4 x 4 grid, measured far worse than 4 x 4 sampling should be;
//                none  the mono converter, pixel centres, but it bridges one-pixel gaps
//                      between spans of one fill.
//              All four tor modes are listed so that a report can show they coincide for
//              fills (tests/peers_test.cpp checks it). `subpixel` is left out: it means LCD
//              sub-pixel order, which an A8 surface has none of (for fills it is tor too).
//              Measured accuracy of each, and the quirks: docs/methods-peers.md.
//   paths      merged|per-shape, default merged: what one fill is
//              (methods/scan/kernel/peer_coverage.h). merged: each run of consecutive shapes of one
//              value, orientations made consistent, as a user drawing the scene as one path
//              would; per-shape: each shape alone, so coverage is composited where shapes of
//              one value meet (the star's centre). The rmse between the two is the row's
//              conflation figure (docs/metrics.md).
#include <cairo.h>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <vector>

#include <fmt/format.h>

#include "methods/cost_model.h"
#include "methods/memory_model.h"
#include "methods/method.h"
#include "methods/scan/kernel/peer_coverage.h"
#include "patterns/scene/bezier.h"

namespace aabench {
namespace {

// Cairo's 24.8 fixed point holds +-2^23 px: contours beyond kPeerSafeCoordinate (2^20, which
// leaves room for its intermediate products) are clipped first
// (methods/scan/kernel/peer_coverage.h).

void add_contour_path(cairo_t* cr, const Contour& contour, bool reverse) {
    if (contour.empty()) return;
    bool first = true;
    for_each_vertex(contour, reverse, [&](const Point& p) {
        if (first) {
            cairo_move_to(cr, p.x, p.y);
            first = false;
        } else {
            cairo_line_to(cr, p.x, p.y);
        }
    });
    cairo_close_path(cr);
}

// A contour of Bezier segments as Cairo's path: quadratics raised to cubics exactly (the
// cubic with controls p0 + 2/3 (c - p0) and p2 + 2/3 (c - p2) is the same curve), which Cairo
// flattens at its tolerance when it fills.
void add_outline_path(cairo_t* cr, const SegmentContour& contour, bool reverse) {
    bool first = true;
    for_each_segment(contour, reverse, [&](const Segment& s) {
        if (first) {
            cairo_move_to(cr, s.p[0].x, s.p[0].y);
            first = false;
        }
        if (s.degree == 1) {
            cairo_line_to(cr, s.p[1].x, s.p[1].y);
        } else if (s.degree == 2) {
            const Point a = s.p[0], c = s.p[1], b = s.p[2];
            cairo_curve_to(cr, a.x + 2.0 / 3.0 * (c.x - a.x), a.y + 2.0 / 3.0 * (c.y - a.y),
                           b.x + 2.0 / 3.0 * (c.x - b.x), b.y + 2.0 / 3.0 * (c.y - b.y), b.x, b.y);
        } else {
            cairo_curve_to(cr, s.p[1].x, s.p[1].y, s.p[2].x, s.p[2].y, s.p[3].x, s.p[3].y);
        }
    });
    cairo_close_path(cr);
}

struct CairoScratch {
    cairo_surface_t* surface = nullptr;
    cairo_t* cr = nullptr;
    int width = 0, height = 0;

    void ensure(int w, int h) {
        if (cr && w == width && h == height) return;
        release();
        surface = cairo_image_surface_create(CAIRO_FORMAT_A8, w, h);
        cr = cairo_create(surface);
        width = w;
        height = h;
    }
    void release() {
        if (cr) cairo_destroy(cr);
        if (surface) cairo_surface_destroy(surface);
        cr = nullptr;
        surface = nullptr;
        width = height = 0;
    }
    ~CairoScratch() { release(); }
};

class CairoMethod : public Method {
public:
    CairoMethod(cairo_antialias_t antialias, PeerPaths paths, double tolerance)
        : antialias_(antialias), paths_(paths), tolerance_(tolerance) {}

protected:
    void draw_rows(const Scene& scene, Image& out, int row_lo, int row_hi) const override {
        std::fill(out.row(row_lo), out.row(row_hi), static_cast<float>(scene.background));
        if (scene.width <= 0 || scene.shapes.empty()) return;

        // The surface and context are kept per thread and size (one Method object may render
        // on several threads at once, compare --jobs), so a warm render creates neither. Old
        // bytes on a reused surface are never read: each shape's box is zeroed before its fill.
        thread_local CairoScratch scratch;
        scratch.ensure(scene.width, scene.height);
        cairo_surface_t* surface = scratch.surface;
        cairo_t* cr = scratch.cr;
        cairo_new_path(cr);
        cairo_set_antialias(cr, antialias_);
        cairo_set_fill_rule(cr, CAIRO_FILL_RULE_WINDING);
        cairo_set_tolerance(cr, tolerance_);  // how finely it flattens curves
        // On a cleared A8 destination, OVER with an opaque source writes the coverage itself.
        cairo_set_operator(cr, CAIRO_OPERATOR_OVER);
        cairo_set_source_rgba(cr, 0.0, 0.0, 0.0, 1.0);
        // A band is a clip rectangle of whole rows: Cairo fills its rows only. The whole
        // image is drawn unclipped, as always.
        cairo_reset_clip(cr);
        if (row_lo > 0 || row_hi < scene.height) {
            cairo_rectangle(cr, 0.0, row_lo, scene.width, row_hi - row_lo);
            cairo_clip(cr);
        }
        const int stride = cairo_image_surface_get_stride(surface);

        const double clip_x0 = -1.0, clip_y0 = -1.0;
        const double clip_x1 = scene.width + 1.0, clip_y1 = scene.height + 1.0;
        for (std::size_t first = 0; first < scene.shapes.size();) {
            const ShapeRun run = next_shape_run(scene.shapes, first, paths_);
            first = run.last;
            PixelBox box = run_pixel_box(scene.shapes, run, scene.width, scene.height);
            box.y0 = std::max(box.y0, row_lo);
            box.y1 = std::min(box.y1, row_hi);
            if (box.empty()) continue;
            // Clear the box by hand (cheaper than a Cairo CLEAR fill); Cairo is told which
            // bytes changed behind its back.
            cairo_surface_flush(surface);
            unsigned char* data = cairo_image_surface_get_data(surface);
            for (int j = box.y0; j < box.y1; ++j) {
                std::memset(data + static_cast<std::size_t>(j) * stride + box.x0, 0,
                            static_cast<std::size_t>(box.x1 - box.x0));
            }
            cairo_surface_mark_dirty_rectangle(surface, box.x0, box.y0, box.x1 - box.x0,
                                               box.y1 - box.y0);

            cairo_new_path(cr);
            for (std::size_t k = run.first; k < run.last; ++k) {
                const Shape& shape = scene.shapes[k];
                const bool reverse = reverse_for_run(shape, paths_);
                if (draws_outline(shape)) {  // Bezier curves as curves
                    for (const SegmentContour& c : shape.outline) add_outline_path(cr, c, reverse);
                    continue;
                }
                for (const Contour& contour : shape.contours) {
                    if (needs_clipping(contour)) {
                        add_contour_path(
                            cr, clip_contour(contour, clip_x0, clip_y0, clip_x1, clip_y1), reverse);
                    } else {
                        add_contour_path(cr, contour, reverse);
                    }
                }
            }
            cairo_fill(cr);

            cairo_surface_flush(surface);
            data = cairo_image_surface_get_data(surface);
            const double value = scene.shapes[run.first].value;
            for (int j = box.y0; j < box.y1; ++j) {
                composite_coverage_row(data + static_cast<std::size_t>(j) * stride + box.x0,
                                       out.row(j) + box.x0, box.x1 - box.x0, value);
            }
        }
        const cairo_status_t status = cairo_status(cr);
        if (status != CAIRO_STATUS_SUCCESS) {
            scratch.release();  // a context in an error state stays in it: start afresh
            throw std::runtime_error(
                fmt::format("cairo: fill failed: {}", cairo_status_to_string(status)));
        }
    }

public:
    // Cairo's own flattening: each curved shape's outline as its path, flattened by
    // cairo_copy_path_flat at the tolerance (the vertices in Cairo's 24.8 fixed point, as it
    // fills them).
    std::optional<Scene> own_flattening(const Scene& scene) const override {
        if (!has_bezier(scene)) return std::nullopt;
        thread_local CairoScratch scratch;
        scratch.ensure(1, 1);
        cairo_t* cr = scratch.cr;
        cairo_set_tolerance(cr, tolerance_);
        Scene out = scene;
        for (Shape& shape : out.shapes) {
            if (!draws_outline(shape)) continue;
            shape.contours.clear();
            for (const SegmentContour& c : shape.outline) {
                cairo_new_path(cr);
                add_outline_path(cr, c, false);
                cairo_path_t* path = cairo_copy_path_flat(cr);
                Contour contour;
                for (int k = 0; k < path->num_data; k += path->data[k].header.length) {
                    const cairo_path_data_t& d = path->data[k];
                    if (d.header.type == CAIRO_PATH_MOVE_TO || d.header.type == CAIRO_PATH_LINE_TO) {
                        contour.push_back({path->data[k + 1].point.x, path->data[k + 1].point.y});
                    }
                }
                cairo_path_destroy(path);
                if (contour.size() >= 3) shape.contours.push_back(std::move(contour));
            }
            cairo_new_path(cr);
            shape.outline.clear();
        }
        return out;
    }

private:
    cairo_antialias_t antialias_;
    PeerPaths paths_;
    double tolerance_;
};

cairo_antialias_t antialias_from_name(const std::string& name) {
    if (name == "none") return CAIRO_ANTIALIAS_NONE;
    if (name == "gray") return CAIRO_ANTIALIAS_GRAY;
    if (name == "fast") return CAIRO_ANTIALIAS_FAST;
    if (name == "good") return CAIRO_ANTIALIAS_GOOD;
    if (name == "best") return CAIRO_ANTIALIAS_BEST;
    return CAIRO_ANTIALIAS_DEFAULT;  // the table admits no other name
}

}  // namespace

// What the harness knows of `cairo` (methods/method_traits.h).
MethodTraits cairo_traits() {
    MethodTraits t;
    t.curves = "natively: cairo_curve_to (quadratics raised to cubics exactly), flattened by Cairo at `tolerance`";
    t.working_bytes = [](const ParamValues&, const SceneSize& s) {
        // An 8-bit coverage plane (Cairo pads rows to 4 bytes) and the rasteriser's cells.
        return 1.0 * (s.width + 3) * s.height +
               memory_model::kPeerCellBytes * (s.edge_columns + s.edge_rows);
    };
    t.time_ms = [](const ParamValues&, const SceneSize& s) {
        return cost_model::linear_ms(cost_model::kCairo, s.pixels(), s.vertices);
    };
    t.hard_cases.properties = {
        {Invariant::kContinuity, CaseSet::kAll, DocumentedBound::kLocalChanges,
         "vertices rounded to 1/256 px and coverage to 8 bits: steps, not a continuum"},
        {Invariant::kArea, CaseSet::kAll, DocumentedBound::kQuantisedArea,
         "8-bit coverage on a 1/256 px vertex grid, 15 sub-rows where edges start or cross"},
    };
    t.hard_cases.figures = [](const ParamValues&) {
        // Coverage quantisation per edge pixel (docs/hardcases.md, "area"): the tor
        // converter adds its 15 sub-rows in rows where edges start, end or cross (a point
        // rule in y of step 1/15), and stores 8 bits.
        // Vertices rounded to 1/256 px: each edge moves by at most 2^-9 px in x and in y,
        // which changes the area by at most (edge length) x 2^-9 x sqrt(2) < (edge length) x
        // 2^-8.
        return BoundFigures{.coverage_step = 1.0 / 15.0 + 2.0 / 255.0, .vertex_grid_px = 0x1p-8};
    };
    return t;
}

MethodInfo cairo_method() {
    return {"cairo",
            fmt::format("Cairo {} polygon fill (image backend, A8 coverage / 255), composited "
                        "in float",
                        cairo_version_string()),
            {{"antialias", ParamKind::kChoice, 0, 0, 0,
              {"default", "none", "gray", "fast", "good", "best"},
              "Cairo's antialias mode for fills; default is Cairo's own default (the tor "
              "converter, as are gray, good, best); none: pixel centres; fast: 4x4 samples"},
             {"paths", ParamKind::kChoice, 0, 0, 0, {"merged", "per-shape"},
              "merged: each run of consecutive shapes of one value is one fill (orientations "
              "made consistent), as a user drawing the scene as one path; per-shape: one fill "
              "per shape, composited where shapes meet"},
             {"tolerance", ParamKind::kReal, 0.1, 0.001, 10, {},
              "cairo_set_tolerance: how far (px) Cairo's flattening of a curve may depart from "
              "it; 0.1 is Cairo's default. Polygons do not depend on it"}},
            [](const ParamValues& p) -> std::unique_ptr<Method> {
                return std::make_unique<CairoMethod>(
                    antialias_from_name(p.get_choice("antialias")),
                    peer_paths_from_name(p.get_choice("paths")), p.get_real("tolerance"));
            },
            // The accuracy-time curve of its flattening, on scenes with curves.
            "tolerance",
            {1, 0.3, 0.03, 0.01},
            {},
            /*sweep_on_curves_only=*/true};
}

}  // namespace aabench
