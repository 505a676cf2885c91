// exact-8bit — the exact image rounded to 8 bits: the quantisation floor of 8-bit renderers.
//
// Computes: the exact box reference (methods/scan/box_coverage.cpp), rounded to 255 levels across
// the scene's value range [min, max] of background and shape values (for the built-in 0/1
// patterns: to multiples of 1/255). No method that stores 8-bit coverage (the peers cairo and
// agg) can beat this image, so the comparison lists it beside them: their error above this
// floor is their rasteriser's, the rest is the 8-bit format's.
//
// Parameters: none (the bit depth is what the peers store).
#include <algorithm>
#include <cmath>

#include "methods/scan/box_coverage.h"
#include "methods/method.h"

namespace aabench {
namespace {

constexpr double kLevels = 255.0;

class Exact8BitMethod : public Method {
public:
    void render(const Scene& scene, Image& out) const override {
        const Coverage coverage = box_coverage(scene);
        const auto [lo, hi] = scene.value_range();
        const double span = hi - lo;
        for (std::size_t k = 0; k < coverage.data.size(); ++k) {
            if (!(span > 0.0)) {  // one value everywhere: nothing to round
                out.data[k] = static_cast<float>(coverage.data[k]);
                continue;
            }
            const double t = std::clamp((coverage.data[k] - lo) / span, 0.0, 1.0);
            out.data[k] = static_cast<float>(lo + span * (std::round(t * kLevels) / kLevels));
        }
    }
};

}  // namespace

MethodInfo exact_8bit_method() {
    return {"exact-8bit",
            "the exact image rounded to 8 bits: the quantisation floor of 8-bit renderers",
            {},
            [](const ParamValues&) { return std::make_unique<Exact8BitMethod>(); }};
}

}  // namespace aabench
