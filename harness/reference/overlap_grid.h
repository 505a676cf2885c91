// Candidate pairs for exact visibility: the pairs of bounding boxes that overlap with positive
// area, found with a uniform grid rather than by testing all n^2 pairs.
#pragma once

#include <utility>
#include <vector>

#include "harness/reference/convex_split.h"

namespace aabench {

// Every pair (a, b), a < b, with boxes[a].overlaps(boxes[b]), each pair once, sorted (or, when
// `sorted` is false, in the grid's order: a caller that builds partner lists needs no sort).
// The boxes must be finite. Cost O(n + cells + sum over cells of (boxes in the cell)^2).
std::vector<std::pair<int, int>> overlapping_box_pairs(const std::vector<Bounds>& boxes,
                                                       bool sorted = true);

// An upper bound on the number of pairs overlapping_box_pairs() returns, from the same grid's
// cell counts alone (the sum over cells of k(k-1)/2), in O(n + cells) without listing a pair:
// what exact visibility estimates its memory from before it starts.
double box_pair_bound(const std::vector<Bounds>& boxes);

// The number of pairs overlapping_box_pairs() returns, counted without listing them, or
// `stop_after` + 1 as soon as the count passes it (so that a scene of 10^10 pairs is found
// too large in the time of `stop_after` box tests).
double count_box_pairs(const std::vector<Bounds>& boxes, double stop_after);

// The boxes' indices along a Z-order curve of their centres (16 bits per axis over their common
// extent; equal keys keep the given order): boxes near each other in the plane come near each
// other in the order. Exact visibility resolves its sources in this order, so that a source's
// partners come soon after it and what it leaves them waits briefly.
std::vector<int> z_order(const std::vector<Bounds>& boxes);

}  // namespace aabench
