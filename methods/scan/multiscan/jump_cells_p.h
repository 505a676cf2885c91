// The accumulation cells of LineIntegralRow (methods/scan/multiscan/subscanline.h), shared by its
// line-by-line sums (subscanline.cpp) and its whole-row sums (subscanline_rows.cpp).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace aabench::detail {

// The pixel holding x > 0 (truncation is floor there, and cheaper than std::floor). Callers
// pass x < width: through a signed integer, one instruction (a double to an unsigned 64-bit
// integer is a test and two paths on x86-64).
inline std::size_t cell_of(double x) {
    return static_cast<std::size_t>(static_cast<std::int64_t>(x));
}

// A change of the value by dv at x adds dv * (c + 1 - x) to the pixel c holding x and the rest
// of dv to pixel c + 1 (whence it reaches every pixel right of it through the prefix sum). The
// two cells are summed in registers while the changes stay in one pixel (a line's changes
// come left to right, and a grating puts two in most pixels): adding to the array change by
// change made every change wait for the store of the one before. Any order is still correct
// (a new pixel flushes the sums), only slower. Flushed by the destructor.
//
// Every block of kBlockCells cells it writes to is marked in `touched` (one byte per block), so
// that the row's prefix sum and its clearing skip the blocks nothing was added to
// (LineIntegralRow::resolve). Block 0 is not marked: callers write diff[0] directly (a change
// left of the image), so the row treats block 0 as always touched.
inline constexpr std::size_t kBlockCells = 8;  // a cache line of doubles

class JumpCells {
public:
    // The vectors' memory, held as pointers: they are not resized while a JumpCells adds.
    JumpCells(std::vector<double>& diff, std::vector<unsigned char>& touched)
        : diff_(diff.data()), touched_(touched.data()) {}
    JumpCells(const JumpCells&) = delete;
    JumpCells& operator=(const JumpCells&) = delete;
    ~JumpCells() { flush(); }

    void add(double x, double dv, int width) {
        if (x <= 0.0) {  // left of the image: every pixel lies right of it
            diff_[0] += dv;
        } else if (x < width) {
            const std::size_t c = cell_of(x);
            const double right = (c + 1.0) - x;  // part of pixel c right of x, in (0, 1]
            add_cell(c, dv * right, dv * (1.0 - right));
        }  // right of the image: no pixel lies right of it
    }
    // Adds `here` to pixel c's cell and `next` to pixel c + 1's (c < width).
    void add_cell(std::size_t c, double here, double next) {
        if (c != cell_) {
            flush();
            cell_ = c;
        }
        here_ += here;
        next_ += next;
    }
    // The same with `after` added to pixel c + 2's cell (the row keeps width + 2 cells).
    // `after` is written at once, not held: holding three cells made every flush write three
    // (slower on gratings, whose changes mostly stay in one pixel); the cost is that changes
    // of one pixel wait for each other's store of c + 2.
    void add_cells(std::size_t c, double here, double next, double after) {
        if (c != cell_) {
            flush();
            cell_ = c;
        }
        here_ += here;
        next_ += next;
        diff_[c + 2] += after;
        touched_[(c + 2) / kBlockCells] = 1;
    }

    // Forgets the sums not yet written (the caller is about to clear the row).
    void discard() {
        cell_ = kNone;
        here_ = next_ = 0.0;
    }

private:
    static constexpr std::size_t kNone = static_cast<std::size_t>(-1);
    void flush() {
        if (cell_ == kNone) return;
        diff_[cell_] += here_;
        diff_[cell_ + 1] += next_;
        touched_[cell_ / kBlockCells] = 1;
        touched_[(cell_ + 1) / kBlockCells] = 1;
        here_ = next_ = 0.0;
    }
    double* diff_;
    unsigned char* touched_;
    std::size_t cell_ = kNone;
    double here_ = 0.0, next_ = 0.0;
};

}  // namespace aabench::detail
