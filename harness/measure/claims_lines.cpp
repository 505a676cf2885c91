// The claims of Saito & Takahashi 1990 about the edge stage's line image: jaggies shrink when the
// depth image is antialiased (§3.5), and polygonised curved surfaces show facet creases
// (§6.2(2)).
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "harness/measure/claims.h"
#include "harness/measure/line_scores.h"
#include "harness/measure/symptoms.h"
#include "harness/world/frame.h"
#include "methods/method.h"
#include "patterns/pattern.h"

namespace aabench {
namespace {

// The scenes with an edges block whose line image comes from the method's own depth image (the
// mirror's comes from the ray-cast optical-path depth, the same for every method).
const char* const kLineScenes[] = {"torus", "room:edges=black"};
// The torus at its default facets and at twice and four times as many each way.
const int kFacets[][2] = {{48, 24}, {96, 48}, {192, 96}};

// Per-pixel running sums of (line image - true line drawing) over the frames.
struct CrawlSums {
    std::vector<double> sum, sum2;
    void add(const Image& lines, const Coverage& truth) {
        if (sum.empty()) sum.assign(lines.data.size(), 0.0), sum2.assign(lines.data.size(), 0.0);
        for (std::size_t k = 0; k < lines.data.size(); ++k) {
            const double d = static_cast<double>(lines.data[k]) - truth.data[k];
            sum[k] += d;
            sum2[k] += d * d;
        }
    }
    // Mean over pixels of the standard deviation over frames (population), as `crawl`.
    double crawl(int frames) const {
        double total = 0.0;
        for (std::size_t k = 0; k < sum.size(); ++k) {
            const double mean = sum[k] / frames;
            total += std::sqrt(std::max(0.0, sum2[k] / frames - mean * mean));
        }
        return total / static_cast<double>(sum.size());
    }
};

}  // namespace

ClaimResult claim_line_crawl(const ClaimsOptions& options) {
    ClaimResult r;
    r.source = "Saito & Takahashi 1990, §3.5";
    r.claim = "Jaggies in the line image shrink when the depth image is antialiased.";
    r.measure = fmt::format(
        "`torus` and `room:edges=black` at {}², filmed over {} camera offsets along the "
        "diagonal of one pixel (the crawl figure's motion: eye and target moved together). Each "
        "method that draws the depth image draws it, the edge stage makes the line image, and "
        "line crawl is the mean over pixels of the standard deviation over the frames of (line "
        "image - exact line drawing). `exact depth` is the edge stage on the exact depth image. "
        "Checks: every method that antialiases its depth image below `none` (the aliased "
        "depth image) on each scene.",
        options.motion_size, options.motion_frames);
    const int frames = options.motion_frames;
    for (const char* spec : kLineScenes) {
        const Scene scene = make_pattern(spec, options.motion_size, options.motion_size);
        std::vector<MethodInstance> methods;
        for (const MethodInfo& info : method_registry()) {
            MethodInstance m = make_method(info.id);
            if (m.method->affine_values() && m.method->not_applicable(scene).empty()) {
                methods.push_back(std::move(m));
            }
        }
        std::vector<CrawlSums> sums(methods.size() + 1);  // the last: the exact depth image
        std::vector<double> rmse(methods.size() + 1, 0.0);
        for (int t = 0; t < frames; ++t) {
            const double offset = static_cast<double>(t) / frames;
            const PreparedFrame frame = PreparedFrame::prepare(camera_moved(scene, offset, offset));
            const LineTruth truth = prepare_line_truth(frame, *frame.given().world->edges);
            for (std::size_t k = 0; k < methods.size(); ++k) {
                const Method& m = *methods[k].method;
                const Image shaded = render_scene(m, frame.input_for(m));
                const AfterMethod after = frame.after_method(m, methods[k].spec, shaded);
                sums[k].add(after.edges->lines, truth.drawing);
                rmse[k] +=
                    score_lines(*after.edges, truth.spec, truth.distance, truth.drawing).rmse /
                    frames;
            }
            EdgeImages exact;
            frame.edge_stage(truth.exact_depth, Image(scene.width, scene.height), exact);
            sums.back().add(exact.lines, truth.drawing);
            rmse.back() += truth.exact_scores.rmse / frames;
        }
        ClaimTable t;
        t.header = {fmt::format("{}: depth image of", spec), "line crawl", "line_rmse (mean)"};
        double none_crawl = NAN;
        std::vector<std::pair<std::string, double>> crawls;
        for (std::size_t k = 0; k <= methods.size(); ++k) {
            const std::string name = k < methods.size() ? methods[k].spec : "exact depth";
            const double c = sums[k].crawl(frames);
            t.rows.push_back({"`" + name + "`", claim_number(c), claim_number(rmse[k])});
            if (k < methods.size() && methods[k].id == "none") none_crawl = c;
            crawls.emplace_back(k < methods.size() ? methods[k].id : name, c);
        }
        for (const auto& [name, c] : crawls) {
            if (name == "none" || name == "exact depth") continue;
            r.checks.push_back({CheckKind::kOrdering, fmt::format("{}, {}", spec, name), name, c,
                                "none", none_crawl});
        }
        r.tables.push_back(std::move(t));
    }
    r.finding = fmt::format("{} of {} methods-on-scenes crawl less than `none`", r.checks_holding(),
                            r.checks.size());
    return r;
}

ClaimResult claim_facet_creases(const ClaimsOptions& options) {
    ClaimResult r;
    r.source = "Saito & Takahashi 1990, §6.2(2)";
    r.claim =
        "On curved surfaces approximated by polygons the edge stage draws the facets' creases, "
        "which the smooth surface does not have.";
    r.measure = fmt::format(
        "`torus` at {}² with 48 x 24, 96 x 48 and 192 x 96 facets; the edge stage on the exact "
        "depth image (the operator alone, no method's error). The smooth torus has contours "
        "only, so every crease detection (crease_weight |e| > 0.025) is a facet crease; the "
        "count, its share of the detected line pixels and the contour recall beside it. "
        "Checks: facet creases occur at every facet count.",
        options.size);
    ClaimTable t;
    t.header = {"facets", "crease pixels", "share of line pixels", "contour recall",
                "crease recall (of the facet edges)"};
    for (const auto& [major, minor] : kFacets) {
        const std::string spec =
            fmt::format("torus:major_segments={},minor_segments={}", major, minor);
        const PreparedFrame frame =
            PreparedFrame::prepare(make_pattern(spec, options.size, options.size));
        const LineTruth truth = prepare_line_truth(frame, *frame.given().world->edges);
        EdgeImages edges;
        frame.edge_stage(truth.exact_depth, Image(options.size, options.size), edges);
        const double crease_threshold = kCreaseDetectDarkness / truth.spec.crease_weight;
        long long creases = 0, lines = 0;
        for (std::size_t k = 0; k < edges.p.data.size(); ++k) {
            const bool crease = std::abs(edges.e.data[k]) > crease_threshold;
            const bool contour = edges.p.data[k] > kContourDetectThreshold;
            creases += crease;
            lines += crease || contour;
        }
        const std::string facets = fmt::format("{} x {}", major, minor);
        t.rows.push_back({facets, std::to_string(creases),
                          claim_number(lines > 0 ? static_cast<double>(creases) / lines : NAN),
                          claim_number(truth.exact_scores.contour_recall),
                          claim_number(truth.exact_scores.crease_recall)});
        r.checks.push_back({CheckKind::kOccurrence, "torus " + facets, "facet crease pixels",
                            static_cast<double>(creases), "", 0.0});
    }
    r.tables.push_back(std::move(t));
    r.finding = fmt::format("facet creases drawn at {} of {} facet counts", r.checks_holding(),
                            r.checks.size());
    return r;
}

}  // namespace aabench
