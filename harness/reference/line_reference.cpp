// Ground-truth lines from the exact visible pieces (line_reference.h; docs/edges.md).
//
// How the boundary is found. The pieces are disjoint convex polygons that tile what is seen, so
// every piece edge has on its outer side either pieces whose edges run along it the other way
// (the pieces are split at different points, so the neighbours' edges overlap it in
// sub-intervals: T-junctions everywhere) or the background. For each edge a -> b of piece P
// every edge of another piece that lies on the same line within kCollinearPx and runs the
// opposite way is found (candidates from a uniform grid over the edges' boxes,
// overlap_grid.h); its projection onto a -> b gives an interval of the parameter t in which
// that piece is P's neighbour. The edge is cut at every interval end; each part's neighbour is
// the piece whose interval holds its middle, or the background when none does.
//
// How a part is classified. Both depth planes are affine, so their difference d along the part
// is linear in t: where |d| <= kDepthContinuityRelative of the depth at both ends the part is
// continuous, elsewhere it is a jump — a contour, reported once, from the nearer piece. A
// continuous part between different faces is a crease when the slope of depth across it jumps
// (more than kSlopeJumpRelative of the slopes): convex when z_P - z_N grows from P into N (z_s
// is then the smaller plane on each side: a ridge), concave otherwise; reported once, from the
// piece that comes first. Parts between pieces of one face, and between coplanar faces, are no
// line.
#include "harness/reference/line_reference.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <utility>

#include "harness/reference/box_reference.h"
#include "harness/reference/convex_split.h"
#include "harness/reference/overlap_grid.h"

namespace aabench {
namespace {

// Two edges lie on one line when each endpoint of one is within this distance of the other's
// line. Shared edges of adjacent pieces are the same line up to the rounding of the vertices
// that cuts made (a few ulps of coordinates below ~1e4 px: < 1e-11 px) and the slack that
// visibility's contour cleaning allows (1.5e-10 px, convex_split.h); 1e-7 px is far above both
// and far below anything a pixel shows (a line image is one pixel wide).
constexpr double kCollinearPx = 1e-7;
// Parts of an edge shorter than this are dropped (ends of neighbours' intervals that differ by
// rounding): their strips cover at most 1e-7 px^2.
constexpr double kMinPartPx = 1e-7;
// Depth is continuous across a part where the two planes differ by at most this fraction of
// the depth. Planes of faces that share an edge in 3-D agree along it up to their own rounding
// (~1e-13 relative for well-shaped faces, 1e-10 for ill-shaped ones: visibility.cpp's tie
// tolerance); a jump of 1e-6 of z_s changes the first derivative of depth by ~1e-6 z_s per
// pixel, 1e-3 of k_p = 10 for the torus's z_s ~ 300, which the paper's operator cannot draw.
constexpr double kDepthContinuityRelative = 1e-6;
// A continuous part is a crease when the slope of depth across it jumps by more than this
// fraction of the larger of the two slopes (plus kSlopeFloorRelative of the depth per pixel,
// for faces nearly parallel to the screen). Coplanar faces fitted from different vertices have
// slopes that agree to ~1e-10 relative; the smallest crease the operators draw (k_l = 2 with
// slopes of order 1) is a jump of order 1e-2.
constexpr double kSlopeJumpRelative = 1e-6;
constexpr double kSlopeFloorRelative = 1e-12;

struct Edge {
    Point a, b;
    int piece = 0;
};

struct Neighbour {
    double t0 = 0.0, t1 = 0.0;  // in the edge's parameter, t0 < t1
    int piece = -1;
};

AffinePlane depth_plane(const Shape& s, std::size_t index) {
    if (s.value_plane) return *s.value_plane;
    if (s.inv_depth) return *s.inv_depth;
    throw InputError(fmt::format("true_lines: piece {} has no depth plane", index));
}

double cross(double ax, double ay, double bx, double by) { return ax * by - ay * bx; }

// Signed distance of p from the line a -> b (|b - a| > 0).
double line_distance(const Point& a, const Point& b, const Point& p) {
    const double dx = b.x - a.x, dy = b.y - a.y;
    return cross(dx, dy, p.x - a.x, p.y - a.y) / std::hypot(dx, dy);
}

// The parameter of p's projection onto a -> b.
double param(const Point& a, const Point& b, const Point& p) {
    const double dx = b.x - a.x, dy = b.y - a.y;
    return ((p.x - a.x) * dx + (p.y - a.y) * dy) / (dx * dx + dy * dy);
}

Point lerp(const Point& a, const Point& b, double t) {
    return {a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)};
}

// Clips a -> b to the window [0, w] x [0, h] (Liang-Barsky); false when nothing is left.
bool clip_to_window(Point& a, Point& b, int w, int h) {
    double t0 = 0.0, t1 = 1.0;
    const double dx = b.x - a.x, dy = b.y - a.y;
    const double p[4] = {-dx, dx, -dy, dy};
    const double q[4] = {a.x, w - a.x, a.y, h - a.y};
    for (int k = 0; k < 4; ++k) {
        if (p[k] == 0.0) {
            if (q[k] < 0.0) return false;
            continue;
        }
        const double r = q[k] / p[k];
        if (p[k] < 0.0)
            t0 = std::max(t0, r);
        else
            t1 = std::min(t1, r);
    }
    if (!(t1 - t0 > 0.0)) return false;
    const Point a0 = a;
    a = lerp(a0, b, t0);
    b = lerp(a0, b, t1);
    return true;
}

// True when the segment runs along the window's frame (a piece cut by the frame).
bool on_frame(const Point& a, const Point& b, int w, int h) {
    auto near = [](double u, double v) { return std::abs(u - v) <= kCollinearPx; };
    return (near(a.x, 0) && near(b.x, 0)) || (near(a.x, w) && near(b.x, w)) ||
           (near(a.y, 0) && near(b.y, 0)) || (near(a.y, h) && near(b.y, h));
}

class LineFinder {
public:
    explicit LineFinder(const Scene& scene) : scene_(scene) {
        for (std::size_t s = 0; s < scene.shapes.size(); ++s) {
            const Shape& shape = scene.shapes[s];
            if (shape.contours.size() != 1) {
                throw InputError(
                    fmt::format("true_lines: piece {} has {} contours", s, shape.contours.size()));
            }
            planes_.push_back(depth_plane(shape, s));
            Contour c = shape.contours[0];
            if (twice_signed_area(c) < 0.0) std::reverse(c.begin(), c.end());
            for (std::size_t k = 0; k < c.size(); ++k) {
                const Point& a = c[k];
                const Point& b = c[(k + 1) % c.size()];
                if (a == b) continue;
                edges_.push_back({a, b, static_cast<int>(s)});
            }
        }
        neighbours_.resize(edges_.size());
    }

    std::vector<LineSegment> run() {
        match_edges();
        for (std::size_t k = 0; k < edges_.size(); ++k) classify_edge(k);
        return std::move(out_);
    }

private:
    void match_edges() {
        std::vector<Bounds> boxes;
        boxes.reserve(edges_.size());
        for (const Edge& e : edges_) {
            // Inflated so that edges on one axis-parallel line (zero-height boxes) overlap.
            boxes.push_back(
                {std::min(e.a.x, e.b.x) - kCollinearPx, std::min(e.a.y, e.b.y) - kCollinearPx,
                 std::max(e.a.x, e.b.x) + kCollinearPx, std::max(e.a.y, e.b.y) + kCollinearPx});
        }
        for (const auto& [i, j] : overlapping_box_pairs(boxes)) {
            const Edge& p = edges_[i];
            const Edge& q = edges_[j];
            if (p.piece == q.piece) continue;
            if (!collinear(p, q)) continue;
            add_overlap(i, j);
            add_overlap(j, i);
        }
    }

    // The shorter edge's endpoints lie on the longer edge's line (the longer one's line is
    // the better conditioned: two rounded endpoints close together point anywhere).
    static bool collinear(const Edge& p, const Edge& q) {
        const bool p_longer =
            std::hypot(p.b.x - p.a.x, p.b.y - p.a.y) >= std::hypot(q.b.x - q.a.x, q.b.y - q.a.y);
        const Edge& l = p_longer ? p : q;
        const Edge& s = p_longer ? q : p;
        return std::abs(line_distance(l.a, l.b, s.a)) <= kCollinearPx &&
               std::abs(line_distance(l.a, l.b, s.b)) <= kCollinearPx;
    }

    void add_overlap(int i, int j) {
        const Edge& p = edges_[i];
        const Edge& q = edges_[j];
        // Adjacent pieces of one orientation run along a shared edge in opposite directions.
        if ((p.b.x - p.a.x) * (q.b.x - q.a.x) + (p.b.y - p.a.y) * (q.b.y - q.a.y) >= 0.0) return;
        const double ta = param(p.a, p.b, q.a), tb = param(p.a, p.b, q.b);
        const double t0 = std::max(0.0, std::min(ta, tb)), t1 = std::min(1.0, std::max(ta, tb));
        const double length = std::hypot(p.b.x - p.a.x, p.b.y - p.a.y);
        if ((t1 - t0) * length <= kMinPartPx) return;
        neighbours_[i].push_back({t0, t1, q.piece});
    }

    void classify_edge(std::size_t k) {
        const Edge& e = edges_[k];
        std::vector<double> cuts = {0.0, 1.0};
        for (const Neighbour& n : neighbours_[k]) {
            cuts.push_back(n.t0);
            cuts.push_back(n.t1);
        }
        std::sort(cuts.begin(), cuts.end());
        const double length = std::hypot(e.b.x - e.a.x, e.b.y - e.a.y);
        for (std::size_t c = 0; c + 1 < cuts.size(); ++c) {
            const double t0 = cuts[c], t1 = cuts[c + 1];
            if ((t1 - t0) * length <= kMinPartPx) continue;
            const double mid = 0.5 * (t0 + t1);
            int other = -1;
            for (const Neighbour& n : neighbours_[k]) {
                if (n.t0 <= mid && mid <= n.t1) other = n.piece;
            }
            classify_part(e, t0, t1, other);
        }
    }

    void classify_part(const Edge& e, double t0, double t1, int other) {
        const Point a = lerp(e.a, e.b, t0), b = lerp(e.a, e.b, t1);
        const Shape& mine = scene_.shapes[e.piece];
        if (other < 0) {
            emit(a, b, LineKind::kContour, mine.face, -1);
            return;
        }
        const Shape& theirs = scene_.shapes[other];
        if (theirs.face == mine.face) return;  // cells of one face: no line
        const AffinePlane& zp = planes_[e.piece];
        const AffinePlane& zn = planes_[other];
        const double da = zp.at(a.x, a.y) - zn.at(a.x, a.y);
        const double db = zp.at(b.x, b.y) - zn.at(b.x, b.y);
        const double scale = std::max({std::abs(zp.at(a.x, a.y)), std::abs(zp.at(b.x, b.y)),
                                       std::abs(zn.at(a.x, a.y)), std::abs(zn.at(b.x, b.y))});
        // d is linear along the part, so it is either zero all along (the planes meet on the
        // edge's line: continuous) or zero at one point at most (a depth jump that closes at
        // a vertex, as a silhouette edge does where it meets the floor: a contour all along).
        if (std::abs(da) > kDepthContinuityRelative * scale ||
            std::abs(db) > kDepthContinuityRelative * scale) {
            // Once, from the nearer piece (the occluder's edge).
            if (da + db > 0.0) emit(a, b, LineKind::kContour, mine.face, theirs.face);
            return;
        }
        if (other < e.piece) return;  // a crease: once, from the piece that comes first
        // The slope across the edge, outward from P (to the right of a -> b).
        const double nx = (e.b.y - e.a.y) / std::hypot(e.b.x - e.a.x, e.b.y - e.a.y);
        const double ny = -(e.b.x - e.a.x) / std::hypot(e.b.x - e.a.x, e.b.y - e.a.y);
        const double jump_slope = (zp.gx - zn.gx) * nx + (zp.gy - zn.gy) * ny;
        const double slopes = std::max(std::hypot(zp.gx, zp.gy), std::hypot(zn.gx, zn.gy));
        if (std::abs(jump_slope) <= kSlopeJumpRelative * slopes + kSlopeFloorRelative * scale) {
            return;  // coplanar faces
        }
        emit(a, b, jump_slope > 0.0 ? LineKind::kConvexCrease : LineKind::kConcaveCrease, mine.face,
             theirs.face);
    }

    void emit(Point a, Point b, LineKind kind, int face, int other_face) {
        if (!clip_to_window(a, b, scene_.width, scene_.height)) return;
        if (std::hypot(b.x - a.x, b.y - a.y) <= kMinPartPx) return;
        if (on_frame(a, b, scene_.width, scene_.height)) return;
        out_.push_back({a, b, kind, face, other_face});
    }

    const Scene& scene_;
    std::vector<AffinePlane> planes_;
    std::vector<Edge> edges_;
    std::vector<std::vector<Neighbour>> neighbours_;
    std::vector<LineSegment> out_;
};

// A 2-D scene of the strips of the lines of one kind, each value 1 on background 0: later
// shapes cover earlier ones, so its box reference is the coverage of the union.
Scene strip_scene(const std::vector<LineSegment>& lines, LineKind kind, int width, int height) {
    Scene s;
    s.width = width;
    s.height = height;
    s.background = 0.0;
    for (const LineSegment& l : lines) {
        if (l.kind != kind) continue;
        const double len = std::hypot(l.b.x - l.a.x, l.b.y - l.a.y);
        const double hx = 0.5 * (l.b.y - l.a.y) / len, hy = -0.5 * (l.b.x - l.a.x) / len;
        Shape strip;
        strip.contours.push_back({{l.a.x + hx, l.a.y + hy},
                                  {l.b.x + hx, l.b.y + hy},
                                  {l.b.x - hx, l.b.y - hy},
                                  {l.a.x - hx, l.a.y - hy}});
        s.shapes.push_back(std::move(strip));
    }
    return s;
}

}  // namespace

const char* line_kind_name(LineKind kind) {
    switch (kind) {
        case LineKind::kContour:
            return "contour";
        case LineKind::kConvexCrease:
            return "convex crease";
        case LineKind::kConcaveCrease:
            return "concave crease";
    }
    return "?";
}

std::vector<LineSegment> true_lines(const Scene& depth_pieces) {
    require_window_frame(depth_pieces, "true_lines");
    return LineFinder(depth_pieces).run();
}

LineCoverage line_coverage(const std::vector<LineSegment>& lines, int width, int height) {
    return {box_reference(strip_scene(lines, LineKind::kContour, width, height)),
            box_reference(strip_scene(lines, LineKind::kConvexCrease, width, height)),
            box_reference(strip_scene(lines, LineKind::kConcaveCrease, width, height))};
}

Coverage line_drawing_reference(const LineCoverage& cov, const EdgesSpec& spec) {
    Coverage out(cov.contour.width, cov.contour.height);
    const double wc = spec.contour_weight;
    const double wk = spec.crease != "none" ? spec.crease_weight : 0.0;
    const bool black = spec.style == "black";
    for (std::size_t i = 0; i < out.data.size(); ++i) {
        const double cc = cov.contour.data[i], cx = cov.convex.data[i], cv = cov.concave.data[i];
        if (black) {
            out.data[i] = std::clamp(wc * cc + wk * (cx + cv), 0.0, 1.0);
        } else {
            const double dark = std::clamp(wc * cc + wk * cv, 0.0, 1.0);
            const double light = std::clamp(wk * cx, 0.0, 1.0);
            out.data[i] = light - dark;
        }
    }
    return out;
}

}  // namespace aabench
