// Candidate pairs for exact visibility: the pairs of bounding boxes that overlap with positive
// area, found with a uniform grid rather than by testing all n^2 pairs.
#pragma once

#include <utility>
#include <vector>

#include "harness/reference/convex_split.h"

namespace aabench {

// Every pair (a, b), a < b, with boxes[a].overlaps(boxes[b]), each pair once, sorted. The
// boxes must be finite. Cost O(n + cells + sum over cells of (boxes in the cell)^2).
std::vector<std::pair<int, int>> overlapping_box_pairs(const std::vector<Bounds>& boxes);

}  // namespace aabench
