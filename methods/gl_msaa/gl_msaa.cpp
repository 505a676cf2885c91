// gl-msaa — MSAA as a real OpenGL driver rasterises and resolves it: Mesa's llvmpipe through
// OSMesa (GL 4.5 core, off-screen; no GPU needed), read back in float.
//
// Computes: the frame's shapes drawn by the driver into a float32 (GL_R32F) target with
// `samples` samples per pixel, in order, by stencil-then-cover with the nonzero winding rule
// (holes and overlaps as the scene defines them, docs/scene-format.md), then resolved by the
// driver (glBlitFramebuffer into a single-sample float32 target: the box average of each
// pixel's samples, in linear float, no 8-bit step) and read back. samples=4: llvmpipe's 4x
// MSAA, whose sample positions are the Direct3D / Vulkan standard 4x ones; samples=1: one
// sample at each pixel centre, the driver's aliased rasterisation (`none` drawn by a GPU).
// Vertices reach the rasteriser on its 1/256 px grid. methods/gl_msaa/gl_raster_p.h has the
// machinery; docs/gl-msaa.md the choices and the differential test against ssaa.
//
// 3-D scenes (a ScreenScene; own_visibility): every face drawn with its depth plane through
// the driver's depth test, one depth per sample (GL_GEQUAL: nearer wins, ties to the later
// face). Affine values (depth images) are shaded once per pixel at its centre and written to
// every covered sample, as MSAA shades.
//
// Times: llvmpipe emulates the GPU on the CPU (rasterising in the calling thread here), so a
// time is the cost of that emulation, never the cost of MSAA on a GPU.
//
// Parameters:
//   samples  1|4, default 4. GL_MAX_SAMPLES of llvmpipe is 4: 4 is all the driver offers, 1
//            is the same path without multisampling (checked against `none`).
#include <fmt/format.h>

#include <memory>
#include <string>

#include "methods/cost_model.h"
#include "methods/gl_msaa/gl_raster_p.h"
#include "methods/memory_model.h"
#include "methods/method.h"
#include "patterns/scene/bezier.h"

namespace aabench {
namespace {

class GlMsaaMethod : public Method {
public:
    GlMsaaMethod(int samples, double flatness) : samples_(samples), flatness_(flatness) {}

protected:
    // A GPU draws triangles: curves are tessellated first, each Bezier segment cut into chords
    // within `flatness` px of it (patterns/scene/bezier.h), as a vector renderer feeding it does.
    void draw_rows(const Scene& scene, Image& out, int row_lo, int row_hi) const override {
        if (has_bezier(scene)) {
            gl_draw_rows(flattened_scene(scene, flatness_), samples_, out, row_lo, row_hi);
        } else {
            gl_draw_rows(scene, samples_, out, row_lo, row_hi);
        }
    }

public:
    std::optional<Scene> own_flattening(const Scene& scene) const override {
        if (!has_bezier(scene)) return std::nullopt;
        return flattened_scene(scene, flatness_);
    }

private:
    int samples_;
    double flatness_;
};

}  // namespace

// The time estimate's coefficients (t_ms = fixed + per Mpixel + per Medge, methods/cost_model.h's
// form; gl-msaa is not in the cost-model run): compare's single-threaded medians at 256^2 on a
// loaded 2-core machine, samples = 4: star (216 edges) 30 ms, a fill of about 400 ms per Mpixel;
// rings, zoneplate, terrain, checkerboard (2,562 .. 20,678 edges) 112 .. 621 ms, about 27 us per
// edge (each shape's stencil fans and cover box sweep its whole area). samples = 1 took 0.36 of
// that on rings. Discs and rings are drawn from a polygon about 140 times coarser than the
// scene's (methods/gl_msaa/gl_raster_p.h): on them this overstates the time up to ~300x (circles:
// 150 ms measured).
constexpr cost_model::Coefficients kGlMsaaCost{0.5, 400.0, 27000.0};  // samples = 4
constexpr double kGlMsaaOneSampleFactor = 0.36;

// What the harness knows of `gl-msaa` (methods/method_traits.h).
MethodTraits gl_msaa_traits() {
    MethodTraits t;
    t.curves = "tessellated at `flatness` px: the driver draws triangles";
    t.time_caveat =
        "llvmpipe, Mesa's CPU emulation of a GPU (rasterising in the calling thread): the cost "
        "of that emulation, not of MSAA on a GPU.";
    t.own_visibility = true;  // the driver's depth test
    t.affine_values = true;   // shaded at the pixel centre
    t.working_bytes = [](const ParamValues& p, const SceneSize& s) {
        // The driver's targets for one tile (float colour and a 32-bit depth + 8-bit stencil per
        // sample, the float resolve target), and our vertex list (3 floats per vertex and per
        // cover corner, grown by push_back: x2) and fan lists.
        const double samples = p.get_int("samples");
        const double tile =
            std::min<double>(s.width, kGlTileSidePx) * std::min<double>(s.height, kGlTileSidePx);
        return tile * (samples * (4.0 + 8.0) + 4.0) + 2.0 * 12.0 * (s.vertices + 4.0 * s.shapes) +
               2.0 * 8.0 * s.contours;
    };
    t.time_ms = [](const ParamValues& p, const SceneSize& s) {
        const double factor = p.get_int("samples") > 1 ? 1.0 : kGlMsaaOneSampleFactor;
        return cost_model::linear_ms(kGlMsaaCost, s.pixels(), s.vertices) * factor;
    };
    t.hard_cases.properties = {
        {Invariant::kContinuity, CaseSet::kAll, DocumentedBound::kLocalChanges,
         "point samples on the driver's 1/256 px vertex grid: a sample flips as an edge moves"},
        {Invariant::kTranslation, CaseSet::kAll, DocumentedBound::kLocalChanges,
         "vertices rounded to 1/256 px: a sample near an edge flips"},
        {Invariant::kArea, CaseSet::kAll, DocumentedBound::kSamplingArea,
         "4 (or 1) samples per pixel: area is conserved only on average"},
    };
    // No proof for the standard 4x positions (as for ssaa's patterns): the whole span.
    t.hard_cases.figures = [](const ParamValues&) { return BoundFigures{.edge_pixel_error = 1.0}; };
    return t;
}

MethodInfo gl_msaa_method() {
    return {"gl-msaa",
            "MSAA by a real OpenGL driver (Mesa llvmpipe via OSMesa, CPU emulation: its times are "
            "not a GPU's), float32 target, stencil-then-cover, resolved in linear float",
            {{"samples",
              ParamKind::kInt,
              4,
              1,
              4,
              {},
              "samples per pixel: 4 (llvmpipe's maximum, the standard 4x positions) or 1 (pixel "
              "centres)"},
             {"flatness", ParamKind::kReal, 0.25, 0.0001, 10, {},
              "px the chords of a tessellated curve may depart from it; 0.25 is what vector "
              "renderers on GPUs (Skia, Qt) tessellate to. Polygons do not depend on it"}},
            [](const ParamValues& p) -> std::unique_ptr<Method> {
                const int samples = p.get_int("samples");
                if (samples != 1 && samples != 4) {
                    throw InputError(fmt::format(
                        "method 'gl-msaa': samples takes 1 or 4 (what llvmpipe offers), not {}",
                        samples));
                }
                return std::make_unique<GlMsaaMethod>(samples, p.get_real("flatness"));
            },
            // The accuracy-time curve of its tessellation, on scenes with curves.
            "flatness",
            {1, 0.05},
            {},
            /*sweep_on_curves_only=*/true};
}

}  // namespace aabench
