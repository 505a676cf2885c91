// none — no antialiasing: each pixel takes the scene's visible value at its centre.
//
// Computes: out(i, j) = v(i + 0.5, j + 0.5), one sample per pixel, the image every
// antialiasing method improves upon (method A of Nishita & Nakamae 1984, §4).
//
// Tie rule for a centre that lies exactly on an edge: the centre takes the value of the
// region to its right (larger x); on a horizontal edge, of the region below (larger y). This
// is the usual "top-left" fill convention: a pixel-aligned square [a, b] x [c, d] with
// integer corners lights exactly the pixels i in [a, b), j in [c, d), and two shapes sharing
// an edge never both claim, nor both miss, a centre on it. It follows from counting a
// crossing at x <= centre and an edge at heights y0 <= y < y1 (EdgeTable::crossings_at).
//
// Parameters: none.
#include "methods/edge_table.h"
#include "methods/method.h"

namespace aabench {
namespace {

class NoneMethod : public Method {
public:
    void render(const Scene& scene, Image& out) const override {
        const EdgeTable table(scene);
        VisibilityWalker walker(table);
        std::vector<Crossing> crossings;
        for (int j = 0; j < scene.height; ++j) {
            table.crossings_at(j + 0.5, crossings);
            walker.reset();
            std::size_t next = 0;
            float* row = out.row(j);
            for (int i = 0; i < scene.width; ++i) {
                const double cx = i + 0.5;
                while (next < crossings.size() && crossings[next].x <= cx) {
                    walker.cross(crossings[next].shape, crossings[next].winding);
                    ++next;
                }
                row[i] = static_cast<float>(walker.value());
            }
        }
    }
};

}  // namespace

MethodInfo none_method() {
    return {"none", "no antialiasing: the visible value at each pixel centre (top-left tie rule)",
            {},
            [](const ParamValues&) { return std::make_unique<NoneMethod>(); }};
}

}  // namespace aabench
