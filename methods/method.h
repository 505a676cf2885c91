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
    // `out` has the scene's size; every pixel is written.
    virtual void render(const Scene& scene, Image& out) const = 0;
    // The filter whose exact reference this method approximates: "box" (area coverage) for
    // the box-type and point-sampling methods; a radial filter spec for the others.
    virtual std::string reference_filter() const { return "box"; }
    // Empty when the method can draw the scene; otherwise the reason it cannot (aa-circle draws
    // only unit-width rings on the pixel grid). A capability, not a fallback: compare shows
    // "n/a" with the reason instead of errors, and render() of such a scene writes NaN.
    virtual std::string not_applicable(const Scene&) const { return {}; }
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
