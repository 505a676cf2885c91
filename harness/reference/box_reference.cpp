// The box reference: the 2-D engine for scenes of constant values, and for ScreenScenes with
// depth planes or affine values the visible pieces (visibility.h) integrated exactly by
// methods/scan/reference/piece_coverage.cpp (areas and first moments; its opening comment says why
// that is exact).
#include "harness/reference/box_reference.h"

#include <algorithm>

#include "harness/reference/visibility.h"
#include "methods/scan/reference/bezier_coverage.h"
#include "methods/scan/reference/box_coverage.h"
#include "methods/scan/reference/curve_coverage.h"
#include "methods/scan/reference/piece_coverage.h"
#include "patterns/scene/bezier.h"
#include "patterns/scene/curves.h"

namespace aabench {

bool has_planes(const Scene& scene) {
    return std::any_of(scene.shapes.begin(), scene.shapes.end(), [](const Shape& s) {
        return s.inv_depth.has_value() || s.value_plane.has_value();
    });
}

Coverage box_reference(const SceneInput& in) {
    const Scene& scene = in.scene();
    require_window_frame(scene, "box reference");
    // Exact visibility's output (a prepared frame's pieces, depth planes dropped): integrated
    // piece by piece in time linear in their vertices. The 2-D engine would sweep them as
    // overlapping shapes, at a cost that grows faster than their number (52,008 pieces took
    // 3.3 s, the 250,000 of a 200,000-triangle soup minutes).
    if (in.is_disjoint_pieces() && !has_curves(scene)) return box_reference_of_pieces(scene);
    if (has_bezier(scene)) {  // Bezier segments: the exact band sweep, no flattening (2-D only)
        if (has_depth_planes(scene) || (has_planes(scene) && has_curves(scene))) {
            throw InputError(
                "box reference: a scene with Bezier segments has no depth planes, nor affine "
                "values beside discs or rings, yet");
        }
        // Affine values too (their first moments). With discs or rings: the curve engine's
        // layers, its Bezier runs by the band sweep.
        if (!has_curves(scene)) return bezier_box_coverage(scene);
    }
    if (has_curves(scene)) {  // discs and rings: the closed-form curve engine (2-D only)
        if (has_planes(scene)) {
            throw InputError("box reference: a scene with curves has no depth planes or affine values");
        }
        return curve_box_coverage(scene);
    }
    if (!has_planes(scene)) return box_coverage(scene);  // the 2-D engine, unchanged
    return box_reference_of_pieces(visible_pieces(scene));
}

Coverage box_reference_of_pieces(const Scene& pieces) { return piece_box_coverage(pieces); }

}  // namespace aabench
