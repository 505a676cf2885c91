// The SMAA 1x pass (Jimenez, Echevarria, Sousa & Gutierrez 2012, "SMAA: Enhanced Subpixel
// Morphological Antialiasing", Eurographics), written from the paper on a float image of one
// plane (grey) or three (colour):
//
//   1. Edges (§2.1, edge detection with local contrast adaptation): pixel (x, y) has a left
//      edge when its delta to (x - 1, y) is >= threshold and a top edge when its delta to
//      (x, y - 1) is. An edge is then dropped when a neighbouring edge is more than
//      kSmaaLocalContrastFactor times stronger: c_max, the largest of the deltas to the left,
//      top, right and bottom neighbours and the two far deltas below, must be <= factor x the
//      edge's own delta (a strong edge hides a weak one next to it). A neighbour outside the
//      image has delta 0: no edge on the image's border. The delta, as the reference
//      implementation's two colour detectors compute it (SMAALumaEdgeDetectionPS,
//      SMAAColorEdgeDetectionPS):
//      - luma edges (the default): |L(p) - L(q)|, L the luma (Rec. 709 weights on the encoded
//        colour; a grey image's encoded value); the far deltas are the left neighbour's to its
//        left and the top neighbour's to its top;
//      - colour edges: the largest over channels of |C_c(p) - C_c(q)| on the encoded channels
//        (a grey image: its one channel); the far deltas are the pixel's own to the pixel two
//        to the left and two above, as the published colour detector takes them (unlike its luma
//        detector). An edge between colours of equal luma is found here and not by luma edges.
//      SMAA's third detector, on depth, is not built: the passes here read a colour image only.
//   2. Blending weights (§3): for every edge, the share of each pixel beside it that belongs to
//      the other side of the line reconstructed from the edge's shape:
//      - diagonal patterns first (§3.1): a pixel on a staircase of unit steps (a left and a top
//        edge: "/"; a top edge and its right neighbour's left edge: "\"), with at least one
//        neighbouring step on the same diagonal, takes the staircase's midline
//        (methods/smaa/smaa_area_p.h): its top edge's two pixels get the corner triangles of that
//        line, and the edges of the step are not read again as orthogonal patterns;
//      - orthogonal patterns (MLAA's L, Z and U shapes with SMAA's search): along the edge line,
//        search each way for the segment's end, at most 2 x max_search_steps pixels (SMAA's
//        searches read two pixels per step: its step counts are in pairs of pixels), read the
//        crossing edges at each end (none when the search stopped at its limit or at the
//        image's border), and look the shares up in the area table;
//      - corner rounding (§3.2, sharp geometric features): when a crossing edge continues past
//        the step for a second pixel, the end is a corner of the shape, not a step of a
//        staircase: the shares that end gives are scaled by corner_rounding (1: MLAA's rounded
//        corners, 0: sharp). A pixel takes the end whose half of the segment it lies in (the
//        middle pixel of an odd segment the mean of both ends).
//   3. Neighbourhood blending (§2.3): each pixel gathers the shares of its four edges (own top
//      and left, its bottom neighbour's top and right neighbour's left) and blends along one
//      axis only, the one with the larger share (vertical on a tie): a corner pixel is one
//      shape's corner, and blending it both ways would count its corner twice. Reading left
//      open: on that axis out = v + a1 (v1 - v) + a2 (v2 - v), the area reading (a share a of
//      the pixel has its neighbour's value); a1 + a2 > 1 is scaled to 1. A colour image's shares
//      are found once and every channel is blended with them.
//
// Readings of the diagonal patterns left open by the paper: a run needs two steps (one lone
// step is a shape's corner, read as orthogonal patterns), and the run's ends take no crossing
// edges (the midline stops at the midpoints of its first and last unit edges; whatever the
// boundary does past them is an orthogonal segment of its own). Under this reading a pixel's
// shares depend only on whether its diagonal neighbours are steps, so the search along the
// diagonal never goes past one pixel each way; max_diag_steps = 0 turns diagonals off (presets
// low and medium, as published).
//
// Bands: rows [row_lo, row_hi) of the output read the base image's rows within
// smaa_reach_rows() of them and nothing else, so a band's result is the whole image's.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "methods/scan/kernel/image.h"
#include "methods/smaa/smaa_area_p.h"

namespace aabench {

// The paper's λ: an edge survives next to one at most this many times stronger.
inline constexpr float kSmaaLocalContrastFactor = 2.0f;

struct SmaaSettings {
    float threshold = 0.1f;         // on luma (0..1]
    int max_search_steps = 16;      // orthogonal search, pairs of pixels each way
    int max_diag_steps = 8;         // 0: no diagonal patterns
    float corner_rounding = 0.25f;  // 1: no corner detection (MLAA's rounding)
    // The farthest end an orthogonal search finds, in pixels: the area table's size.
    int max_distance() const { return 2 * max_search_steps; }
};

// The presets published with the reference implementation (SMAA 1x's SMAA_PRESET_LOW, _MEDIUM,
// _HIGH, _ULTRA): threshold 0.15, 0.1, 0.1, 0.05; search steps 4, 8, 16, 32; diagonal steps
// 0 (off), 0, 8, 16; corner rounding off (1: MLAA's full rounding), off, 25 %, 25 %. `name`
// is one of kSmaaPresetNames (std::invalid_argument otherwise: callers check first).
inline const std::array<std::string, 4> kSmaaPresetNames = {"low", "medium", "high", "ultra"};
SmaaSettings smaa_preset(const std::string& name);

// Per-thread working memory, grown to the image's size and kept: a warm pass allocates nothing.
struct SmaaScratch {
    std::vector<std::uint8_t> edges;           // bit 0: left edge, bit 1: top edge
    std::vector<std::array<float, 4>> shares;  // top own, top other, left own, left other
};

// Rows of the base image an output row reads above and below it.
int smaa_reach_rows(const SmaaSettings& settings);

// What edges are found on (step 1): one luma plane, or 1 to 3 encoded channels compared one by
// one. The planes have the image's size and hold their rows within smaa_reach_rows() of the
// range asked.
struct SmaaEdgeInput {
    std::array<const Image*, 3> planes{};
    int channels = 1;
    bool colour = false;  // colour edges (per channel), else luma edges on planes[0]
};

// Steps 1 and 2: the edges and shares that rows [row_lo, row_hi) of the output read, into
// `scratch` (grown to the image's size and kept).
void smaa_shares_rows(const SmaaEdgeInput& input, const SmaaSettings& settings,
                      const SmaaAreaTable& areas, SmaaScratch& scratch, int row_lo, int row_hi);
// Step 3: rows [row_lo, row_hi) of `out` from `values` (one plane) with the shares that
// smaa_shares_rows left in `scratch` for the same rows; called once per channel.
void smaa_blend_rows(const Image& values, const SmaaScratch& scratch, Image& out, int row_lo,
                     int row_hi);

// Rows [row_lo, row_hi) of `out` (same size as `values`): SMAA of `values` with edges found
// on `luma` (same size). Both must hold their rows within smaa_reach_rows() of the range.
void smaa_pass_rows(const Image& values, const Image& luma, const SmaaSettings& settings,
                    const SmaaAreaTable& areas, SmaaScratch& scratch, Image& out, int row_lo,
                    int row_hi);

}  // namespace aabench
