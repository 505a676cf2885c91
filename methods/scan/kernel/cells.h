// One row of accumulation cells: the difference array every scan engine and reference of the
// suite adds to, and the prefix sum that turns it into pixel values.
//
// What a cell holds. Cell i holds the change of the pixel value at pixel i: what pixel i has
// more than pixel i - 1, so that pixel i's value is start + cells 0..i (base() is what every
// pixel starts from, cell -1 in effect). An edge, a change of a sample row's value, a jump of
// a sub-scanline's visible value: each is a step of the value at some x, and a step by dv at x
// inside pixel c adds dv times the part of pixel c right of x to cell c and the rest of dv to
// cell c + 1 (from where the prefix sum carries it to every pixel right of it). That is the
// "cover and area" cell of FreeType's smooth rasterizer (ftgrays.c), folded into one number:
// ftgrays keeps (cover, area) per cell and its sweep carries the cover along the row; here the
// area part goes to cell c and the rest of the cover to cell c + 1, so that the sweep is a
// plain prefix sum. What a cell is:
//   - double: the area cells of `exact` (area_cover_row.h), the sub-scanline rows of
//     box-multiscan (multiscan/jump_cells_p.h), the box reference (reference/box_coverage.cpp),
//     the jump-set average of the radial references (harness/reference/filter_reference.cpp);
//   - RowPair (two doubles): gauss-multiscan's region rows, whose change writes the pixel row
//     above and the one below it side by side (multiscan/region_rows.h);
//   - ChannelValues (a colour scene's R, G, B as one value, kernel/channel_values.h): the area
//     cells of `exact`'s colour rows, each component the grey row of its channel bit for bit,
//     resolved into three planes through a RowSink (below);
//   - std::int64_t: the run sums of `ssaa` and `nishita-d` in units of 2^e
//     (sampling/run_sums.h);
//   - double pixel values, not changes (Prefix::kNone): the Gaussian supersamplers' rows
//     (methods/ssaa/accumulator_ring_p.h).
//
// Touched blocks. The cells are flagged in blocks of kBlock (one byte a block; a byte that is
// not a char, which would alias every pointer); the prefix sum runs only through flagged
// blocks, a run of unflagged blocks is one fill of the last value (found eight flags at a time),
// and only flagged blocks are zeroed. Strips, gratings and stars touch a few blocks a row, and
// filling or summing every cell of every row was a tenth to a half of their renders. Block 0 is
// always summed and zeroed, so a step left of the image may be written to cell 0 unflagged
// (operator[]): such steps come from every row of a shape left of the image, and the flag's
// store would cost each of them. A block holds 16 cells in `exact` (its pieces reach three
// cells), 8 (a cache line of doubles) in the multi-scans and references, 1 in the run sums,
// whose per-pixel function may be a window sum (nishita-d's fallback): it is called only at
// pixel 0 and at flagged pixels.
//
// Why skipping is exact. An unflagged block's cells are +0.0, and sum + 0.0 == sum for every
// sum except -0.0; the sums start from a background or a sum from +0.0 (round to nearest never
// gives -0.0 from them) and the first block is always summed, so skipping changes no bit (a
// background of -0.0 comes out +0.0, as it did wherever a row's first cell was summed).
// Every pixel of an unflagged run is given the value its left neighbour was given, the same
// function of the same sum: the per-pixel function must depend on the sum alone there (the
// run sums call it at flagged pixels only, as they always did: sampling/run_sums.h).
//
// The rounding, and its order (the images are hashed, so it is fixed):
//   - the cells receive their steps in the order the engine gives them (each engine says
//     which: pieces in the order of the edges, changes left to right), each one rounding of
//     a double addition;
//   - Prefix::kInOrder: sum += cell[i], pixel by pixel from the start value: the multi-scans,
//     the references and the run sums;
//   - Prefix::kFourWide: four cells summed apart, then added to the running sum (`exact`,
//     whose prefix sum was the whole render on small images of few edges): pixel i + 1 gets
//     sum + (a0 + a1), pixel i + 3 sum + ((a0 + a1) + (a2 + a3)); it differs from kInOrder by
//     ulps of a double, far below float32's rounding (docs/architecture.md, the 1e-6 budget);
//   - the pixel value is the sum rounded once, to float32 or (the references) not at all.
// In double a row of 400 unit steps (rings) carries about 400 * 2^-53 = 4.4e-14 of rounding;
// in float it would be 2.4e-5, 24 times the 1e-6 budget, which is why cells are never float.
//
// Where the bit widths run out. Doubles: no exactness is claimed, only the rounding above. The
// integer cells are exact until a sum passes 2^63: the run sums keep every value below 2^20
// units and a pixel's sum below 64^2 samples of it, 2^32, and DyadicValues keeps it below 2^53
// so that the double it is converted to is exact too (sampling/run_sums.h). Indices: cells
// 0..width + 1 exist (an engine's step may reach two cells past the last pixel's), in whole
// words of kFlagWord blocks.
#pragma once

#include <algorithm>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <vector>

namespace aabench {

// How resolve() turns cells into pixel values (see the essay above).
enum class Prefix { kInOrder, kFourWide, kNone };

template <class Cell, std::size_t kBlockCells>
class CellRow {
public:
    static constexpr std::size_t kBlock = kBlockCells;
    // Flags read as one 64-bit word when a run of unflagged blocks is skipped.
    static constexpr std::size_t kFlagWord = 8;
    // A byte, but not a char (see the essay).
    enum class Flag : std::uint8_t { kClear = 0, kSet = 1 };

    // A row of `width` pixels, every cell zero, reusing the memory held (no allocation once it
    // has held a row this wide).
    void reset(int width) {
        width_ = width;
        constexpr std::size_t kWordCells = kFlagWord * kBlock;
        const std::size_t words =
            (static_cast<std::size_t>(width) + kSpareCells + kWordCells - 1) / kWordCells;
        cells_.assign(words * kWordCells, Cell{});
        flags_.assign(words * kFlagWord, Flag::kClear);
        base_ = Cell{};
    }
    int width() const { return width_; }

    // Zeroes what was added (the flagged blocks and block 0) and the base.
    void clear() {
        base_ = Cell{};
        for (std::size_t b = 0; b < flags_.size(); b = next_flagged(b + 1)) zero_block(b);
    }
    // Zeroes every cell, flagged or not (rows written unflagged throughout: affine lines).
    void clear_all() {
        base_ = Cell{};
        std::fill(cells_.begin(), cells_.end(), Cell{});
        std::fill(flags_.begin(), flags_.end(), Flag::kClear);
    }
    // Flags every block (rows whose every cell is written: Prefix::kNone).
    void flag_all() { std::fill(flags_.begin(), flags_.end(), Flag::kSet); }

    // What every pixel starts from (cell -1 in effect); the caller adds it to resolve()'s start.
    Cell& base() { return base_; }
    const Cell& base() const { return base_; }

    // Unflagged access: cell 0 (always summed), or cells of a row written dense (clear_all()).
    Cell& operator[](std::size_t i) { return cells_[i]; }
    const Cell& operator[](std::size_t i) const { return cells_[i]; }
    Cell* cells() { return cells_.data(); }
    const Cell* cells() const { return cells_.data(); }
    Flag* flags() { return flags_.data(); }
    const Flag* flags() const { return flags_.data(); }

    // What an engine's loop over its steps writes through: the two pointers held in registers
    // (through the row they would be reloaded after every store).
    class Writer {
    public:
        void add(std::size_t i, Cell amount) const {
            cells_[i] += amount;
            flags_[i / kBlock] = Flag::kSet;
        }
        void flag(std::size_t i) const { flags_[i / kBlock] = Flag::kSet; }
        // Flags the blocks of cells first..last (first <= last): the two ends, then any between.
        // Nearly every range is one or two blocks, and GCC turns a loop over all of them into a
        // call to memset (a near-horizontal edge's run of cells cost a third more).
        void flag_range(std::size_t first, std::size_t last) const {
            const std::size_t b0 = first / kBlock, b1 = last / kBlock;
            flags_[b0] = Flag::kSet;
            flags_[b1] = Flag::kSet;
            for (std::size_t b = b0 + 1; b < b1; ++b) flags_[b] = Flag::kSet;
        }
        Cell* cells() const { return cells_; }
        Flag* flags() const { return flags_; }

    private:
        friend class CellRow;
        Writer(Cell* cells, Flag* flags) : cells_(cells), flags_(flags) {}
        Cell* cells_;
        Flag* flags_;
    };
    Writer writer() { return {cells_.data(), flags_.data()}; }

    // Steps of a value along a line (double cells): a step by dv at x adds dv (c + 1 - x) to
    // the pixel c holding x and the rest of dv to pixel c + 1. The two cells are summed in
    // registers while the steps stay in one pixel (a line's steps come left to right, and a
    // grating puts two in most pixels): adding to the array step by step made every step wait
    // for the store of the one before. Any order is still correct (a new pixel flushes the
    // sums), only slower. Flushed by the destructor; the row is not resized meanwhile.
    class HeldPair {
    public:
        explicit HeldPair(CellRow& row) : cells_(row.cells_.data()), flags_(row.flags_.data()) {}
        HeldPair(const HeldPair&) = delete;
        HeldPair& operator=(const HeldPair&) = delete;
        ~HeldPair() { flush(); }

        void add(double x, double dv, int width) {
            if (x <= 0.0) {  // left of the image: every pixel lies right of it (cell 0 unflagged)
                cells_[0] += dv;
            } else if (x < width) {
                // x > 0: truncation is floor, through a signed integer (one instruction).
                const auto c = static_cast<std::size_t>(static_cast<std::int64_t>(x));
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
        // The same with `after` added to pixel c + 2's cell. `after` is written at once, not
        // held: holding three cells made every flush write three (slower on gratings, whose
        // steps mostly stay in one pixel); the cost is that steps of one pixel wait for each
        // other's store of c + 2.
        void add_cells(std::size_t c, double here, double next, double after) {
            if (c != cell_) {
                flush();
                cell_ = c;
            }
            here_ += here;
            next_ += next;
            cells_[c + 2] += after;
            flags_[(c + 2) / kBlock] = Flag::kSet;
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
            cells_[cell_] += here_;
            cells_[cell_ + 1] += next_;
            flags_[cell_ / kBlock] = Flag::kSet;
            flags_[(cell_ + 1) / kBlock] = Flag::kSet;
            here_ = next_ = 0.0;
        }
        Cell* cells_;
        Flag* flags_;
        std::size_t cell_ = kNone;
        double here_ = 0.0, next_ = 0.0;
    };

    // out[i] = value(i, sum_i) for the pixels i of the row, sum_i = start + the terms 0..i in
    // kOrder (with Prefix::kNone, sum_i = term i alone); term(i) is cell i unless given (a pair
    // of rows combined). A block flagged in neither this row nor `also` (a row resolved with
    // it, or nullptr) copies the value last written. Reads only. `out` is a T* or a RowSink
    // (below).
    template <Prefix kOrder = Prefix::kInOrder, class Sum, class Out, class Value>
    void resolve(Sum start, Out out, Value value) const {
        const_cast<CellRow*>(this)->sweep<kOrder, false>(
            start, out, value, [this](std::size_t i) { return cells_[i]; }, nullptr);
    }
    // resolve(), each summed block zeroed and unflagged as soon as it is read, and the blocks
    // past the last pixel after the row, and the base: the row is clear() after it (one pass
    // over flags and cells, not two: a second one was a tenth of box-multiscan's render on
    // star, a fifth of gauss-multiscan's).
    template <Prefix kOrder = Prefix::kInOrder, class Sum, class Out, class Value>
    void resolve_and_clear(Sum start, Out out, Value value) {
        sweep<kOrder, true>(
            start, out, value, [this](std::size_t i) { return cells_[i]; }, nullptr);
    }
    template <Prefix kOrder = Prefix::kInOrder, class Sum, class Out, class Value, class Term>
    void resolve_and_clear(Sum start, Out out, Value value, Term term, const CellRow* also) {
        sweep<kOrder, true>(start, out, value, term, also ? also->flags_.data() : nullptr);
    }

private:
    // Cells 0..width + 1: a step's cells reach two past its pixel's.
    static constexpr std::size_t kSpareCells = 2;

    void zero_block(std::size_t b) {
        Cell* block = cells_.data() + b * kBlock;
        for (std::size_t k = 0; k < kBlock; ++k) block[k] = Cell{};  // vectorised
        flags_[b] = Flag::kClear;
    }
    static std::uint64_t flag_word(const Flag* flags) {
        std::uint64_t word;
        std::memcpy(&word, flags, sizeof word);
        return word;
    }
    // The first block >= b flagged here (or in `also`), or the number of blocks.
    std::size_t next_flagged(std::size_t b, const Flag* also = nullptr) const {
        const std::size_t blocks = flags_.size();
        const Flag* flags = flags_.data();
        for (; b < blocks && b % kFlagWord != 0; ++b) {
            if (flags[b] != Flag::kClear || (also && also[b] != Flag::kClear)) return b;
        }
        for (; b < blocks; b += kFlagWord) {
            const std::uint64_t word = flag_word(flags + b) | (also ? flag_word(also + b) : 0);
            if (word != 0) {
                // Little-endian: the lowest byte is the first block (x86-64, the build target).
                return b + static_cast<std::size_t>(std::countr_zero(word)) / 8;
            }
        }
        return blocks;
    }

    template <Prefix kOrder, bool kClear, class Sum, class Out, class Value, class Term>
    [[gnu::always_inline]] void sweep(Sum sum, Out out, Value value, Term term, const Flag* also) {
        const std::size_t width = static_cast<std::size_t>(width_);
        typename RowSink<Out>::Pixel last{};
        std::size_t b = 0;
        while (b * kBlock < width) {
            const std::size_t i0 = b * kBlock;
            if (b != 0 && flags_[b] == Flag::kClear && !(also && also[b] != Flag::kClear)) {
                const std::size_t e = next_flagged(b + 1, also);
                RowSink<Out>::fill(out, i0, std::min(e * kBlock, width) - i0, last);
                b = e;
                continue;
            }
            if (i0 + kBlock <= width) {
                sum_block<kOrder, kBlock>(sum, out, i0, value, term);
            } else {
                sum_block<kOrder, 0>(sum, out, i0, value, term, width - i0);
            }
            last = RowSink<Out>::get(out, std::min(i0 + kBlock, width) - 1);
            if constexpr (kClear) zero_block(b);
            ++b;
        }
        if constexpr (kClear) {
            // The partial block and those past it (cells width, width + 1 take steps too).
            base_ = Cell{};
            if (b == 0 && b < flags_.size()) zero_block(b++);
            for (b = next_flagged(b); b < flags_.size(); b = next_flagged(b + 1)) zero_block(b);
        }
    }

public:
    // `count` copies of `value` from out on: whole chunks of 64, then of 8 (unrolled stores; a
    // loop of variable length was a fifth slower on strips), then the rest.
    template <class T>
    [[gnu::always_inline]] static void fill(T* out, std::size_t count, T value) {
        constexpr std::size_t kChunk = 64;
        std::size_t k = 0;
        for (; k + kChunk <= count; k += kChunk) {
            for (std::size_t c = 0; c < kChunk; ++c) out[k + c] = value;
        }
        for (; k + 8 <= count; k += 8) {
            for (std::size_t c = 0; c < 8; ++c) out[k + c] = value;
        }
        for (; k < count; ++k) out[k] = value;
    }

    // Where resolve() writes: a row of T (out[i]), or a sink of several rows that says how to
    // set, read back and fill a pixel (Sink::Pixel, set, get, fill: a colour row's three
    // planes, each pixel's components to its own plane).
    template <class Out>
    struct RowSink {
        using Pixel = typename Out::Pixel;
        static void set(Out& out, std::size_t i, const Pixel& v) { out.set(i, v); }
        static Pixel get(const Out& out, std::size_t i) { return out.get(i); }
        static void fill(Out& out, std::size_t i0, std::size_t count, const Pixel& v) {
            out.fill(i0, count, v);
        }
    };
    template <class T>
    struct RowSink<T*> {
        using Pixel = T;
        [[gnu::always_inline]] static void set(T* out, std::size_t i, const T& v) { out[i] = v; }
        [[gnu::always_inline]] static T get(T* out, std::size_t i) { return out[i]; }
        [[gnu::always_inline]] static void fill(T* out, std::size_t i0, std::size_t count,
                                                T v) {
            CellRow::fill(out + i0, count, v);
        }
    };

private:
    // The pixels i0 .. i0 + count - 1 of one block (kCount of them when kCount > 0: a loop of
    // fixed length, unrolled).
    template <Prefix kOrder, std::size_t kCount, class Sum, class Out, class Value, class Term>
    [[gnu::always_inline]] static void sum_block(Sum& sum, Out& out, std::size_t i0, Value& value,
                                                 Term& term, std::size_t count = kCount) {
        using Sink = RowSink<Out>;
        if constexpr (kCount > 0) count = kCount;
        const std::size_t i1 = i0 + count;
        std::size_t i = i0;
        if constexpr (kOrder == Prefix::kFourWide) {
            // The partial sums of four cells are independent of `sum`: the chain of
            // dependent additions is one per four pixels, not one per pixel.
            for (; i + 4 <= i1; i += 4) {
                const Sum a0 = term(i), a1 = term(i + 1), a2 = term(i + 2), a3 = term(i + 3);
                const Sum p1 = a0 + a1;
                const Sum p2 = p1 + a2;
                const Sum p3 = p1 + (a2 + a3);
                if constexpr (requires { Out::kSetsFour; }) {  // a sink storing four at once
                    out.set4(i, value(i, sum + a0), value(i + 1, sum + p1),
                             value(i + 2, sum + p2), value(i + 3, sum + p3));
                } else {
                    Sink::set(out, i, value(i, sum + a0));
                    Sink::set(out, i + 1, value(i + 1, sum + p1));
                    Sink::set(out, i + 2, value(i + 2, sum + p2));
                    Sink::set(out, i + 3, value(i + 3, sum + p3));
                }
                sum += p3;
            }
        }
        for (; i < i1; ++i) {
            if constexpr (kOrder == Prefix::kNone) {
                Sink::set(out, i, value(i, term(i)));
            } else {
                sum += term(i);
                Sink::set(out, i, value(i, sum));
            }
        }
    }

    int width_ = 0;
    std::vector<Cell> cells_;  // width + kSpareCells or more, in whole words of blocks
    std::vector<Flag> flags_;  // per block; block 0 is always summed and zeroed
    Cell base_{};
};

}  // namespace aabench
