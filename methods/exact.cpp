// exact — the exact box reference as a fast renderer.
//
// Computes: the exact area-weighted value of the scene over each pixel square, rounded once to
// float32. It is the ceiling every box-filter method converges to, and the suite's answer to
// "what should this pixel be". The engine is methods/scan/fast_coverage.cpp (cell
// accumulation of area and cover along chains, double per-row accumulators, sparse resolve,
// no allocation once warm; rows where boundaries cross go through the double engine's band
// sweep); it is held within 1e-6 of the double box reference (methods/scan/box_coverage.cpp,
// the slow check) by tests/fast_coverage_test.cpp on seeded random scenes and the hard cases.
//
// Affine values (a depth image, whose pieces are disjoint: harness/world/frame.h) are
// integrated exactly from each piece's area and first moments (methods/scan/piece_coverage.h),
// the same engine as the box reference of depth; so are visible pieces that outnumber the
// pixels (kDirectPiecesPerPixel below says why).
//
// Discs and rings (scene file `disc`/`ring`, patterns/scene/curves.h) are drawn as curves by
// the closed-form engine of methods/scan/curve_coverage.h, never as their polygonisation.
//
// Parameters: none.
#include "methods/cost_model.h"
#include "methods/memory_model.h"
#include "methods/method.h"
#include "methods/scan/curve_coverage.h"
#include "methods/scan/fast_coverage.h"
#include "methods/scan/piece_coverage.h"
#include "patterns/scene/curves.h"

namespace aabench {

void exact_rows(const Scene& scene, Image& out, int row_lo, int row_hi);  // below

namespace {

// Disjoint pieces (a 3-D frame's visible pieces) more numerous than this many per pixel are
// summed piece by piece (the box reference's engine, linear in the pieces) rather than by the
// fast engine: where boundaries cross, its rows sweep every chain of the row once per band,
// which is quadratic when thousands of pieces meet in one row (100,000 triangles fanned inside
// one pixel: 522,514 pieces, 620 s). Below it the fast engine is the faster of the two.
constexpr double kDirectPiecesPerPixel = 1.0;

bool dense_disjoint_pieces(const Scene& scene) {
    const double pixels = static_cast<double>(scene.width) * static_cast<double>(scene.height);
    return scene.disjoint_pieces &&
           static_cast<double>(scene.shapes.size()) > kDirectPiecesPerPixel * pixels;
}

class ExactMethod : public Method {
protected:
    void draw_rows(const Scene& scene, Image& out, int row_lo, int row_hi) const override {
        exact_rows(scene, out, row_lo, row_hi);
    }
};

}  // namespace

// The exact image's rows, by the engine that suits the scene (exact-8bit rounds these).
void exact_rows(const Scene& scene, Image& out, int row_lo, int row_hi) {
    // Discs and rings: the closed-form curve engine, not their polygonisation.
    if (has_curves(scene)) {
        curve_rows(scene, out, row_lo, row_hi);
        return;
    }
    if (has_affine_values(scene) || dense_disjoint_pieces(scene)) {
        // The piece engine computes the whole image; a band keeps its own rows.
        const Coverage coverage = piece_box_coverage(scene);
        for (int j = row_lo; j < row_hi; ++j) {
            const double* src = &coverage.data[static_cast<std::size_t>(j) * scene.width];
            float* row = out.row(j);
            for (int i = 0; i < scene.width; ++i) row[i] = static_cast<float>(src[i]);
        }
        return;
    }
    fast_coverage_rows(scene, out, row_lo, row_hi);
}

namespace {

// The fast engine (fast_coverage.cpp): its own edge records, chains and events, one row of
// double accumulators; rows where boundaries cross also build the edge table and the band
// sweep. Per-pixel state only for affine values and curves: affine values take one double
// raster (piece_coverage.h); curves (curve_coverage.cpp) keep value and base (doubles), a flag
// and a list head per pixel (21 bytes) over the curves' boxes, and each run of polygons among
// them two double rasters plus the polygon engine's own: kCurvePixelBytes covers the lot.
double exact_working_bytes(const ParamValues&, const SceneSize& s) {
    using namespace memory_model;
    return kFastEdgeBytes * s.vertices + 8.0 * (s.width + 32) + kRowBytes * (s.height + 1) +
           edge_table_bytes(s) + kSweepBytesPerEdge * s.vertices +
           (s.exact_raster ? kCurvePixelBytes * s.pixels() : 0.0);
}

}  // namespace

// What the harness knows of `exact` (methods/method_traits.h).
MethodTraits exact_traits() {
    MethodTraits t;
    t.affine_values = true;
    t.reference_renderer = true;
    t.working_bytes = exact_working_bytes;
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
