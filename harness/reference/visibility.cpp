// Exact visibility by pairwise convex subtraction.
//
// What it computes. For shapes P_1..P_n (convex polygons) with depth planes w_k (1/z_v as an
// affine function of the screen position; larger is nearer), the visible part of P is
//     V(P) = P \ union over Q != P of O(Q, P),   O(Q, P) = P ∩ Q ∩ {Q beats P},
// where Q beats P at a point when w_Q > w_P there, or w_Q = w_P and Q comes later (2-D scenes:
// when Q comes later, at every point). A point of P is visible exactly when no other shape
// containing it beats P, and "beats" is decided pair by pair, so the union of the O(Q, P)
// is exactly what hides P: no depth order of the shapes is ever needed, which is why
// interpenetrating faces and cyclic overlaps (three bars each over the next) are no special
// case. Since w_Q - w_P is affine, {w_Q > w_P} is a half-plane and O(Q, P) is convex: the
// overlap P ∩ Q (P clipped by the edges of Q) cut once by the line w_Q = w_P. Each pair is
// handled once: its overlap is cut into the part where Q is nearer (hides P) and the part
// where P is nearer (hides Q). Subtracting a convex region C from a convex piece R splits R
// by C's edges one at a time (convex_split.h): the part outside each edge line is kept, the
// part inside goes on to the next edge, and what is left at the end (R ∩ C) is dropped. So
// every piece stays convex, and V(P) comes out as disjoint convex pieces. The pieces of
// different shapes are disjoint because of any two shapes covering a point exactly one beats
// the other; shapes on the same face (equal face >= 0) are disjoint cells by construction and
// are never compared.
//
// Where it is not exact, and by how much. Real arithmetic is replaced by double in three
// places, each with a tolerance named below:
//   1. Which side of a line a vertex lies on (kSideRelative). A vertex within 16 ulps of the
//      coordinate scale M = max(1, |coordinates|) of a line counts as on it. The computed
//      distance of a vertex from an edge line is off by a few ulps of M (differences and one
//      product each rounded; vertices made by earlier cuts are off by a few ulps themselves),
//      so 16 ulps (3.6e-15 M) is above that noise and no rounding error can create a split
//      that is not there. Shapes that share an edge (the faces of a tessellated sphere) touch
//      along it with their vertices on it, find an empty overlap and are left whole.
//   2. Slivers (the same width, kSideRelative M). A piece or overlap thinner than that is
//      dropped (a piece) or treated as empty (an overlap: the pieces it would cut stay whole).
//      By is_sliver() (convex_split.h) what is dropped inside any one pixel has area at most
//      2 * 3.6e-15 M: 3.6e-13 at M = 50, 7e-12 at M = 1000, far inside the 1e-9 per pixel that
//      the references promise; and slivers are rare (a vertex a hair from a cut line), a few
//      per pixel at worst.
//   3. Equal depth planes: the one depth tie of every engine (kDepthTieRelative,
//      methods/scan/visibility_rule.h, which says why). Where |w_Q - w_P| is within
//      depth_tie_tolerance (kDepthTieRelative of the size of the terms |c| + |gx x| + |gy y|
//      of the larger plane) at every vertex of the overlap, the two planes are taken as equal
//      there and the later shape is seen, the rule's tie for a region. Coplanar faces of
//      different index get their planes from different vertices, which agree to ~1e-13 for
//      well-shaped faces. Where the line w_Q = w_P does cross the overlap, its vertices within
//      this tolerance of it count as on it (the cut moves by at most that depth difference).
// Two more decisions keep rounding from turning into topology:
//   - Input contours are cleaned (cleaned_contour, convex_split.h): repeated vertices and
//     vertices within kConvexSlackPx of the chord of their neighbours are removed (upstream
//     stages, projection and clipping against patterns and shadows, leave collinear vertices
//     a rounding error off their line), which moves at most 1.5e-10 px^2 per pixel; what is
//     left must be convex to the same slack, or the input is refused.
//   - Every region used to clip carries the line of each of its edges (ConvexPolygon): an
//     input edge or the line of equal depth, never a line through two computed vertices that
//     may lie a few ulps apart and so point anywhere.
//
// Cost. Candidate pairs come from a uniform grid over the bounding boxes (overlap_grid.h);
// a pair costs O(|P| |Q|) to intersect. Each shape then subtracts its hiding regions, largest
// first (a big one removes most of the piece before small ones can fragment it), testing
// bounding boxes before splitting. Touching pairs cost one intersection and no pieces.
#include "harness/reference/visibility.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <utility>
#include <vector>

#include "harness/reference/convex_split.h"
#include "harness/reference/occlusion_tiles.h"
#include "harness/reference/overlap_grid.h"
#include "methods/scan/visibility_rule.h"

namespace aabench {
namespace {

// 1. and 2. above: a side tolerance and a sliver width of 16 ulps of the coordinate scale.
constexpr double kSideRelative = 16.0 * std::numeric_limits<double>::epsilon();
// Collinearity and convexity slack for input shapes, in pixels (see above): far below
// anything visible, far above the rounding of coordinates up to ~1e5 px (~1e-11).
constexpr double kConvexSlackPx = 1e-10;

// An input shape that survived the checks, positively oriented, with its edge lines.
struct Source {
    int shape = 0;  // index in the input scene
    ConvexPolygon poly;
    Bounds box;
    double scale = 1.0;  // coordinate_scale(poly.v)
};

// A convex region that hides part of a source: subtracted from its pieces. Its edge lines are
// those of the two sources' edges and of the line of equal depth (ConvexPolygon says why).
struct Hider {
    ConvexPolygon poly;
    Bounds box;
    double scale = 1.0;
    double twice_area = 0.0;
};

Hider make_hider(ConvexPolygon poly, double scale) {
    Hider h;
    h.box = bounds_of(poly.v);
    h.twice_area = twice_signed_area(poly.v);
    h.poly = std::move(poly);
    h.scale = scale;
    return h;
}

void check_depth_planes(const Scene& screen) {
    std::size_t with = 0;
    for (const Shape& s : screen.shapes) with += s.inv_depth.has_value();
    if (with != 0 && with != screen.shapes.size()) {
        throw InputError(fmt::format(
            "visibility: {} of {} shapes have a depth plane; a ScreenScene has one on every "
            "shape (3-D) or on none (2-D)",
            with, screen.shapes.size()));
    }
}

bool finite(const std::optional<AffinePlane>& plane) {
    return !plane ||
           (std::isfinite(plane->c) && std::isfinite(plane->gx) && std::isfinite(plane->gy));
}

// Checks one shape and returns its cleaned, positively oriented contour, or nothing when it
// is degenerate.
std::optional<Contour> usable_contour(const Shape& shape, int index) {
    if (shape.contours.size() > 1) {
        throw InputError(fmt::format(
            "visibility: shape {} has {} contours; exact visibility and affine values need "
            "convex pieces of one contour each",
            index, shape.contours.size()));
    }
    if (!finite(shape.inv_depth) || !finite(shape.value_plane)) {
        throw InputError(fmt::format("visibility: shape {} has a non-finite plane", index));
    }
    if (shape.contours.empty()) return std::nullopt;
    for (const Point& p : shape.contours[0]) {
        if (!std::isfinite(p.x) || !std::isfinite(p.y)) {
            throw InputError(fmt::format("visibility: shape {} has a non-finite vertex", index));
        }
    }
    const Contour poly = cleaned_contour(shape.contours[0], kConvexSlackPx);
    if (poly.empty()) return std::nullopt;
    const double scale = coordinate_scale(poly);
    if (is_sliver(poly, kSideRelative * scale)) return std::nullopt;
    if (!is_convex(poly, kConvexSlackPx + kSideRelative * scale)) {
        throw InputError(fmt::format(
            "visibility: shape {} is not convex; exact visibility and affine values need "
            "convex pieces of one contour each",
            index));
    }
    return poly;
}

std::vector<Source> usable_sources(const Scene& screen, VisibilityStats& stats) {
    std::vector<Source> sources;
    for (int k = 0; k < static_cast<int>(screen.shapes.size()); ++k) {
        std::optional<Contour> poly = usable_contour(screen.shapes[k], k);
        if (!poly) {
            ++stats.degenerate_dropped;
            continue;
        }
        Source s;
        s.shape = k;
        s.box = bounds_of(*poly);
        s.scale = coordinate_scale(*poly);
        s.poly.e = edge_forms(*poly);
        s.poly.v = std::move(*poly);
        sources.push_back(std::move(s));
    }
    return sources;
}

// P ∩ Q (P clipped by Q's edge lines), or nothing when the overlap is empty or a sliver.
std::optional<ConvexPolygon> overlap(const Source& p, const Source& q, double tolerance) {
    ConvexPolygon current = p.poly, inside, outside;
    for (const LinearForm& edge : q.poly.e) {
        switch (split_convex(current, edge, tolerance, &inside, &outside)) {
            case SplitOutcome::kPositive:
                break;
            case SplitOutcome::kNegative:
            case SplitOutcome::kOnLine:
                return std::nullopt;  // disjoint or touching
            case SplitOutcome::kSplit:
                std::swap(current, inside);
                break;
        }
    }
    if (is_sliver(current.v, tolerance)) return std::nullopt;
    return current;
}

// w_Q - w_P relative to the overlap's vertex mean, and the depth tie over the overlap (the
// largest of the rule's tolerances at its vertices).
struct DepthDifference {
    LinearForm form;
    double tolerance = 0.0;
};

DepthDifference depth_difference(const AffinePlane& wp, const AffinePlane& wq,
                                 const Contour& region) {
    double mx = 0.0, my = 0.0, tie = 0.0;
    for (const Point& v : region) {
        mx += v.x;
        my += v.y;
        tie = std::max(tie, depth_tie_tolerance(wp, wq, v.x, v.y));
    }
    mx /= static_cast<double>(region.size());
    my /= static_cast<double>(region.size());
    DepthDifference d;
    d.form = LinearForm{wq.at(mx, my) - wp.at(mx, my), wq.gx - wp.gx, wq.gy - wp.gy, mx, my};
    d.tolerance = tie;
    return d;
}

// One candidate pair, a before b in the input: appends what each hides of the other.
void resolve_pair(const Scene& screen, const Source& a, const Source& b,
                  std::vector<std::vector<Hider>>& hidden, std::size_t ia, std::size_t ib,
                  VisibilityStats& stats) {
    const double scale = std::max(a.scale, b.scale);
    const double tolerance = kSideRelative * scale;
    std::optional<ConvexPolygon> both = overlap(a, b, tolerance);
    if (!both) return;
    ++stats.overlapping_pairs;
    const std::optional<AffinePlane>& wa = screen.shapes[a.shape].inv_depth;
    const std::optional<AffinePlane>& wb = screen.shapes[b.shape].inv_depth;
    if (!wa) {  // 2-D: the later shape covers the earlier one
        hidden[ia].push_back(make_hider(std::move(*both), scale));
        return;
    }
    const DepthDifference d = depth_difference(*wa, *wb, both->v);
    ConvexPolygon b_nearer, a_nearer;
    // The split is decided in depth units; the new edge is stored as a distance. (Parallel
    // planes, gradient zero, never split: every vertex sees the same difference.)
    const bool parallel = d.form.nx == 0.0 && d.form.ny == 0.0;
    const LinearForm cut_edge = parallel ? d.form : unit_form(d.form);
    switch (split_convex(*both, d.form, d.tolerance, &b_nearer, &a_nearer, &cut_edge)) {
        case SplitOutcome::kPositive:  // b nearer everywhere (or equal on a zero-area part)
        case SplitOutcome::kOnLine:    // equal planes: the later shape, b, is seen
            hidden[ia].push_back(make_hider(std::move(*both), scale));
            break;
        case SplitOutcome::kNegative:
            hidden[ib].push_back(make_hider(std::move(*both), scale));
            break;
        case SplitOutcome::kSplit:  // the faces interpenetrate inside their overlap
            if (!is_sliver(b_nearer.v, tolerance)) {
                hidden[ia].push_back(make_hider(std::move(b_nearer), scale));
            }
            if (!is_sliver(a_nearer.v, tolerance)) {
                hidden[ib].push_back(make_hider(std::move(a_nearer), scale));
            }
            break;
    }
}

struct Piece {
    ConvexPolygon poly;  // edge lines not tracked: a piece is never clipped against
    Bounds box;
};

// Appends piece \ hider to `out` as convex pieces; a piece the hider only touches (or
// overlaps by a sliver) is appended whole, so touching shapes are not fragmented.
void subtract(const Piece& piece, const Hider& hider, double tolerance, std::vector<Piece>& out) {
    const std::size_t first_out = out.size();
    ConvexPolygon rest = piece.poly, inside, outside;
    for (const LinearForm& edge : hider.poly.e) {
        switch (split_convex(rest, edge, tolerance, &inside, &outside)) {
            case SplitOutcome::kPositive:
                break;
            case SplitOutcome::kNegative:
            case SplitOutcome::kOnLine:  // the piece lies outside the hider: untouched
                out.resize(first_out);
                out.push_back(piece);
                return;
            case SplitOutcome::kSplit:
                if (!is_sliver(outside.v, tolerance)) {
                    const Bounds box = bounds_of(outside.v);
                    out.push_back(Piece{std::move(outside), box});
                    outside = ConvexPolygon();
                }
                std::swap(rest, inside);
                break;
        }
    }
    if (is_sliver(rest.v, tolerance)) {  // what the hider covers is a sliver: keep the piece
        out.resize(first_out);
        out.push_back(piece);
    }
}

std::vector<Piece> carve(const Source& source, std::vector<Hider>& hiders) {
    std::sort(hiders.begin(), hiders.end(),
              [](const Hider& x, const Hider& y) { return x.twice_area > y.twice_area; });
    std::vector<Piece> pieces{Piece{ConvexPolygon{source.poly.v, {}}, source.box}}, next;
    for (const Hider& h : hiders) {
        const double tolerance = kSideRelative * std::max(source.scale, h.scale);
        next.clear();
        for (const Piece& piece : pieces) {
            if (piece.box.overlaps(h.box)) {
                subtract(piece, h, tolerance, next);
            } else {
                next.push_back(piece);
            }
        }
        pieces.swap(next);
        if (pieces.empty()) break;
    }
    return pieces;
}

// Drops the sources the tile occlusion structure finds wholly hidden (3-D only: in 2-D the
// order alone decides, and no depth margin exists).
void drop_wholly_hidden(const Scene& screen, std::vector<Source>& sources,
                        VisibilityStats& stats) {
    if (sources.size() < 2 || !screen.shapes[sources[0].shape].inv_depth) return;
    std::vector<OcclusionInput> in;
    in.reserve(sources.size());
    for (const Source& s : sources) {
        in.push_back(OcclusionInput{&s.poly.v, &s.poly.e, s.box,
                                    *screen.shapes[s.shape].inv_depth, kSideRelative * s.scale});
    }
    OcclusionStats os;
    const std::vector<char> hidden = wholly_hidden(in, &os);
    stats.tiles = os.tiles;
    stats.hidden_by_tiles = os.hidden;
    if (os.hidden == 0) return;
    std::size_t kept = 0;
    for (std::size_t k = 0; k < sources.size(); ++k) {
        if (hidden[k]) continue;
        if (kept != k) sources[kept] = std::move(sources[k]);  // a self-move would empty it
        ++kept;
    }
    sources.resize(kept);
}

}  // namespace

long long& visible_pieces_calls() {
    thread_local long long calls = 0;
    return calls;
}

Scene visible_pieces(const Scene& screen, VisibilityStats* stats_out,
                     const VisibilityOptions& options) {
    ++visible_pieces_calls();
    VisibilityStats stats;
    stats.shapes_in = screen.shapes.size();
    check_depth_planes(screen);
    std::vector<Source> sources = usable_sources(screen, stats);
    if (options.occlusion_tiles) drop_wholly_hidden(screen, sources, stats);

    std::vector<Bounds> boxes;
    boxes.reserve(sources.size());
    for (const Source& s : sources) boxes.push_back(s.box);
    // The memory of the pairwise stage, estimated before it starts: from the grid's cheap upper
    // bound on the pairs, and only when that is over the budget from counting them, stopping
    // as soon as the count passes what the budget allows (a fan of shapes over one point asks
    // for 10^10 pairs: refused in a fraction of a second, not killed after minutes).
    const double per_pair = static_cast<double>(kVisibilityBytesPerPair);
    const double allowed_pairs = static_cast<double>(options.memory_budget_bytes) / per_pair;
    if (box_pair_bound(boxes) > allowed_pairs) {
        const double pairs = count_box_pairs(boxes, allowed_pairs);
        if (pairs > allowed_pairs) {
            throw InputError(fmt::format(
                "visibility: needs more than {:.1f} GiB by estimate (more than {:.3g} candidate "
                "pairs of overlapping shapes, {} of {} shapes left after {} were found wholly "
                "hidden), more than the memory budget of {:.1f} GiB (docs/limits.md)",
                allowed_pairs * per_pair / (1u << 30), allowed_pairs, sources.size(),
                stats.shapes_in, stats.hidden_by_tiles,
                static_cast<double>(options.memory_budget_bytes) / (1u << 30)));
        }
    }
    std::vector<std::vector<Hider>> hidden(sources.size());
    for (const auto& [ia, ib] : overlapping_box_pairs(boxes)) {
        ++stats.candidate_pairs;
        const Source& a = sources[ia];
        const Source& b = sources[ib];
        const int face_a = screen.shapes[a.shape].face, face_b = screen.shapes[b.shape].face;
        if (face_a >= 0 && face_a == face_b) {
            ++stats.same_face_pairs;
            continue;
        }
        resolve_pair(screen, a, b, hidden, ia, ib, stats);
    }

    Scene out = screen;
    out.shapes.clear();
    for (std::size_t k = 0; k < sources.size(); ++k) {
        const Shape& src = screen.shapes[sources[k].shape];
        for (Piece& piece : carve(sources[k], hidden[k])) {
            Shape shape = src;  // value, planes, face, role: everything but the contour
            shape.contours.assign(1, std::move(piece.poly.v));
            out.shapes.push_back(std::move(shape));
        }
    }
    stats.pieces_out = out.shapes.size();
    if (stats_out) *stats_out = stats;
    return out;
}

}  // namespace aabench
