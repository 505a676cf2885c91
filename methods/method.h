// The one interface every antialiasing method implements, and the one registry table.
//
// A method is a small plain class built by its registry row's factory from resolved
// parameters. render() turns a Scene into a float32 linear Image of the scene's size; it
// does no I/O. The output buffer is allocated by the caller (so timing excludes allocation);
// render() overwrites every pixel.
//
// The scene is in its window frame (no window origin: is_window_frame, patterns/scene/scene.h):
// the precondition of every entry below, as of the references and the metrics. The prepared
// frame (harness/world/frame.h) is what takes a scene's origin out, once; render_rows checks
// the precondition (require_window_frame) and never converts.
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "methods/method_traits.h"
#include "methods/motion.h"
#include "methods/scan/kernel/filter.h"
#include "methods/scan/kernel/image.h"
#include "patterns/scene/params.h"
#include "patterns/scene/scene.h"
#include "patterns/scene/scene_input.h"

namespace aabench {

struct MethodInstance;
MethodInstance make_method(const std::string& spec);

class Method {
public:
    virtual ~Method() = default;
    // `out` has the scene's size; every pixel is written. render_rows over all rows.
    // `in` is a Scene, or a prepared frame's visible pieces (patterns/scene/scene_input.h).
    void render(const SceneInput& in, Image& out) const {
        render_rows(in, out, 0, in.scene().height);
    }
    // Rows [row_lo, row_hi) of what render() writes (clamped to the image), other rows
    // untouched; safe to call from several threads at once on disjoint row ranges
    // (render_in_bands). A band is a row range
    // handed to the method's engine, never a copy of the scene. A post-process method
    // (methods/post_process.h) renders its base's rows within its pass's reach of the band
    // (all rows for a pass that needs whole columns) and runs the pass on the band's rows: the
    // same image as render(), the base's cost paid again for each band's halo.
    void render_rows(const SceneInput& in, Image& out, int row_lo, int row_hi) const;
    // Colour (Scene::channels == 3): every plane of the image, `out` holding the scene's
    // channels as planes of its size; a grey scene's one plane is render() above. (A grey
    // render() of a colour scene draws its shapes' luminances, patterns/scene/scene.h: its
    // luminance image for every method linear in the values, all but exact-8bit, which rounds
    // each value to 8 bits.) The same band contract as render_rows.
    void render(const SceneInput& in, ImagePlanes& out) const {
        render_rows(in, out, 0, in.scene().height);
    }
    void render_rows(const SceneInput& in, ImagePlanes& out, int row_lo, int row_hi) const;
    // The row's traits (methods/method_traits.h) and the filter for this method's parameters,
    // set by make_method: code holding only a Method asks them here.
    const MethodTraits& traits() const;
    const Filter& filter() const { return filter_; }
    // Shorthands of the two capabilities the prepared frame asks (MethodTraits says what they
    // mean): own_visibility, a method that removes hidden surfaces itself and so draws the
    // ScreenScene of a world (harness/world/frame.h, input_for); affine_values, a method that
    // draws the depth image the way it draws values.
    bool own_visibility() const { return traits().own_visibility; }
    bool affine_values() const { return traits().affine_values; }
    // Empty when the method can draw the scene; otherwise the reason it cannot (aa-circle draws
    // only unit-width rings on the pixel grid). A capability, not a fallback: compare shows
    // "n/a" with the reason instead of errors, and render() of such a scene writes NaN.
    virtual std::string not_applicable(const Scene&) const { return {}; }
    // The polygon the method fills where it flattens the scene's Bezier curves itself, at its
    // own tolerance (fast-edge, gl-msaa: patterns/scene/bezier.h's flattening; cairo, agg: the
    // vertices their library makes): the scene with every curved shape replaced by it.
    // nullopt for a method that does not flatten (exact: analytic; the others draw the
    // scene's own fine flattening) or a scene without curves. What `flatten_bias` measures
    // against (harness/measure/metric_registry.cpp).
    virtual std::optional<Scene> own_flattening(const Scene&) const { return std::nullopt; }

    // Sequences (methods/motion.h). A temporal method (traits().temporal) allocates its
    // history for frames of width x height here; a spatial method keeps nothing (nullptr).
    virtual std::unique_ptr<TemporalState> begin(int /*width*/, int /*height*/) const {
        return nullptr;
    }
    // Frame `frame_index` (0, 1, ...) of the sequence begun with `state` (nullptr for a
    // spatial method): draws `scene` (the frame's input_for(method)) into `out`, using
    // `motion` (the frame's motion vectors) to find the previous frames' surfaces. A spatial
    // method's is render(scene, out).
    virtual void render_frame(const SceneInput& in, const MotionVectors& /*motion*/,
                              int /*frame_index*/, TemporalState* /*state*/, Image& out) const {
        render(in, out);
    }
    // The same for every plane (`out` holding the scene's channels, as render(in, ImagePlanes&)):
    // a grey scene's one plane is the frame above; a spatial method's colour frame is its
    // render(in, out). A temporal method that keeps a colour history overrides it (taa).
    virtual void render_frame(const SceneInput& in, const MotionVectors& motion, int frame_index,
                              TemporalState* state, ImagePlanes& out) const {
        if (out.channels() == 1) {
            render_frame(in, motion, frame_index, state, out[0]);
        } else {
            render(in, out);
        }
    }

protected:
    // What a method implements: rows [row_lo, row_hi) of the image of `scene`, with
    // 0 <= row_lo < row_hi <= scene.height, every pixel of those rows written and no other.
    // `scene` has no window origin (render_rows checked it). Called from several threads at
    // once on disjoint row ranges: per-thread scratch only.
    virtual void draw_rows(const Scene& scene, Image& out, int row_lo, int row_hi) const = 0;
    // draw_rows for `pieces` known to be disjoint convex constant-valued pieces (what a prepared
    // frame hands a method that draws the visible pieces of a world). A method whose engine can
    // use that knowledge overrides it (exact: pieces more numerous than pixels summed one by
    // one); the same image as draw_rows up to that engine's rounding.
    virtual void draw_disjoint_piece_rows(const Scene& pieces, Image& out, int row_lo,
                                          int row_hi) const {
        draw_rows(pieces, out, row_lo, row_hi);
    }

    // Rows [row_lo, row_hi) of every plane of a colour scene (render_rows checked the frame,
    // the rows and the planes). The default draws each channel's grey scene (in.channel(c), or
    // channel_scene) in turn: the geometry three times. A method whose engine finds coverage
    // once and composites every channel from it overrides this; its traits say which
    // (MethodTraits::colour).
    virtual void draw_colour_rows(const SceneInput& in, ImagePlanes& out, int row_lo,
                                  int row_hi) const;

private:
    friend MethodInstance make_method(const std::string& spec);
    std::shared_ptr<const MethodTraits> traits_;  // the row's, shared: a Method may outlive
                                                  // a scoped row (ScopedMethodRow)
    Filter filter_;
};

struct MethodInfo {
    std::string id;
    std::string summary;
    std::vector<ParamSpec> params;
    std::function<std::unique_ptr<Method>(const ParamValues&)> factory;
    // The parameter that trades time for accuracy, and the values `compare --sweep` runs it
    // at, so the method is a curve on the accuracy-time plot (empty: a single point).
    std::string cost_param = {};
    std::vector<double> sweep_values = {};
    // Other readings of the method the default comparison runs beside its default, as full
    // specs: where a paper leaves a choice open, both answers are shown rather than one hidden.
    std::vector<std::string> default_run_variants = {};
    // The cost parameter matters only where a scene has Bezier curves (a flattening
    // tolerance): `compare --sweep` runs its sweep on such scenes only, not as identical
    // points on every polygon pattern.
    bool sweep_on_curves_only = false;
    // Everything else the harness knows about the method (methods/method_traits.h).
    std::shared_ptr<const MethodTraits> traits = std::make_shared<const MethodTraits>();
};

// `info` with `traits` as its traits: a registry row (methods/registry.cpp). Throws
// std::logic_error when an estimate is missing.
MethodInfo with_traits(MethodInfo info, MethodTraits traits);

// The one registry table (methods/registry.cpp), in the order reports list methods.
const std::vector<MethodInfo>& method_registry();

// A row added at the end of the registry for this object's lifetime, for tests that prove a
// new method needs nothing but its row (tests/method_traits_test.cpp). Not thread-safe: made
// and destroyed while nothing else reads the registry. Throws InputError when the id is taken.
class ScopedMethodRow {
public:
    explicit ScopedMethodRow(MethodInfo row);
    ~ScopedMethodRow();
    ScopedMethodRow(const ScopedMethodRow&) = delete;
    ScopedMethodRow& operator=(const ScopedMethodRow&) = delete;

private:
    std::string id_;
};

// A method built from a spec string, with its canonical name for reports.
struct MethodInstance {
    std::string id;
    ParamValues params;
    std::string spec;  // canonical: "id" or "id:k=v,..." with every parameter
    std::unique_ptr<Method> method;
};

// Parses `ID[:key=value,...]`; unknown ids and keys are InputErrors listing valid ones.
MethodInstance make_method(const std::string& spec);

// Convenience for callers that only need pixels: allocates and renders.
Image render_scene(const Method& method, const SceneInput& in);
// The same for every plane: the scene's channels (one for a grey scene).
ImagePlanes render_planes(const Method& method, const SceneInput& in);

// render() split into `threads` horizontal bands of equal height rendered in parallel (TBB,
// render_rows); threads <= 1 is render() itself. The image is the same as render()'s.
void render_in_bands(const Method& method, const SceneInput& in, Image& out, int threads);
void render_in_bands(const Method& method, const SceneInput& in, ImagePlanes& out, int threads);

// render_in_bands in `bands` bands of rows (at least `threads`; a long render shows its
// progress through them), on `threads` threads; `progress(rows_done, height)` is called after
// each band, from one thread at a time. The image is the same as render()'s.
void render_with_progress(const Method& method, const SceneInput& in, Image& out, int threads,
                          int bands, const std::function<void(int, int)>& progress);
void render_with_progress(const Method& method, const SceneInput& in, ImagePlanes& out,
                          int threads, int bands, const std::function<void(int, int)>& progress);

}  // namespace aabench
