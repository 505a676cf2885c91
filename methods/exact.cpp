// exact — the exact box reference as a fast renderer.
//
// Computes: the exact area-weighted value of the scene over each pixel square, rounded once to
// float32. It is the ceiling every box-filter method converges to, and the suite's answer to
// "what should this pixel be". The engine is methods/scan/exact/fast_coverage.cpp (cell
// accumulation of area and cover along chains, double per-row accumulators, sparse resolve,
// no allocation once warm; rows where boundaries cross go through the double engine's band
// sweep); it is held within 1e-6 of the double box reference
// (methods/scan/reference/box_coverage.cpp, the slow check) by tests/fast_coverage_test.cpp on
// seeded random scenes and the hard cases.
//
// Affine values (a depth image, whose pieces are disjoint: harness/world/frame.h) are
// integrated exactly from each piece's area and first moments
// (methods/scan/reference/piece_coverage.h), the same engine as the box reference of depth; so are
// visible pieces that outnumber the pixels (kDirectPiecesPerPixel below says why).
//
// Discs and rings (scene file `disc`/`ring`, patterns/scene/curves.h) are drawn as curves by
// the closed-form engine of methods/scan/reference/curve_coverage.h, never as their polygonisation.
//
// Colour scenes (docs/colour.md): the fast engine's colour instance sweeps the geometry once
// with three-component steps and cells (methods/scan/kernel/channel_values.h), each plane the
// grey image of its channel bit for bit; scenes another engine draws (discs and rings, Bezier
// segments, affine values, dense visible pieces) and rows with crossings' band sweep are drawn
// per channel.
//
// Parameters: none.
#include "methods/cost_model.h"
#include "methods/memory_model.h"
#include "methods/method.h"
#include "methods/scan/exact/exact_image.h"

namespace aabench {
namespace {

class ExactMethod : public Method {
protected:
    void draw_rows(const Scene& scene, Image& out, int row_lo, int row_hi) const override {
        exact_image_rows(scene, out, row_lo, row_hi);
    }
    void draw_disjoint_piece_rows(const Scene& pieces, Image& out, int row_lo,
                                  int row_hi) const override {
        exact_image_rows(SceneInput::disjoint_pieces(pieces), out, row_lo, row_hi);
    }
    void draw_colour_rows(const SceneInput& in, ImagePlanes& out, int row_lo,
                          int row_hi) const override {
        if (!exact_colour_image_rows(in, out, row_lo, row_hi)) {
            Method::draw_colour_rows(in, out, row_lo, row_hi);
        }
    }
};

}  // namespace

// What the harness knows of `exact` (methods/method_traits.h).
MethodTraits exact_traits() {
    MethodTraits t;
    t.curves = "analytic: the exact band sweep of the segments, no flattening";
    t.affine_values = true;
    t.reference_renderer = true;
    t.colour = "one sweep: three-component steps and cells (per channel for discs, rings, "
               "Bezier segments, affine values, dense pieces)";
    t.working_bytes = [](const ParamValues&, const SceneSize& s) {
        return memory_model::exact_colour_bytes(s);
    };
    t.time_ms = [](const ParamValues&, const SceneSize& s) {
        return cost_model::linear_ms(cost_model::kExact, s.pixels(), s.vertices);
    };
    return t;
}

MethodInfo exact_method() {
    return {"exact",
            "exact area coverage per pixel (the box reference, rounded to float32)",
            {},
            [](const ParamValues&) { return std::make_unique<ExactMethod>(); }};
}

}  // namespace aabench
