// The plumbing every post-process method shares (fxaa, mlaa, ...): a method that reads an
// image already rendered by another method of the registry (its `base`, `none` by default) and
// writes the antialiased image. Post-process antialiasing as renderers ship it works on the
// aliased frame alone; here the frame is any registry method's image, so the pass can be scored
// on point samples (base=none, what a renderer hands it) or on an already antialiased image.
//
// A post-process row (MethodTraits::post_process) is a PostProcessMethod built by
// make_post_process: its parameters are its pass's plus `base` (post_process_base_param), and
// its render is the base method's render followed by the pass over the base image. The harness
// times the whole (base + pass, what tables and plots show) and, through pass(), the pass alone
// on a base image rendered once (compare's time_pass_ms column).
//
// Bands (Method::render_rows on a row range, render_in_bands): the pass needs neighbourhoods,
// so a band renders the base rows it reads, its rows widened by the pass's reach_rows() above
// and below (clamped to the image), into per-thread scratch, then runs the pass on its own rows
// only. A pass whose output row depends on base rows at most reach_rows() away gives the same
// image in bands as in one piece; a pass that needs whole columns (mlaa's runs along an edge
// are unbounded) says so with reach_rows() = height, and each band then renders the whole base
// (bands cost the base once per band: compare's timed renders are one band).
//
// Luma: FXAA and SMAA take their thresholds on the luma of the sRGB-encoded value, as they
// ship (the frame they see is the display's encoded one); `space=linear` takes them on the
// linear value. On a grey image luma is the (encoded) value itself. The blend itself is done on
// the linear values (a GPU samples an sRGB texture decoded before filtering), so a blend weight
// is an area weight on light.
//
// Colour (Scene::channels == 3; docs/post-process.md, "Colour"): the base draws its planes
// (its own colour path, in the same bands with the same halo), then the pass runs once on the
// colour image (pass_colour_rows): it finds its edges from the colour as the published pass
// does (each pass's file says how: a luma of the encoded colour, or a per-channel test) and
// applies the same blend weights and offsets to every channel. A grey image goes through
// pass_rows unchanged, and a colour image whose every pixel is grey gives each plane exactly
// the grey image: a luma here is written G + wr (R - G) + wb (B - G), equal to the weighted sum
// when the weights sum to 1 and exactly G when R = G = B (colour_luma_rows), and a per-channel
// difference's maximum over equal channels is the one difference.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "methods/method.h"

namespace aabench {

// The `base` parameter of every post-process row: the registry methods a pass may read, at
// their default parameters (a spec cannot nest another spec's `:k=v,...`). Post-process and
// circle-only methods are not bases (no chaining; circle methods refuse most scenes).
ParamSpec post_process_base_param();
// The `space` parameter: `srgb` (thresholds on the sRGB-encoded value, default) or `linear`.
ParamSpec post_process_space_param();

// The sRGB transfer function (IEC 61966-2-1), clamped to [0, 1]: the luma the thresholds see.
float srgb_encode(float linear);

// Per-pixel luma of `in` into `luma` (same size; resized without allocating when warm): the
// sRGB-encoded value when `srgb`, the value itself otherwise. Rows [row_lo, row_hi) only.
void luma_rows(const Image& in, bool srgb, Image& luma, int row_lo, int row_hi);

// The weights of a luma of R, G, B, summing to 1.
struct LumaWeights {
    float r, g, b;
};
// Rec. 709 (ITU-R BT.709: SMAA's luma edge detection) and Rec. 601 (ITU-R BT.601: the luma
// FXAA 3.11's pre-pass stores in alpha), and green alone (FXAA_GREEN_AS_LUMA).
inline constexpr LumaWeights kRec709Luma{0.2126f, 0.7152f, 0.0722f};
inline constexpr LumaWeights kRec601Luma{0.299f, 0.587f, 0.114f};
inline constexpr LumaWeights kGreenLuma{0.0f, 1.0f, 0.0f};

// Per-pixel luma of the three planes of `in` into `luma`, rows [row_lo, row_hi): the weights on
// the sRGB-encoded channels when `srgb`, on the linear ones otherwise, summed as
// G + r (R - G) + b (B - G) (see above: exactly G on a grey pixel). Resized as luma_rows.
void colour_luma_rows(const ImagePlanes& in, bool srgb, LumaWeights weights, Image& luma,
                      int row_lo, int row_hi);

// Every plane of `in`, sRGB-encoded when `srgb` (copied otherwise), into `encoded` (given the
// planes and size of `in` without allocating when warm), rows [row_lo, row_hi): what a pass
// that compares channels one by one reads.
void encoded_planes_rows(const ImagePlanes& in, bool srgb, ImagePlanes& encoded, int row_lo,
                         int row_hi);

// Gives `planes` `channels` planes of width x height, keeping their buffers: a warm call on an
// image no larger allocates nothing. Pixel values are left as they were.
void fit_planes(ImagePlanes& planes, int channels, int width, int height);

class PostProcessMethod : public Method {
public:
    explicit PostProcessMethod(const std::string& base_id);
    // The method whose image the pass reads.
    const Method& base() const { return *base_; }
    const std::string& base_spec() const { return base_spec_; }
    // The pass alone: rows [row_lo, row_hi) of `out` from `in`, the base image of the same
    // size whose rows within reach_rows() of the range are rendered. No allocation once warm
    // (per-thread scratch); safe from several threads on disjoint row ranges.
    virtual void pass_rows(const Image& in, Image& out, int row_lo, int row_hi) const = 0;
    void pass(const Image& in, Image& out) const { pass_rows(in, out, 0, in.height); }
    // The pass alone on a colour image (three planes, `out` the same): edges found once from the
    // colour, every channel blended alike. The same contract as pass_rows.
    virtual void pass_colour_rows(const ImagePlanes& in, ImagePlanes& out, int row_lo,
                                  int row_hi) const = 0;
    // Either image: one plane through pass_rows, three through pass_colour_rows.
    void pass(const ImagePlanes& in, ImagePlanes& out) const;
    // How many rows above and below an output row the pass reads (height: every row).
    virtual int reach_rows(int height) const = 0;
    // The base's reason, when the base cannot draw the scene.
    std::string not_applicable(const Scene& scene) const override;
    // The base's: the pass reads the image of the polygon the base fills.
    std::optional<Scene> own_flattening(const Scene& scene) const override;

protected:
    void draw_rows(const Scene& scene, Image& out, int row_lo, int row_hi) const final;
    // The base draws the pieces as it would draw them itself (exact sums dense ones directly).
    void draw_disjoint_piece_rows(const Scene& pieces, Image& out, int row_lo,
                                  int row_hi) const final;
    // A colour scene: the base's planes within reach of the band, then pass_colour_rows.
    void draw_colour_rows(const SceneInput& in, ImagePlanes& out, int row_lo,
                          int row_hi) const final;

private:
    void draw_over_base(const SceneInput& in, Image& out, int row_lo, int row_hi) const;
    std::string base_spec_;
    std::unique_ptr<Method> base_;
};

// A post-process row's traits: box filter, post_process = true, the 2-D input (own_visibility
// false: a 3-D scene arrives as its exact visible pieces, which every base draws), and the
// estimates of the base's row plus the pass's (`pass_ms_per_mpixel`, `pass_bytes_per_pixel`
// of scratch besides the base image the plumbing keeps). The hard-case properties are those
// of a pass that moves values only next to discontinuities of the base image.
MethodTraits post_process_traits(double pass_ms_per_mpixel, double pass_bytes_per_pixel);

}  // namespace aabench
