// Scores of a line drawing (the edge stage, Saito & Takahashi 1990) against the ground-truth lines
// (harness/reference/line_reference.h). Pure functions: no I/O. Definitions (docs/edges.md,
// "Scores"):
//   detected   pixels with p > kContourDetectThreshold or crease_weight |e| >
//              kCreaseDetectDarkness (the latter only when the scene draws creases);
//   true       pixels whose centre lies within kTruePixelRadiusPx of a true segment (the pixels
//              a one-pixel-wide line covers at its centre);
//   precision  the fraction of detected pixels whose centre lies within kMatchRadiusPx of a
//              true segment;
//   recall     the fraction of true pixels with a detected pixel within kMatchRadiusPx (centre
//              to centre: itself or a 4-neighbour);
//   line_rmse  sqrt(mean((lines - line_drawing_reference)^2)) over all pixels: the line image
//              against the perfect antialiased line drawing.
// and the same precision and recall for contours and creases apart: detected contour pixels
// (p > kContourDetectThreshold) against the true contours only, detected crease pixels
// (crease_weight |e| > kCreaseDetectDarkness) against the true creases (convex and concave)
// only. A contour pixel found beside a crease is a false contour there.
#pragma once

#include <optional>
#include <vector>

#include "harness/reference/line_reference.h"
#include "harness/world/edges.h"
#include "harness/world/frame.h"
#include "methods/method.h"
#include "methods/scan/kernel/image.h"
#include "patterns/scene/world.h"

namespace aabench {

// p is normalised to [0, 1] by the local range of g (eq. 7): a contour's own pixels reach 1,
// so half of the full range separates a contour from a slope's residue (at most g/k_p there).
inline constexpr double kContourDetectThreshold = 0.5;
// e is l (eq. 8) away from contours, the jump in the slope of depth across a crease, and is
// not normalised: it is drawn as crease_weight |e|. A crease pixel is one that this darkens (or,
// white-convex, lightens) by more than 2.5%, about the smallest step a display shows: with the
// paper's weight 0.5 that is |e| > 0.05. On the torus at 256^2 (exact depth, pixels whose
// centre is within 0.5 px of a true crease and more than 3 px from a contour) |e| reads 0.03 /
// 0.19 / 0.43 at the 5th / 50th / 95th percentile; on its faces, more than 2.5 px from any
// crease, at most 1.4e-4 (float32 rounding of z_s ~ 300): the threshold is 360 times that. A
// scene at another scale scales the weight (the room: docs/edges.md).
inline constexpr double kCreaseDetectDarkness = 0.025;
// A line pixel: its centre within half a pixel of the line (the one-pixel-wide strip).
inline constexpr double kTruePixelRadiusPx = 0.5;
// "Within 1 px" (docs/edges.md, "Scores"): the tolerance of a detection, centre to line or centre
// to centre.
inline constexpr double kMatchRadiusPx = 1.0;

struct LineScores {
    double precision = 0.0;  // NaN when nothing is detected
    double recall = 0.0;     // NaN when there is no true line pixel
    double rmse = 0.0;
    long long detected = 0;
    long long true_pixels = 0;
    // Contours and creases apart (score_line_kinds). NaN as above: nothing detected of the
    // kind, or no true pixel of the kind.
    double contour_precision = 0.0;
    double contour_recall = 0.0;
    double crease_precision = 0.0;
    double crease_recall = 0.0;
};

// The distance from each pixel centre to the nearest segment, up to `cap` (farther: cap).
Raster<float> distance_to_lines(const std::vector<LineSegment>& lines, int width, int height,
                                double cap);

// `distance`: distance_to_lines(lines, ..., cap >= kMatchRadiusPx), computed once per scene.
LineScores score_lines(const EdgeImages& edges, const EdgesSpec& spec,
                       const Raster<float>& distance, const Coverage& line_reference);

// The contour_* and crease_* fields of `scores`, from the distances to the true contours and to
// the true creases alone (distance_to_lines of each kind's segments, cap >= kMatchRadiusPx).
void score_line_kinds(const EdgeImages& edges, const EdgesSpec& spec,
                      const Raster<float>& contour_distance,
                      const Raster<float>& crease_distance, LineScores& scores);

// Everything a comparison needs to score the lines of one scene with `edges`, made once.
struct LineTruth {
    EdgesSpec spec;
    std::vector<LineSegment> lines;
    Raster<float> distance;   // distance_to_lines, capped past kMatchRadiusPx
    Raster<float> contour_distance;  // the same to the contours alone
    Raster<float> crease_distance;   // and to the creases (convex and concave) alone
    Coverage drawing;         // line_drawing_reference in the scene's style
    Image exact_depth;        // the exact box reference of the depth image
    // Scenes with mirrors (the plan's reflections stage): the ray-cast optical-path depth of
    // eq. 9, which the edge stage reads for every method instead of the method's own depth
    // image (so the line scores are the same on every row). The truth has no lines inside
    // reflections (docs/edges.md).
    std::optional<Image> optical_depth;
    LineScores exact_scores;  // the edge stage on exact_depth: what the operator alone loses
};

// From a prepared frame whose plan has the edge stage (a scene with `edges`).
LineTruth prepare_line_truth(const PreparedFrame& frame, const EdgesSpec& spec);

// The stages after the method on `frame` (its own depth image, drawn the way it draws values;
// with mirrors the optical-path depth instead; then the edge stage on it and the shaded image it
// drew), and the scores. nullopt for a method that draws no affine values.
std::optional<LineScores> score_method_lines(const LineTruth& truth, const PreparedFrame& frame,
                                             const Method& method, const std::string& method_name,
                                             const Image& shaded);

// The report's figures of a scene with `edges`: the edge stage on the exact depth image and the
// exact shaded image, in both compositing styles, beside the ground truth.
struct EdgeFigures {
    EdgesSpec spec;
    Image depth;         // the exact depth image z_s (0: background); with mirrors the
                         // optical-path depth of eq. 9, which the figures below come from
    Image p;             // eq. 7 on it
    Image e;             // eq. 8 on it (> 0 convex)
    Image black;         // composite, every edge black (Fig. 3 h')
    Image white_convex;  // composite, convex creases white (Fig. 3 h)
    Image lines;         // the line image in the scene's style
    Image truth;         // line_drawing_reference in the scene's style
};
EdgeFigures edge_figures(const LineTruth& truth, const PreparedFrame& frame,
                         const Coverage& shaded);

}  // namespace aabench
