// exact — the exact box reference used as a renderer.
//
// Computes: the exact area-weighted value of the scene over each pixel square (harness/
// methods/scan/box_coverage.cpp explains how and why it is exact), rounded once to float32. It is the
// ceiling every box-filter method converges to, and the suite's answer to "what should this
// pixel be": its error against the box reference is float32 rounding only (<= 2^-24 relative).
//
// Affine values (a depth image, whose pieces are disjoint: harness/world/pipeline.h) are
// integrated exactly from each piece's area and first moments (methods/scan/piece_coverage.h),
// the same engine as the box reference of depth.
//
// Parameters: none.
#include "methods/method.h"
#include "methods/scan/box_coverage.h"
#include "methods/scan/piece_coverage.h"

namespace aabench {
namespace {

class ExactMethod : public Method {
public:
    void render(const Scene& scene, Image& out) const override {
        const Coverage coverage =
            has_affine_values(scene) ? piece_box_coverage(scene) : box_coverage(scene);
        for (std::size_t k = 0; k < coverage.data.size(); ++k) {
            out.data[k] = static_cast<float>(coverage.data[k]);
        }
    }
    bool affine_values() const override { return true; }
};

}  // namespace

MethodInfo exact_method() {
    return {"exact", "exact area coverage per pixel (the box reference, rounded to float32)",
            {},
            [](const ParamValues&) { return std::make_unique<ExactMethod>(); }};
}

}  // namespace aabench
