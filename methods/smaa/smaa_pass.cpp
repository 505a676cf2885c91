// The SMAA 1x pass (methods/smaa/smaa_pass_p.h).
#include "methods/smaa/smaa_pass_p.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace aabench {
namespace {

constexpr std::uint8_t kLeft = 1, kTop = 2;
enum Share { kTopOwn = 0, kTopOther = 1, kLeftOwn = 2, kLeftOther = 3 };

// Edge rows the shares of a row read beyond the segment search: the crossing edges one row
// past a segment's end and the corner test's second pixel.
constexpr int kSearchMarginRows = 3;

// Read-only view of the edge buffer with the image's borders as "no edge".
class Edges {
public:
    Edges(const std::vector<std::uint8_t>& edges, int width, int height)
        : edges_(edges), width_(width), height_(height) {}
    bool left(int x, int y) const { return has(x, y, kLeft); }
    bool top(int x, int y) const { return has(x, y, kTop); }
    int width() const { return width_; }
    int height() const { return height_; }

private:
    bool has(int x, int y, std::uint8_t bit) const {
        if (x < 0 || y < 0 || x >= width_ || y >= height_) return false;
        return (edges_[static_cast<std::size_t>(y) * width_ + x] & bit) != 0;
    }
    const std::vector<std::uint8_t>& edges_;
    int width_, height_;
};

// Step 1 with `delta(x0, y0, x1, y1)` the delta between two pixels and the far deltas taken
// from the left and top neighbours (luma edges) or from the pixel itself (colour edges).
template <class Delta>
void detect_edges(const Delta& delta, bool far_from_pixel, int w, int h, float threshold,
                  std::vector<std::uint8_t>& edges, int lo, int hi) {
    const int far_from = far_from_pixel ? 0 : 1;  // the far deltas' first pixel, this many back
    for (int y = lo; y < hi; ++y) {
        for (int x = 0; x < w; ++x) {
            const float d_left = x > 0 ? delta(x, y, x - 1, y) : 0.0f;
            const float d_top = y > 0 ? delta(x, y, x, y - 1) : 0.0f;
            bool left = d_left >= threshold, top = d_top >= threshold;
            if (left || top) {
                const float d_right = x + 1 < w ? delta(x, y, x + 1, y) : 0.0f;
                const float d_bottom = y + 1 < h ? delta(x, y, x, y + 1) : 0.0f;
                const float d_left2 = x > 1 ? delta(x - far_from, y, x - 2, y) : 0.0f;
                const float d_top2 = y > 1 ? delta(x, y - far_from, x, y - 2) : 0.0f;
                const float c_max = std::max({d_left, d_top, d_right, d_bottom, d_left2, d_top2});
                left = left && kSmaaLocalContrastFactor * d_left >= c_max;
                top = top && kSmaaLocalContrastFactor * d_top >= c_max;
            }
            edges[static_cast<std::size_t>(y) * w + x] =
                static_cast<std::uint8_t>((left ? kLeft : 0) | (top ? kTop : 0));
        }
    }
}

SmaaCrossing crossing(bool own, bool other) {
    if (own && other) return SmaaCrossing::kBoth;
    if (own) return SmaaCrossing::kOwn;
    return other ? SmaaCrossing::kOther : SmaaCrossing::kNone;
}

// One end of a segment: its crossing edges and its corner factors for the two shares.
struct End {
    SmaaCrossing crossing = SmaaCrossing::kNone;
    float own_factor = 1.0f, other_factor = 1.0f;
};

// The shares of a segment's pixel from its two ends (see "corner rounding" in the header).
SmaaArea segment_shares(const SmaaAreaTable& areas, const End& first, const End& second,
                        int d_first, int d_second) {
    SmaaArea a = areas.at(first.crossing, second.crossing, d_first, d_second);
    float own = first.own_factor, other = first.other_factor;
    if (d_first > d_second) {
        own = second.own_factor;
        other = second.other_factor;
    } else if (d_first == d_second) {
        own = 0.5f * (first.own_factor + second.own_factor);
        other = 0.5f * (first.other_factor + second.other_factor);
    }
    a.own *= own;
    a.other *= other;
    return a;
}

// Diagonal steps (header, "diagonal patterns").
bool slash_step(const Edges& e, int x, int y) { return e.left(x, y) && e.top(x, y); }
bool backslash_step(const Edges& e, int x, int y) { return e.top(x, y) && e.left(x + 1, y); }

enum class Diagonal { kNone, kSlash, kBackslash };

// The diagonal reading of pixel (x, y)'s top edge, and whether the upper neighbour has a corner
// on the far side of the midline (it lies between two steps of the run).
struct DiagonalShape {
    Diagonal kind = Diagonal::kNone;
    bool upper_corner = false;
};

DiagonalShape diagonal_at(const Edges& e, int x, int y, int max_diag_steps) {
    if (max_diag_steps <= 0) return {};
    // "/": steps at (x - 1, y + 1) and (x + 1, y - 1); the upper neighbour (x, y - 1) is the
    // left neighbour of the next step up. "\": steps at (x - 1, y - 1) and (x + 1, y + 1); the
    // upper neighbour is the right neighbour of the step before.
    if (slash_step(e, x, y)) {
        const bool down = slash_step(e, x - 1, y + 1), up = slash_step(e, x + 1, y - 1);
        if (down || up) return {Diagonal::kSlash, up};
    }
    if (backslash_step(e, x, y)) {
        const bool before = backslash_step(e, x - 1, y - 1),
                   after = backslash_step(e, x + 1, y + 1);
        if (before || after) return {Diagonal::kBackslash, before};
    }
    return {};
}

// A left edge that a diagonal run read already.
bool left_edge_in_diagonal(const Edges& e, int x, int y, int max_diag_steps) {
    return diagonal_at(e, x, y, max_diag_steps).kind == Diagonal::kSlash ||
           diagonal_at(e, x - 1, y, max_diag_steps).kind == Diagonal::kBackslash;
}

SmaaArea horizontal_shares(const Edges& e, const SmaaAreaTable& areas, const SmaaSettings& settings,
                           int x, int y) {
    const int max_d = areas.max_distance();
    int d_left = 0, d_right = 0;
    while (d_left < max_d && e.top(x - d_left - 1, y)) ++d_left;
    while (d_right < max_d && e.top(x + d_right + 1, y)) ++d_right;
    const int x_first = x - d_left, x_past = x + d_right + 1;  // the ends' boundaries
    const float rounding = settings.corner_rounding;
    End first, second;
    if (!e.top(x_first - 1, y)) {  // the segment ends here (not the search's limit)
        first.crossing = crossing(e.left(x_first, y), e.left(x_first, y - 1));
        if (e.left(x_first, y + 1)) first.own_factor = rounding;
        if (e.left(x_first, y - 2)) first.other_factor = rounding;
    }
    if (!e.top(x_past, y)) {
        second.crossing = crossing(e.left(x_past, y), e.left(x_past, y - 1));
        if (e.left(x_past, y + 1)) second.own_factor = rounding;
        if (e.left(x_past, y - 2)) second.other_factor = rounding;
    }
    return segment_shares(areas, first, second, d_left, d_right);
}

SmaaArea vertical_shares(const Edges& e, const SmaaAreaTable& areas, const SmaaSettings& settings,
                         int x, int y) {
    const int max_d = areas.max_distance();
    int d_up = 0, d_down = 0;
    while (d_up < max_d && e.left(x, y - d_up - 1)) ++d_up;
    while (d_down < max_d && e.left(x, y + d_down + 1)) ++d_down;
    const int y_first = y - d_up, y_past = y + d_down + 1;
    const float rounding = settings.corner_rounding;
    End first, second;
    if (!e.left(x, y_first - 1)) {
        first.crossing = crossing(e.top(x, y_first), e.top(x - 1, y_first));
        if (e.top(x + 1, y_first)) first.own_factor = rounding;
        if (e.top(x - 2, y_first)) first.other_factor = rounding;
    }
    if (!e.left(x, y_past)) {
        second.crossing = crossing(e.top(x, y_past), e.top(x - 1, y_past));
        if (e.top(x + 1, y_past)) second.own_factor = rounding;
        if (e.top(x - 2, y_past)) second.other_factor = rounding;
    }
    return segment_shares(areas, first, second, d_up, d_down);
}

void compute_shares(const Edges& e, const SmaaAreaTable& areas, const SmaaSettings& settings,
                    std::vector<std::array<float, 4>>& shares, int lo, int hi) {
    const int w = e.width();
    for (int y = lo; y < hi; ++y) {
        for (int x = 0; x < w; ++x) {
            std::array<float, 4>& s = shares[static_cast<std::size_t>(y) * w + x];
            s = {0.0f, 0.0f, 0.0f, 0.0f};
            if (e.top(x, y)) {
                const DiagonalShape diagonal = diagonal_at(e, x, y, settings.max_diag_steps);
                if (diagonal.kind != Diagonal::kNone) {
                    s[kTopOwn] = kSmaaDiagonalCornerArea;
                    s[kTopOther] = diagonal.upper_corner ? kSmaaDiagonalCornerArea : 0.0f;
                } else {
                    const SmaaArea a = horizontal_shares(e, areas, settings, x, y);
                    s[kTopOwn] = a.own;
                    s[kTopOther] = a.other;
                }
            }
            if (e.left(x, y) && !left_edge_in_diagonal(e, x, y, settings.max_diag_steps)) {
                const SmaaArea a = vertical_shares(e, areas, settings, x, y);
                s[kLeftOwn] = a.own;
                s[kLeftOther] = a.other;
            }
        }
    }
}

void detect_edges(const SmaaEdgeInput& input, float threshold, std::vector<std::uint8_t>& edges,
                  int lo, int hi) {
    const Image& first = *input.planes[0];
    const int w = first.width, h = first.height;
    const auto at = [w](const Image& plane, int x, int y) {
        return plane.data[static_cast<std::size_t>(y) * w + x];
    };
    if (!input.colour) {
        const auto luma_delta = [&](int x0, int y0, int x1, int y1) {
            return std::abs(at(first, x0, y0) - at(first, x1, y1));
        };
        detect_edges(luma_delta, false, w, h, threshold, edges, lo, hi);
        return;
    }
    const auto colour_delta = [&](int x0, int y0, int x1, int y1) {
        float d = 0.0f;  // the largest channel's: max(max(t.r, t.g), t.b)
        for (int c = 0; c < input.channels; ++c) {
            const Image& plane = *input.planes[static_cast<std::size_t>(c)];
            d = std::max(d, std::abs(at(plane, x0, y0) - at(plane, x1, y1)));
        }
        return d;
    };
    detect_edges(colour_delta, true, w, h, threshold, edges, lo, hi);
}

void blend(const Image& values, const std::vector<std::array<float, 4>>& shares, Image& out, int lo,
           int hi) {
    const int w = values.width, h = values.height;
    auto share = [&](int x, int y, int k) {
        return shares[static_cast<std::size_t>(y) * w + x][k];
    };
    for (int y = lo; y < hi; ++y) {
        const float* row = values.row(y);
        float* dst = out.row(y);
        for (int x = 0; x < w; ++x) {
            const float up = share(x, y, kTopOwn), left = share(x, y, kLeftOwn);
            const float down = y + 1 < h ? share(x, y + 1, kTopOther) : 0.0f;
            const float right = x + 1 < w ? share(x + 1, y, kLeftOther) : 0.0f;
            const float v = row[x];
            float a1 = 0.0f, a2 = 0.0f, v1 = v, v2 = v;
            if (std::max(left, right) > std::max(up, down)) {
                a1 = left, a2 = right;
                if (left > 0.0f) v1 = row[x - 1];
                if (right > 0.0f) v2 = row[x + 1];
            } else {
                a1 = up, a2 = down;
                if (up > 0.0f) v1 = values.row(y - 1)[x];
                if (down > 0.0f) v2 = values.row(y + 1)[x];
            }
            const float total = a1 + a2;
            if (total > 1.0f) a1 /= total, a2 /= total;
            dst[x] = v + a1 * (v1 - v) + a2 * (v2 - v);
        }
    }
}

}  // namespace

SmaaSettings smaa_preset(const std::string& name) {
    // Threshold, search steps, diagonal steps, corner rounding (1: no corner detection).
    auto settings = [](float threshold, int steps, int diag_steps, float rounding) {
        return SmaaSettings{threshold, steps, diag_steps, rounding};
    };
    if (name == "low") return settings(0.15f, 4, 0, 1.0f);
    if (name == "medium") return settings(0.1f, 8, 0, 1.0f);
    if (name == "high") return settings(0.1f, 16, 8, 0.25f);
    if (name == "ultra") return settings(0.05f, 32, 16, 0.25f);
    throw std::invalid_argument("unknown SMAA preset '" + name + "'");
}

int smaa_reach_rows(const SmaaSettings& settings) {
    // Shares of rows [lo - 1, hi + 1) (the blend reads the row below), each reading edges
    // max_distance + kSearchMarginRows rows away, each edge reading luma two rows up, one down.
    return 1 + std::max(settings.max_distance(), 1) + kSearchMarginRows + 2;
}

void smaa_shares_rows(const SmaaEdgeInput& input, const SmaaSettings& settings,
                      const SmaaAreaTable& areas, SmaaScratch& scratch, int row_lo, int row_hi) {
    const int w = input.planes[0]->width, h = input.planes[0]->height;
    row_lo = std::max(row_lo, 0);
    row_hi = std::min(row_hi, h);
    if (row_lo >= row_hi || w <= 0) return;
    const std::size_t pixels = static_cast<std::size_t>(w) * h;
    // Grown only: a warm pass on an image no larger allocates nothing.
    if (scratch.edges.size() < pixels) scratch.edges.resize(pixels);
    if (scratch.shares.size() < pixels) scratch.shares.resize(pixels);
    const int share_lo = std::max(row_lo - 1, 0), share_hi = std::min(row_hi + 1, h);
    const int margin = std::max(settings.max_distance(), 1) + kSearchMarginRows;
    const int edge_lo = std::max(share_lo - margin, 0), edge_hi = std::min(share_hi + margin, h);
    detect_edges(input, settings.threshold, scratch.edges, edge_lo, edge_hi);
    // The searches read edge rows [share_lo - margin, share_hi + margin) only (clamped to the
    // image), all written above: no row of an earlier render is read.
    const Edges edges(scratch.edges, w, h);
    compute_shares(edges, areas, settings, scratch.shares, share_lo, share_hi);
}

void smaa_blend_rows(const Image& values, const SmaaScratch& scratch, Image& out, int row_lo,
                     int row_hi) {
    row_lo = std::max(row_lo, 0);
    row_hi = std::min(row_hi, values.height);
    if (row_lo >= row_hi || values.width <= 0) return;
    blend(values, scratch.shares, out, row_lo, row_hi);
}

void smaa_pass_rows(const Image& values, const Image& luma, const SmaaSettings& settings,
                    const SmaaAreaTable& areas, SmaaScratch& scratch, Image& out, int row_lo,
                    int row_hi) {
    SmaaEdgeInput input;
    input.planes[0] = &luma;
    smaa_shares_rows(input, settings, areas, scratch, row_lo, row_hi);
    smaa_blend_rows(values, scratch, out, row_lo, row_hi);
}

}  // namespace aabench
