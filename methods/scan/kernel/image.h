// A single-channel raster, row-major, row 0 at the top: pixel (i, j) is at data[j*width + i].
// Methods write Image (float32, linear); references compute in double (Raster<double>).
#pragma once

#include <cstddef>
#include <vector>

namespace aabench {

template <class T>
struct Raster {
    int width = 0;
    int height = 0;
    std::vector<T> data;

    Raster() = default;
    Raster(int w, int h, T fill = T(0))
        : width(w), height(h), data(static_cast<std::size_t>(w) * h, fill) {}

    T& at(int i, int j) { return data[static_cast<std::size_t>(j) * width + i]; }
    const T& at(int i, int j) const { return data[static_cast<std::size_t>(j) * width + i]; }
    T* row(int j) { return data.data() + static_cast<std::size_t>(j) * width; }
    const T* row(int j) const { return data.data() + static_cast<std::size_t>(j) * width; }
    std::size_t pixel_count() const { return data.size(); }
};

using Image = Raster<float>;
using Coverage = Raster<double>;

}  // namespace aabench
