// Running the hard cases (harness/measure/hardcases.h): the subjects (method specs and exact
// references), what each case prepares once, one case against one subject with the documented
// bounds that settle a nominal violation, and run_hard_cases().
//
// Per case, each method (and each reference) renders three scenes: the case itself, the case
// with every vertex moved by at most kContinuityMovePx (continuity), and the case with the
// scene and its window moved together by 2^20 px (translation). The figures:
//   finite       number of non-finite pixels (bound 0);
//   range        largest excursion beyond [min, max] of the background and the shape values;
//   area         |sum of (pixel - background) - exact mass|, for box-filter methods;
//   continuity,  largest per-pixel difference between the two images, with the fraction of
//   translation  pixels that differ by more than the tolerance.
// A nominal violation is a documented property only when the method's row documents it for
// the invariant and case (MethodTraits::hard_cases), and its documented bound holds too; else
// it fails.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <mutex>
#include <string>
#include <tuple>
#include <vector>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "harness/measure/hardcase_internal.h"
#include "harness/measure/hardcases.h"
#include "harness/reference/box_reference.h"
#include "harness/reference/filter_reference.h"
#include "harness/world/frame.h"
#include "methods/method.h"

namespace aabench {

using namespace hardcase_detail;

namespace {

// ---- Image sums ----

Coverage to_coverage(const Image& image) {
    Coverage out(image.width, image.height);
    for (std::size_t k = 0; k < image.data.size(); ++k) out.data[k] = image.data[k];
    return out;
}

double mass_of(const Coverage& c, double background) {
    double sum = 0.0;
    for (double v : c.data) sum += v - background;
    return sum;
}

double abs_sum(const Coverage& c) {
    double sum = 0.0;
    for (double v : c.data) sum += std::abs(v);
    return sum;
}

// True when every pixel differing by more than `tolerance` is marked in `allowed`.
bool changes_within(const Coverage& a, const Coverage& b, double tolerance,
                    const Raster<std::uint8_t>& allowed) {
    for (std::size_t k = 0; k < a.data.size(); ++k) {
        if (!(std::abs(a.data[k] - b.data[k]) <= tolerance) && !allowed.data[k]) return false;
    }
    return true;
}

double marked_fraction(const Raster<std::uint8_t>& mask) {
    std::size_t count = 0;
    for (std::uint8_t m : mask.data) count += m != 0;
    return mask.data.empty() ? 0.0 : static_cast<double>(count) / mask.data.size();
}

// ---- Methods and references under test ----

struct Subject {
    std::string spec;  // row name
    bool reference = false;
    bool box = false;  // box filter: area applies
    bool heavy = false;
    // A method's documented properties and the figures their bounds need (its row's
    // MethodTraits::hard_cases at its parameters); none for the references.
    const std::vector<DocumentedProperty>* properties = nullptr;
    BoundFigures figures;
    std::function<Coverage(const Scene&)> render;
    // A method's declared limits (Method::not_applicable: the circle methods draw no polygons);
    // empty for the references.
    std::function<std::string(const Scene&)> not_applicable;
};

std::vector<Subject> subjects_for(const std::vector<std::string>& specs) {
    std::vector<Subject> out;
    for (const std::string& spec : specs) {
        auto instance = std::make_shared<MethodInstance>(make_method(spec));
        const HardCaseTraits& traits = instance->method->traits().hard_cases;
        Subject s;
        s.spec = instance->spec;
        s.box = instance->method->filter().is_box();
        s.heavy = traits.heavy(instance->params);
        s.properties = &traits.properties;  // the instance holds the row's traits
        s.figures = traits.figures(instance->params);
        s.render = [instance](const Scene& scene) {
            Image out(scene.width, scene.height, std::numeric_limits<float>::quiet_NaN());
            instance->method->render(scene, out);
            return to_coverage(out);
        };
        s.not_applicable = [instance](const Scene& scene) {
            return instance->method->not_applicable(scene);
        };
        out.push_back(std::move(s));
    }
    const Filter gaussian = Filter::parse("gaussian");
    const Filter cone = Filter::parse("cone");
    const auto reference = [](std::string name, bool box,
                              std::function<Coverage(const Scene&)> render) {
        Subject s;
        s.spec = std::move(name);
        s.reference = true;
        s.box = box;
        s.render = std::move(render);
        return s;
    };
    out.push_back(reference("ref:box", true, [](const Scene& scene) { return box_reference(scene); }));
    out.push_back(reference("ref:" + gaussian.text(), false, [gaussian](const Scene& scene) {
        return filtered_reference(scene, gaussian);
    }));
    out.push_back(reference("ref:" + cone.text(), false, [cone](const Scene& scene) {
        return filtered_reference(scene, cone);
    }));
    return out;
}

// The subject's documented property for this invariant and case, if any.
const DocumentedProperty* find_documented(const Subject& s, Invariant invariant,
                                          const std::string& case_name) {
    if (s.properties == nullptr) return nullptr;
    for (const DocumentedProperty& e : *s.properties) {
        if (e.invariant == invariant && case_in_set(e.cases, case_name)) return &e;
    }
    return nullptr;
}

// What a case needs once, whatever the method.
struct PreparedCase {
    const HardCase* info = nullptr;
    HardCaseScene base;
    // What the subjects draw: each scene in its window frame, as a prepared frame hands it on
    // (window_scene, harness/world/frame.h).
    Scene window;   // base.scene
    Scene moved;    // continuity: base.scene perturbed, then taken to its window frame
    Scene shifted;  // translation: base.scene and its window moved, then the same
    double lo = 0.0, hi = 0.0, span = 0.0;
    Raster<std::uint8_t> flip_zone;       // pixels within kFlipReachPx of an edge
    Raster<std::uint8_t> touched;         // pixels touched by an edge
    long long touched_pixels = 0;
    long long multi_edge_pixels = 0;      // touched by two or more edges
    long long zone_pixels = 0;
    double perimeter = 0.0;
};

PreparedCase prepare(const HardCase& hc) {
    PreparedCase p;
    p.info = &hc;
    p.base = hc.make();
    const Scene& scene = p.base.scene;
    p.window = window_scene(scene);
    p.moved = window_scene(perturbed(scene, kContinuityMovePx));
    p.shifted = window_scene(offset_with_window(scene, kTranslationOffsetPx));
    std::tie(p.lo, p.hi) = scene.value_range();
    p.span = p.hi - p.lo;
    p.flip_zone = edge_neighbourhood(p.window, kFlipReachPx);
    constexpr int kMargin = 1;
    const Raster<std::uint8_t> counts = edge_counts(p.window, kMargin);
    p.touched = dilate_and_crop(counts, kMargin, 0, scene.width, scene.height);
    for (int j = 0; j < scene.height; ++j) {
        for (int i = 0; i < scene.width; ++i) {
            const std::uint8_t c = counts.at(i + kMargin, j + kMargin);
            p.touched_pixels += c >= 1;
            p.multi_edge_pixels += c >= 2;
        }
    }
    for (std::uint8_t m : p.flip_zone.data) p.zone_pixels += m != 0;
    p.perimeter = clipped_perimeter(p.window);
    return p;
}

// The documented bound of an entry, for this case and subject.
double documented_area_bound(DocumentedBound kind, const PreparedCase& c, const Subject& s) {
    const double rounding = kFloat32Rounding * (std::abs(c.base.exact_mass.value_or(0.0)) +
                                                c.window.width * c.window.height *
                                                    std::max(std::abs(c.lo), std::abs(c.hi)));
    switch (kind) {
        case DocumentedBound::kSamplingArea:
            // A pixel crossed by one straight edge errs by at most span / k; one holding a
            // vertex or several edges by at most span.
            return c.span * (static_cast<double>(c.touched_pixels - c.multi_edge_pixels) *
                                 s.figures.edge_pixel_error +
                             static_cast<double>(c.multi_edge_pixels)) +
                   rounding;
        case DocumentedBound::kTrapezoidArea:
            return trapezoid_bound(c.window, s.figures.sub_scanlines, c.span) + rounding;
        case DocumentedBound::kQuantisedArea:
            return c.span * (c.zone_pixels * s.figures.coverage_step +
                             c.perimeter * s.figures.vertex_grid_px) +
                   rounding;
        case DocumentedBound::kAnyArea:
            return c.span * static_cast<double>(c.zone_pixels) + rounding;
        case DocumentedBound::kRoundingStep:
            return c.span * 0.5 * kEightBitStep * c.window.width * c.window.height + rounding;
        case DocumentedBound::kLocalChanges:
            break;
    }
    return 0.0;
}

Outcome worst(Outcome a, Outcome b) { return static_cast<int>(a) >= static_cast<int>(b) ? a : b; }

void settle_same(InvariantResult& r, const Coverage& a, const Coverage& b, double tolerance,
                 const PreparedCase& c, const Subject& s, Invariant invariant) {
    r = check_same(a, b, tolerance);
    r.allowed_fraction = marked_fraction(c.flip_zone);
    if (r.outcome != Outcome::kFail) return;
    const DocumentedProperty* e = find_documented(s, invariant, c.info->name);
    if (e != nullptr && e->bound == DocumentedBound::kRoundingStep) {
        // One step, plus the float32 rounding of the two values compared.
        const double step = c.span * kEightBitStep * (1.0 + 1e-6) + tolerance;
        if (r.value <= step) {
            r.outcome = Outcome::kDocumented;
            r.documented_bound = step;
            r.note = e->reason;
        } else {
            r.note = "a change larger than one 8-bit step; " + e->reason;
        }
        return;
    }
    if (e == nullptr || e->bound != DocumentedBound::kLocalChanges) return;
    if (changes_within(a, b, tolerance, c.flip_zone)) {
        r.outcome = Outcome::kDocumented;
        r.documented_bound = r.allowed_fraction;
        r.note = e->reason;
    } else {
        r.note = "changes reach pixels farther than 2 px from every edge; " + e->reason;
    }
}

HardCaseRow run_one(const PreparedCase& c, const Subject& s) {
    HardCaseRow row;
    row.case_name = c.info->name;
    row.method = s.spec;
    row.reference = s.reference;
    row.width = c.base.scene.width;
    row.height = c.base.scene.height;
    const long long pixels = static_cast<long long>(row.width) * row.height;
    if (s.heavy && pixels > kHeavySpecMaxPixels) {
        for (InvariantResult& r : row.results) r.note = "not run: size cap of the heaviest specs";
        return row;
    }
    if (s.not_applicable) {  // a method that declares it cannot draw the case: nothing to check
        const std::string reason = s.not_applicable(c.window);
        if (!reason.empty()) {
            for (InvariantResult& r : row.results) r.note = "n/a: " + reason;
            return row;
        }
    }
    const Coverage image = s.render(c.window);

    row.at(Invariant::kFinite) = check_finite(image);
    const double scale = std::max({1.0, std::abs(c.lo), std::abs(c.hi)});
    row.at(Invariant::kRange) =
        check_range(image, c.lo, c.hi, (s.reference ? kReferenceRangeSlack : kRangeSlack) * scale);

    if (s.box && c.base.exact_mass) {
        const double exact = *c.base.exact_mass;
        // Nominal: the box reference's own error per pixel, the exact mass's shoelace rounding
        // and, for methods, one float32 rounding per pixel.
        double bound = pixels * kBoxReferencePixelError + 1e-12 * std::max(1.0, std::abs(exact));
        if (!s.reference) bound += kFloat32Rounding * abs_sum(image);
        InvariantResult& r = row.at(Invariant::kArea);
        r = check_area(mass_of(image, c.base.scene.background), exact, bound);
        if (r.outcome == Outcome::kFail) {
            if (const DocumentedProperty* e = find_documented(s, Invariant::kArea, c.info->name)) {
                r.documented_bound = documented_area_bound(e->bound, c, s);
                if (r.value <= r.documented_bound) {
                    r.outcome = Outcome::kDocumented;
                    r.note = e->reason;
                } else {
                    r.note = "beyond the documented bound too; " + e->reason;
                }
            }
        }
    }

    settle_same(row.at(Invariant::kContinuity), image, s.render(c.moved), kContinuityTolerance, c,
                s, Invariant::kContinuity);
    settle_same(row.at(Invariant::kTranslation), image, s.render(c.shifted),
                kTranslationTolerance, c, s, Invariant::kTranslation);
    for (const InvariantResult& r : row.results) row.outcome = worst(row.outcome, r.outcome);
    return row;
}

}  // namespace

// ---- Public: the run ----

std::vector<HardCaseRow> run_hard_cases(const std::vector<std::string>& method_specs,
                                        const ProgressFn& progress) {
    const std::vector<Subject> subjects =
        subjects_for(method_specs.empty() ? default_hard_case_methods() : method_specs);
    const std::vector<HardCase>& cases = hard_cases();
    const std::size_t total = cases.size() * subjects.size();
    // Every case prepared, then every (case, method) pair run, both in parallel (TBB): each
    // row lands at its index, so the rows and their order are those of a serial run.
    std::vector<PreparedCase> prepared(cases.size());
    tbb::parallel_for(std::size_t(0), cases.size(),
                      [&](std::size_t c) { prepared[c] = prepare(cases[c]); });
    std::vector<HardCaseRow> rows(total);
    std::mutex progress_mutex;
    std::size_t done = 0;
    tbb::parallel_for(
        tbb::blocked_range<std::size_t>(0, total, 1), [&](const tbb::blocked_range<std::size_t>& r) {
            for (std::size_t k = r.begin(); k < r.end(); ++k) {
                const std::size_t c = k / subjects.size();
                const Subject& s = subjects[k % subjects.size()];
                rows[k] = run_one(prepared[c], s);
                if (!progress) continue;
                std::lock_guard<std::mutex> lock(progress_mutex);
                progress(++done, total, cases[c].name + " " + s.spec);
            }
        });
    return rows;
}

}  // namespace aabench
