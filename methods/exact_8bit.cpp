// exact-8bit — the exact image rounded to 8 bits: the quantisation floor of 8-bit renderers.
//
// Computes: the exact image (`exact`'s engines: methods/scan/exact/fast_coverage.cpp, within 1e-6
// of the box reference methods/scan/reference/box_coverage.cpp, curves and dense pieces as `exact`
// draws them), rounded to 255 levels across the scene's value range [min, max] of background and
// shape values (for the built-in 0/1 patterns: to multiples of 1/255). No method that stores 8-bit
// coverage (the peers cairo and agg) can beat this image, so the comparison lists it beside them:
// their error above this floor is their rasteriser's, the rest is the 8-bit format's.
//
// Parameters: none (the bit depth is what the peers store).
#include <algorithm>
#include <cmath>

#include "methods/cost_model.h"
#include "methods/memory_model.h"
#include "methods/method.h"
#include "methods/scan/exact/exact_image.h"

namespace aabench {

namespace {

constexpr double kLevels = 255.0;

class Exact8BitMethod : public Method {
protected:
    void draw_rows(const Scene& scene, Image& out, int row_lo, int row_hi) const override {
        draw_levels(scene, out, row_lo, row_hi);
    }
    void draw_disjoint_piece_rows(const Scene& pieces, Image& out, int row_lo,
                                  int row_hi) const override {
        draw_levels(SceneInput::disjoint_pieces(pieces), out, row_lo, row_hi);
    }

private:
    void draw_levels(const SceneInput& in, Image& out, int row_lo, int row_hi) const {
        exact_image_rows(in, out, row_lo, row_hi);  // `exact`'s image, by its choice of engine
        const Scene& scene = in.scene();
        const auto [lo, hi] = scene.value_range();
        const double span = hi - lo;
        if (!(span > 0.0)) return;  // one value everywhere: nothing to round
        const double to_levels = kLevels / span, step = span / kLevels;
        for (int j = std::max(row_lo, 0); j < std::min(row_hi, scene.height); ++j) {
            float* row = out.row(j);
            for (int i = 0; i < scene.width; ++i) {
                const double t = std::clamp((row[i] - lo) * to_levels, 0.0, kLevels);
                // Round half up by truncation (t >= 0): a cast, not a libm call, per pixel.
                row[i] = static_cast<float>(lo + step * static_cast<int>(t + 0.5));
            }
        }
    }
};

}  // namespace

// What the harness knows of `exact-8bit` (methods/method_traits.h).
MethodTraits exact_8bit_traits() {
    MethodTraits t;
    t.curves = "analytic: the exact band sweep of the segments, then 8-bit codes";
    // exact's engines, rounding in place
    t.working_bytes = [](const ParamValues&, const SceneSize& s) {
        return memory_model::exact_image_bytes(s);
    };
    t.time_ms = [](const ParamValues&, const SceneSize& s) {
        return cost_model::linear_ms(cost_model::kExact8Bit, s.pixels(), s.vertices);
    };
    t.hard_cases.properties = {
        // Half a step per edge pixel, and a value within rounding of a half step flips under
        // any move.
        {Invariant::kArea, CaseSet::kAll, DocumentedBound::kRoundingStep,
         "exact coverage rounded to 8 bits: up to half a step per pixel"},
        {Invariant::kContinuity, CaseSet::kAll, DocumentedBound::kRoundingStep,
         "rounding to 8 bits: a value at half a step flips when anything moves by any amount"},
        {Invariant::kTranslation, CaseSet::kAll, DocumentedBound::kRoundingStep,
         "rounding to 8 bits: a value at half a step flips under the rounding of 2^20 + x"},
    };
    return t;
}

MethodInfo exact_8bit_method() {
    return {"exact-8bit",
            "the exact image rounded to 8 bits: the quantisation floor of 8-bit renderers",
            {},
            [](const ParamValues&) { return std::make_unique<Exact8BitMethod>(); }};
}

}  // namespace aabench
