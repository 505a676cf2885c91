// The post-process plumbing (methods/post_process.h).
#include "methods/post_process.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace aabench {
namespace {

// The bases a pass may read: every spatial method of the registry that draws any scene, at its
// defaults (the registry's order).
const std::vector<std::string> kBaseIds = {
    "none", "exact", "box-multiscan", "gauss-multiscan", "ssaa",
    "nishita-d", "fast-edge", "cairo", "agg", "exact-8bit"};

// The base's registry row and its default parameters, for the estimates.
const MethodInfo& base_row(const ParamValues& params) {
    const std::string& id = params.get_choice("base");
    for (const MethodInfo& info : method_registry()) {
        if (info.id == id) return info;
    }
    throw std::logic_error("post-process base '" + id + "' is not in the registry");
}

ParamValues base_defaults(const MethodInfo& row) {
    return resolve_params("method '" + row.id + "'", row.params, {});
}

}  // namespace

ParamSpec post_process_base_param() {
    return {"base", ParamKind::kChoice, 0, 0, 0, kBaseIds,
            "the method whose image the pass reads, at its defaults; none: point samples, the "
            "aliased frame a renderer hands a post-process pass"};
}

ParamSpec post_process_space_param() {
    return {"space", ParamKind::kChoice, 0, 0, 0, {"srgb", "linear"},
            "srgb: thresholds on the luma of the sRGB-encoded value, as the pass ships (it sees "
            "the display's frame); linear: on the linear value"};
}

float srgb_encode(float linear) {
    const float v = std::clamp(linear, 0.0f, 1.0f);
    return v <= 0.0031308f ? 12.92f * v : 1.055f * std::pow(v, 1.0f / 2.4f) - 0.055f;
}

void luma_rows(const Image& in, bool srgb, Image& luma, int row_lo, int row_hi) {
    if (luma.width != in.width || luma.height != in.height) {
        luma.width = in.width;
        luma.height = in.height;
        luma.data.resize(in.data.size());  // grows only when the size grows: warm, no allocation
    }
    for (int j = std::max(row_lo, 0); j < std::min(row_hi, in.height); ++j) {
        const float* src = in.row(j);
        float* dst = luma.row(j);
        for (int i = 0; i < in.width; ++i) dst[i] = srgb ? srgb_encode(src[i]) : src[i];
    }
}

void fit_planes(ImagePlanes& planes, int channels, int width, int height) {
    planes.planes.resize(static_cast<std::size_t>(channels));
    for (Image& plane : planes.planes) {
        plane.width = width;
        plane.height = height;
        // Grows only when the size grows: warm, no allocation.
        plane.data.resize(static_cast<std::size_t>(width) * height);
    }
}

void colour_luma_rows(const ImagePlanes& in, bool srgb, LumaWeights weights, Image& luma,
                      int row_lo, int row_hi) {
    const int w = in.width(), h = in.height();
    if (luma.width != w || luma.height != h) {
        luma.width = w;
        luma.height = h;
        luma.data.resize(static_cast<std::size_t>(w) * h);
    }
    for (int j = std::max(row_lo, 0); j < std::min(row_hi, h); ++j) {
        const float *r = in[0].row(j), *g = in[1].row(j), *b = in[2].row(j);
        float* dst = luma.row(j);
        for (int i = 0; i < w; ++i) {
            const float er = srgb ? srgb_encode(r[i]) : r[i];
            const float eg = srgb ? srgb_encode(g[i]) : g[i];
            const float eb = srgb ? srgb_encode(b[i]) : b[i];
            // The weighted sum about G: R - G = B - G = 0 on a grey pixel, so its luma is its
            // encoded value bit for bit (the grey path's), whatever the weights' rounding.
            dst[i] = eg + weights.r * (er - eg) + weights.b * (eb - eg);
        }
    }
}

void encoded_planes_rows(const ImagePlanes& in, bool srgb, ImagePlanes& encoded, int row_lo,
                         int row_hi) {
    fit_planes(encoded, in.channels(), in.width(), in.height());
    for (int c = 0; c < in.channels(); ++c) {
        for (int j = std::max(row_lo, 0); j < std::min(row_hi, in.height()); ++j) {
            const float* src = in[c].row(j);
            float* dst = encoded[c].row(j);
            for (int i = 0; i < in.width(); ++i) dst[i] = srgb ? srgb_encode(src[i]) : src[i];
        }
    }
}

PostProcessMethod::PostProcessMethod(const std::string& base_id)
    : base_spec_(base_id), base_(make_method(base_id).method) {}

std::string PostProcessMethod::not_applicable(const Scene& scene) const {
    return base_->not_applicable(scene);
}

void PostProcessMethod::pass(const ImagePlanes& in, ImagePlanes& out) const {
    if (in.channels() == 1) {
        pass_rows(in[0], out[0], 0, in.height());
    } else {
        pass_colour_rows(in, out, 0, in.height());
    }
}

std::optional<Scene> PostProcessMethod::own_flattening(const Scene& scene) const {
    return base_->own_flattening(scene);
}

void PostProcessMethod::draw_rows(const Scene& scene, Image& out, int row_lo, int row_hi) const {
    draw_over_base(scene, out, row_lo, row_hi);
}

void PostProcessMethod::draw_disjoint_piece_rows(const Scene& pieces, Image& out, int row_lo,
                                                 int row_hi) const {
    draw_over_base(SceneInput::disjoint_pieces(pieces), out, row_lo, row_hi);
}

void PostProcessMethod::draw_over_base(const SceneInput& in, Image& out, int row_lo,
                                       int row_hi) const {
    const Scene& scene = in.scene();
    // Per-thread scratch kept between renders (a warm render allocates nothing): the base image.
    // Only the rows within reach of this band are rendered; the pass reads no others.
    thread_local Image base_image;
    if (base_image.width != scene.width || base_image.height != scene.height) {
        base_image.width = scene.width;
        base_image.height = scene.height;
        base_image.data.resize(static_cast<std::size_t>(scene.width) * scene.height);
    }
    const int reach = reach_rows(scene.height);
    base_->render_rows(in, base_image, row_lo - reach, row_hi + reach);
    pass_rows(base_image, out, row_lo, row_hi);
}

void PostProcessMethod::draw_colour_rows(const SceneInput& in, ImagePlanes& out, int row_lo,
                                         int row_hi) const {
    // A pass finds its edges from the colour and blends every channel alike; drawn channel by
    // channel (the default) it would find edges in each channel apart, which no renderer ships.
    // The base's planes: per-thread scratch kept between renders, the band's rows and the
    // pass's reach around them, as the grey path (draw_over_base).
    const Scene& scene = in.scene();
    thread_local ImagePlanes base_planes;
    fit_planes(base_planes, scene.channels, scene.width, scene.height);
    const int reach = reach_rows(scene.height);
    base_->render_rows(in, base_planes, row_lo - reach, row_hi + reach);
    pass_colour_rows(base_planes, out, row_lo, row_hi);
}

MethodTraits post_process_traits(double pass_ms_per_mpixel, double pass_bytes_per_pixel) {
    MethodTraits t;
    t.post_process = true;
    t.curves = "through its base method (the pass reads its image)";
    t.colour =
        "the base's planes, then one pass: edges found from the colour, every channel blended "
        "with the same weights";
    t.working_bytes = [pass_bytes_per_pixel](const ParamValues& p, const SceneSize& s) {
        const MethodInfo& base = base_row(p);
        // The base's own working memory, its image (float32) and the pass's scratch.
        return base.traits->working_bytes(base_defaults(base), s) +
               (4.0 + pass_bytes_per_pixel) * s.pixels();
    };
    t.time_ms = [pass_ms_per_mpixel](const ParamValues& p, const SceneSize& s) {
        const MethodInfo& base = base_row(p);
        return base.traits->time_ms(base_defaults(base), s) +
               pass_ms_per_mpixel * s.pixels() * 1e-6;
    };
    t.hard_cases.properties = {
        {Invariant::kContinuity, CaseSet::kAll, DocumentedBound::kLocalChanges,
         "a pass over point samples: a sample on an edge flips, and the pass moves values only "
         "next to discontinuities"},
        {Invariant::kTranslation, CaseSet::kAll, DocumentedBound::kLocalChanges,
         "2^20 + x rounds x by up to 2^-33 px: a sample exactly on an edge flips"},
        {Invariant::kArea, CaseSet::kAll, DocumentedBound::kAnyArea,
         "blends guessed from the aliased image's shapes, not from area: only locality holds"},
    };
    return t;
}

}  // namespace aabench
