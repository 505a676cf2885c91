// A colour scene's three channel values (R, G, B) as one value: what a colour engine carries
// where a grey engine carries a double (a step dv, a cell, a running sum), so that one sweep of
// the geometry composites every channel (docs/colour.md, "Who draws what").
//
// Every operation is the double operation on each component, in the order the expression
// writes it (a * b * c is (a * b) * c on each), so an engine templated on its value type does
// on component c exactly the arithmetic its grey instance does on channel c's scene: the
// planes equal the grey images of the channels bit for bit, wherever the engine's decisions
// (which rows, which chains, which pieces) depend on the geometry alone. Where the grey engine
// skips a step whose value is zero, the colour one skips it only when every component is zero
// and adds the others' +-0 otherwise: a cell or a sum is never -0 once its first block is
// summed (methods/scan/kernel/cells.h, "Why skipping is exact"), so adding a zero changes no bit.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>

#if defined(__SSE2__)
#include <emmintrin.h>
#include <xmmintrin.h>
#endif

namespace aabench {

// One pixel of the three planes: a colour value rounded once to float32 per component, as the
// lanes (R, G, B, 0) of one SSE register.
struct ColourPixel {
#if defined(__SSE2__)
    __m128 rgb0 = _mm_setzero_ps();
    float r() const { return _mm_cvtss_f32(rgb0); }
    float g() const { return _mm_cvtss_f32(_mm_shuffle_ps(rgb0, rgb0, 1)); }
    float b() const { return _mm_cvtss_f32(_mm_shuffle_ps(rgb0, rgb0, 2)); }
#else
    float r_ = 0.0f, g_ = 0.0f, b_ = 0.0f;
    float r() const { return r_; }
    float g() const { return g_; }
    float b() const { return b_; }
#endif
};

// Four doubles, the fourth always +0 (0 + 0, 0 * s and 0 / s are +-0 for the finite s of the
// geometry), as two SSE2 pairs: each operation is two packed instructions, the IEEE operation
// of the scalar code in every lane (the build targets baseline x86-64: SSE2).
struct ChannelValues {
#if defined(__SSE2__)
    __m128d rg = _mm_setzero_pd(), b0 = _mm_setzero_pd();

    ChannelValues() = default;
    ChannelValues(double r, double g, double b) : rg(_mm_set_pd(g, r)), b0(_mm_set_sd(b)) {}
    double operator[](std::size_t c) const {
        alignas(16) double v[4];
        _mm_store_pd(v, rg);
        _mm_store_pd(v + 2, b0);
        return v[c];
    }
    void set(std::size_t c, double value) {
        alignas(16) double v[4];
        _mm_store_pd(v, rg);
        _mm_store_pd(v + 2, b0);
        v[c] = value;
        rg = _mm_load_pd(v);
        b0 = _mm_load_pd(v + 2);
    }
    ChannelValues& operator+=(const ChannelValues& o) {
        rg = _mm_add_pd(rg, o.rg);
        b0 = _mm_add_pd(b0, o.b0);
        return *this;
    }
    friend ChannelValues operator+(ChannelValues a, const ChannelValues& b) { return a += b; }
    friend ChannelValues operator-(const ChannelValues& a, const ChannelValues& b) {
        return from(_mm_sub_pd(a.rg, b.rg), _mm_sub_pd(a.b0, b.b0));
    }
    // IEEE multiplication commutes, so s * a and a * s are the grey code's v * s and s * v.
    friend ChannelValues operator*(const ChannelValues& a, double s) {
        const __m128d ss = _mm_set1_pd(s);
        return from(_mm_mul_pd(a.rg, ss), _mm_mul_pd(a.b0, ss));
    }
    friend ChannelValues operator*(double s, const ChannelValues& a) { return a * s; }
    friend ChannelValues operator/(const ChannelValues& a, double s) {
        const __m128d ss = _mm_set1_pd(s);
        return from(_mm_div_pd(a.rg, ss), _mm_div_pd(a.b0, ss));
    }
    // Each component rounded once to float32 (cvtpd2ps rounds each lane as cvtsd2ss does, by
    // the same MXCSR mode: static_cast<float>).
    ColourPixel rounded() const {
        ColourPixel p;
        p.rgb0 = _mm_movelh_ps(_mm_cvtpd_ps(rg), _mm_cvtpd_ps(b0));
        return p;
    }
    bool zero() const {
        const __m128d z = _mm_setzero_pd();
        return _mm_movemask_pd(_mm_and_pd(_mm_cmpeq_pd(rg, z), _mm_cmpeq_pd(b0, z))) == 3;
    }

private:
    static ChannelValues from(__m128d rg, __m128d b0) {
        ChannelValues v;
        v.rg = rg;
        v.b0 = b0;
        return v;
    }
#else
    std::array<double, 4> v{};

    ChannelValues() = default;
    ChannelValues(double r, double g, double b) : v{r, g, b, 0.0} {}
    double operator[](std::size_t c) const { return v[c]; }
    void set(std::size_t c, double value) { v[c] = value; }
    ChannelValues& operator+=(const ChannelValues& o) {
        for (std::size_t c = 0; c < 4; ++c) v[c] += o.v[c];
        return *this;
    }
    friend ChannelValues operator+(ChannelValues a, const ChannelValues& b) { return a += b; }
    friend ChannelValues operator-(const ChannelValues& a, const ChannelValues& b) {
        ChannelValues r;
        for (std::size_t c = 0; c < 4; ++c) r.v[c] = a.v[c] - b.v[c];
        return r;
    }
    friend ChannelValues operator*(const ChannelValues& a, double s) {
        ChannelValues r;
        for (std::size_t c = 0; c < 4; ++c) r.v[c] = a.v[c] * s;
        return r;
    }
    friend ChannelValues operator*(double s, const ChannelValues& a) { return a * s; }
    friend ChannelValues operator/(const ChannelValues& a, double s) {
        ChannelValues r;
        for (std::size_t c = 0; c < 4; ++c) r.v[c] = a.v[c] / s;
        return r;
    }
    ColourPixel rounded() const {
        ColourPixel p;
        p.r_ = static_cast<float>(v[0]);
        p.g_ = static_cast<float>(v[1]);
        p.b_ = static_cast<float>(v[2]);
        return p;
    }
    bool zero() const { return v[0] == 0.0 && v[1] == 0.0 && v[2] == 0.0; }
#endif
};

// Whether a step of this value changes nothing: the grey engines' `dv != 0.0` tests.
inline bool is_zero(double v) { return v == 0.0; }
inline bool is_zero(const ChannelValues& v) { return v.zero(); }

// Rows of the three planes (R, G, B) at one image row.
using PlaneRows = std::array<float*, 3>;

// The three planes' rows as where a CellRow resolves a colour row (CellRow::RowSink): each
// pixel's components stored to their planes, four pixels at a time where the prefix sum gives
// four (one 16-byte store a plane), a run of one pixel filled in each plane.
struct PlaneSink {
    using Pixel = ColourPixel;
    static constexpr bool kSetsFour = true;
    PlaneRows rows;
    void set(std::size_t i, const ColourPixel& p) const {
        rows[0][i] = p.r();
        rows[1][i] = p.g();
        rows[2][i] = p.b();
    }
    void set4(std::size_t i, ColourPixel p0, ColourPixel p1, ColourPixel p2,
              ColourPixel p3) const {
#if defined(__SSE2__)
        _MM_TRANSPOSE4_PS(p0.rgb0, p1.rgb0, p2.rgb0, p3.rgb0);  // now R, G, B and the zeros
        _mm_storeu_ps(rows[0] + i, p0.rgb0);
        _mm_storeu_ps(rows[1] + i, p1.rgb0);
        _mm_storeu_ps(rows[2] + i, p2.rgb0);
#else
        set(i, p0);
        set(i + 1, p1);
        set(i + 2, p2);
        set(i + 3, p3);
#endif
    }
    ColourPixel get(std::size_t i) const {
        ColourPixel p;
#if defined(__SSE2__)
        p.rgb0 = _mm_setr_ps(rows[0][i], rows[1][i], rows[2][i], 0.0f);
#else
        p.r_ = rows[0][i];
        p.g_ = rows[1][i];
        p.b_ = rows[2][i];
#endif
        return p;
    }
    void fill(std::size_t i0, std::size_t count, const ColourPixel& p) const {
        const float r = p.r(), g = p.g(), b = p.b();
        std::fill(rows[0] + i0, rows[0] + i0 + count, r);
        std::fill(rows[1] + i0, rows[1] + i0 + count, g);
        std::fill(rows[2] + i0, rows[2] + i0 + count, b);
    }
};

}  // namespace aabench
