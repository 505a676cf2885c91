// The line scores (harness/measure/line_scores.h) on hand-made images whose answers are counted
// by hand: a contour along one column, a crease along another, detections placed on purpose.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "harness/measure/line_scores.h"

namespace aabench {
namespace {

constexpr int kW = 20, kH = 20;
// A contour through the centres of column 5, a convex crease through those of column 14.
const std::vector<LineSegment> kLines = {
    {{5.5, 0.0}, {5.5, 20.0}, LineKind::kContour, 0, -1},
    {{14.5, 0.0}, {14.5, 20.0}, LineKind::kConvexCrease, 0, 1},
};

std::vector<LineSegment> of_kind(bool contours) {
    std::vector<LineSegment> out;
    for (const LineSegment& l : kLines) {
        if ((l.kind == LineKind::kContour) == contours) out.push_back(l);
    }
    return out;
}

// p = 1 on the contour's column and on the crease's column in rows 0..9 (a contour drawn where
// there is only a crease); e = 1 on the crease's column.
EdgeImages detections() {
    EdgeImages e{Image(kW, kH), Image(kW, kH), Image(kW, kH),
                 Image(kW, kH), Image(kW, kH), Image(kW, kH)};
    for (int j = 0; j < kH; ++j) {
        e.p.at(5, j) = 1.0f;
        if (j < 10) e.p.at(14, j) = 1.0f;
        e.e.at(14, j) = 1.0f;
    }
    return e;
}

// Counts of whole pixels: the ratios are exact up to one division.
constexpr double kExact = 1e-15;

TEST(LineScores, ContoursAndCreasesApart) {
    const double cap = 2.0 * kMatchRadiusPx;
    const Raster<float> all = distance_to_lines(kLines, kW, kH, cap);
    const Raster<float> contours = distance_to_lines(of_kind(true), kW, kH, cap);
    const Raster<float> creases = distance_to_lines(of_kind(false), kW, kH, cap);
    const EdgeImages e = detections();
    EdgesSpec spec;  // crease_weight 0.5: |e| = 1 is a crease detection
    LineScores s = score_lines(e, spec, all, Coverage(kW, kH));
    // Pooled: every detection lies on some line, every line pixel is found.
    EXPECT_NEAR(s.precision, 1.0, kExact);
    EXPECT_NEAR(s.recall, 1.0, kExact);
    score_line_kinds(e, spec, contours, creases, s);
    // Apart: 30 contour detections, 20 on the contour, 10 on the crease only.
    EXPECT_NEAR(s.contour_precision, 20.0 / 30.0, kExact);
    EXPECT_NEAR(s.contour_recall, 1.0, kExact);
    EXPECT_NEAR(s.crease_precision, 1.0, kExact);
    EXPECT_NEAR(s.crease_recall, 1.0, kExact);

    // No crease operator: no crease detection (precision undefined), no crease found.
    spec.crease = "none";
    score_line_kinds(e, spec, contours, creases, s);
    EXPECT_TRUE(std::isnan(s.crease_precision));
    EXPECT_NEAR(s.crease_recall, 0.0, kExact);
    EXPECT_NEAR(s.contour_precision, 20.0 / 30.0, kExact);

    // The contour detected in rows 0..9 only, and the misplaced detections gone: precision 1.
    EdgeImages half = detections();
    for (int j = 0; j < kH; ++j) {
        if (j >= 10) half.p.at(5, j) = 0.0f;
        half.p.at(14, j) = 0.0f;
    }
    spec.crease = "laplacian8";
    score_line_kinds(half, spec, contours, creases, s);
    EXPECT_NEAR(s.contour_precision, 1.0, kExact);
    // Rows 0..9 found, and row 10 by its 4-neighbour in row 9: 11 of 20.
    EXPECT_NEAR(s.contour_recall, 11.0 / 20.0, kExact);
    EXPECT_THROW(score_line_kinds(half, spec, Raster<float>(kW + 1, kH), creases, s), InputError);
}

}  // namespace
}  // namespace aabench
