// Scanline hidden-surface removal on a ScreenScene (Nishita & Nakamae 1984, §3.2–3.3): the
// visible value along one sub-scanline, computed while walking its crossings left to right
// with the paper's NEXT stack, for the multi-scanning methods that do their own visibility
// (box-multiscan, gauss-multiscan; Method::own_visibility()).
//
// Input: a scene whose shapes all carry a depth plane, or none does (then the shape order is
// the priority, a later shape nearer: the 2-D rule, used for 2-D scenes with affine values,
// e.g. depth images) (inv_depth = 1/z_v, affine in screen
// position; the larger is nearer). Overlapping shapes are all present (hidden surfaces
// included), as harness/world/ projects them, every shape with its face's depth plane: for
// these methods the overlay (harness/world/overlay.h), each face whole with its patterns and
// its shadow layer laid over it as coplanar polygons, as the paper draws them (the disjoint
// cells of the other methods work too).
//
// On each line:
//   1. Crossings. Every edge crossing the line (the active-edge list: edges sorted by their
//      top y enter as the lines move down and leave below their bottom y, so memory is
//      O(edges), never O(edges x rows)). Per shape, the nonzero winding rule turns crossings
//      into spans: a shape's "left crossing" is where its winding number leaves 0, its "right
//      crossing" where it returns to 0.
//   2. Tie order. Of two shapes on the same face, the shadow lies in front of the pattern and
//      the pattern in front of the face ("patterns and shadows on one face are taken to lie in
//      front, the shadow first, then the pattern", §3.2); two of one role, the later shape.
//      Crossings at exactly the same x are applied as one group in the matching order: right
//      crossings before left ones, shadow-right, pattern-right, face-right, then face-left,
//      pattern-left, shadow-left; within one kind, by shape index. On the overlay this order
//      decides which coplanar polygon is seen (tests/overlay_test.cpp swaps it and sees the
//      image change).
//   3. NEXT. `current` is the visible shape (or the background). A left crossing of shape c
//      at x: if c is nearer than current at (x, y), current goes onto NEXT and c becomes
//      current; else c goes onto NEXT. A right crossing of current: the nearest shape on NEXT
//      at (x, y) is popped and becomes current (the background if NEXT is empty). A right
//      crossing of a hidden shape: it is removed from NEXT.
//   4. Output. After each group, if the visible value function changed, one ValueChange (its
//      value at x and its slope along the line: shapes with an affine `value_plane` give
//      affine runs, so the consumers integrate them exactly).
//
// Readings of the paper that had to be decided (the paper assumes a priority order holds
// along each span, i.e. faces that do not interpenetrate):
// - "Nearer" at a crossing is decided by the depth planes evaluated at the crossing point
//   itself, (x, y_line), by the one visibility rule of methods/scan/kernel/visibility_rule.h: larger
//   inv_depth wins. When the two planes tie there (kDepthTieRelative: a face starting exactly
//   where it touches the current one: a shared edge, or the line of an interpenetration), the
//   one nearer just right of x wins (larger d(inv_depth)/dx); when the slopes tie too
//   (coplanar shapes), the later shape wins, as in 2-D.
// - Depth is compared only at crossings. Where two faces interpenetrate, the one in front
//   changes along the span without any crossing; this method keeps the one that was in front
//   at the span's last crossing, as the paper's method does. The difference from the exact
//   answer is measured, not hidden (tests/scanline_visibility_test.cpp, docs/methods-multiscan.md).
// - Coincident crossings beyond the five roles (two different faces' crossings at exactly the
//   same x; a shape whose winding returns to its value within one group, e.g. a vertex on
//   the line, makes no event): rights before lefts keeps a face that ends where its neighbour
//   begins from being compared with it; ties within a kind go by shape index.
// - Horizontal edges and vertices exactly on a line: the two one-sided limits y' -> y+ and
//   y' -> y- are traced as by SubscanlineTracer (methods/scan/multiscan/subscanline.h), same rules.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "methods/scan/kernel/edge_table.h"
#include "methods/scan/kernel/visibility_rule.h"
#include "methods/scan/multiscan/subscanline.h"
#include "patterns/scene/scene.h"

namespace aabench {

// True when some shape has an affine value (value_plane).
bool has_value_planes(const Scene& scene);

// Which role lies in front on one face, indexed by ShapeRole (face, pattern, shadow): the larger
// is nearer. The paper's: the shadow, then the pattern, then the face.
using RoleFront = std::array<int, 3>;
inline constexpr RoleFront kPaperRoleFront = {0, 1, 2};

class ScanlineVisibility {
public:
    ScanlineVisibility() = default;
    // (Re)builds for `scene` (window frame: no origin), reusing the memory it holds. Every
    // shape carries inv_depth, or none does (std::invalid_argument otherwise). A shape with
    // Bezier segments is its flattening, or with `curve_lines` (the lines the caller traces,
    // ascending) the polygon meeting each of them where its curves do (polygon_on_lines).
    void reset(const Scene& scene, std::span<const double> curve_lines = {});
    // Another tie order among the roles, for tests only: swapping it must change what the
    // overlay shows (tests/overlay_test.cpp). Takes effect at the next reset().
    void set_role_front(const RoleFront& front) { role_front_ = front; }

    // Same contract as SubscanlineTracer::trace, for lines in ascending y (a line above the
    // previous one restarts the active-edge walk from the top).
    bool trace(double y, LineProfile& below, LineProfile& above);

    // Heap bytes held (the tests' and the memory measurement's check that it is O(edges)).
    std::size_t bytes_held() const;

private:
    struct ShapeInfo {
        AffinePlane value;  // constant values as {value, 0, 0}
        int rank_right;     // tie order of its right crossings (0 first)
        int rank_left;
        int face;   // Shape::face: -1 for a 2-D shape
        int front;  // role_front_[role]
        bool affine;
    };
    struct Event {
        int rank;
        int shape;
        bool left;
    };

    void advance(double y);
    void walk(double y, bool from_below, LineProfile& out);
    void apply_group(std::size_t first, std::size_t last, double x, double y);
    bool nearer(int a, int b, double x, double y) const;
    void left(int shape, double x, double y);
    void right(int shape, double x, double y);

    double background_ = 0.0;
    bool priority_only_ = false;  // no depth planes: the later shape is nearer
    RoleFront role_front_ = kPaperRoleFront;
    std::vector<ShapeInfo> shapes_;
    std::vector<AffinePlane> inv_depth_;  // per shape; empty when priority_only_
    std::vector<Edge> edges_;
    std::vector<int> contour_index_;     // scratch of the edge builder
    Contour on_lines_;  // scratch of reset() on curves: polygon_on_lines()
    std::vector<std::uint32_t> by_top_;  // edges_ indices sorted by y0
    std::size_t cursor_ = 0;             // edges by_top_[0..cursor_) have entered
    std::vector<std::uint32_t> active_;  // entered and not yet left (y1 >= last y)
    double last_y_ = 0.0;
    std::vector<double> endpoint_ys_;       // sorted y of every edge endpoint
    std::vector<Crossing> crossings_;
    std::vector<int> winding_;              // per shape
    std::vector<int> before_;               // winding at the start of the group, per touched shape
    std::vector<int> touched_;
    std::vector<Event> events_;
    std::vector<int> next_;                 // the paper's NEXT: active shapes hidden behind current
    int current_ = -1;                      // the visible shape, -1: the background
};

}  // namespace aabench
