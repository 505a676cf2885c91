// SMAA's area texture, computed here from its definition (Jimenez, Echevarria, Sousa &
// Gutierrez 2012, "SMAA: Enhanced Subpixel Morphological Antialiasing", §3; the orthogonal
// shapes are those of MLAA, Reshetov 2009): for a pixel on an aliased edge line, which share of
// it lies on the other side of the line reconstructed from the edge's shape. No texture is
// loaded or copied: every entry is an integral of a straight line over a unit interval.
//
// Frame of one orthogonal edge segment (methods/smaa/smaa_pass_p.h finds them): a run of
// `d = d_first + d_second + 1` pixels whose common boundary is the edge line, here the x axis
// from 0 to d. "Own" is the side of the pixel being weighted (for a top edge: the pixel below
// the line; for a left edge: the pixel right of it), y > 0; "other" is the neighbour across the
// line, y < 0. The pixel of interest spans [d_first, d_first + 1].
//
// At each end of the segment the edge line meets crossing edges: unit edges across the line at
// the end's boundary, on the own side, the other side, both or neither. The reconstructed line
// (MLAA's reading, which SMAA keeps) passes through the midpoint of a crossing edge, height
// +1/2 (own) or -1/2 (other):
//   Z shape (own at one end, other at the other): one line from end to end, crossing the edge
//     line at the segment's middle;
//   U shape (the same side at both ends): two lines, each from its end's midpoint to the edge
//     line at the middle, d / 2;
//   L shape (a crossing edge at one end, none at the other): the one line from that end to the
//     middle. Readings left open by the paper, written down here: an end without a crossing
//     edge says nothing about where the line goes, so the line reaches the edge line where it
//     would in a Z or U shape of the same length (the middle), and nothing is blended beyond;
//   both sides at an end (the edge meets a line crossing it: a T or X junction) gives no single
//     direction: the area is the mean of the two readings (own, other) at that end;
//   no crossing edge at either end: no line, no blend.
// Where the line runs on the own side (y > 0) the part of the own pixel between the edge line
// and the reconstructed line belongs to the other side's region: `own` is that area. Where it
// runs on the other side, `other` is the area of the neighbour across the line that belongs to
// the own side's region. A Z shape's middle pixel has both.
//
// Diagonal patterns (§3.1 of the paper): a staircase of unit steps is read as the line through
// the midpoints of its unit edges, so each pixel of the staircase, and each neighbour across it
// between two steps, has one corner triangle of legs 1/2 on the far side of the line:
// kSmaaDiagonalCornerArea.
#pragma once

#include <array>
#include <cstddef>
#include <vector>

namespace aabench {

// Crossing edges at one end of a segment.
enum class SmaaCrossing { kNone = 0, kOwn = 1, kOther = 2, kBoth = 3 };
inline constexpr int kSmaaCrossingCount = 4;

// The two shares of one pixel on an edge line (see above), each in [0, 1/2].
struct SmaaArea {
    float own = 0.0f;
    float other = 0.0f;
};

// The corner triangle of a 45-degree staircase's midline: legs 1/2, area 1/8.
inline constexpr float kSmaaDiagonalCornerArea = 0.125f;

// The area of the pixel [d_first, d_first + 1] of a segment of d_first + d_second + 1 pixels
// with crossing edges `first` (at x = 0) and `second` (at x = d), by its closed form.
SmaaArea smaa_orthogonal_area(SmaaCrossing first, SmaaCrossing second, int d_first, int d_second);

// smaa_orthogonal_area for every crossing pair and every distance 0..max_distance on each side,
// computed once (construction); lookups are a single read. The pass's searches stop at
// max_distance pixels, so no lookup falls outside.
class SmaaAreaTable {
public:
    explicit SmaaAreaTable(int max_distance);
    int max_distance() const { return max_distance_; }
    SmaaArea at(SmaaCrossing first, SmaaCrossing second, int d_first, int d_second) const {
        const std::size_t side = static_cast<std::size_t>(max_distance_) + 1;
        const std::size_t pattern =
            static_cast<std::size_t>(first) * kSmaaCrossingCount + static_cast<std::size_t>(second);
        return areas_[(pattern * side + d_first) * side + d_second];
    }

private:
    int max_distance_;
    std::vector<SmaaArea> areas_;
};

}  // namespace aabench
