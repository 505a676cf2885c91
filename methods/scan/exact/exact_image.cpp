// The exact image's engine choice (exact_image.h).
#include "methods/scan/exact/exact_image.h"

#include "methods/scan/exact/fast_bezier.h"
#include "methods/scan/exact/fast_coverage.h"
#include "methods/scan/reference/bezier_coverage.h"
#include "methods/scan/reference/curve_coverage.h"
#include "methods/scan/reference/piece_coverage.h"
#include "patterns/scene/bezier.h"
#include "patterns/scene/curves.h"

namespace aabench {
namespace {

// Disjoint pieces (a 3-D frame's visible pieces) more numerous than this many per pixel are
// summed piece by piece (the box reference's engine, linear in the pieces) rather than by the
// fast engine: where boundaries cross, its rows sweep every chain of the row once per band,
// which is quadratic when thousands of pieces meet in one row (100,000 triangles fanned inside
// one pixel: 522,514 pieces, 620 s). Below it the fast engine is the faster of the two.
constexpr double kDirectPiecesPerPixel = 1.0;

bool dense_disjoint_pieces(const SceneInput& in) {
    const Scene& scene = in.scene();
    const double pixels = static_cast<double>(scene.width) * static_cast<double>(scene.height);
    return in.is_disjoint_pieces() &&
           static_cast<double>(scene.shapes.size()) > kDirectPiecesPerPixel * pixels;
}

// Whether exact_image_rows draws `in` with the fast engine (the one with a colour instance).
bool fast_engine_draws(const SceneInput& in) {
    const Scene& scene = in.scene();
    return !(has_bezier(scene) && !has_curves(scene) && !has_depth_planes(scene)) &&
           !has_curves(scene) && !has_affine_values(scene) && !dense_disjoint_pieces(in);
}

}  // namespace

bool exact_colour_image_rows(const SceneInput& in, ImagePlanes& out, int row_lo, int row_hi) {
    if (!fast_engine_draws(in)) return false;
    fast_colour_coverage_rows(in.scene(), out, row_lo, row_hi);
    return true;
}

void exact_image_rows(const SceneInput& in, Image& out, int row_lo, int row_hi) {
    const Scene& scene = in.scene();
    // Bezier segments: the segments themselves, not the flattening the other methods draw; the
    // fast engine proves each row free of crossings (fast_bezier.h) and hands the rest to the
    // exact band sweep, which also takes affine values (their first moments; not depth
    // planes, which only 3-D frames have).
    if (fast_bezier_draws(scene)) {
        fast_bezier_rows(scene, out, row_lo, row_hi);
        return;
    }
    if (has_bezier(scene) && !has_curves(scene) && !has_depth_planes(scene)) {
        bezier_rows(scene, out, row_lo, row_hi);
        return;
    }
    // Discs and rings: the closed-form curve engine, not their polygonisation.
    if (has_curves(scene)) {
        curve_rows(scene, out, row_lo, row_hi);
        return;
    }
    if (has_affine_values(scene) || dense_disjoint_pieces(in)) {
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

}  // namespace aabench
