// stb-truetype — stb_truetype's rasterizer (the single-header font library of games and
// tools), as a peer to the sources' methods.
//
// Computes: for each fill in order, stb_truetype's 8-bit coverage of the fill (stbtt_Rasterize
// into a one-channel bitmap), read back as a = byte / 255 and composited in float over the
// frame buffer, which starts as the background (as agg does: methods/agg.cpp says why).
//
// How the fill reaches stb_truetype, as its users give it: stbtt_vertex records (move, line,
// quadratic `vcurve`, cubic `vcubic`) whose coordinates are int16, so a user scales them: a
// glyph's vertices are font units (2048 per em in DejaVu) and the glyph's scale maps them to
// pixels. Here each fill's points are taken relative to the top-left of its pixel box and
// multiplied by the largest power of two q <= 256 that keeps them within int16 (q = 256 for a
// fill up to 127 px across, 1/256 px steps; 32 for a whole 1024-px image, 1/32 px), rounded,
// and handed over with scale 1/q and the box's corner as the shift: sub-pixel positions
// survive to 1/(2q) px. The y axis goes in as it is (invert = 0): the bitmap's rows are the
// image's rows. A disc or a ring goes in as eight cubic arcs per circle, as FreeType's does
// (circle_arc_contours, peer_coverage.h), not as the scene's fine polygonisation.
//
// What its coverage is (stb_truetype.h v1.26, rasterizer version 2): curves flattened by
// recursive midpoint subdivision in float until a distance test passes at `flatness` px (its
// own parameter; 0.35 px is what its glyph functions pass), then the exact area of the polygon
// in each pixel accumulated per scanline in float and written as min(|sum| x 255 + 0.5, 255):
// the nonzero rule on a pixel's summed signed area, as AGG's (docs/methods-peers.md).
//
// Parameters:
//   flatness  0.35 px (stb_truetype's own), the cost parameter swept on curve scenes
//   paths     merged|per-shape, default merged: what one fill is (peer_coverage.h).
// The implementation compiled here, its functions static to this file (the font-file half is
// unused: no warnings for it, nor for the library's own code).
#define STB_TRUETYPE_IMPLEMENTATION
#define STBTT_STATIC
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wsign-compare"
#pragma GCC diagnostic ignored "-Wunused-parameter"
#include <stb/stb_truetype.h>
#pragma GCC diagnostic pop

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "build_info.h"  // generated: the stb_truetype version of the package built against
#include "methods/cost_model.h"
#include "methods/memory_model.h"
#include "methods/method.h"
#include "methods/scan/kernel/peer_coverage.h"
#include "patterns/scene/bezier.h"

namespace aabench {
namespace {

// The finest vertex step: 1/256 px, finer than the bitmap's float sums can tell apart.
constexpr double kMaxUnitsPerPx = 256.0;
constexpr double kMaxVertex = 32767.0;  // int16

struct StbScratch {
    std::vector<stbtt_vertex> vertices;
    std::vector<std::uint8_t> coverage;
    Contour clipped;  // a contour clipped near the image
};

class StbTruetypeMethod : public Method {
public:
    StbTruetypeMethod(double flatness, PeerPaths paths) : flatness_(flatness), paths_(paths) {}

    // stb_truetype's own flattening (stbtt_FlattenCurves, the function stbtt_Rasterize calls)
    // of each curved shape's vertices, mapped back to pixels.
    std::optional<Scene> own_flattening(const Scene& scene) const override {
        const bool any_arcs =
            std::any_of(scene.shapes.begin(), scene.shapes.end(), [&](const Shape& shape) {
                return draws_arcs(shape, scene.width, scene.height);
            });
        if (!has_bezier(scene) && !any_arcs) return std::nullopt;
        Scene out = scene;
        std::vector<stbtt_vertex> vertices;
        for (std::size_t first = 0; first < scene.shapes.size();) {
            const ShapeRun run = next_shape_run(scene.shapes, first, paths_);
            first = run.last;
            const PixelBox box = run_pixel_box(scene.shapes, run, scene.width, scene.height);
            if (box.empty()) continue;
            const Placement at = placement(run_bounds(scene, run), box);
            for (std::size_t k = run.first; k < run.last; ++k) {
                Shape& shape = out.shapes[k];
                vertices.clear();
                if (draws_outline(shape)) {
                    for (const SegmentContour& c : shape.outline) {
                        add_outline(vertices, c, false, at);
                    }
                    shape.outline.clear();
                } else if (draws_arcs(shape, scene.width, scene.height)) {
                    for (const SegmentContour& c : circle_arc_contours(*shape.circle)) {
                        add_outline(vertices, c, false, at);
                    }
                    shape.circle.reset();
                } else {
                    continue;
                }
                shape.contours = flatten_vertices(vertices, at);
            }
        }
        return out;
    }

protected:
    void draw_rows(const Scene& scene, Image& out, int row_lo, int row_hi) const override {
        std::fill(out.row(row_lo), out.row(row_hi), static_cast<float>(scene.background));
        if (scene.width <= 0 || scene.shapes.empty()) return;
        const int width = scene.width, height = scene.height;
        thread_local StbScratch scratch;
        scratch.coverage.resize(static_cast<std::size_t>(width) * height);
        for (std::size_t first = 0; first < scene.shapes.size();) {
            const ShapeRun run = next_shape_run(scene.shapes, first, paths_);
            first = run.last;
            PixelBox box = run_pixel_box(scene.shapes, run, width, height);
            box.y0 = std::max(box.y0, row_lo);
            box.y1 = std::min(box.y1, row_hi);
            if (box.empty()) continue;
            // The vertex grid is placed by the run's whole box, not the band's: every band of
            // a render draws the same vertices.
            const Bounds bounds = run_bounds(scene, run);
            if (bounds.empty()) continue;
            const Placement at = placement(bounds, run_pixel_box(scene.shapes, run, width, height));
            std::vector<stbtt_vertex>& v = scratch.vertices;
            v.clear();
            for (std::size_t k = run.first; k < run.last; ++k) {
                const Shape& shape = scene.shapes[k];
                const bool reverse = reverse_for_run(shape, paths_);
                if (draws_outline(shape)) {
                    for (const SegmentContour& c : shape.outline) add_outline(v, c, reverse, at);
                    continue;
                }
                if (draws_arcs(shape, width, height)) {
                    // As stb_truetype's users draw a circle: cubic arcs (vcubic).
                    for (const SegmentContour& c : circle_arc_contours(*shape.circle)) {
                        add_outline(v, c, reverse, at);
                    }
                    continue;
                }
                for (const Contour& original : shape.contours) {
                    const bool clip =
                        needs_clipping(original) || reaches_far(original, width, height);
                    if (clip) {
                        scratch.clipped =
                            clip_contour(original, -1.0, -1.0, width + 1.0, height + 1.0);
                    }
                    const Contour& contour = clip ? scratch.clipped : original;
                    if (contour.size() < 2) continue;
                    bool first_vertex = true;
                    for_each_vertex(contour, reverse, [&](const Point& p) {
                        v.push_back(vertex(first_vertex ? STBTT_vmove : STBTT_vline, p, at));
                        first_vertex = false;
                    });
                }
            }
            if (v.empty()) continue;
            stbtt__bitmap bitmap;
            bitmap.w = box.x1 - box.x0;
            bitmap.h = box.y1 - box.y0;
            bitmap.stride = width;
            bitmap.pixels =
                scratch.coverage.data() + static_cast<std::size_t>(box.y0) * width + box.x0;
            const float scale = static_cast<float>(1.0 / at.units_per_px);
            // The shift maps the vertices back to image pixels (v / q + corner); the bitmap's
            // pixel (x, y) is image pixel (x_off + x, y_off + y). The same vertices and shift in
            // every band; stb_truetype still steps an edge's x row by row in float from the
            // band's first row, so a band may differ from the whole image by a rounding, an
            // 8-bit step at most (tests/render_threads_test.cpp).
            stbtt_Rasterize(&bitmap, static_cast<float>(flatness_), v.data(),
                            static_cast<int>(v.size()), scale, scale, static_cast<float>(at.x0),
                            static_cast<float>(at.y0), box.x0, box.y0, /*invert=*/0, nullptr);
            const double value = scene.shapes[run.first].value;
            for (int j = box.y0; j < box.y1; ++j) {
                composite_coverage_row(
                    scratch.coverage.data() + static_cast<std::size_t>(j) * width + box.x0,
                    out.row(j) + box.x0, box.x1 - box.x0, value);
            }
        }
    }

private:
    struct Bounds {
        double x0 = HUGE_VAL, y0 = HUGE_VAL, x1 = -HUGE_VAL, y1 = -HUGE_VAL;
        void add(const Point& p) {
            x0 = std::min(x0, p.x), y0 = std::min(y0, p.y);
            x1 = std::max(x1, p.x), y1 = std::max(y1, p.y);
        }
        void add(const Bounds& b) {
            if (b.empty()) return;
            add(Point{b.x0, b.y0});
            add(Point{b.x1, b.y1});
        }
        bool empty() const { return !(x0 <= x1); }
    };
    // Where a fill's int16 vertices sit: v = round((p - corner) q), corner (x0, y0) integers.
    struct Placement {
        double x0, y0, units_per_px;
    };

    // The points a run hands over: outlines' control points, contours clipped near the image.
    static Bounds run_bounds(const Scene& scene, ShapeRun run) {
        Bounds b;
        for (std::size_t k = run.first; k < run.last; ++k) {
            const Shape& shape = scene.shapes[k];
            if (draws_outline(shape)) {
                b.add(outline_bounds(shape.outline));
                continue;
            }
            if (draws_arcs(shape, scene.width, scene.height)) {
                b.add(outline_bounds(circle_arc_contours(*shape.circle)));
                continue;
            }
            for (const Contour& c : shape.contours) {
                const bool clip = needs_clipping(c) || reaches_far(c, scene.width, scene.height);
                const Contour clipped =
                    clip ? clip_contour(c, -1.0, -1.0, scene.width + 1.0, scene.height + 1.0)
                         : Contour{};
                for (const Point& p : clip ? clipped : c) b.add(p);
            }
        }
        return b;
    }

    // stbtt_FlattenCurves (the flattening stbtt_Rasterize runs) of a fill's vertices, mapped
    // back to pixels.
    std::vector<Contour> flatten_vertices(std::vector<stbtt_vertex>& vertices,
                                          const Placement& at) const {
        std::vector<Contour> out;
        int contours = 0;
        int* lengths = nullptr;
        stbtt__point* points = stbtt_FlattenCurves(
            vertices.data(), static_cast<int>(vertices.size()),
            static_cast<float>(flatness_ * at.units_per_px), &lengths, &contours, nullptr);
        int start = 0;
        for (int k = 0; k < contours; ++k) {
            Contour contour;
            for (int i = start; i < start + lengths[k]; ++i) {
                contour.push_back(
                    {points[i].x / at.units_per_px + at.x0, points[i].y / at.units_per_px + at.y0});
            }
            start += lengths[k];
            if (contour.size() >= 3) out.push_back(std::move(contour));
        }
        STBTT_free(points, nullptr);
        STBTT_free(lengths, nullptr);
        return out;
    }

    static Bounds outline_bounds(const std::vector<SegmentContour>& outline) {
        Bounds b;
        for (const SegmentContour& c : outline) {
            for (const Segment& s : c) {
                for (int k = 0; k <= s.degree; ++k) b.add(s.p[k]);
            }
        }
        return b;
    }

    // A disc or ring drawn as cubic arcs: one whose circle stays within the reach below (a
    // larger one is drawn as its clipped polygonisation, so that the run's int16 grid stays
    // fine).
    static bool draws_arcs(const Shape& shape, int width, int height) {
        if (!shape.circle || !draws_circle_as_arcs(*shape.circle)) return false;
        const Circle& c = *shape.circle;
        const double mx = std::max(width, 1), my = std::max(height, 1);
        // The arcs' controls lie within 1.04 r of the centre (sqrt(1 + (4/3 tan(pi/16))^2)).
        const double reach = 1.04 * c.outer;
        return c.center.x - reach >= -mx && c.center.y - reach >= -my &&
               c.center.x + reach <= width + mx && c.center.y + reach <= height + my;
    }

    // A contour reaching beyond the image by more than the image's own size is clipped near it
    // first, so that the fill's int16 grid stays fine (the grid covers the fill's extent); one
    // reaching less (grating's bars) is drawn as it is, with no copy (a warm render allocates
    // nothing).
    static bool reaches_far(const Contour& c, int width, int height) {
        const double mx = std::max(width, 1), my = std::max(height, 1);
        for (const Point& p : c) {
            if (p.x < -mx || p.y < -my || p.x > width + mx || p.y > height + my) return true;
        }
        return false;
    }

    // The corner at or left of / above both the bounds and the box, and the largest power of
    // two units per px (at most kMaxUnitsPerPx) that keeps every point within int16 of it.
    static Placement placement(const Bounds& b, const PixelBox& box) {
        const double x0 = std::min(std::floor(b.x0), static_cast<double>(box.x0));
        const double y0 = std::min(std::floor(b.y0), static_cast<double>(box.y0));
        const double extent = std::max({b.x1 - x0, b.y1 - y0, 1.0});
        double q = kMaxUnitsPerPx;
        while (q > 0x1p-20 && extent * q > kMaxVertex) q *= 0.5;
        return {x0, y0, q};
    }

    static stbtt_vertex_type unit(double v) {
        return static_cast<stbtt_vertex_type>(std::clamp(std::lround(v), -32767L, 32767L));
    }
    static stbtt_vertex vertex(unsigned char type, const Point& p, const Placement& at) {
        stbtt_vertex v{};
        v.type = type;
        v.x = unit((p.x - at.x0) * at.units_per_px);
        v.y = unit((p.y - at.y0) * at.units_per_px);
        return v;
    }

    static void add_outline(std::vector<stbtt_vertex>& out, const SegmentContour& c, bool reverse,
                            const Placement& at) {
        bool first = true;
        for_each_segment(c, reverse, [&](const Segment& s) {
            if (first) {
                out.push_back(vertex(STBTT_vmove, s.p[0], at));
                first = false;
            }
            stbtt_vertex v = vertex(s.degree == 1   ? STBTT_vline
                                    : s.degree == 2 ? STBTT_vcurve
                                                    : STBTT_vcubic,
                                    s.p[s.degree], at);
            if (s.degree >= 2) {
                const stbtt_vertex c1 = vertex(0, s.p[1], at);
                v.cx = c1.x, v.cy = c1.y;
            }
            if (s.degree == 3) {
                const stbtt_vertex c2 = vertex(0, s.p[2], at);
                v.cx1 = c2.x, v.cy1 = c2.y;
            }
            out.push_back(v);
        });
    }

    double flatness_;
    PeerPaths paths_;
};

}  // namespace

// What the harness knows of `stb-truetype` (methods/method_traits.h).
MethodTraits stb_truetype_traits() {
    MethodTraits t;
    t.curves =
        "natively: vcurve / vcubic vertices, flattened by stbtt_FlattenCurves at `flatness` px";
    t.working_bytes = [](const ParamValues&, const SceneSize& s) {
        // An 8-bit coverage plane, the vertices and the edge list.
        return 1.0 * s.width * s.height + 48.0 * s.vertices;
    };
    t.time_ms = [](const ParamValues&, const SceneSize& s) {
        // Fitted as every row (methods/cost_model.h).
        return cost_model::linear_ms(cost_model::kStbTruetype, s.pixels(), s.vertices);
    };
    t.hard_cases.properties = {
        {Invariant::kContinuity, CaseSet::kAll, DocumentedBound::kLocalChanges,
         "int16 vertices and 8-bit coverage: steps, not a continuum"},
        {Invariant::kArea, CaseSet::kAll, DocumentedBound::kQuantisedArea,
         "8-bit coverage on a vertex grid of 1/256 px or coarser (int16 vertices)"},
        {Invariant::kTranslation, CaseSet::kAll, DocumentedBound::kLocalChanges,
         "the vertex grid is placed at each fill's pixel box: moving a fill moves the grid"},
    };
    t.hard_cases.figures = [](const ParamValues&) {
        // 8-bit coverage within 2/255 of c per edge pixel; the hard cases' fills are below
        // 128 px across, on the 1/256 px grid (vertices move by at most 2^-9 px).
        return BoundFigures{.coverage_step = 2.0 / 255.0, .vertex_grid_px = 0x1p-8};
    };
    return t;
}

MethodInfo stb_truetype_method() {
    return {"stb-truetype",
            fmt::format("stb_truetype {} stbtt_Rasterize (int16 vertices, float area sums, "
                        "8-bit), composited in float",
                        build_info::kStbTruetypeVersion),
            {{"flatness",
              ParamKind::kReal,
              0.35,
              0.01,
              10,
              {},
              "stbtt_Rasterize's flatness in px: how far its curve subdivision may leave the "
              "curve; 0.35 is what its glyph functions pass"},
             {"paths",
              ParamKind::kChoice,
              0,
              0,
              0,
              {"merged", "per-shape"},
              "merged: each run of consecutive shapes of one value is one fill (orientations "
              "made consistent); per-shape: one fill per shape, composited where shapes meet"}},
            [](const ParamValues& p) {
                return std::make_unique<StbTruetypeMethod>(
                    p.get_real("flatness"), peer_paths_from_name(p.get_choice("paths")));
            },
            "flatness",
            {0.05, 0.1, 1.0},
            {},
            /*sweep_on_curves_only=*/true};
}

}  // namespace aabench
