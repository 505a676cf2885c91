// The one interface every antialiasing method implements, and the one registry table.
//
// A method is a small plain class built by its registry row's factory from resolved
// parameters. render() turns a Scene into a float32 linear Image of the scene's size; it
// does no I/O. The output buffer is allocated by the caller (so timing excludes allocation);
// render() overwrites every pixel.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "methods/scan/image.h"
#include "patterns/scene/params.h"
#include "patterns/scene/scene.h"

namespace aabench {

class Method {
public:
    virtual ~Method() = default;
    // `out` has the scene's size; every pixel is written. render_rows over all rows.
    void render(const Scene& scene, Image& out) const { render_rows(scene, out, 0, scene.height); }
    // Rows [row_lo, row_hi) of what render() writes (clamped to the image), other rows
    // untouched; safe to call from several threads at once on disjoint row ranges
    // (render_in_bands). The one window-origin path of every method: a scene with an origin
    // is taken to its window frame here (in_window_frame, patterns/scene/scene.h: one copy
    // per call), and draw_rows only ever sees a scene without one. A band is a row range
    // handed to the method's engine, never a copy of the scene.
    void render_rows(const Scene& scene, Image& out, int row_lo, int row_hi) const;
    // The filter whose exact reference this method approximates: "box" (area coverage) for
    // the box-type and point-sampling methods; a radial filter spec for the others.
    virtual std::string reference_filter() const { return "box"; }
    // True for a method that removes hidden surfaces itself (depth-aware scanline or z-buffer):
    // for a 3-D scene the harness hands it the ScreenScene (WorldRender::screen: every face's
    // cells with their depth planes, overlapping) instead of the exact visible pieces
    // (WorldRender::pieces), which the others draw in order. For a 2-D scene both are the scene.
    virtual bool own_visibility() const { return false; }
    // True for a method that draws affine values (Shape::value_plane) the way it draws
    // constant ones: the depth image of the edge stage (Saito & Takahashi 1990, §3.5: antialiasing
    // done on the depth image by averaging depth the way the shaded image averages colour) is the
    // depth scene rendered by the method itself. A method without it is refused a depth
    // image with a one-line error, never given a silently different one.
    virtual bool affine_values() const { return false; }
    // Empty when the method can draw the scene; otherwise the reason it cannot (aa-circle draws
    // only unit-width rings on the pixel grid). A capability, not a fallback: compare shows
    // "n/a" with the reason instead of errors, and render() of such a scene writes NaN.
    virtual std::string not_applicable(const Scene&) const { return {}; }

protected:
    // What a method implements: rows [row_lo, row_hi) of the image of `scene`, with
    // 0 <= row_lo < row_hi <= scene.height, every pixel of those rows written and no other.
    // `scene` has no window origin (render_rows took it out). Called from several threads at
    // once on disjoint row ranges: per-thread scratch only.
    virtual void draw_rows(const Scene& scene, Image& out, int row_lo, int row_hi) const = 0;
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
};

// The one registry table (methods/registry.cpp), in the order reports list methods.
const std::vector<MethodInfo>& method_registry();

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
Image render_scene(const Method& method, const Scene& scene);

// render() split into `threads` horizontal bands of equal height rendered in parallel (TBB,
// render_rows); threads <= 1 is render() itself. The image is the same as render()'s. A
// window origin is taken out once, before the bands.
void render_in_bands(const Method& method, const Scene& scene, Image& out, int threads);

// Each method file defines one of these; the registry lists them.
MethodInfo none_method();
MethodInfo ssaa_method();
MethodInfo nishita_d_method();
MethodInfo fast_edge_method();
MethodInfo box_multiscan_method();
MethodInfo gauss_multiscan_method();
MethodInfo exact_method();
MethodInfo cairo_method();
MethodInfo agg_method();
MethodInfo exact_8bit_method();
MethodInfo aa_circle_method();
MethodInfo wu_circle_method();
MethodInfo midpoint_circle_method();

// Entries of aa-circle's D[r][y] table for a radius_max (one byte each at alpha_max = 255):
// the benchmark's memory column and the test of the source's size formula.
std::size_t aa_circle_table_entries(int radius_max);

}  // namespace aabench
