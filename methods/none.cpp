// none — no antialiasing: each pixel takes the scene's visible value at its centre.
//
// Computes: out(i, j) = v(i + 0.5, j + 0.5), one sample per pixel, the image every
// antialiasing method improves upon (method A of Nishita & Nakamae 1984, §4).
//
// Tie rule for a centre that lies exactly on an edge: the centre takes the value of the
// region to its right (larger x); on a horizontal edge, of the region below (larger y). This
// is the usual "top-left" fill convention: a pixel-aligned square [a, b] x [c, d] with
// integer corners lights exactly the pixels i in [a, b), j in [c, d), and two shapes sharing
// an edge never both claim, nor both miss, a centre on it. It follows from counting a
// crossing at x <= centre and an edge at heights y0 <= y < y1 (the sampling loop is shared with
// ssaa, nishita-d and fast-edge: methods/scan/sampling/point_sampling.h).
//
// 3-D scenes (a ScreenScene with depth planes; Method::own_visibility()): the sample is the
// shape nearest at the centre by its depth plane, a z-buffer with one depth per pixel
// (methods/scan/sampling/point_sampling.h); affine values are taken at the centre.
//
// Colour scenes (docs/colour.md): one walk of each row's crossings finds the runs of centres
// that see one shape, and each run is filled in every plane with the shape's colour
// (PointSampler::centre_runs): which shape a centre sees depends on the geometry alone, so each
// plane is the grey image of its channel bit for bit, for the geometry's cost once. Scenes with
// depth or value planes (3-D frames, affine values) are drawn per channel, the default.
//
// Parameters: none.
#include <array>
#include <vector>

#include "methods/cost_model.h"
#include "methods/memory_model.h"
#include "methods/method.h"
#include "methods/scan/sampling/point_sampling.h"

namespace aabench {
namespace {

// Per-thread scratch (one Method may render from several threads at once), kept between
// renders: a warm render allocates nothing.
thread_local PointSampler t_sampler;

class NoneMethod : public Method {
protected:
    void draw_rows(const Scene& scene, Image& out, int row_lo, int row_hi) const override {
        PointSampler& sampler = t_sampler;
        thread_local std::vector<double> centres, values;
        if (row_lo >= row_hi) return;  // no row: no line to sample
        // Only the edges that a row's centre line y = j + 0.5 meets (EdgeTable's LineGrid): a
        // polygonised circle's edges lie mostly between two of them.
        sampler.reset(scene, LineGrid{0.5, 1, row_lo, row_hi - 1});
        if (sampler.flat()) {
            // Constant values between crossings: the same samples, written as runs.
            for (int j = row_lo; j < row_hi; ++j) {
                sampler.sample_centres(j + 0.5,
                                       {out.row(j), static_cast<std::size_t>(scene.width)});
            }
            return;
        }
        centres.resize(scene.width);
        values.resize(scene.width);
        for (int i = 0; i < scene.width; ++i) centres[i] = i + 0.5;
        for (int j = row_lo; j < row_hi; ++j) {
            sampler.sample_values(j + 0.5, centres, values);
            float* row = out.row(j);
            for (int i = 0; i < scene.width; ++i) row[i] = static_cast<float>(values[i]);
        }
    }

    void draw_colour_rows(const SceneInput& in, ImagePlanes& out, int row_lo,
                          int row_hi) const override {
        const Scene& scene = in.scene();
        PointSampler& sampler = t_sampler;
        sampler.reset(scene, LineGrid{0.5, 1, row_lo, row_hi - 1});
        if (!sampler.flat()) {
            Method::draw_colour_rows(in, out, row_lo, row_hi);
            return;
        }
        // Entry 0 the background, entry k + 1 shape k: the floats each channel's grey render
        // writes (its values rounded once).
        thread_local std::vector<std::array<float, 3>> palette;
        palette.resize(scene.shapes.size() + 1);
        for (int c = 0; c < 3; ++c) {
            palette[0][c] = static_cast<float>(channel_background(scene, c));
            for (std::size_t k = 0; k < scene.shapes.size(); ++k) {
                palette[k + 1][c] = static_cast<float>(channel_value(scene.shapes[k], c));
            }
        }
        const auto width = static_cast<std::size_t>(scene.width);
        for (int j = row_lo; j < row_hi; ++j) {
            float* r = out[0].row(j);
            float* g = out[1].row(j);
            float* b = out[2].row(j);
            sampler.centre_runs(j + 0.5, width, [&](std::size_t first, std::size_t end, int top) {
                const std::array<float, 3>& colour = palette[static_cast<std::size_t>(top + 1)];
                std::fill(r + first, r + end, colour[0]);
                std::fill(g + first, g + end, colour[1]);
                std::fill(b + first, b + end, colour[2]);
            });
        }
    }
};

}  // namespace

// What the harness knows of `none` (methods/method_traits.h).
MethodTraits none_traits() {
    MethodTraits t;
    t.curves = "exact crossings of each sample row: the roots of y(t) = row, no flattening";
    t.own_visibility = true;
    t.affine_values = true;  // z-buffer per sample in 3-D
    t.colour = "one walk per row: each run of centres filled with its shape's colour in every "
               "plane (per channel with depth or value planes)";
    t.working_bytes = [](const ParamValues&, const SceneSize& s) {
        // The edge table and a row; a colour scene's palette, three floats a shape.
        return memory_model::edge_table_and_rows_bytes(s, 3.0) +
               (s.channels == 3 ? 12.0 * (s.shapes + 1) : 0.0);
    };
    t.time_ms = [](const ParamValues&, const SceneSize& s) {
        return cost_model::linear_ms(cost_model::kNone, s.pixels(), s.vertices);
    };
    t.hard_cases.properties = {
        {Invariant::kContinuity, CaseSet::kAll, DocumentedBound::kLocalChanges,
         "point sampling: a sample on an edge flips when the edge moves by any amount"},
        {Invariant::kTranslation, CaseSet::kAll, DocumentedBound::kLocalChanges,
         "2^20 + x rounds x by up to 2^-33 px: a sample exactly on an edge flips"},
        {Invariant::kArea, CaseSet::kAll, DocumentedBound::kSamplingArea,
         "one sample per pixel: area is conserved only on average (a sliver is lost)"},
    };
    // One sample: a pixel crossed by one edge errs by up to the whole span.
    t.hard_cases.figures = [](const ParamValues&) { return BoundFigures{.edge_pixel_error = 1.0}; };
    return t;
}

MethodInfo none_method() {
    return {"none", "no antialiasing: the visible value at each pixel centre (top-left tie rule)",
            {},
            [](const ParamValues&) { return std::make_unique<NoneMethod>(); }};
}

}  // namespace aabench
