// Precision, recall and line RMSE of the edge stage's output (line_scores.h).
#include "harness/measure/line_scores.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>
#include <utility>
#include <vector>

#include "harness/reference/box_reference.h"

namespace aabench {
namespace {

// The recall loop below looks at the four neighbours: centres within kMatchRadiusPx = 1 px.
static_assert(kMatchRadiusPx == 1.0);

// Distance from p to the segment a-b.
double segment_distance(double px, double py, const Point& a, const Point& b) {
    const double dx = b.x - a.x, dy = b.y - a.y;
    const double len2 = dx * dx + dy * dy;
    double t = len2 > 0.0 ? ((px - a.x) * dx + (py - a.y) * dy) / len2 : 0.0;
    t = std::clamp(t, 0.0, 1.0);
    return std::hypot(px - (a.x + t * dx), py - (a.y + t * dy));
}

// Precision and recall of the pixels `detected` says yes to, against one distance raster (the
// definitions of line_scores.h). {precision, recall}, NaN for an empty denominator.
std::pair<double, double> precision_recall(const Raster<std::uint8_t>& detected,
                                           const Raster<float>& distance) {
    const int w = detected.width, h = detected.height;
    long long found = 0, matched = 0, truth = 0, recalled = 0;
    for (int j = 0; j < h; ++j) {
        for (int i = 0; i < w; ++i) {
            if (detected.at(i, j)) {
                ++found;
                if (distance.at(i, j) <= kMatchRadiusPx) ++matched;
            }
            if (!(distance.at(i, j) <= kTruePixelRadiusPx)) continue;
            ++truth;
            // Pixel centres within kMatchRadiusPx = 1: itself and its four neighbours.
            if (detected.at(i, j) || (i > 0 && detected.at(i - 1, j)) ||
                (i + 1 < w && detected.at(i + 1, j)) || (j > 0 && detected.at(i, j - 1)) ||
                (j + 1 < h && detected.at(i, j + 1))) {
                ++recalled;
            }
        }
    }
    const double nan = std::numeric_limits<double>::quiet_NaN();
    return {found > 0 ? static_cast<double>(matched) / found : nan,
            truth > 0 ? static_cast<double>(recalled) / truth : nan};
}

std::vector<LineSegment> of_kind(const std::vector<LineSegment>& lines, bool contours) {
    std::vector<LineSegment> out;
    for (const LineSegment& l : lines) {
        if ((l.kind == LineKind::kContour) == contours) out.push_back(l);
    }
    return out;
}

}  // namespace

Raster<float> distance_to_lines(const std::vector<LineSegment>& lines, int width, int height,
                                double cap) {
    Raster<float> dist(width, height, static_cast<float>(cap));
    for (const LineSegment& l : lines) {
        // Only the pixels whose centre can be within `cap`: the segment's box grown by cap.
        const int i0 = std::max(0, static_cast<int>(std::floor(std::min(l.a.x, l.b.x) - cap)));
        const int i1 =
            std::min(width - 1, static_cast<int>(std::ceil(std::max(l.a.x, l.b.x) + cap)));
        const int j0 = std::max(0, static_cast<int>(std::floor(std::min(l.a.y, l.b.y) - cap)));
        const int j1 =
            std::min(height - 1, static_cast<int>(std::ceil(std::max(l.a.y, l.b.y) + cap)));
        for (int j = j0; j <= j1; ++j) {
            for (int i = i0; i <= i1; ++i) {
                const double d = segment_distance(i + 0.5, j + 0.5, l.a, l.b);
                float& cell = dist.at(i, j);
                cell = std::min(cell, static_cast<float>(std::min(d, cap)));
            }
        }
    }
    return dist;
}

LineScores score_lines(const EdgeImages& edges, const EdgesSpec& spec,
                       const Raster<float>& distance, const Coverage& line_reference) {
    const int w = edges.p.width, h = edges.p.height;
    if (distance.width != w || distance.height != h || line_reference.width != w ||
        line_reference.height != h) {
        throw InputError(fmt::format("score_lines: images of {}x{}, truth of {}x{}", w, h,
                                     distance.width, distance.height));
    }
    const bool creases = spec.crease != "none";
    const double crease_threshold = kCreaseDetectDarkness / spec.crease_weight;
    Raster<std::uint8_t> detected(w, h);
    LineScores s;
    long long matched = 0;
    for (int j = 0; j < h; ++j) {
        for (int i = 0; i < w; ++i) {
            // Written so that NaN is not a detection (!(x > t)).
            const bool hit = edges.p.at(i, j) > kContourDetectThreshold ||
                             (creases && std::abs(edges.e.at(i, j)) > crease_threshold);
            if (!hit) continue;
            detected.at(i, j) = 1;
            ++s.detected;
            if (distance.at(i, j) <= kMatchRadiusPx) ++matched;
        }
    }
    long long recalled = 0;
    for (int j = 0; j < h; ++j) {
        for (int i = 0; i < w; ++i) {
            if (!(distance.at(i, j) <= kTruePixelRadiusPx)) continue;
            ++s.true_pixels;
            // Pixel centres within kMatchRadiusPx = 1: itself and its four neighbours.
            const bool found = detected.at(i, j) || (i > 0 && detected.at(i - 1, j)) ||
                               (i + 1 < w && detected.at(i + 1, j)) ||
                               (j > 0 && detected.at(i, j - 1)) ||
                               (j + 1 < h && detected.at(i, j + 1));
            if (found) ++recalled;
        }
    }
    const double nan = std::numeric_limits<double>::quiet_NaN();
    s.precision = s.detected > 0 ? static_cast<double>(matched) / s.detected : nan;
    s.recall = s.true_pixels > 0 ? static_cast<double>(recalled) / s.true_pixels : nan;
    double sum = 0.0;
    for (std::size_t k = 0; k < line_reference.data.size(); ++k) {
        const double d = edges.lines.data[k] - line_reference.data[k];
        sum += d * d;
    }
    s.rmse = std::sqrt(sum / static_cast<double>(line_reference.data.size()));
    return s;
}

void score_line_kinds(const EdgeImages& edges, const EdgesSpec& spec,
                      const Raster<float>& contour_distance,
                      const Raster<float>& crease_distance, LineScores& scores) {
    const int w = edges.p.width, h = edges.p.height;
    for (const Raster<float>* d : {&contour_distance, &crease_distance}) {
        if (d->width != w || d->height != h) {
            throw InputError(fmt::format("score_line_kinds: images of {}x{}, distances of {}x{}",
                                         w, h, d->width, d->height));
        }
    }
    const bool creases = spec.crease != "none";
    const double crease_threshold = kCreaseDetectDarkness / spec.crease_weight;
    Raster<std::uint8_t> contour(w, h), crease(w, h);
    for (int j = 0; j < h; ++j) {
        for (int i = 0; i < w; ++i) {
            // As in score_lines: NaN is not a detection.
            contour.at(i, j) = edges.p.at(i, j) > kContourDetectThreshold;
            crease.at(i, j) = creases && std::abs(edges.e.at(i, j)) > crease_threshold;
        }
    }
    std::tie(scores.contour_precision, scores.contour_recall) =
        precision_recall(contour, contour_distance);
    std::tie(scores.crease_precision, scores.crease_recall) =
        precision_recall(crease, crease_distance);
}

LineTruth prepare_line_truth(const PreparedFrame& frame, const EdgesSpec& spec) {
    if (!frame.has_depth_stage()) {
        throw std::logic_error("prepare_line_truth: the plan has no depth stage");
    }
    LineTruth t;
    t.spec = spec;
    const Scene& depth = frame.depth_pieces().scene();  // read as pieces: box_reference_of_pieces
    const int w = depth.width, h = depth.height;
    t.optical_depth = frame.optical_depth();
    t.lines = true_lines(depth);
    // Capped just past the match radius: farther distances are never looked at.
    t.distance = distance_to_lines(t.lines, w, h, 2.0 * kMatchRadiusPx);
    t.contour_distance = distance_to_lines(of_kind(t.lines, true), w, h, 2.0 * kMatchRadiusPx);
    t.crease_distance = distance_to_lines(of_kind(t.lines, false), w, h, 2.0 * kMatchRadiusPx);
    t.drawing = line_drawing_reference(line_coverage(t.lines, w, h), spec);
    const Coverage exact = box_reference_of_pieces(depth);
    t.exact_depth = Image(w, h);
    for (std::size_t k = 0; k < exact.data.size(); ++k) {
        t.exact_depth.data[k] = static_cast<float>(exact.data[k]);
    }
    // The scores read p, e and the line image, none of which depends on the shaded image.
    EdgeImages edges;
    frame.edge_stage(t.exact_depth, Image(w, h), edges, &spec);
    t.exact_scores = score_lines(edges, spec, t.distance, t.drawing);
    score_line_kinds(edges, spec, t.contour_distance, t.crease_distance, t.exact_scores);
    return t;
}

std::optional<LineScores> score_method_lines(const LineTruth& truth, const PreparedFrame& frame,
                                             const Method& method, const std::string& method_name,
                                             const Image& shaded) {
    if (!method.affine_values()) return std::nullopt;
    const AfterMethod after = frame.after_method(method, method_name, shaded);
    LineScores s = score_lines(*after.edges, truth.spec, truth.distance, truth.drawing);
    // With mirrors (the optical-path depth) only the overall scores are made, as always.
    if (!truth.optical_depth) {
        score_line_kinds(*after.edges, truth.spec, truth.contour_distance, truth.crease_distance,
                         s);
    }
    return s;
}

EdgeFigures edge_figures(const LineTruth& truth, const PreparedFrame& frame,
                         const Coverage& shaded) {
    EdgeFigures f;
    f.spec = truth.spec;
    f.depth = truth.exact_depth;
    Image s(shaded.width, shaded.height);
    for (std::size_t k = 0; k < s.data.size(); ++k) s.data[k] = static_cast<float>(shaded.data[k]);
    EdgesSpec black = truth.spec, white = truth.spec;
    black.style = "black";
    white.style = "white-convex";
    // With mirrors, the depth the edge stage reads is the optical-path depth (eq. 9).
    const Image& depth = truth.optical_depth ? *truth.optical_depth : truth.exact_depth;
    if (truth.optical_depth) f.depth = *truth.optical_depth;
    EdgeImages b, w;
    frame.edge_stage(depth, s, b, &black);
    frame.edge_stage(depth, s, w, &white);
    f.p = std::move(b.p);
    f.e = std::move(b.e);
    f.black = std::move(b.composite);
    f.white_convex = std::move(w.composite);
    f.lines = truth.spec.style == "black" ? std::move(b.lines) : std::move(w.lines);
    f.truth = Image(s.width, s.height);
    for (std::size_t k = 0; k < s.data.size(); ++k) {
        f.truth.data[k] = static_cast<float>(truth.drawing.data[k]);
    }
    return f;
}

}  // namespace aabench
