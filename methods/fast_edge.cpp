// fast-edge — Kato & Kameyama's fast antialiased polygons: an aliased fill, then every edge
// walked by a DDA that blends the two pixels straddling it.
//
// Source: Kato & Kameyama, "A fast and simple antialiased polygon rendering" (Mitsubishi
// Electric), §3 (1) and (2), Fig. 1–3. Derivations and measured weaknesses:
// docs/methods-sampling.md, "fast-edge".
//
// Step 1, the aliased fill, exactly as `none` (bit for bit: methods/scan/sampling/point_sampling.h,
// centre samples, top-left tie rule), keeping for each pixel the index of the topmost shape at its
// centre (-1 for the background). That index is the z-buffer: in a 2-D scene depth is the
// drawing order, a later shape is nearer.
//
// Step 2, for every edge of every contour (shapes in drawing order, horizontal and vertical
// edges included): a DDA along the edge's major axis (x when |dx| >= |dy|), one step per pixel
// column (row) whose centre line t = i + 1/2 lies in the edge's half-open major range
// [min, max). At each step the true crossing c of the edge with that centre line is computed
// from the edge's first endpoint (c = a_minor + (t - a_major) * slope, not accumulated, so no
// drift and an integer translation moves it exactly). The paper: "the Y distances D_Q, D_P
// from the centres of the two pixels P, Q that straddle (X_i, Y_i) ... I_P = Filter(D_Q) =
// Filter(Y_i - Floor(Y_i)), I_Q = Filter(D_P) = Filter(1 - D_Q)". Here:
//   s     = c + side * inset - 1/2,  side = +1 if the shape lies towards larger minor
//           coordinates across this edge, -1 otherwise;
//   Q     = pixel floor(s) on the minor axis, P = floor(s) + 1 (P is the pixel at the larger
//           minor coordinate, the paper's upper pixel in its y-up figure);
//   frac  = s - floor(s): the distance from Q's centre to the (moved) crossing, the paper's D_Q;
//   I_P   = Filter(frac), I_Q = Filter(1 - frac): each pixel's alpha is one minus its distance
//           to the crossing, a tent of half-width one pixel.
// The default, inset = 0, is the paper's formula: D_Q, D_P measured from the pixel centres to
// the true crossing, whichever side the polygon lies on. It ignores the side, and pays for it:
// a tent about the edge puts half a pixel of the shape's value outside every edge (a
// pixel-aligned square grows a ring of 0.5); on the 256^2 `star` it scores worse than no
// antialiasing at all (docs/methods-sampling.md). It is the default because it is what the
// paper describes, and that finding is worth showing. The variant inset = 1/2 centres the tent
// half a pixel inside the edge. It is the paper's Filter(Y - Floor(Y)) read in this suite's
// pixel-corner coordinates measured along the minor axis pointing into the shape (a reading
// the paper does not give: it never says on which side the polygon lies): the pixel holding
// the crossing gets 1 - (its part outside the edge) and its inner neighbour the rest. So the pixel
// holding the crossing, if the fill left it empty, gets alpha = its exact coverage up to a corner
// triangle of area at most |slope|/8, and a pixel-aligned shape is exact (frac = 0: alpha 1 on the
// inner pixel, which the fill already holds, and 0 on the outer). (With side = -1 the pixel holding
// the crossing is the code's P, with side = +1 it is Q: P and Q are always named by image
// coordinate.) The side: crossing a directed edge a -> b along n = (-(b.y - a.y), b.x - a.x) raises
// its shape's winding number by one (the sign convention under which a contour of positive
// shoelace area winds +1 around its interior). So the shape's inside lies along +n where its
// winding numbers are positive and along -n where they are negative. Contours drawn the usual
// way (outer ones of positive shoelace area, holes negative: patterns/pattern.h's
// circle_contour, the rings, the strips) give winding numbers >= 0 everywhere, so every edge,
// a hole's included, has the inside along +n; a shape drawn all the other way round has it
// along -n. The side is therefore taken per shape, from the sign of the shape's total signed
// area (the integral of its winding number); a shape of zero total area is skipped. (A
// contour's own orientation would be wrong for holes: a hole's enclosed disc is outside.)
// Blend, for each of P and Q inside the image that passes the z-test:
//   out = out + alpha * (value - out), in double, rounded once to float32.
// z-test and no z-write (paper: "Z-buffer hidden surface removal, but the Z-buffer is not
// updated, so that pixels with alpha < 1 are never Z-compared"): the edge of shape s blends
// pixel p only where top(p) <= s, i.e. where no later shape covers p's centre. The paper's
// test is strict (Z_P < Z-buffer); the two give the same image: when the edges of s reach a
// pixel with top(p) == s it still holds float(value of s) (edges of earlier shapes fail the test
// there, edges of later shapes come after), and blending a float towards the double it was
// rounded from rounds back to the same float.
//
// 3-D scenes (a ScreenScene with depth planes; Method::own_visibility()): the fill is a real
// z-buffer, the nearest shape at each pixel centre by its 1/z_v plane there
// (methods/scan/sampling/point_sampling.h), and step 2 walks every edge of every shape of the
// ScreenScene (silhouettes, edges two faces share and pattern and shadow borders alike, hidden
// ones too) with the paper's z-test and no z-write: the edge of shape s blends pixel p unless
// the shape the fill put at p is strictly nearer there than s's plane at p's centre, beyond
// the one depth tie of every engine (kDepthTieRelative, methods/scan/kernel/visibility_rule.h).
// Values with a value_plane are taken at the pixel centre. A 2-D scene takes the path above, bit
// for bit.
//
// Known weaknesses, kept (docs/methods-sampling.md measures them; tests/fast_edge_test.cpp
// asserts them):
//   - blending only moves a pixel towards the shape: a pixel whose centre the fill found
//     inside stays at the full value however little of it is covered (error up to 1/2 on a
//     straight edge, where `none` has the same bound);
//   - vertices: near a vertex the steps of both edges can land on the same pixel, which is then
//     blended twice (1 - (1 - a1)(1 - a2)); a corner pixel outside both edges' step ranges is
//     not blended at all;
//   - thin strips: the two edges of a strip thinner than a pixel blend the same pixels, each as
//     if the whole far side were inside (a 0.4 px strip comes out near 1);
//   - the side of an edge is the shape's net orientation: in a shape whose winding numbers
//     take both signs (a figure 8, or two disjoint contours drawn in opposite senses) the
//     minority part gets the wrong side; edges inside a shape (one shape's overlapping
//     contours) are blended too;
//   - the z-test is per pixel centre: an edge hidden by a later shape still blends the pixels
//     whose centre that shape misses.
//
// Parameters:
//   gamma  real, default 1, range 0.1..10. Filter(a) = a^(1/gamma): the paper's Filter is
//          "gamma correction and the like", and gamma correction for a display of gamma g
//          raises a linear intensity to 1/g. 1 is the identity, the only value right for this
//          suite's linear measurements; other values show what the correction costs.
//   inset  real, default 0, range 0..1 px. How far towards the inside of the shape the tent
//          is centred. 0 is the paper's formula about the true edge, 0.5 px too fat; 0.5
//          makes pixel-aligned shapes exact and gives the outer pixel its coverage (see
//          above). The default comparison runs both (MethodInfo::default_run_variants).
//
// Cost: O(pixels) for the fill (plus the crossings of each centre row) and O(sum over edges of
// their major-axis length in pixels, clipped to the image) for step 2.
#include <algorithm>
#include <cmath>
#include <vector>

#include "methods/cost_model.h"
#include "methods/memory_model.h"
#include "methods/method.h"
#include "methods/scan/kernel/visibility_rule.h"
#include "methods/scan/sampling/point_sampling.h"
#include "patterns/scene/bezier.h"

namespace aabench {
namespace {

class FastEdgeMethod : public Method {
public:
    FastEdgeMethod(double gamma, double inset, double flatness)
        : inv_gamma_(1.0 / gamma), inset_(inset), flatness_(flatness) {}

protected:
    // Curves first become the polygon its DDA can walk: each Bezier segment cut into chords
    // within `flatness` px of it (patterns/scene/bezier.h), as a user of an edge walker does.
    void draw_rows(const Scene& scene, Image& out, int row_lo, int row_hi) const override {
        if (has_bezier(scene)) {
            draw_polygons(flattened_scene(scene, flatness_), out, row_lo, row_hi);
        } else {
            draw_polygons(scene, out, row_lo, row_hi);
        }
    }

public:
    std::optional<Scene> own_flattening(const Scene& scene) const override {
        if (!has_bezier(scene)) return std::nullopt;
        return flattened_scene(scene, flatness_);
    }

private:
    // A band fills its own rows and blends only pixels in them: each pixel sees the same
    // blends in the same order (edges in drawing order) as in the whole image.
    void draw_polygons(const Scene& scene, Image& out, int row_lo, int row_hi) const {
        const int width = scene.width, height = scene.height;
        // Step 1: aliased fill and z-buffer (the visible shape per pixel centre: the topmost
        // in 2-D, the nearest by its depth plane at the centre in 3-D).
        // Per-thread scratch (one Method may render from several threads at once), kept between
        // renders: a warm render allocates nothing.
        thread_local std::vector<int> top;
        thread_local std::vector<double> centres;
        thread_local PointSampler sampler;
        top.resize(static_cast<std::size_t>(width) * height);
        sampler.reset(scene);
        {
            centres.resize(width);
            for (int i = 0; i < width; ++i) centres[i] = i + 0.5;
            for (int j = row_lo; j < row_hi; ++j) {
                int* top_row = top.data() + static_cast<std::size_t>(j) * width;
                sampler.sample_top(j + 0.5, centres, {top_row, static_cast<std::size_t>(width)});
                float* row = out.row(j);
                for (int i = 0; i < width; ++i) {
                    row[i] = static_cast<float>(sampler.value_at(top_row[i], i + 0.5, j + 0.5));
                }
            }
        }
        // Step 2: every edge, in drawing order.
        for (int s = 0; s < static_cast<int>(scene.shapes.size()); ++s) {
            const Shape& shape = scene.shapes[s];
            // One side for the whole shape, from its total signed area: see "the side" above.
            double orientation = 0.0;
            for (const Contour& contour : shape.contours) orientation += twice_signed_area(contour);
            if (orientation == 0.0) continue;
            const double sign = orientation > 0.0 ? 1.0 : -1.0;
            for (const Contour& contour : shape.contours) {
                const std::size_t n = contour.size();
                for (std::size_t k = 0; k < n; ++k) {
                    blend_edge(contour[k], contour[(k + 1) % n], sign, s, sampler, top,
                               {row_lo, row_hi}, out);
                }
            }
        }
    }

    struct Rows {
        int lo, hi;  // the band [lo, hi) being drawn
    };

    double filter(double a) const { return inv_gamma_ == 1.0 ? a : std::pow(a, inv_gamma_); }

    void blend_edge(Point a, Point b, double sign, int shape, const PointSampler& sampler,
                    const std::vector<int>& top, Rows rows, Image& out) const {
        const double dx = b.x - a.x, dy = b.y - a.y;
        if (dx == 0.0 && dy == 0.0) return;
        const bool x_major = std::abs(dx) >= std::abs(dy);
        const double a_major = x_major ? a.x : a.y, b_major = x_major ? b.x : b.y;
        const double a_minor = x_major ? a.y : a.x;
        const double slope = x_major ? dy / dx : dx / dy;  // |slope| <= 1
        // Inside normal sign * (-dy, dx): its minor component decides the side.
        const double inside_minor = x_major ? sign * dx : -sign * dy;
        const double side = inside_minor > 0.0 ? 1.0 : -1.0;
        const double offset = side * inset_ - 0.5;
        // The major range is clipped to the band's rows when the major axis is y; the minor
        // pixels outside the band are skipped in blend().
        const int major_lo = x_major ? 0 : rows.lo;
        const int major_size = x_major ? out.width : rows.hi;
        const int minor_size = x_major ? out.height : out.width;
        // Centre lines t = i + 1/2 with lo <= t < hi, clipped to the image (in double first,
        // so a far-away edge cannot overflow the int conversion).
        const double lo = std::min(a_major, b_major), hi = std::max(a_major, b_major);
        const double first = std::max<double>(major_lo, std::ceil(lo - 0.5));
        const double last = std::min(major_size - 1.0, std::ceil(hi - 0.5) - 1.0);
        // An edge wholly past the image's far side has first > last; converting such a `first`
        // (up to 1e15 and more) to int would overflow, so stop here, in double.
        if (!(first <= last)) return;
        for (int i = static_cast<int>(first); i <= last; ++i) {
            const double c = a_minor + (i + 0.5 - a_major) * slope;
            const double shifted = c + offset;
            const double q = std::floor(shifted);
            // Both pixels outside the image (also keeps the int conversion in range).
            if (q < -1.0 || q >= minor_size) continue;
            const double frac = shifted - q;
            const int qi = static_cast<int>(q);
            blend(x_major, i, qi, filter(1.0 - frac), shape, sampler, top, rows, out);
            blend(x_major, i, qi + 1, filter(frac), shape, sampler, top, rows, out);
        }
    }

    static void blend(bool x_major, int major, int minor, double alpha, int shape,
                      const PointSampler& sampler, const std::vector<int>& top, Rows rows,
                      Image& out) {
        const int i = x_major ? major : minor, j = x_major ? minor : major;
        if (minor < 0 || i >= out.width || j < rows.lo || j >= rows.hi) return;
        const std::size_t p = static_cast<std::size_t>(j) * out.width + i;
        const double cx = i + 0.5, cy = j + 0.5;
        if (!sampler.has_depth()) {
            if (top[p] > shape) return;  // z-test: a later shape covers this centre
        } else if (top[p] >= 0 && top[p] != shape &&
                   depth_order(sampler.inv_depth(top[p]), sampler.inv_depth(shape), cx, cy) ==
                       DepthOrder::kFirstNearer) {
            // z-test, no z-write (3-D): the edge's face, its plane taken at this centre, lies
            // behind what the fill put here, beyond the one depth tie of
            // methods/scan/kernel/visibility_rule.h. A tie (cells of one face, z-fighting) passes.
            return;
        }
        const double value = sampler.value_at(shape, cx, cy);
        const double current = out.data[p];
        out.data[p] = static_cast<float>(current + alpha * (value - current));
    }

    double inv_gamma_;
    double inset_;
    double flatness_;
};

}  // namespace

// What the harness knows of `fast-edge` (methods/method_traits.h).
MethodTraits fast_edge_traits() {
    MethodTraits t;
    t.curves = "flattened at `flatness` px: its DDA walks straight edges";
    t.own_visibility = true;
    t.affine_values = true;
    t.working_bytes = [](const ParamValues&, const SceneSize& s) {
        return memory_model::edge_table_bytes(s) + 4.0 * s.pixels();  // z-buffer of indices
    };
    t.time_ms = [](const ParamValues&, const SceneSize& s) {
        return cost_model::linear_ms(cost_model::kFastEdge, s.pixels(), s.vertices);
    };
    t.hard_cases.properties = {
        {Invariant::kContinuity, CaseSet::kAll, DocumentedBound::kLocalChanges,
         "aliased fill by pixel centres: a centre on an edge flips"},
        {Invariant::kTranslation, CaseSet::kAll, DocumentedBound::kLocalChanges,
         "2^20 + x rounds x by up to 2^-33 px: a centre exactly on an edge flips"},
        {Invariant::kArea, CaseSet::kAll, DocumentedBound::kAnyArea,
         "edge blending by distance, not area: thin shapes come out too heavy, fills too light"},
    };
    return t;
}

MethodInfo fast_edge_method() {
    return {"fast-edge",
            "Kato & Kameyama: aliased fill with z-buffer, then a DDA along every edge blending "
            "the two straddling pixels (alpha = Filter of the sub-pixel distance)",
            {{"gamma", ParamKind::kReal, 1, 0.1, 10, {},
              "Filter(a) = a^(1/gamma); 1 (identity) is right for linear measurement"},
             {"inset", ParamKind::kReal, 0, 0, 1, {},
              "px the alpha tent is centred inside the edge; 0 is the paper's formula about the "
              "true edge (0.5 px fatter), 0.5 is exact on pixel-aligned shapes"},
             {"flatness", ParamKind::kReal, 0.25, 0.0001, 10, {},
              "px the chords of a flattened curve may depart from it (the DDA walks straight "
              "edges); 0.25 is FreeType's, Skia's and Qt's choice. Polygons do not depend on it"}},
            [](const ParamValues& p) {
                return std::make_unique<FastEdgeMethod>(p.get_real("gamma"), p.get_real("inset"),
                                                        p.get_real("flatness"));
            },
            // The accuracy-time curve of its flattening, on scenes with curves.
            "flatness",
            {1, 0.05},
            {"fast-edge:inset=0.5"},
            /*sweep_on_curves_only=*/true};
}

}  // namespace aabench
