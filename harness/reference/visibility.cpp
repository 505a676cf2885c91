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
//      methods/scan/kernel/visibility_rule.h, which says why). Where |w_Q - w_P| is within
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
// Cost. Fans (many triangles of one plane around one vertex) are first resolved among
// themselves by an angular sweep (fan_groups.h) and their pieces never paired with each other.
// Candidate pairs come from a uniform grid over the bounding boxes (overlap_grid.h); each is
// clipped once, by the source that comes first along a Z-order of the sources, which keeps
// what it hides of the other until that one's turn (PendingHiders). A pair costs
// O(|P| |Q|) to intersect. Each shape then subtracts its hiding regions, largest
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
#include "harness/reference/fan_groups.h"
#include "harness/reference/occlusion_tiles.h"
#include "harness/reference/overlap_grid.h"
#include "methods/scan/kernel/visibility_rule.h"

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
    // Copies of the shape's face and depth plane: read for every pair, and a read through the
    // scene's shapes (144 bytes apart, in random order) was a cache miss per partner, 40% of
    // the stage's time on a 200,000-triangle soup.
    int face = -1;
    std::optional<AffinePlane> inv_depth;
    int group = -1;  // its fan (fan_groups.h): pieces of one fan are disjoint, never compared
};

// A convex region that hides part of a source: subtracted from its pieces. Its edge lines are
// those of the two sources' edges and of the line of equal depth (ConvexPolygon says why).
struct Hider {
    ConvexPolygon poly;
    Bounds box;
    double scale = 1.0;
    double twice_area = 0.0;
    int partner = 0;  // the source (index in the sources) whose overlap this is
};

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
    // A cleaned triangle is convex (each vertex lies more than kConvexSlackPx off its
    // neighbours' chord, on the inner side): its check, three atan2, is skipped.
    if (poly.size() > 3 && !is_convex(poly, kConvexSlackPx + kSideRelative * scale)) {
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
        s.face = screen.shapes[k].face;
        s.inv_depth = screen.shapes[k].inv_depth;
        sources.push_back(std::move(s));
    }
    return sources;
}

// The buffers of one visible_pieces() call, reused from pair to pair and from source to
// source: a polygon buffer keeps its capacity when it is cleared, copied over or swapped, so
// after the first few pairs nothing is allocated per pair or per cut (the pairwise stage made
// 86 million allocations on a 200,000-triangle soup when each clip made its own polygons).
struct Scratch {
    ConvexPolygon current, inside, outside, b_nearer, a_nearer, rest;
    std::vector<Hider> hiders;  // the first hider_count are the current source's
    std::size_t hider_count = 0;
    std::vector<const Hider*> by_partner;
    std::vector<std::size_t> order;
};

// Hiders computed for a source before its turn (its partner came first), kept in slots whose
// buffers are reused once the source has been carved: a pair is clipped once, from the side
// that comes first, instead of once from each side. The pool is capped (kMaxPendingHiders): a
// source whose later partners would overflow it stores nothing, and those partners compute
// the pair again themselves, as before, so memory stays bounded whatever the order.
struct PendingHiders {
    struct Slot {
        Hider hider;
        int next = -1;  // the next slot of the same source, -1 at the end
    };
    std::vector<Slot> slots;
    std::vector<int> free_slots;
    std::vector<int> head;  // per source: its first slot, -1 for none
    std::size_t in_use = 0;
    std::size_t peak = 0;

    Hider& add(int source) {
        int slot;
        if (!free_slots.empty()) {
            slot = free_slots.back();
            free_slots.pop_back();
        } else {
            slot = static_cast<int>(slots.size());
            slots.emplace_back();
        }
        slots[slot].next = head[source];
        head[source] = slot;
        peak = std::max(peak, ++in_use);
        return slots[slot].hider;
    }
    void release(int source) {
        for (int slot = head[source]; slot >= 0; slot = slots[slot].next) {
            free_slots.push_back(slot);
            --in_use;
        }
        head[source] = -1;
    }
};

// A list of pieces whose buffers are kept when it is cleared.
struct PieceList {
    struct Piece {
        ConvexPolygon poly;  // edge lines not tracked: a piece is never clipped against
        Bounds box;
    };
    std::vector<Piece> items;
    std::size_t count = 0;

    Piece& add() {
        if (count == items.size()) items.emplace_back();
        return items[count++];
    }
    // Moves a piece of another list here by swapping buffers (that list is cleared after).
    void add_moved(Piece& piece) {
        Piece& p = add();
        std::swap(p.poly.v, piece.poly.v);
        p.poly.e.clear();
        p.box = piece.box;
    }
};
using Piece = PieceList::Piece;

// P ∩ Q (P clipped by Q's edge lines) into scratch.current; false when the overlap is empty or
// a sliver. Disjoint pairs (nearly half the candidates of a soup) leave at the separating-axis
// test: where all of P lies beyond an edge line of Q the clip would stop at that line too
// (what earlier cuts make lies in P); where all of Q lies beyond one of P's, the overlap is
// empty. The clip reads P in place and copies it only when no line cuts it.
bool overlap(const Source& p, const Source& q, double tolerance, Scratch& s) {
    if (separated_by_an_edge(p.poly, q.poly, tolerance)) return false;
    const ConvexPolygon* current = &p.poly;
    for (const LinearForm& edge : q.poly.e) {
        switch (split_convex(*current, edge, tolerance, &s.inside, nullptr)) {
            case SplitOutcome::kPositive:
                break;
            case SplitOutcome::kNegative:
            case SplitOutcome::kOnLine:
                return false;  // disjoint or touching
            case SplitOutcome::kSplit:
                std::swap(s.current, s.inside);
                current = &s.current;
                break;
        }
    }
    if (current == &p.poly) s.current = p.poly;
    return !is_sliver(s.current.v, tolerance);
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

// Fills `h` from `poly` (its buffer swapped in, so no copy).
void fill_hider(Hider& h, ConvexPolygon& poly, double scale, int partner) {
    h.box = bounds_of(poly.v);
    h.twice_area = twice_signed_area(poly.v);
    std::swap(h.poly, poly);
    h.scale = scale;
    h.partner = partner;
}

// One candidate pair, a before b in the input (a and b index the sources): the overlap a ∩ b
// cut by the line of equal depth, computed once for both. What b hides of a goes to
// to_a(poly, scale), what a hides of b to to_b(poly, scale). Returns true when they overlap.
template <class ToA, class ToB>
bool resolve_pair(const std::vector<Source>& sources, int ia, int ib, Scratch& s, ToA&& to_a,
                  ToB&& to_b) {
    const Source& a = sources[ia];
    const Source& b = sources[ib];
    const double scale = std::max(a.scale, b.scale);
    const double tolerance = kSideRelative * scale;
    if (!overlap(a, b, tolerance, s)) return false;
    if (!a.inv_depth) {  // 2-D: the later shape covers the earlier one
        to_a(s.current, scale);
        return true;
    }
    const DepthDifference d = depth_difference(*a.inv_depth, *b.inv_depth, s.current.v);
    // The split is decided in depth units; the new edge is stored as a distance. (Parallel
    // planes, gradient zero, never split: every vertex sees the same difference.)
    const bool parallel = d.form.nx == 0.0 && d.form.ny == 0.0;
    const LinearForm cut_edge = parallel ? d.form : unit_form(d.form);
    switch (split_convex(s.current, d.form, d.tolerance, &s.b_nearer, &s.a_nearer, &cut_edge)) {
        case SplitOutcome::kPositive:  // b nearer everywhere (or equal on a zero-area part)
        case SplitOutcome::kOnLine:    // equal planes: the later shape, b, is seen
            to_a(s.current, scale);
            break;
        case SplitOutcome::kNegative:
            to_b(s.current, scale);
            break;
        case SplitOutcome::kSplit:  // the faces interpenetrate inside their overlap
            if (!is_sliver(s.b_nearer.v, tolerance)) to_a(s.b_nearer, scale);
            if (!is_sliver(s.a_nearer.v, tolerance)) to_b(s.a_nearer, scale);
            break;
    }
    return true;
}

// Appends piece \ hider to `out` as convex pieces; a piece the hider only touches (or
// overlaps by a sliver) is moved over whole, so touching shapes are not fragmented.
void subtract(Piece& piece, const Hider& hider, double tolerance, PieceList& out, Scratch& s) {
    const std::size_t first_out = out.count;
    const ConvexPolygon* rest = &piece.poly;  // read in place until the first cut
    for (const LinearForm& edge : hider.poly.e) {
        switch (split_convex(*rest, edge, tolerance, &s.inside, &s.outside)) {
            case SplitOutcome::kPositive:
                break;
            case SplitOutcome::kNegative:
            case SplitOutcome::kOnLine:  // the piece lies outside the hider: untouched
                out.count = first_out;
                out.add_moved(piece);
                return;
            case SplitOutcome::kSplit:
                if (!is_sliver(s.outside.v, tolerance)) {
                    Piece& kept = out.add();
                    kept.box = bounds_of(s.outside.v);
                    std::swap(kept.poly, s.outside);
                    kept.poly.e.clear();
                }
                std::swap(s.rest, s.inside);
                rest = &s.rest;
                break;
        }
    }
    if (is_sliver(rest->v, tolerance)) {  // what the hider covers is a sliver: keep the piece
        out.count = first_out;
        out.add_moved(piece);
    }
}

// The source's visible part: itself less its hiders (s.by_partner, in ascending partner order),
// largest first; into `pieces`.
void carve(const Source& source, Scratch& s, PieceList& pieces, PieceList& next) {
    // Sorting indices by the same comparison sorts them into the order sorting the hiders
    // themselves gave (std::sort's steps depend on the comparisons alone), from the same
    // starting order: ascending partner, the order in which the sorted pairs gave them.
    const std::vector<const Hider*>& hiders = s.by_partner;
    s.order.resize(hiders.size());
    for (std::size_t k = 0; k < hiders.size(); ++k) s.order[k] = k;
    std::sort(s.order.begin(), s.order.end(), [&](std::size_t x, std::size_t y) {
        return hiders[x]->twice_area > hiders[y]->twice_area;
    });
    pieces.count = 0;
    Piece& whole = pieces.add();
    whole.poly.v = source.poly.v;
    whole.poly.e.clear();
    whole.box = source.box;
    for (const std::size_t index : s.order) {
        const Hider& h = *hiders[index];
        const double tolerance = kSideRelative * std::max(source.scale, h.scale);
        next.count = 0;
        for (std::size_t k = 0; k < pieces.count; ++k) {
            Piece& piece = pieces.items[k];
            if (piece.box.overlaps(h.box)) {
                subtract(piece, h, tolerance, next, s);
            } else {
                next.add_moved(piece);
            }
        }
        std::swap(pieces, next);
        if (pieces.count == 0) break;
    }
}

// Resolves the fans (fan_groups.h) among the sources. A scene that is one fan alone: returns
// the output, written straight from the sweep's result (no pair, no tile has anything to add).
// Otherwise replaces each fan's triangles by their visible parts among themselves, in the
// input's order; the pieces of one fan share its group and are never paired.
std::optional<Scene> resolve_fan_groups(const Scene& screen, std::vector<Source>& sources,
                                        VisibilityStats& stats) {
    std::vector<FanInput> in;
    in.reserve(sources.size());
    for (const Source& s : sources) {
        in.push_back(FanInput{&s.poly.v, &s.inv_depth, kSideRelative * s.scale});
    }
    const FanResult fans = resolve_fans(in);
    if (fans.fans == 0) return std::nullopt;
    stats.fans = fans.fans;
    if (fans.fans == 1 &&
        std::all_of(fans.group.begin(), fans.group.end(), [](int g) { return g == 0; })) {
        std::vector<int> shapes;
        for (const Source& s : sources) shapes.push_back(s.shape);
        stats.fan_triangles = sources.size();
        return one_fan_scene(screen, shapes, fans);
    }
    std::vector<std::size_t> first;
    const std::vector<std::size_t> order = fan_pieces_by_input(fans, first);
    std::vector<Source> out;
    out.reserve(sources.size() + fans.pieces.size());
    for (int k = 0; k < static_cast<int>(sources.size()); ++k) {
        if (fans.group[k] < 0) {
            out.push_back(std::move(sources[k]));
            continue;
        }
        ++stats.fan_triangles;
        for (std::size_t q = first[k]; q < first[k + 1]; ++q) {
            const auto contour = fans.contour(fans.pieces[order[q]]);
            Source& piece = out.emplace_back();
            piece.shape = sources[k].shape;
            piece.face = sources[k].face;
            piece.inv_depth = sources[k].inv_depth;
            piece.group = fans.group[k];
            piece.poly.v.assign(contour.begin(), contour.end());
            piece.poly.e = edge_forms(piece.poly.v);
            piece.box = bounds_of(piece.poly.v);
            piece.scale = coordinate_scale(piece.poly.v);
        }
    }
    sources = std::move(out);
    return std::nullopt;
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

// The sources in the resolution order (z_order of their boxes), so that the shapes a source
// meets lie near it in memory too; the input's order is still what decides ties and orders
// the output (Source::shape). A scene that is one fan alone: returns its output instead.
std::optional<Scene> in_resolution_order(const Scene& screen, const VisibilityOptions& options,
                                         VisibilityStats& stats, std::vector<Source>& sources) {
    std::vector<Source> in_input_order = usable_sources(screen, stats);
    std::optional<Scene> alone;
    if (options.fans && (alone = resolve_fan_groups(screen, in_input_order, stats))) return alone;
    sources.reserve(in_input_order.size());
    std::vector<Bounds> boxes;
    boxes.reserve(in_input_order.size());
    for (const Source& s : in_input_order) boxes.push_back(s.box);
    for (const int k : z_order(boxes)) sources.push_back(std::move(in_input_order[k]));
    return std::nullopt;
}

// The memory of the pairwise stage, estimated before it starts: from the grid's cheap upper
// bound on the pairs, and only when that is over the budget from counting them, stopping
// as soon as the count passes what the budget allows (a fan of shapes over one point asks
// for 10^10 pairs: refused in a fraction of a second, not killed after minutes).
void check_pair_memory(const std::vector<Bounds>& boxes, const VisibilityStats& stats,
                       const VisibilityOptions& options) {
    const double per_pair = static_cast<double>(kVisibilityBytesPerPair);
    const double allowed_pairs =
        std::max(0.0, static_cast<double>(options.memory_budget_bytes) -
                          static_cast<double>(kMaxPendingHiders * kPendingHiderBytes)) /
        per_pair;
    if (!(box_pair_bound(boxes) > allowed_pairs)) return;
    if (!(count_box_pairs(boxes, allowed_pairs) > allowed_pairs)) return;
    throw InputError(fmt::format(
        "visibility: needs more than {:.1f} GiB by estimate (more than {:.3g} candidate pairs of "
        "overlapping shapes, {} of {} shapes left after {} were found wholly hidden), more than "
        "the memory budget of {:.1f} GiB (docs/limits.md)",
        allowed_pairs * per_pair / (1u << 30), allowed_pairs, boxes.size(), stats.shapes_in,
        stats.hidden_by_tiles, static_cast<double>(options.memory_budget_bytes) / (1u << 30)));
}

// The partners of each source in both directions (a source whose earlier partner stored
// nothing computes the pair itself): source k's are of[first[k]..first[k + 1]). Pairs on one
// face or in one fan are dropped (cells of one face never occlude); one fan has none.
struct Partners {
    std::vector<std::size_t> first;
    std::vector<int> of;
};
Partners partners_of(const std::vector<Source>& sources, const std::vector<Bounds>& boxes,
                     bool one_fan, VisibilityStats& stats) {
    std::vector<std::pair<int, int>> pairs;
    if (!one_fan) pairs = overlapping_box_pairs(boxes, /*sorted=*/false);
    stats.candidate_pairs = pairs.size();
    std::vector<int> face(sources.size()), group(sources.size());
    for (std::size_t k = 0; k < sources.size(); ++k) {
        face[k] = sources[k].face;
        group[k] = sources[k].group;
    }
    std::erase_if(pairs, [&](const std::pair<int, int>& p) {
        return (face[p.first] >= 0 && face[p.first] == face[p.second]) ||
               (group[p.first] >= 0 && group[p.first] == group[p.second]);
    });
    stats.same_face_pairs = stats.candidate_pairs - pairs.size();
    Partners partners{std::vector<std::size_t>(sources.size() + 1, 0), {}};
    std::vector<std::size_t>& first = partners.first;
    for (const auto& [ia, ib] : pairs) {
        ++first[ia + 1];
        ++first[ib + 1];
    }
    for (std::size_t k = 0; k < sources.size(); ++k) first[k + 1] += first[k];
    partners.of.resize(first.back());
    std::vector<std::size_t> fill(first.begin(), first.end() - 1);
    for (const auto& [ia, ib] : pairs) {
        partners.of[fill[ia]++] = ib;
        partners.of[fill[ib]++] = ia;
    }
    return partners;
}

// The pieces, in resolution order, in one vertex array; each source's range of them.
struct CarvedPieces {
    std::vector<Point> vertices;
    std::vector<std::pair<std::size_t, std::size_t>> ranges;     // vertex [begin, end)
    std::vector<std::pair<std::size_t, std::size_t>> of_source;  // its ranges [begin, end)
};
// Each source carved by its hiders. A pair is resolved by the source that comes first; the
// hider it makes for the other waits in the pending pool (while it has room) until its turn.
CarvedPieces carve_sources(const std::vector<Source>& sources, const Partners& partners,
                           VisibilityStats& stats) {
    const std::vector<std::size_t>& first = partners.first;
    Scratch scratch;
    PendingHiders pending;
    pending.head.assign(sources.size(), -1);
    std::vector<char> stored(sources.size(), 0);  // its later partners' hiders are pending
    PieceList pieces, next;
    CarvedPieces out{{}, {}, std::vector<std::pair<std::size_t, std::size_t>>(sources.size())};
    for (int k = 0; k < static_cast<int>(sources.size()); ++k) {
        const Source& source = sources[k];
        std::size_t later = 0;
        for (std::size_t p = first[k]; p < first[k + 1]; ++p) later += partners.of[p] > k;
        const bool store = pending.in_use + later <= kMaxPendingHiders;
        stored[k] = store;
        scratch.hider_count = 0;
        // A hider's partner is the other source's input index: hiders are carved in ascending
        // input order of the partner (then by area), as when the pairs were taken sorted.
        auto to_current = [&](int m) {
            const int partner = sources[m].shape;
            return [&scratch, partner](ConvexPolygon& poly, double scale) {
                if (scratch.hider_count == scratch.hiders.size()) scratch.hiders.emplace_back();
                fill_hider(scratch.hiders[scratch.hider_count++], poly, scale, partner);
            };
        };
        auto to_pending = [&](int m) {
            // Only for a partner still to come, and only when this source stores at all.
            const bool keep = store && m > k;
            const int partner = source.shape;
            return [&pending, keep, m, partner](ConvexPolygon& poly, double scale) {
                if (keep) fill_hider(pending.add(m), poly, scale, partner);
            };
        };
        for (std::size_t p = first[k]; p < first[k + 1]; ++p) {
            const int m = partners.of[p];
            if (m < k && stored[m]) continue;  // resolved by m: its hider for k is pending
            // The pair's arithmetic is that of the input order: the earlier shape is `a`.
            const bool overlapping =
                source.shape < sources[m].shape
                    ? resolve_pair(sources, k, m, scratch, to_current(m), to_pending(m))
                    : resolve_pair(sources, m, k, scratch, to_pending(m), to_current(m));
            // A pair resolved twice (m stored nothing) is counted by whichever comes first.
            stats.overlapping_pairs += overlapping && m > k;
        }
        scratch.by_partner.clear();
        for (std::size_t h = 0; h < scratch.hider_count; ++h) {
            scratch.by_partner.push_back(&scratch.hiders[h]);
        }
        for (int slot = pending.head[k]; slot >= 0; slot = pending.slots[slot].next) {
            scratch.by_partner.push_back(&pending.slots[slot].hider);
        }
        std::sort(scratch.by_partner.begin(), scratch.by_partner.end(),
                  [](const Hider* x, const Hider* y) { return x->partner < y->partner; });
        carve(source, scratch, pieces, next);
        pending.release(k);
        out.of_source[k].first = out.ranges.size();
        for (std::size_t q = 0; q < pieces.count; ++q) {
            const Contour& v = pieces.items[q].poly.v;
            out.ranges.emplace_back(out.vertices.size(), out.vertices.size() + v.size());
            out.vertices.insert(out.vertices.end(), v.begin(), v.end());
        }
        out.of_source[k].second = out.ranges.size();
    }
    stats.pending_peak = pending.peak;
    return out;
}

// The output: the carved pieces in the input's order, each a shape like its source's.
Scene pieces_in_input_order(const Scene& screen, const std::vector<Source>& sources,
                            const CarvedPieces& carved) {
    std::vector<int> by_input(sources.size());
    for (std::size_t k = 0; k < sources.size(); ++k) by_input[k] = static_cast<int>(k);
    std::sort(by_input.begin(), by_input.end(),
              [&](int x, int y) { return sources[x].shape < sources[y].shape; });
    Scene out = without_shapes(screen);
    out.shapes.reserve(carved.ranges.size());
    for (const int k : by_input) {
        const Shape proto = without_contours(screen.shapes[sources[k].shape]);
        for (std::size_t q = carved.of_source[k].first; q < carved.of_source[k].second; ++q) {
            Shape& shape = out.shapes.emplace_back(proto);
            shape.contours.emplace_back(carved.vertices.begin() + carved.ranges[q].first,
                                        carved.vertices.begin() + carved.ranges[q].second);
        }
    }
    return out;
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
    const auto done = [&](Scene out) {  // every exit: the stats with its output's count
        stats.pieces_out = out.shapes.size();
        if (stats_out) *stats_out = stats;
        return out;
    };
    check_depth_planes(screen);
    std::vector<Source> sources;
    if (std::optional<Scene> alone = in_resolution_order(screen, options, stats, sources)) {
        return done(std::move(*alone));
    }
    // All the sources in one fan: they tie everywhere, so none hides another wholly (the tiles
    // find nothing) and none is paired.
    const bool one_fan =
        !sources.empty() && sources[0].group >= 0 &&
        std::all_of(sources.begin(), sources.end(),
                    [&](const Source& s) { return s.group == sources[0].group; });
    if (options.occlusion_tiles && !one_fan) drop_wholly_hidden(screen, sources, stats);

    std::vector<Bounds> boxes;
    boxes.reserve(sources.size());
    for (const Source& s : sources) boxes.push_back(s.box);
    if (!one_fan) check_pair_memory(boxes, stats, options);
    const Partners partners = partners_of(sources, boxes, one_fan, stats);
    return done(pieces_in_input_order(screen, sources, carve_sources(sources, partners, stats)));
}

}  // namespace aabench
