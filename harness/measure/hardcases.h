// The hard-case suite: degenerate and enormous geometry on purpose, run against every method
// and every exact reference, each result checked against invariants with stated bounds. Pure
// computation, no I/O: the CLI (`aabench hardcases`) prints format_hard_case_table(), the
// report embeds it. Cases, invariants, bounds and the documented properties are explained in
// docs/hardcases.md; the constants below carry their reasons.
//
// A result is one case x one method (or reference) with one outcome per invariant:
//   pass        within the invariant's nominal bound;
//   documented  outside it, but documented by the method's row (MethodTraits::hard_cases)
//               for this invariant and case (a property of the method, e.g. point sampling is
//               discontinuous), and still within that entry's documented bound;
//   fail        anything else: a bug, reported with its worst value and pixel;
//   n/a         the invariant does not apply (area for radial filters) or the case was not run
//               for this method (the size cap of the heaviest specs).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "harness/measure/compare.h"
#include "methods/method_traits.h"
#include "methods/scan/kernel/image.h"
#include "patterns/scene/scene.h"

namespace aabench {

// ---- Bounds (docs/hardcases.md derives each) ----

// Range: a method's pixel is a weighted mean of scene values with non-negative weights summing
// to 1, accumulated in double and rounded to float32 once or a few times (fast-edge, the peers
// blend shape by shape): each rounding is within 2^-24 relative, so 1e-6 (about 16 float32
// ulps at 1) is ample, scaled by the largest |value| when that exceeds 1.
inline constexpr double kRangeSlack = 1e-6;
// References are double throughout: the box reference is exact to 1e-12 per pixel, the radial
// ones to 1e-10 (docs/references.md); 1e-9 leaves an order of magnitude.
inline constexpr double kReferenceRangeSlack = 1e-9;
// Area: exact rounds each pixel once to float32 (2^-24 of the pixel's value, all of one sign
// in the sum's worst case), on top of the box reference's 1e-12 per pixel.
inline constexpr double kFloat32Rounding = 0x1p-24;
inline constexpr double kBoxReferencePixelError = 1e-12;
// Continuity: every vertex moved by at most this far (in x and in y, independently)...
inline constexpr double kContinuityMovePx = 1e-9;
// ...may change a continuous method's output by at most this much per pixel. The exact box
// value is Lipschitz in the vertices: it moves by at most (edge length inside the pixel) x
// 1e-9, a few 1e-9 for ordinary pixels; 1e-6 also absorbs one float32 rounding step at 1.
inline constexpr double kContinuityTolerance = 1e-6;
// Translation: the scene and its window moved together by this many pixels...
inline constexpr double kTranslationOffsetPx = 1048576.0;  // 2^20
// ...give the same image to within this. Adding 2^20 rounds a coordinate to 2^-32 px (the
// ulp at 2^20..2^21), which moves an exact pixel value by about 2^-32 x edge length: 1e-5
// leaves room for float32 rounding and for references of scenes already far from 0.
inline constexpr double kTranslationTolerance = 1e-5;
// A documented discontinuity may change pixels only this close to an edge: the support
// radius of every registered filter (1 px, measured from the pixel centre) plus the pixel's
// own extent. Pixels touched by an edge, dilated by this many pixels (Chebyshev).
inline constexpr int kFlipReachPx = 2;
// The heaviest specs (n = 256 multiscan, k = 64 ssaa: 4096 samples per pixel) run only on
// cases of at most this many pixels, so the whole suite stays within seconds; the one larger
// case is 16384x16, whose point is the image's shape, not the parameters.
inline constexpr long long kHeavySpecMaxPixels = 4096;

// ---- Cases ----

struct HardCaseScene {
    Scene scene;
    // Sum over the image of (visible value - background) times area, computed independently of
    // every renderer (shoelace on simple polygons, closed forms); nullopt when none is known.
    std::optional<double> exact_mass;
};

struct HardCase {
    std::string name;         // short, stable: "sliver-1e-9"
    std::string description;  // one line
    std::function<HardCaseScene()> make;  // pure: same scene, bit for bit, every call
};

// The named list, in report order.
const std::vector<HardCase>& hard_cases();

// The method specs run when none are given: every registered method at its defaults, then the
// sub-scanline counts of the on-sub-scanline cases and the parameter maxima.
std::vector<std::string> default_hard_case_methods();

// ---- Invariants and outcomes ----

// Invariant and kInvariantCount: methods/method_traits.h (a method's row documents its
// properties per invariant).
const char* invariant_name(Invariant invariant);  // "finite", "range", ...

enum class Outcome { kNotApplicable, kPass, kDocumented, kFail };
const char* outcome_name(Outcome outcome);  // "n/a", "pass", "documented", "FAIL"

// How a documented property is still checked: DocumentedBound (methods/method_traits.h).
inline constexpr double kEightBitStep = 1.0 / 255.0;

// Whether `case_name` is one of the cases `set` names (a method's documented properties are
// limited to a CaseSet: MethodTraits::hard_cases).
bool case_in_set(CaseSet set, const std::string& case_name);

struct InvariantResult {
    Outcome outcome = Outcome::kNotApplicable;
    double value = 0.0;      // the measured figure the bound applies to (see docs)
    double bound = 0.0;      // the nominal bound
    double documented_bound = 0.0;  // the documented entry's bound, when documented
    double changed_fraction = 0.0;  // continuity, translation: pixels beyond the tolerance
    double allowed_fraction = 0.0;  // ... and the fraction within kFlipReachPx of an edge
    int x = -1;              // worst pixel, when the figure is per pixel
    int y = -1;
    std::string note;        // documented: the reason; fail: what went wrong
};

struct HardCaseRow {
    std::string case_name;
    std::string method;  // canonical method spec, or "ref:box", "ref:gaussian:...", ...
    bool reference = false;
    int width = 0;
    int height = 0;
    std::array<InvariantResult, kInvariantCount> results;
    Outcome outcome = Outcome::kNotApplicable;  // the worst of the results

    const InvariantResult& at(Invariant i) const { return results[static_cast<std::size_t>(i)]; }
    InvariantResult& at(Invariant i) { return results[static_cast<std::size_t>(i)]; }
};

// Runs every case against each method spec (empty: default_hard_case_methods()) and each
// exact reference (box, gaussian, cone at their defaults). Specs are checked first (an
// InputError before any work). Rows come in case order, then methods, then references.
std::vector<HardCaseRow> run_hard_cases(const std::vector<std::string>& method_specs,
                                        const ProgressFn& progress = {});

// The nominal checks on their own (tests build violations with them), on images widened to
// double (a float32 image converts exactly). Each is written so that NaN fails.
InvariantResult check_finite(const Coverage& image);
// `lo`, `hi`: the value range; the figure is the largest excursion beyond it.
InvariantResult check_range(const Coverage& image, double lo, double hi, double slack);
// mass = sum of (pixel - background); the figure is |mass - exact_mass|, `bound` absolute.
InvariantResult check_area(double mass, double exact_mass, double bound);
// The figure is the largest per-pixel difference; changed_fraction counts the pixels that
// differ by more than `tolerance`.
InvariantResult check_same(const Coverage& a, const Coverage& b, double tolerance);

// The scene with every vertex moved by a deterministic offset in [-move, move]^2, hashed from
// its coordinates: vertices that coincide move together, so a shared vertex stays shared.
// (Moving them apart turns the 1024-spoke star's centre into ~10^6 edge crossings within
// 1e-9 px: a different scene, and one the exact references take minutes on.)
Scene perturbed(const Scene& scene, double move_px);
// The scene and its window moved together by (offset, offset).
Scene offset_with_window(const Scene& scene, double offset_px);
// Pixels touched by some edge of the scene (in its window frame), dilated by `reach` pixels.
Raster<std::uint8_t> edge_neighbourhood(const Scene& scene, int reach);

// Text: a grid of cases x methods, then every failure with its worst value and pixel, then the
// documented properties seen (with their reasons), then the worst value per invariant.
std::string format_hard_case_table(const std::vector<HardCaseRow>& rows);
// The rows as a JSON array (one object per row, every invariant with its figures).
std::string format_hard_case_json(const std::vector<HardCaseRow>& rows);

}  // namespace aabench
