// The accumulation cells of LineIntegralRow (methods/scan/multiscan/subscanline.h), shared by its
// line-by-line sums (subscanline.cpp) and its whole-row sums (subscanline_rows.cpp).
#pragma once

#include <cstddef>
#include <cstdint>

#include "methods/scan/multiscan/subscanline.h"

namespace aabench::detail {

// The pixel holding x > 0 (truncation is floor there, and cheaper than std::floor). Callers
// pass x < width: through a signed integer, one instruction (a double to an unsigned 64-bit
// integer is a test and two paths on x86-64).
inline std::size_t cell_of(double x) {
    return static_cast<std::size_t>(static_cast<std::int64_t>(x));
}

// A change of the value by dv at x adds dv * (c + 1 - x) to the pixel c holding x and the rest
// of dv to pixel c + 1, the last pixel's two cells held in registers (the kernel row's
// HeldPair, methods/scan/kernel/cells.h, which says why). Blocks of kBlockCells cells are
// flagged as they are written; block 0 is always summed (callers write diff[0] directly, a
// change left of the image).
inline constexpr std::size_t kBlockCells = LineCells::kBlock;
using JumpCells = LineCells::HeldPair;

}  // namespace aabench::detail
