// The Python module `aabench` (docs/python.md): scenes, renders, exact references, scores and
// the registries of the library, with NumPy arrays for images (rows x columns, float32, linear).
//
// A front end beside the CLI (harness/cli/): each entry runs what the matching subcommand runs,
// in the same order and with the same checks, so that an image or a figure is the one the CLI
// writes, bit for bit (tests/python/). Bad input is the CLI's one-line InputError message,
// raised as ValueError; nothing is printed. C++ runs without the GIL; a returned image owns the
// buffer the render wrote (no copy).
#include <fmt/format.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cstdint>
#include <filesystem>
#include <limits>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "build_info.h"
#include "harness/measure/limits.h"
#include "harness/measure/score.h"
#include "harness/reference/filter_reference.h"
#include "harness/report/image_read.h"
#include "harness/report/score_report.h"
#include "harness/world/frame.h"
#include "harness/world/plan.h"
#include "methods/method.h"
#include "patterns/pattern.h"
#include "patterns/scene/scene_io.h"

namespace py = pybind11;

namespace aabench {
namespace {

// The name a scene read from text gives its messages ("<json>: shapes[0]: ...").
constexpr const char* kJsonSource = "<json>";
// render's --threads range (harness/cli/cmd_render.cpp).
constexpr int kMinThreads = 1;
constexpr int kMaxThreads = 256;

// A scene and where it came from: score() names it as `aabench score` names its --pattern or
// --scene (the row's pattern, pattern_id and scene_file).
struct PyScene {
    Scene scene;
    std::string pattern;     // the spec as given to Scene.pattern, or empty
    std::string scene_file;  // the path given to Scene.from_file, or empty
};

// A str or an os.PathLike as a path string.
std::string path_string(const py::object& path) {
    return py::str(py::module_::import("os").attr("fspath")(path)).cast<std::string>();
}

PyScene scene_from_json(const py::object& source) {
    std::string text;
    if (py::isinstance<py::dict>(source)) {
        text = py::module_::import("json").attr("dumps")(source).cast<std::string>();
    } else if (py::isinstance<py::str>(source)) {
        text = source.cast<std::string>();
    } else {
        throw py::type_error("Scene.from_json: expected the scene as JSON text (str) or a dict");
    }
    return {parse_scene_json(text, kJsonSource), {}, {}};
}

PyScene scene_from_pattern(const std::string& spec, const py::object& size) {
    std::pair<long long, long long> wh;
    try {
        wh = size.cast<std::pair<long long, long long>>();
    } catch (const py::cast_error&) {
        throw py::value_error("size: expected (width, height), two integers");
    }
    check_image_size(wh.first, wh.second, "size");
    return {make_pattern(spec, static_cast<int>(wh.first), static_cast<int>(wh.second)), spec, {}};
}

std::string scene_repr(const PyScene& s) {
    const std::string kind =
        s.scene.world ? std::string("3-D") : fmt::format("2-D, {} edges", s.scene.edge_count());
    const std::string from = !s.pattern.empty()      ? fmt::format("pattern '{}'", s.pattern)
                             : !s.scene_file.empty() ? fmt::format("file '{}'", s.scene_file)
                                                     : std::string("JSON");
    return fmt::format("<aabench.Scene {}x{} ({}) from {}>", s.scene.width, s.scene.height, kind,
                       from);
}

// The image as a float32 NumPy array of shape (height, width) that owns its pixels: the
// vector is moved into a heap object the array's base capsule deletes. No copy.
py::array_t<float> to_array(std::vector<float>&& pixels, int width, int height) {
    auto owned = std::make_unique<std::vector<float>>(std::move(pixels));
    float* data = owned->data();
    py::capsule base(owned.get(), [](void* p) { delete static_cast<std::vector<float>*>(p); });
    owned.release();  // the capsule's now
    return py::array_t<float>(
        {static_cast<py::ssize_t>(height), static_cast<py::ssize_t>(width)},
        {static_cast<py::ssize_t>(width * sizeof(float)), static_cast<py::ssize_t>(sizeof(float))},
        data, base);
}

// `aabench render --method SPEC --threads N` without its file and options: the same steps as
// RenderCommand::run (harness/cli/cmd_render.cpp), in its order, so the same image. A 3-D scene
// goes through the prepared frame; with an edge stage the image is the composite, as --out.
Image render_image(const Scene& scene, const std::string& spec, int threads) {
    const MethodInstance method = make_method(spec);  // check before work
    if (threads < kMinThreads || threads > kMaxThreads) {
        throw InputError(
            fmt::format("threads: {} is out of range {}..{}", threads, kMinThreads, kMaxThreads));
    }
    const Plan plan = make_plan(scene, {.depth_image = false});
    if (plan.in(Stage::kDepthImage) && !method.method->affine_values()) {
        throw InputError(fmt::format(
            "--method: {} draws no depth image (affine values), which {} needs", method.spec,
            plan.in(Stage::kEdges) ? "the scene's edges block" : "--depth-out"));
    }
    const PreparedFrame frame = PreparedFrame::prepare(scene, {.depth_image = false});
    const SceneInput input = frame.input_for(*method.method);
    const Scene& drawn = input.scene();
    const SceneSize size = measure_scene(drawn);
    check_job_memory(estimate_job_bytes(size, {method.spec}, {}), kDefaultMemoryBudgetBytes,
                     "render");
    const std::string reason = method.method->not_applicable(drawn);
    if (!reason.empty()) {
        throw InputError(fmt::format("{}: not applicable: {}", method.spec, reason));
    }
    Image shaded(drawn.width, drawn.height);
    render_in_bands(*method.method, input, shaded, threads);
    AfterMethod after = frame.after_method(*method.method, method.spec, shaded, false);
    if (after.edges) return std::move(after.edges->composite);
    return shaded;
}

// `aabench reference --filter F` without its file: ReferenceCommand::run's steps (no --depth).
std::vector<float> reference_pixels(const Scene& scene, const std::string& filter_text) {
    Filter filter;
    try {
        filter = Filter::parse(filter_text);  // check before any work
    } catch (const InputError& e) {
        throw InputError(std::string("--filter: ") + e.what());
    }
    const PreparedFrame frame = PreparedFrame::prepare(scene, {.depth_image = false});
    const SceneInput measured = frame.pieces();
    check_job_memory(estimate_job_bytes(measure_scene(measured.scene()), {}, {filter_text}),
                     kDefaultMemoryBudgetBytes, "reference");
    const Coverage cov = exact_reference(measured, filter);
    std::vector<float> pixels(cov.data.size());
    for (std::size_t k = 0; k < cov.data.size(); ++k) pixels[k] = static_cast<float>(cov.data[k]);
    return pixels;
}

// ---- score ----

enum class Given { kNone, kLinear, kSrgb };

Given parse_encoding(const std::optional<std::string>& encoding) {
    if (!encoding) return Given::kNone;
    if (*encoding == "srgb") return Given::kSrgb;
    if (*encoding == "linear") return Given::kLinear;
    throw InputError(fmt::format(
        "encoding: '{}' is not one of srgb, linear (or None for float arrays)", *encoding));
}

// Integer codes normalised by `max_code`, then decoded as `aabench score` decodes a PNG's
// codes (harness/report/image_read.cpp): in double, sRGB by its transfer function, rounded
// once to float.
template <class T>
Image decode_codes(const py::array& array, double max_code, bool srgb) {
    const auto view = array.unchecked<T, 2>();
    Image image(static_cast<int>(view.shape(1)), static_cast<int>(view.shape(0)));
    for (py::ssize_t j = 0; j < view.shape(0); ++j) {
        for (py::ssize_t i = 0; i < view.shape(1); ++i) {
            const double v = view(j, i) / max_code;
            image.at(static_cast<int>(i), static_cast<int>(j)) =
                static_cast<float>(srgb ? srgb_to_linear(v) : v);
        }
    }
    return image;
}

// Linear float data as they are (float64 rounded once to float, as a double EXR is read).
template <class T>
Image copy_floats(const py::array& array) {
    const auto view = array.unchecked<T, 2>();
    Image image(static_cast<int>(view.shape(1)), static_cast<int>(view.shape(0)));
    for (py::ssize_t j = 0; j < view.shape(0); ++j) {
        for (py::ssize_t i = 0; i < view.shape(1); ++i) {
            image.at(static_cast<int>(i), static_cast<int>(j)) = static_cast<float>(view(j, i));
        }
    }
    return image;
}

// The test array as the image `score` reads: checked for rank, size and dtype first.
Image image_to_score(const py::array& test, const Scene& scene, Given given) {
    const std::string expected = fmt::format("shape ({}, {}) (rows x columns of the {}x{} scene)",
                                             scene.height, scene.width, scene.width, scene.height);
    if (test.ndim() != 2) {
        throw InputError(
            fmt::format("test: a {}-D array; expected a 2-D array of {}", test.ndim(), expected));
    }
    if (test.shape(0) != scene.height || test.shape(1) != scene.width) {
        throw InputError(fmt::format("test: shape ({}, {}); expected {}", test.shape(0),
                                     test.shape(1), expected));
    }
    const std::string dtype = py::str(test.dtype()).cast<std::string>();
    if (py::isinstance<py::array_t<float>>(test) || py::isinstance<py::array_t<double>>(test)) {
        if (given == Given::kSrgb) {
            throw InputError(
                fmt::format("encoding: 'srgb' on {} data, linear by definition "
                            "(encoding is for uint8 or uint16 codes)",
                            dtype));
        }
        return py::isinstance<py::array_t<float>>(test) ? copy_floats<float>(test)
                                                        : copy_floats<double>(test);
    }
    const bool u8 = py::isinstance<py::array_t<std::uint8_t>>(test);
    if (u8 || py::isinstance<py::array_t<std::uint16_t>>(test)) {
        if (given == Given::kNone) {
            throw InputError(fmt::format(
                "test: {} codes need encoding='srgb' or encoding='linear': integer codes are not "
                "light until decoded, and no decoding is guessed",
                dtype));
        }
        const bool srgb = given == Given::kSrgb;
        return u8 ? decode_codes<std::uint8_t>(test, 255.0, srgb)
                  : decode_codes<std::uint16_t>(test, 65535.0, srgb);
    }
    throw InputError(
        fmt::format("test: dtype {}; expected float32 or float64 (linear light), or "
                    "uint8 or uint16 codes with encoding='srgb' or 'linear'",
                    dtype));
}

// A JSON value of results.json's encoding as Python: null (a figure that does not apply) as
// NaN and "inf"/"-inf" as infinities, so every figure is a float (or an int for counts).
py::object to_python(const nlohmann::ordered_json& value) {
    if (value.is_null()) return py::float_(std::numeric_limits<double>::quiet_NaN());
    if (value.is_boolean()) return py::bool_(value.get<bool>());
    if (value.is_number_integer()) return py::int_(value.get<long long>());
    if (value.is_number()) return py::float_(value.get<double>());
    if (value.is_string()) {
        const std::string& s = value.get_ref<const std::string&>();
        if (s == "inf") return py::float_(std::numeric_limits<double>::infinity());
        if (s == "-inf") return py::float_(-std::numeric_limits<double>::infinity());
        return py::str(s);
    }
    throw std::logic_error("score: a figure of an unexpected JSON type");
}

py::dict score(const py::array& test, const PyScene& scene,
               const std::optional<std::string>& filter,
               const std::optional<std::string>& encoding) {
    const Image image = image_to_score(test, scene.scene, parse_encoding(encoding));
    nlohmann::ordered_json figures;
    {
        py::gil_scoped_release release;
        ResultRow row = score_image(image, scene.scene, filter.value_or("box"), "test");
        // Named as cmd_score.cpp names the scene of --pattern or --scene.
        if (!scene.pattern.empty()) {
            const PatternInstance instance = resolve_pattern(scene.pattern);
            row.pattern = instance.spec;
            row.pattern_id = instance.info->id;
        } else if (!scene.scene_file.empty()) {
            row.pattern = row.pattern_id = std::filesystem::path(scene.scene_file).stem().string();
            row.scene_file = scene.scene_file;
        }
        figures = score_figures(row);
    }
    py::dict out;
    for (const auto& [key, value] : figures.items()) out[py::str(key)] = to_python(value);
    return out;
}

// ---- registries ----

py::dict param_dict(const ParamSpec& p) {
    py::dict d;
    d["name"] = p.name;
    // A choice without choices is free text its owner parses (ParamSpec::range_string).
    d["kind"] = p.kind == ParamKind::kInt    ? "int"
                : p.kind == ParamKind::kReal ? "real"
                : p.choices.empty()          ? "text"
                                             : "choice";
    if (p.kind == ParamKind::kChoice) {
        d["default"] = p.choices.empty() ? std::string() : p.choices.front();
    } else if (p.kind == ParamKind::kInt) {
        d["default"] = static_cast<long long>(p.default_value);
        d["min"] = static_cast<long long>(p.min_value);
        d["max"] = static_cast<long long>(p.max_value);
    } else {
        d["default"] = p.default_value;
        d["min"] = p.min_value;
        d["max"] = p.max_value;
    }
    d["choices"] = p.choices;
    d["range"] = p.range_string();  // as `aabench list` prints them
    d["default_text"] = p.default_string();
    d["doc"] = p.doc;
    return d;
}

py::list param_list(const std::vector<ParamSpec>& params) {
    py::list out;
    for (const ParamSpec& p : params) out.append(param_dict(p));
    return out;
}

py::list method_rows() {
    py::list out;
    for (const MethodInfo& row : method_registry()) {
        const MethodTraits& t = *row.traits;
        py::dict traits;
        traits["own_visibility"] = t.own_visibility;
        traits["coplanar_overlays"] = t.coplanar_overlays;
        traits["affine_values"] = t.affine_values;
        traits["applies_to"] =
            t.applies_to == Applicability::kAnyScene ? "any scene" : "grid circles only";
        traits["temporal"] = t.temporal;
        traits["post_process"] = t.post_process;
        traits["time_caveat"] = t.time_caveat;
        traits["curves"] = t.curves;
        traits["reference_renderer"] = t.reference_renderer;
        traits["cost_param"] = row.cost_param;
        traits["sweep_values"] = row.sweep_values;
        traits["sweep_on_curves_only"] = row.sweep_on_curves_only;
        traits["default_run_variants"] = row.default_run_variants;
        const MethodInstance method = make_method(row.id);
        traits["filter"] = method.method->filter().text();  // at the defaults
        py::dict d;
        d["id"] = row.id;
        d["summary"] = row.summary;
        d["spec"] = method.spec;
        d["parameters"] = param_list(row.params);
        d["traits"] = traits;
        out.append(d);
    }
    return out;
}

py::list pattern_rows() {
    py::list out;
    for (const PatternInfo& row : pattern_registry()) {
        py::dict traits;
        traits["in_default_run"] = row.in_default_run;
        traits["bezier"] = row.bezier;
        py::dict d;
        d["id"] = row.id;
        d["summary"] = row.summary;
        d["spec"] = resolve_pattern(row.id).spec;
        d["parameters"] = param_list(row.params);
        d["traits"] = traits;
        out.append(d);
    }
    return out;
}

}  // namespace
}  // namespace aabench

PYBIND11_MODULE(aabench, m) {
    using namespace aabench;
    m.doc() =
        "aabench: antialiasing methods, exact references and image-quality figures "
        "(docs/python.md). Images are float32 NumPy arrays of shape (height, width), linear light.";
    m.attr("__version__") = AABENCH_VERSION;
    m.attr("git_revision") = build_info::kGitRevision;
    // The CLI's one-line messages (bad scene, spec, size, filter, method) as ValueError.
    py::register_exception_translator([](std::exception_ptr error) {
        try {
            if (error) std::rethrow_exception(error);
        } catch (const InputError& e) {
            PyErr_SetString(PyExc_ValueError, e.what());
        }
    });

    py::class_<PyScene>(m, "Scene",
                        "A scene: a built-in pattern at a size, or a scene file "
                        "(docs/scene-format.md), read as the CLI reads it.")
        .def_static(
            "from_file",
            [](const py::object& path) {
                const std::string p = path_string(path);
                return PyScene{read_scene_file(p), {}, p};
            },
            py::arg("path"), "The scene file at `path` (as aabench --scene reads it).")
        .def_static("from_json", &scene_from_json, py::arg("json"),
                    "A scene from its JSON text, or from a dict (serialised with the json module, "
                    "then read as a scene file is).")
        .def_static("pattern", &scene_from_pattern, py::arg("spec"), py::arg("size"),
                    "The built-in pattern `spec` (ID[:key=value,...]) at size=(width, height).")
        .def(
            "to_json", [](const PyScene& s) { return scene_to_json(s.scene); },
            "The scene as scene-file JSON text (as aabench export writes it).")
        .def_property_readonly("width", [](const PyScene& s) { return s.scene.width; })
        .def_property_readonly("height", [](const PyScene& s) { return s.scene.height; })
        .def_property_readonly("is_3d", [](const PyScene& s) { return s.scene.world.has_value(); })
        // 3 for a colour scene (docs/colour.md), whose render() and reference() here are its
        // luminance; the CLI writes its R, G, B.
        .def_property_readonly("channels", [](const PyScene& s) { return s.scene.channels; })
        .def("__repr__", &scene_repr);

    m.def(
        "render",
        [](const PyScene& scene, const std::string& method, int threads) {
            Image image;
            {
                py::gil_scoped_release release;
                image = render_image(scene.scene, method, threads);
            }
            return to_array(std::move(image.data), image.width, image.height);
        },
        py::arg("scene"), py::arg("method") = "box-multiscan:n=3", py::arg("threads") = 1,
        "The scene drawn by `method` (ID[:key=value,...]): the image `aabench render` writes, "
        "float32 of shape (height, width). threads=N renders N bands in parallel (same image).");
    m.def(
        "reference",
        [](const PyScene& scene, const std::string& filter) {
            std::vector<float> pixels;
            {
                py::gil_scoped_release release;
                pixels = reference_pixels(scene.scene, filter);
            }
            return to_array(std::move(pixels), scene.scene.width, scene.scene.height);
        },
        py::arg("scene"), py::arg("filter") = "box",
        "The exact reference `aabench reference --filter` writes: box, "
        "gaussian[:sigma=S,radius=R] or cone[:radius=R].");
    m.def("score", &score, py::arg("test"), py::arg("scene"), py::kw_only(),
          py::arg("filter") = py::none(), py::arg("encoding") = py::none(),
          "The figures `aabench score --json` prints for the image `test` (2-D array of the "
          "scene's shape), under its keys. float32/float64: linear light; uint8/uint16: give "
          "encoding='srgb' or 'linear'. NaN: the figure does not apply.");
    m.def("methods", &method_rows,
          "The method registry: one dict per method (id, summary, spec, parameters, traits).");
    m.def("patterns", &pattern_rows,
          "The pattern registry: one dict per pattern (id, summary, spec, parameters, traits).");
}
