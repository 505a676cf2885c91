// The one rule for which shape is seen at a point, shared by every engine that decides it: the
// point sampler (point_sampling.h), the fast exact engine (fast_coverage.cpp), the band sweep's
// walker (edge_table.h), the scanline visibility of the multi-scanning methods
// (scanline_visibility.h), fast-edge's z-test and the exact visibility of the reference
// (harness/reference/visibility.cpp). A change here changes all of them together
// (tests/visibility_rule_test.cpp holds them to it).
//
// The rule:
//   1. Coverage: a shape covers a point where its nonzero winding number is nonzero.
//   2. 2-D (no depth planes): of the shapes covering the point, the topmost (the largest index:
//      a later shape covers an earlier one) is seen, else the background.
//   3. Depth planes (a ScreenScene: every shape has inv_depth = 1/z_v, affine in screen
//      position, larger is nearer): of the shapes covering the point, the nearest there is
//      seen. Two depths closer than kDepthTieRelative of the size of their terms are a tie
//      (depth_order); a tie at the point goes to the shape nearer just right of it (larger
//      d(inv_depth)/dx, the same tie, relative to the slopes), as a point on an edge takes
//      the region to its right (point_sampling.h); a tie in slope too (coplanar shapes) goes
//      to the later shape, as in 2-D.
// Engines that decide a whole region at once (the reference cuts an overlap by the line of
// equal depth) use the same tolerance at each vertex (depth_tie_tolerance); a region tied at
// every vertex goes to the later shape. Fast-edge's z-test ("no z-write", Kato & Kameyama)
// blocks only a shape strictly behind, beyond the tie (depth_order).
#pragma once

#include <algorithm>
#include <cmath>
#include <span>
#include <vector>

#include "patterns/scene/scene.h"

namespace aabench {

// Two depths closer than this, relative to the size of their terms (|c| + |gx x| + |gy y| of
// the larger plane at the point), are a tie. Why a tolerance and not `==`: where two faces
// meet along an edge, or coplanar faces carry planes fitted from different vertices, their
// depths at one point are computed by different roundings and agree only to ~1e-13 relative
// (1e-15 for shared edges, more for ill-shaped faces); deciding on the sign of that noise
// puts an arbitrary face in front (for the rest of the span, in a scanline walk). Why 1e-9:
// three orders above that noise, and far below anything a depth buffer resolves (a 32-bit
// z-buffer resolves ~1e-7), so two distinct surfaces this close are z-fighting that the tie
// decides. A real depth difference this small is misjudged only within
// ~1e-9 w / |d(w_a - w_b)/dx| px of the line where the faces meet (< 1e-6 px on every
// built-in scene), below the 1e-6 per pixel the exact engines are held to.
inline constexpr double kDepthTieRelative = 1e-9;

// The size of the terms of plane p at (x, y): the scale of its rounding there.
inline double depth_term_size(const AffinePlane& p, double x, double y) {
    return std::abs(p.c) + std::abs(p.gx * x) + std::abs(p.gy * y);
}

// The largest difference of a's and b's depth at (x, y) that is a tie.
inline double depth_tie_tolerance(const AffinePlane& a, const AffinePlane& b, double x, double y) {
    return kDepthTieRelative * std::max(depth_term_size(a, x, y), depth_term_size(b, x, y));
}

enum class DepthOrder { kFirstNearer, kTie, kSecondNearer };

// Which of the planes a, b is nearer at (x, y), ties by kDepthTieRelative. A NaN is a tie.
inline DepthOrder depth_order(const AffinePlane& a, const AffinePlane& b, double x, double y) {
    const double difference = a.at(x, y) - b.at(x, y);
    const double tie = depth_tie_tolerance(a, b, x, y);
    if (difference > tie) return DepthOrder::kFirstNearer;
    if (-difference > tie) return DepthOrder::kSecondNearer;
    return DepthOrder::kTie;
}

// True when shape `a` (depth plane pa) is seen rather than shape `b` (pb) at (x, y), both
// covering it: rule 3 above. Without depth planes (`planes` empty) rule 2: a > b.
inline bool seen_over(int a, int b, std::span<const AffinePlane> planes, double x, double y) {
    if (planes.empty()) return a > b;
    const AffinePlane& pa = planes[a];
    const AffinePlane& pb = planes[b];
    switch (depth_order(pa, pb, x, y)) {
        case DepthOrder::kFirstNearer:
            return true;
        case DepthOrder::kSecondNearer:
            return false;
        case DepthOrder::kTie:
            break;
    }
    // Tied at the point: the one nearer just right of it (the same tie, on the slopes).
    const double slope_tie = kDepthTieRelative * std::max(std::abs(pa.gx), std::abs(pb.gx));
    if (std::abs(pa.gx - pb.gx) > slope_tie) return pa.gx > pb.gx;
    return a > b;  // coplanar: the later shape, as in 2-D
}

// The shape seen at (x, y) among `covering` (the shapes covering the point), -1 for none:
// one pass keeping the one seen over the others so far.
inline int seen_among(std::span<const int> covering, std::span<const AffinePlane> planes, double x,
                      double y) {
    if (covering.empty()) return -1;
    int best = covering[0];
    for (std::size_t k = 1; k < covering.size(); ++k) {
        if (seen_over(covering[k], best, planes, x, y)) best = covering[k];
    }
    return best;
}

// Rules 1 and 2 along a horizontal walk over a scene of one shape (gratings, rings, every
// built-in 2-D pattern): the nonzero rule is one counter, and what is seen right of a crossing
// is `inside` (the shape: its value, or its index) or `outside` (the background, or -1).
// CoverWalk's one-shape case, and the walks that keep it in registers instead of paying
// CoverWalk's bookkeeping per crossing: the sub-scanline walks (subscanline.cpp,
// subscanline_rows.cpp) and the fast exact engine's steady chains (fast_tracked.cpp).
template <class Value = double>
class OneShapeWalk {
public:
    OneShapeWalk(Value inside, Value outside) : inside_(inside), outside_(outside) {}
    // The rule itself: `winding` added to the shape's winding number, whether the shape then
    // covers (the nonzero rule). CoverWalk keeps the counter in its own state and its values
    // as constants; the walks below keep both in registers.
    static bool covers_after(int& winding_number, int winding) {
        winding_number += winding;
        return winding_number != 0;
    }
    // Applies one crossing adding `winding` to the shape's winding number; returns what is
    // seen right of it.
    Value cross(int winding) { return covers_after(winding_, winding) ? inside_ : outside_; }
    // Back to outside the shape.
    void clear() { winding_ = 0; }

private:
    Value inside_, outside_;
    int winding_ = 0;
};

// Rules 1 and 2 along a horizontal walk: per-shape winding numbers fed crossings left to
// right, the shapes covering the current point, and the topmost of them, kept current at
// O(1) per crossing except when the topmost shape stops covering (then a scan of the few
// covering shapes: few overlap at one point, so it beats a balanced tree).
class CoverWalk {
public:
    // Starts a walk over `shape_count` shapes, reusing the memory held: no allocation once it
    // has held as many shapes.
    void reset(int shape_count) {
        winding_.assign(static_cast<std::size_t>(shape_count), 0);
        covering_.clear();
        top_ = -1;
        one_shape_ = shape_count == 1;
    }
    // Applies one crossing of a boundary of `shape` adding `winding` to its winding number.
    void cross(int shape, int winding) {
        if (one_shape_) {
            top_ = OneShapeWalk<>::covers_after(winding_[0], winding) ? kFirstShape : -1;
            return;
        }
        const int before = winding_[shape];
        const int after = before + winding;
        winding_[shape] = after;
        if (before == 0 && after != 0) {
            covering_.push_back(shape);
            top_ = std::max(top_, shape);
        } else if (before != 0 && after == 0) {
            covering_.erase(std::find(covering_.begin(), covering_.end(), shape));
            if (shape == top_) {
                top_ =
                    covering_.empty() ? -1 : *std::max_element(covering_.begin(), covering_.end());
            }
        }
    }
    // The topmost covering shape (rule 2), -1 for none.
    int top() const { return top_; }
    // The covering shapes, unordered.
    std::span<const int> covering() const {
        if (one_shape_) return {&kFirstShape, top_ < 0 ? 0u : 1u};
        return covering_;
    }
    // The shape seen at (x, y) on the walk: the topmost, or with depth planes the nearest.
    int seen(std::span<const AffinePlane> planes, double x, double y) const {
        return planes.empty() ? top_ : seen_among(covering(), planes, x, y);
    }
    // Back to no shape covering, touching only the winding numbers a walk changed (a walk may
    // stop before its last crossings).
    void clear() {
        if (one_shape_) winding_[0] = 0;
        for (const int s : covering_) winding_[s] = 0;
        covering_.clear();
        top_ = -1;
    }

private:
    static constexpr int kFirstShape = 0;
    std::vector<int> winding_;   // per shape
    std::vector<int> covering_;  // shapes with nonzero winding (unsorted)
    int top_ = -1;
    bool one_shape_ = false;
};

}  // namespace aabench
