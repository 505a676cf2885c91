// smaa — SMAA 1x, Enhanced Subpixel Morphological Antialiasing, as a post-process over a
// registry method's image (methods/post_process.h: base, bands, luma, timing).
//
// Source: J. Jimenez, J. I. Echevarria, T. Sousa, D. Gutierrez, "SMAA: Enhanced Subpixel
// Morphological Antialiasing", Computer Graphics Forum (Eurographics 2012); the orthogonal
// shapes are MLAA's (Reshetov 2009). Written from the paper; no code or texture copied. The
// pass (methods/smaa/smaa_pass_p.h) runs the paper's three steps: luma edges with local contrast
// adaptation, blending weights from diagonal and orthogonal pattern searches, an area table
// computed here from the shapes' definition (methods/smaa/smaa_area_p.h) and corner rounding, and
// neighbourhood blending. Every reading the paper leaves open is written down in those two
// headers; in short:
//   - L shapes reach the edge line at the segment's middle; an end with crossing edges on both
//     sides is the mean of its two readings; no crossing edge at either end: no blend;
//   - the search's step counts are pairs of pixels (the reference implementation reads two
//     pixels per step), so preset high finds ends up to 32 px away each way;
//   - a diagonal run needs two unit steps and is read as its staircase's midline (corner
//     triangles of 1/8), its ends left to the orthogonal patterns;
//   - corner rounding scales the shares an end gives when its crossing edge runs on for a
//     second pixel (a shape's corner, not a staircase step);
//   - the blend takes one axis, the one with the larger share, and adds each neighbour's value
//     in proportion to its share (an area reading) on linear values.
// Thresholds act on the sRGB-encoded colour, as SMAA ships ("edge detection requires
// gamma-corrected colors"; space=linear: on the linear values). Edges (`edges`, the reference
// implementation's luma and colour detectors, smaa_pass_p.h step 1): luma (the default, as
// SMAA ships) thresholds the Rec. 709 luma 0.2126 R' + 0.7152 G' + 0.0722 B' of the encoded
// colour, and so does not see an edge between two colours of equal luma; color thresholds the
// largest of the encoded channels' differences, with the far deltas of local contrast
// adaptation taken from the pixel itself as SMAAColorEdgeDetectionPS takes them. A grey image's
// luma is its encoded value, so luma edges find on it what they find on a grey scene; colour
// edges on a grey image compare its one channel (the far deltas as above, so edges=color may
// differ from edges=luma on grey). SMAA's depth edge detection is not built. The shares are
// found once and every channel is blended with them.
//
// Parameters: base (none), space (srgb), preset (high), edges (luma). The presets are those
// published with the reference implementation (methods/smaa/smaa_pass_p.h, smaa_preset): low
// (threshold 0.15, 4 search steps, no diagonals, no corner detection), medium (0.1, 8, none,
// none), high (0.1, 16, 8 diagonal steps, corner rounding 25 %), ultra (0.05, 32, 16, 25 %).
// High is the default of the reference implementation's configurable values; the local
// contrast adaptation factor is its 2.0 (kSmaaLocalContrastFactor) in every preset.
//
// Cost: O(pixels) for edges and blending, plus O(segment search) per edge pixel, at most
// 2 x 2 x search steps reads each.
#include <algorithm>
#include <vector>

#include "methods/post_process.h"
#include "methods/smaa/smaa_area_p.h"
#include "methods/smaa/smaa_pass_p.h"

namespace aabench {
namespace {

// The choices, the default first (a choice parameter's default is its first choice).
std::vector<std::string> preset_names() { return {"high", "low", "medium", "ultra"}; }

class SmaaMethod : public PostProcessMethod {
public:
    explicit SmaaMethod(const ParamValues& p)
        : PostProcessMethod(p.get_choice("base")),
          srgb_(p.get_choice("space") == "srgb"),
          colour_edges_(p.get_choice("edges") == "color"),
          settings_(smaa_preset(p.get_choice("preset"))),
          areas_(settings_.max_distance()) {}

    int reach_rows(int height) const override {
        return std::min(smaa_reach_rows(settings_), height);
    }

    void pass_rows(const Image& in, Image& out, int row_lo, int row_hi) const override {
        // Per-thread scratch, kept: a warm pass allocates nothing.
        thread_local Image luma;
        thread_local SmaaScratch scratch;
        const int reach = smaa_reach_rows(settings_);
        // The encoded value: a grey image's luma, and its one channel for colour edges.
        luma_rows(in, srgb_, luma, row_lo - reach, row_hi + reach);
        SmaaEdgeInput input;
        input.planes[0] = &luma;
        input.colour = colour_edges_;
        smaa_shares_rows(input, settings_, areas_, scratch, row_lo, row_hi);
        smaa_blend_rows(in, scratch, out, row_lo, row_hi);
    }

    void pass_colour_rows(const ImagePlanes& in, ImagePlanes& out, int row_lo,
                          int row_hi) const override {
        // Per-thread scratch, kept: a warm pass allocates nothing.
        thread_local Image luma;
        thread_local ImagePlanes encoded;
        thread_local SmaaScratch scratch;
        const int reach = smaa_reach_rows(settings_);
        SmaaEdgeInput input;
        if (colour_edges_) {
            encoded_planes_rows(in, srgb_, encoded, row_lo - reach, row_hi + reach);
            input.channels = encoded.channels();
            for (int c = 0; c < input.channels; ++c) input.planes[c] = &encoded[c];
            input.colour = true;
        } else {
            colour_luma_rows(in, srgb_, kRec709Luma, luma, row_lo - reach, row_hi + reach);
            input.planes[0] = &luma;
        }
        smaa_shares_rows(input, settings_, areas_, scratch, row_lo, row_hi);
        for (int c = 0; c < in.channels(); ++c) {
            smaa_blend_rows(in[c], scratch, out[c], row_lo, row_hi);
        }
    }

private:
    bool srgb_;
    bool colour_edges_;
    SmaaSettings settings_;
    SmaaAreaTable areas_;  // built once per method object: a render only reads it
};

}  // namespace

MethodTraits smaa_traits() {
    // The pass's estimate besides the base: luma (4 bytes), edges (1) and four shares (16) per
    // pixel of scratch. Time: fxaa's figure, since the two passes took the same order of time
    // in one default run (256^2, the same load: star 11.8 ms against fxaa's 14.7, rings 20
    // against 31, strips 0.87 against 0.75, base included).
    constexpr double kPassMsPerMpixel = 20.0, kScratchBytesPerPixel = 21.0;
    return post_process_traits(kPassMsPerMpixel, kScratchBytesPerPixel);
}

MethodInfo smaa_method() {
    return {"smaa",
            "SMAA 1x (Jimenez, Echevarria, Sousa & Gutierrez 2012): luma or colour edges with "
            "local contrast adaptation, orthogonal and diagonal pattern search, area table, corner "
            "rounding, neighbourhood blending, as a pass over the base method's image",
            {post_process_base_param(),
             post_process_space_param(),
             {"preset", ParamKind::kChoice, 0, 0, 0, preset_names(),
              "the reference implementation's presets: threshold, search steps, diagonal steps, "
              "corner rounding (low 0.15/4/off/off, medium 0.1/8/off/off, high 0.1/16/8/25%, "
              "ultra 0.05/32/16/25%)"},
             {"edges", ParamKind::kChoice, 0, 0, 0, {"luma", "color"},
              "the edge detector: luma, Rec. 709 luma of the encoded colour (as SMAA ships; blind "
              "to edges between colours of equal luma); color, the largest encoded channel "
              "difference (SMAAColorEdgeDetectionPS)"}},
            [](const ParamValues& p) { return std::make_unique<SmaaMethod>(p); }};
}

}  // namespace aabench
