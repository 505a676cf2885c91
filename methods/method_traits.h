// What the harness knows about a method besides its pixels, held in the method's registry row
// (MethodInfo::traits, methods/method.h): its capabilities, the filter it approximates, its
// memory and time estimates, the documented bounds the hard-case suite settles a nominal
// violation with, and its benchmark roles. The harness reads these and never compares a method
// id with a string, so adding a method is its own file (its MethodInfo and MethodTraits)
// plus one row in methods/registry.cpp.
//
// Facts that depend on the parameters (ssaa's filter, its samples per pixel) are functions of
// the row taking the resolved ParamValues; the rest are plain fields.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "methods/scan/kernel/filter.h"
#include "patterns/scene/params.h"

namespace aabench {

// What the estimates need to know of a scene: sizes, not geometry (harness/measure/limits.h
// measures it, O(vertices)).
struct SceneSize {
    long long width = 0;
    long long height = 0;
    long long vertices = 0;  // also the edge count: every contour is closed
    long long contours = 0;
    long long shapes = 0;
    // Sum over non-horizontal edges of the image rows each overlaps (clipped to the image):
    // the size of the edge table's row buckets, which an edge 60,000 rows tall in a scene of
    // 10^6 edges would make the largest allocation of all.
    long long edge_rows = 0;
    // Sum over edges of the image columns each spans (clipped): the peers' cell counts.
    long long edge_columns = 0;
    // Affine values (depth images) or discs and rings: `exact` integrates those into a whole
    // double raster (piece_coverage.h, curve_coverage.h); plain polygons it does row by row.
    bool exact_raster = false;
    // 3 for a colour scene (Scene::channels): the colour engines' scratch holds three values
    // where the grey one holds one.
    int channels = 1;

    double pixels() const { return static_cast<double>(width) * static_cast<double>(height); }
};

// Which scenes a method draws at all. A capability, not a fallback: the method's
// not_applicable(scene) gives the reason for a scene it refuses (compare shows "n/a").
enum class Applicability {
    kAnyScene,
    kGridCirclesOnly,  // unit-width rings about pixel centres (the circle methods)
};

// The hard-case suite's invariants (harness/measure/hardcases.h, docs/hardcases.md).
enum class Invariant { kFinite, kRange, kArea, kContinuity, kTranslation };
inline constexpr std::size_t kInvariantCount = 5;

// How a documented property is still checked, so that a documented method cannot drift
// arbitrarily far (docs/hardcases.md).
enum class DocumentedBound {
    kLocalChanges,   // every pixel that changed lies within kFlipReachPx of an edge
    kSamplingArea,   // |mass error| <= (pixels crossed by one edge) x span x per-edge error
                     //                 + (pixels holding several edges or a vertex) x span
    kTrapezoidArea,  // |mass error| <= the trapezoidal rule's bound for the kinks of L(y)
    kQuantisedArea,  // |mass error| <= edge pixels x (coverage step) x span + vertex rounding
    kAnyArea,        // |mass error| <= (pixels touched by an edge) x span: only locality
    // Rounding to 8 bits (exact-8bit): area, |mass error| <= every pixel x span x half a step;
    // continuity and translation, every changed pixel changed by at most one step (a value at
    // exactly half a step, e.g. an interior of value 0.3 = 76.5/255, flips anywhere).
    kRoundingStep,
};

// The hard cases a documented property is limited to.
enum class CaseSet {
    kAll,
    // Cases with horizontal (or nearly horizontal) edges exactly on the sub-scanlines of the
    // multi-scan methods (the suite names them: harness/measure/hardcase_scenes.cpp).
    kHorizontalOnSubscanline,
    // Cases with a curve whose y-extremum lies exactly on a sub-scanline (the Bezier cases).
    kCurveExtremumOnSubscanline,
};

// One property of the method that breaks an invariant's nominal bound by design.
struct DocumentedProperty {
    Invariant invariant;
    CaseSet cases;
    DocumentedBound bound;
    std::string reason;  // one line: why the method has this property
};

// The figures the documented bounds need, for the method at its resolved parameters.
struct BoundFigures {
    // kSamplingArea: the largest error, in units of the value span, of a pixel crossed by one
    // straight edge (a regular k x k grid: 1/k, docs/methods-sampling.md "ssaa error bound").
    double edge_pixel_error = 1.0;
    int sub_scanlines = 0;        // kTrapezoidArea: box-multiscan's n
    double coverage_step = 0.0;   // kQuantisedArea: per edge pixel, in units of the span
    double vertex_grid_px = 0.0;  // kQuantisedArea: how far a vertex moves when rounded
};

struct HardCaseTraits {
    std::vector<DocumentedProperty> properties;
    std::function<BoundFigures(const ParamValues&)> figures = [](const ParamValues&) {
        return BoundFigures{};
    };
    // Settings so costly that they run only on the small cases (kHeavySpecMaxPixels).
    std::function<bool(const ParamValues&)> heavy = [](const ParamValues&) { return false; };
    // Parameter settings run besides the defaults, as "key=value,...": those the
    // on-sub-scanline cases are built for, then the parameter maxima (the suite runs every
    // row's line settings before any row's maxima).
    std::vector<std::string> line_settings;
    std::vector<std::string> maximum_settings;
};

struct MethodTraits {
    // Removes hidden surfaces itself (depth-aware scanline or z-buffer): for a 3-D scene the
    // harness hands it the ScreenScene (every face's cells with their depth planes,
    // overlapping) instead of the exact visible pieces, which the others draw in order.
    bool own_visibility = false;
    // With own_visibility: takes patterns and shadows as the paper's scanline does (Nishita &
    // Nakamae 1984, §3.2), coplanar polygons laid over their face and decided by the tie order
    // (shadow, pattern, face in front), instead of the face cut into disjoint cells: the
    // harness hands it the overlay (harness/world/overlay.h) in place of the cells.
    bool coplanar_overlays = false;
    // Draws affine values (Shape::value_plane) the way it draws constant ones: the depth image
    // of the edge stage (antialiasing done on the depth image by averaging depth the way the
    // shaded image averages colour) is the depth scene rendered by the method itself. A method
    // without it is refused a depth image with a one-line error.
    bool affine_values = false;
    Applicability applies_to = Applicability::kAnyScene;
    // Uses earlier frames (a temporal method), or works on a rendered image (a post-process):
    // the harness must feed such methods differently (Method::begin, render_frame).
    bool temporal = false;
    bool post_process = false;
    // What the method's times are not, where they could be misread (empty: its times mean what
    // every method's do). The reports print it under any table holding the method (gl-msaa's
    // times are a CPU emulation of a GPU driver, not the cost of MSAA on a GPU).
    std::string time_caveat;
    // How the method draws Bezier curves (scene file version 4), one line for `aabench list` and
    // docs/methods.md: analytically, natively through its library at its tolerance, flattened
    // at a stated tolerance, or, the default, the reader's flattening of the scene
    // (Shape::contours, within kBezierViewFlatnessPx = 1e-4 px of the curves).
    std::string curves = "the scene's flattening (chords within 1e-4 px of the curves)";
    // How it draws a colour scene (docs/colour.md): the default, each channel's grey scene in
    // turn (Method::draw_colour_rows), or what its own colour path does.
    std::string colour = "per channel: each channel's grey scene drawn in turn";
    // The exact renderer the harness uses where it needs "the right image" fast (the
    // benchmark's edge-stage input and its threads benchmark).
    bool reference_renderer = false;
    // The filter whose exact reference the method approximates, for its parameters.
    std::function<Filter(const ParamValues&)> filter = [](const ParamValues&) {
        return Filter::box();
    };
    // Working memory of one render in bytes, besides the float32 output and the scene
    // (harness/measure/limits.h adds those): every constant is the size of a data structure
    // the code really allocates (methods/memory_model.h, methods/cost_model.h).
    std::function<double(const ParamValues&, const SceneSize&)> working_bytes;
    // The time of one render in ms on the cost model's machine: a deterministic function of
    // the job, from coefficients committed in methods/cost_model.h, never measured here.
    std::function<double(const ParamValues&, const SceneSize&)> time_ms;
    HardCaseTraits hard_cases;
};

}  // namespace aabench
