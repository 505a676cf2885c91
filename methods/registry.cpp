// The one registry table: every method of the suite is one row here and one file beside it.
#include <algorithm>
#include <map>
#include <memory>
#include <mutex>
#include <stdexcept>

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>

#include "methods/method.h"

namespace aabench {

// Each method file defines its row and its row's traits (nothing else needs to know them).
MethodInfo none_method();
MethodTraits none_traits();
MethodInfo exact_method();
MethodTraits exact_traits();
MethodInfo box_multiscan_method();
MethodTraits box_multiscan_traits();
MethodInfo gauss_multiscan_method();
MethodTraits gauss_multiscan_traits();
MethodInfo ssaa_method();
MethodTraits ssaa_traits();
MethodInfo taa_method();
MethodTraits taa_traits();
MethodInfo nishita_d_method();
MethodTraits nishita_d_traits();
MethodInfo fast_edge_method();
MethodTraits fast_edge_traits();
MethodInfo cairo_method();
MethodTraits cairo_traits();
MethodInfo agg_method();
MethodTraits agg_traits();
MethodInfo freetype_method();
MethodTraits freetype_traits();
MethodInfo stb_truetype_method();
MethodTraits stb_truetype_traits();
MethodInfo exact_8bit_method();
MethodTraits exact_8bit_traits();
MethodInfo aa_circle_method();
MethodTraits aa_circle_traits();
MethodInfo wu_circle_method();
MethodTraits wu_circle_traits();
MethodInfo midpoint_circle_method();
MethodTraits midpoint_circle_traits();
MethodInfo gl_msaa_method();
MethodTraits gl_msaa_traits();
MethodInfo fxaa_method();
MethodTraits fxaa_traits();
MethodInfo smaa_method();
MethodTraits smaa_traits();
#ifdef AABENCH_HAVE_BLEND2D
MethodInfo blend2d_method();  // the optional peer (methods/blend2d.cpp, docs/peers.md)
MethodTraits blend2d_traits();
#endif
MethodInfo mlaa_method();
MethodTraits mlaa_traits();

namespace {

std::vector<MethodInfo>& mutable_registry() {
    static std::vector<MethodInfo> registry = {
        with_traits(none_method(), none_traits()),
        with_traits(exact_method(), exact_traits()),
        with_traits(box_multiscan_method(), box_multiscan_traits()),
        with_traits(gauss_multiscan_method(), gauss_multiscan_traits()),
        with_traits(ssaa_method(), ssaa_traits()),
        with_traits(taa_method(), taa_traits()),
        with_traits(nishita_d_method(), nishita_d_traits()),
        with_traits(fast_edge_method(), fast_edge_traits()),
        with_traits(cairo_method(), cairo_traits()),
        with_traits(agg_method(), agg_traits()),
        with_traits(freetype_method(), freetype_traits()),
        with_traits(stb_truetype_method(), stb_truetype_traits()),
        with_traits(exact_8bit_method(), exact_8bit_traits()),
        with_traits(gl_msaa_method(), gl_msaa_traits()),
        with_traits(aa_circle_method(), aa_circle_traits()),
        with_traits(wu_circle_method(), wu_circle_traits()),
        with_traits(midpoint_circle_method(), midpoint_circle_traits()),
        // Post-process passes over another row's image (methods/post_process.h).
        with_traits(mlaa_method(), mlaa_traits()),
        with_traits(fxaa_method(), fxaa_traits()),
        with_traits(smaa_method(), smaa_traits()),
#ifdef AABENCH_HAVE_BLEND2D
        with_traits(blend2d_method(), blend2d_traits()),
#endif
    };
    return registry;
}

}  // namespace

const std::vector<MethodInfo>& method_registry() { return mutable_registry(); }

namespace {

// The estimates have no neutral default (a guess would be silently wrong): a row without them
// is a programming error, caught when the registry is built.
void check_complete(const std::string& id, const MethodTraits& traits) {
    if (!traits.working_bytes || !traits.time_ms || !traits.filter || !traits.hard_cases.figures ||
        !traits.hard_cases.heavy) {
        throw std::logic_error("method '" + id + "': its row's traits are incomplete");
    }
}

}  // namespace

MethodInfo with_traits(MethodInfo info, MethodTraits traits) {
    check_complete(info.id, traits);
    info.traits = std::make_shared<const MethodTraits>(std::move(traits));
    return info;
}

// Incomplete traits are refused here as by with_traits (std::logic_error).
ScopedMethodRow::ScopedMethodRow(MethodInfo row) : id_(row.id) {
    check_complete(row.id, *row.traits);
    for (const MethodInfo& info : method_registry()) {
        if (info.id == id_) throw InputError(fmt::format("method '{}' is registered already", id_));
    }
    mutable_registry().push_back(std::move(row));
}

ScopedMethodRow::~ScopedMethodRow() {
    std::vector<MethodInfo>& rows = mutable_registry();
    std::erase_if(rows, [this](const MethodInfo& info) { return info.id == id_; });
}

const MethodTraits& Method::traits() const {
    // A Method built by make_method has its row's; one built otherwise the defaults.
    static const MethodTraits kDefaults;
    return traits_ ? *traits_ : kDefaults;
}

MethodInstance make_method(const std::string& spec_text) {
    const SpecString spec = parse_spec_string(spec_text);
    for (const MethodInfo& info : method_registry()) {
        if (info.id != spec.id) continue;
        MethodInstance instance;
        instance.id = info.id;
        instance.params =
            resolve_params(fmt::format("method '{}'", info.id), info.params, spec.assignments);
        const std::string params = instance.params.to_string();
        instance.spec = params.empty() ? info.id : info.id + ":" + params;
        instance.method = info.factory(instance.params);
        instance.method->traits_ = info.traits;
        instance.method->filter_ = info.traits->filter(instance.params);
        return instance;
    }
    std::vector<std::string> ids;
    for (const MethodInfo& info : method_registry()) ids.push_back(info.id);
    throw InputError(fmt::format("unknown method '{}'{} (valid: {})", spec.id,
                                 did_you_mean(spec.id, ids), fmt::join(ids, ", ")));
}

Image render_scene(const Method& method, const SceneInput& in) {
    Image out(in.scene().width, in.scene().height);
    method.render(in, out);
    return out;
}

void Method::render_rows(const SceneInput& in, Image& out, int row_lo, int row_hi) const {
    const Scene& scene = in.scene();
    require_window_frame(scene, "render");
    row_lo = std::max(row_lo, 0);
    row_hi = std::min(row_hi, scene.height);
    if (row_lo >= row_hi) return;
    if (in.is_disjoint_pieces()) {
        draw_disjoint_piece_rows(scene, out, row_lo, row_hi);
    } else {
        draw_rows(scene, out, row_lo, row_hi);
    }
}

ImagePlanes render_planes(const Method& method, const SceneInput& in) {
    ImagePlanes out(in.scene().channels, in.scene().width, in.scene().height);
    method.render(in, out);
    return out;
}

void Method::render_rows(const SceneInput& in, ImagePlanes& out, int row_lo, int row_hi) const {
    const Scene& scene = in.scene();
    if (out.channels() != scene.channels || out.width() != scene.width ||
        out.height() != scene.height) {
        throw std::logic_error("render: the planes do not match the scene's channels and size");
    }
    if (scene.channels == 1) {
        render_rows(in, out[0], row_lo, row_hi);
        return;
    }
    require_window_frame(scene, "render");
    row_lo = std::max(row_lo, 0);
    row_hi = std::min(row_hi, scene.height);
    if (row_lo >= row_hi) return;
    draw_colour_rows(in, out, row_lo, row_hi);
}

void Method::draw_colour_rows(const SceneInput& in, ImagePlanes& out, int row_lo,
                              int row_hi) const {
    for (int c = 0; c < out.channels(); ++c) {
        std::optional<Scene> made;
        render_rows(channel_input(in, c, made), out[c], row_lo, row_hi);
    }
}

namespace {

// Rows [0, height) in `bands` bands on `threads` threads (TBB); `band(lo, hi)` from several
// threads at once on disjoint ranges.
template <class Band>
void for_bands(int height, int bands, int threads, const Band& band) {
    // One arena per thread count and calling thread, kept: making an arena costs about as
    // much as a small render's band (tens of microseconds), paid on every render before.
    thread_local std::map<int, std::unique_ptr<tbb::task_arena>> arenas;
    std::unique_ptr<tbb::task_arena>& kept = arenas[std::max(threads, 1)];
    if (!kept) kept = std::make_unique<tbb::task_arena>(std::max(threads, 1));
    tbb::task_arena& arena = *kept;
    arena.execute([&] {
        tbb::parallel_for(0, bands, [&](int b) {
            const int lo = static_cast<int>(static_cast<long long>(height) * b / bands);
            const int hi = static_cast<int>(static_cast<long long>(height) * (b + 1) / bands);
            band(lo, hi);
        });
    });
}

template <class Out>
void render_in_bands_of(const Method& method, const SceneInput& in, Out& out, int threads) {
    const Scene& scene = in.scene();
    if (threads <= 1 || scene.height < 2) {
        method.render(in, out);
        return;
    }
    for_bands(scene.height, std::min(threads, scene.height), threads,
              [&](int lo, int hi) { method.render_rows(in, out, lo, hi); });
}

template <class Out>
void render_with_progress_of(const Method& method, const SceneInput& in, Out& out, int threads,
                             int bands, const std::function<void(int, int)>& progress) {
    const Scene& scene = in.scene();
    bands = std::clamp(std::max(bands, threads), 1, std::max(scene.height, 1));
    std::mutex report;
    int rows_done = 0;
    for_bands(scene.height, bands, threads, [&](int lo, int hi) {
        method.render_rows(in, out, lo, hi);
        const std::lock_guard lock(report);
        rows_done += hi - lo;
        progress(rows_done, scene.height);
    });
}

}  // namespace

void render_in_bands(const Method& method, const SceneInput& in, Image& out, int threads) {
    render_in_bands_of(method, in, out, threads);
}
void render_in_bands(const Method& method, const SceneInput& in, ImagePlanes& out, int threads) {
    render_in_bands_of(method, in, out, threads);
}

void render_with_progress(const Method& method, const SceneInput& in, Image& out, int threads,
                          int bands, const std::function<void(int, int)>& progress) {
    render_with_progress_of(method, in, out, threads, bands, progress);
}
void render_with_progress(const Method& method, const SceneInput& in, ImagePlanes& out,
                          int threads, int bands, const std::function<void(int, int)>& progress) {
    render_with_progress_of(method, in, out, threads, bands, progress);
}

}  // namespace aabench
