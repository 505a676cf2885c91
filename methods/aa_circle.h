// What the harness may know of aa-circle beyond its registry row (methods/aa_circle.cpp): the
// size of its D[r][y] table, which the row's memory estimate does not expose by itself.
#pragma once

#include <cstddef>

namespace aabench {

// Entries of aa-circle's D[r][y] table for a radius_max (one byte each at alpha_max = 255):
// the benchmark's memory column and the test of the source's size formula.
std::size_t aa_circle_table_entries(int radius_max);

}  // namespace aabench
