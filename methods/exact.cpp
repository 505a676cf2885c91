// exact — the exact box reference used as a renderer.
//
// Computes: the exact area-weighted value of the scene over each pixel square (harness/
// methods/scan/box_coverage.cpp explains how and why it is exact), rounded once to float32. It is the
// ceiling every box-filter method converges to, and the suite's answer to "what should this
// pixel be": its error against the box reference is float32 rounding only (<= 2^-24 relative).
//
// Parameters: none.
#include "methods/scan/box_coverage.h"
#include "methods/scan/curve_coverage.h"
#include "patterns/scene/curves.h"
#include "methods/method.h"

namespace aabench {
namespace {

class ExactMethod : public Method {
public:
    void render(const Scene& scene, Image& out) const override {
        // Discs and rings (issue 12): the closed-form curve engine, not their polygonisation.
        const Coverage coverage = has_curves(scene) ? curve_box_coverage(scene) : box_coverage(scene);
        for (std::size_t k = 0; k < coverage.data.size(); ++k) {
            out.data[k] = static_cast<float>(coverage.data[k]);
        }
    }
};

}  // namespace

MethodInfo exact_method() {
    return {"exact", "exact area coverage per pixel (the box reference, rounded to float32)",
            {},
            [](const ParamValues&) { return std::make_unique<ExactMethod>(); }};
}

}  // namespace aabench
