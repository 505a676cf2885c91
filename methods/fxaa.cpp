// fxaa — Fast Approximate Anti-Aliasing, the quality variant of FXAA 3.11, as a post-process
// over a registry method's image (methods/post_process.h: base, bands, luma, timing).
//
// Source: T. Lottes, "FXAA" (NVIDIA whitepaper, 2009) and the FXAA 3.11 release notes (2011);
// written from their description, no code copied. Per pixel:
//   1. Local contrast: the range of luma over the pixel M and its 4 neighbours N, S, W, E. A
//      pixel whose range is below max(edge_threshold_min, edge_threshold * max luma) is left as
//      it is (the early exit: smooth areas and dark noise are not touched).
//   2. Edge direction: from the 3x3 luma, the horizontal and vertical second differences
//      |N + S - 2M| * 2 + |NW + SW - 2W| + |NE + SE - 2E| against the same across W/E; the
//      larger says the edge runs horizontally (luma changes from row to row) or vertically.
//      Of the two neighbours across the edge the one with the steeper gradient is the side the
//      edge lies on.
//   3. End-of-edge search: from the point half a pixel towards that side (on the edge), step
//      along the edge both ways, sampling luma there bilinearly (the mean of the two rows or
//      columns the edge separates), until the sample differs from the edge's local mean luma
//      by a quarter of the gradient or more (the edge ended or turned), with `steps` steps of
//      the sizes below each way.
//   4. Blend: with the pixel at distance d from the nearer end of a span of length L, the
//      pixel is moved 0.5 - d / L of a pixel towards the other side (a linear edge from end to
//      end), but only if the luma at that nearer end lies on the other side of the local mean
//      than the pixel (else the pixel is on the outside of the step: offset 0).
//   5. Sub-pixel aliasing: a pixel that differs strongly from the 3x3 low-pass of its
//      neighbourhood (weights 2 for N, S, W, E and 1 for the corners, over 12), relative to the
//      range, is moved by subpix * f(c)^2 with f(c) = (3 - 2c) c^2, c that difference over the
//      range; the offset used is the larger of this and step 4's.
//   The output is the image sampled at the pixel centre moved by the offset across the edge:
//   the linear blend (1 - offset) * M + offset * (the neighbour across the edge).
//
// Readings where the published form leaves a choice:
//   - The step sizes are the 12-step "extreme quality" preset 39 of FXAA 3.11 (1, 1, 1, 1, 1,
//     1.5, 2, 2, 2, 2, 4, 8 px); `steps` uses the first `steps` of them. The shipped default,
//     preset 12, takes 5 coarser steps (1, 1.5, 2, 4, 12): fewer texture fetches on a GPU, a
//     shorter exact reach here.
//   - Luma (`luma`): FXAA 3.11 reads luma from alpha, which the pass before it must fill; its
//     integration notes give that pass as the Rec. 601 luma dot(rgb, (0.299, 0.587, 0.114)) of
//     the non-linear (display-encoded) colour, and FXAA_GREEN_AS_LUMA (off by default) reads
//     the encoded green instead, which leaves edges between colours of equal green unseen.
//     luma=rgb (the default) is the first, luma=green the second, both on the sRGB-encoded
//     colour (space=srgb) or the linear one (space=linear). On a grey image both are the
//     (encoded) value, and a grey image takes the grey path: its image is the same under each.
//   - Colour: the luma above decides every step; the offset and the neighbour across the edge
//     it chooses are applied to each channel alike (out = M + offset * (N - M) per channel), as
//     the shader's one bilinear fetch of the colour at the moved position does.
//   - Samples outside the image clamp to its border (a GPU's clamp-to-edge address mode).
//
// Parameters: base (none), space (srgb), edge_threshold 0.166 and edge_threshold_min 0.0833
// (FXAA 3.11's quality defaults: "0.166 default", "0.0833 upper limit of the visible
// threshold"), subpix 0.75 (its default, "default amount of filtering"), steps 12, luma (rgb).
#include <algorithm>
#include <array>
#include <cmath>

#include "methods/post_process.h"

namespace aabench {
namespace {

constexpr std::array<float, 12> kStepPx = {1.0f, 1.0f, 1.0f, 1.0f, 1.0f, 1.5f,
                                           2.0f, 2.0f, 2.0f, 2.0f, 4.0f, 8.0f};
// The 3x3 low-pass of step 5: 2 x (N + S + W + E) + the 4 corners, over 12.
constexpr float kSubpixWeightSum = 12.0f;
// Step 3's "the edge ended": the end sample differs from the local mean by this share of the
// gradient across the edge (FXAA 3.11's gradientScaled).
constexpr float kEndGradientShare = 0.25f;

// What step 4 or 5 decides for a pixel: out = own + offset * (neighbour - own), the neighbour
// (dx, dy) away across the edge; (0, 0) for the early exit (the pixel as it is).
struct FxaaBlend {
    float offset = 0.0f;
    int dx = 0, dy = 0;
};

// Samples outside the image clamp to its border.
struct ClampedAt {
    int w, h;
    float operator()(const Image& img, int i, int j) const {
        return img.at(std::clamp(i, 0, w - 1), std::clamp(j, 0, h - 1));
    }
};

class FxaaMethod : public PostProcessMethod {
public:
    explicit FxaaMethod(const ParamValues& p)
        : PostProcessMethod(p.get_choice("base")),
          srgb_(p.get_choice("space") == "srgb"),
          edge_threshold_(static_cast<float>(p.get_real("edge_threshold"))),
          edge_threshold_min_(static_cast<float>(p.get_real("edge_threshold_min"))),
          subpix_(static_cast<float>(p.get_real("subpix"))),
          steps_(p.get_int("steps")),
          luma_weights_(p.get_choice("luma") == "green" ? kGreenLuma : kRec601Luma) {
        float sum = 0.0f;
        for (int k = 0; k < steps_; ++k) sum += kStepPx[k];
        // The search reads bilinearly one pixel past its farthest position; the 3x3 one row.
        reach_ = static_cast<int>(std::ceil(sum)) + 1;
    }

    int reach_rows(int height) const override { return std::min(reach_, height); }

    void pass_rows(const Image& in, Image& out, int row_lo, int row_hi) const override {
        thread_local Image luma;  // per-thread scratch, kept: a warm pass allocates nothing
        luma_rows(in, srgb_, luma, row_lo - reach_, row_hi + reach_);
        const int w = in.width, h = in.height;
        const ClampedAt at{w, h};
        for (int y = std::max(row_lo, 0); y < std::min(row_hi, h); ++y) {
            for (int x = 0; x < w; ++x) {
                out.at(x, y) = apply(in, at, blend_at(luma, at, x, y), x, y);
            }
        }
    }

    void pass_colour_rows(const ImagePlanes& in, ImagePlanes& out, int row_lo,
                          int row_hi) const override {
        thread_local Image luma;  // per-thread scratch, kept: a warm pass allocates nothing
        colour_luma_rows(in, srgb_, luma_weights_, luma, row_lo - reach_, row_hi + reach_);
        const int w = in.width(), h = in.height();
        const ClampedAt at{w, h};
        for (int y = std::max(row_lo, 0); y < std::min(row_hi, h); ++y) {
            for (int x = 0; x < w; ++x) {
                const FxaaBlend blend = blend_at(luma, at, x, y);  // once, for every channel
                for (int c = 0; c < in.channels(); ++c) {
                    out[c].at(x, y) = apply(in[c], at, blend, x, y);
                }
            }
        }
    }

private:
    template <class At>
    static float apply(const Image& values, const At& at, const FxaaBlend& blend, int x, int y) {
        const float own = values.at(x, y);
        if (blend.dx == 0 && blend.dy == 0) return own;  // the early exit: exactly the input
        const float other = at(values, x + blend.dx, y + blend.dy);
        return own + blend.offset * (other - own);
    }

    template <class At>
    FxaaBlend blend_at(const Image& luma, const At& at, int x, int y) const {
        const float m = at(luma, x, y), n = at(luma, x, y - 1), s = at(luma, x, y + 1);
        const float wl = at(luma, x - 1, y), e = at(luma, x + 1, y);
        const float max_luma = std::max({m, n, s, wl, e});
        const float range = max_luma - std::min({m, n, s, wl, e});
        // 1. The early exit: exactly the input where the local contrast is low.
        if (range < std::max(edge_threshold_min_, max_luma * edge_threshold_)) return {};
        const float nw = at(luma, x - 1, y - 1), ne = at(luma, x + 1, y - 1);
        const float sw = at(luma, x - 1, y + 1), se = at(luma, x + 1, y + 1);
        // 2. Direction: a horizontal edge has luma changing from row to row.
        const float edge_horz = 2.0f * std::abs(n + s - 2.0f * m) +
                                std::abs(nw + sw - 2.0f * wl) + std::abs(ne + se - 2.0f * e);
        const float edge_vert = 2.0f * std::abs(wl + e - 2.0f * m) +
                                std::abs(nw + ne - 2.0f * n) + std::abs(sw + se - 2.0f * s);
        const bool horizontal = edge_horz >= edge_vert;
        const float before = horizontal ? n : wl, after = horizontal ? s : e;
        const bool towards_before = std::abs(before - m) >= std::abs(after - m);
        const int side = towards_before ? -1 : 1;  // across the edge: -1 up / left, +1 down / right
        const float across = towards_before ? before : after;
        const float gradient = std::abs(across - m);
        const float local_mean = 0.5f * (m + across);

        // 5. Sub-pixel aliasing (computed first: it is independent of the search).
        const float low_pass = (2.0f * (n + s + wl + e) + nw + ne + sw + se) / kSubpixWeightSum;
        const float c = std::clamp(std::abs(low_pass - m) / range, 0.0f, 1.0f);
        const float f = (3.0f - 2.0f * c) * c * c;
        const float subpix_offset = f * f * subpix_;

        // 3. End-of-edge search, on the line half a pixel towards the side.
        const auto edge_luma = [&](float along) {
            // Bilinear: `along` on the edge's axis, exactly between the two rows (columns).
            const int a0 = static_cast<int>(std::floor(along));
            const float t = along - static_cast<float>(a0);
            float sum = 0.0f;
            for (int k = 0; k < 2; ++k) {
                const int perp = (horizontal ? y : x) + (k == 0 ? 0 : side);
                const float v0 = horizontal ? at(luma, a0, perp) : at(luma, perp, a0);
                const float v1 = horizontal ? at(luma, a0 + 1, perp) : at(luma, perp, a0 + 1);
                sum += v0 + t * (v1 - v0);
            }
            return 0.5f * sum - local_mean;
        };
        const float origin = static_cast<float>(horizontal ? x : y);
        const float end_threshold = kEndGradientShare * gradient;
        float pos_n = origin - kStepPx[0], pos_p = origin + kStepPx[0];
        float end_n = edge_luma(pos_n), end_p = edge_luma(pos_p);
        bool done_n = std::abs(end_n) >= end_threshold, done_p = std::abs(end_p) >= end_threshold;
        for (int k = 1; k < steps_ && !(done_n && done_p); ++k) {
            if (!done_n) {
                pos_n -= kStepPx[k];
                end_n = edge_luma(pos_n);
                done_n = std::abs(end_n) >= end_threshold;
            }
            if (!done_p) {
                pos_p += kStepPx[k];
                end_p = edge_luma(pos_p);
                done_p = std::abs(end_p) >= end_threshold;
            }
        }
        // 4. The offset from the nearer end.
        const float dist_n = origin - pos_n, dist_p = pos_p - origin;
        const bool nearer_n = dist_n < dist_p;
        const float dist = nearer_n ? dist_n : dist_p;
        const bool m_below = m - local_mean < 0.0f;
        const bool good_span = ((nearer_n ? end_n : end_p) < 0.0f) != m_below;
        const float span_offset = good_span ? 0.5f - dist / (dist_n + dist_p) : 0.0f;
        const float offset = std::max(span_offset, subpix_offset);
        return horizontal ? FxaaBlend{offset, 0, side} : FxaaBlend{offset, side, 0};
    }

    bool srgb_;
    float edge_threshold_, edge_threshold_min_, subpix_;
    int steps_;
    LumaWeights luma_weights_;
    int reach_ = 0;
};

}  // namespace

MethodTraits fxaa_traits() {
    // The pass's estimate besides the base: its pass_ms on the star at 128^2 (0.84 ms, on a
    // loaded machine), per pixel; a luma image (4 bytes per pixel) is its scratch.
    constexpr double kPassMsPerMpixel = 50.0, kLumaBytesPerPixel = 4.0;
    return post_process_traits(kPassMsPerMpixel, kLumaBytesPerPixel);
}

MethodInfo fxaa_method() {
    return {"fxaa",
            "FXAA 3.11 quality (Lottes 2009/2011): luma local-contrast test, edge direction, "
            "end-of-edge search, sub-pixel blend, as a pass over the base method's image",
            {post_process_base_param(),
             post_process_space_param(),
             {"edge_threshold", ParamKind::kReal, 0.166, 0.0, 1.0, {},
              "local contrast needed, relative to the brightest luma around; FXAA 3.11's "
              "quality default (0.333 too little, 0.063 overkill)"},
             {"edge_threshold_min", ParamKind::kReal, 0.0833, 0.0, 1.0, {},
              "local contrast needed in absolute luma (dark areas); FXAA 3.11's default"},
             {"subpix", ParamKind::kReal, 0.75, 0.0, 1.0, {},
              "amount of sub-pixel aliasing removal (0 off, 1 softest); FXAA 3.11's default"},
             {"steps", ParamKind::kInt, 12, 1, 12, {},
              "end-of-edge search steps each way, sizes of the 12-step preset 39 "
              "(1,1,1,1,1,1.5,2,2,2,2,4,8 px)"},
             {"luma", ParamKind::kChoice, 0, 0, 0, {"rgb", "green"},
              "colour scenes: rgb, the Rec. 601 luma of the encoded colour FXAA 3.11's pre-pass "
              "stores in alpha (its default); green, FXAA_GREEN_AS_LUMA's encoded green. The "
              "same image on grey scenes"}},
            [](const ParamValues& p) { return std::make_unique<FxaaMethod>(p); }};
}

}  // namespace aabench
