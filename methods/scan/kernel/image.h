// A single-channel raster, row-major, row 0 at the top: pixel (i, j) is at data[j*width + i].
// Methods write Image (float32, linear); references compute in double (Raster<double>). A
// colour scene's images are three of them (Planes, below).
#pragma once

#include <cstddef>
#include <utility>
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

// An image of one plane (a grey scene's) or three (a colour scene's: linear R, G, B, Rec. 709
// primaries; Scene::channels), each of the same size: methods write Planes<float>, references
// compute Planes<double>.
template <class T>
struct Planes {
    std::vector<Raster<T>> planes;

    Planes() = default;
    Planes(int channels, int w, int h, T fill = T(0))
        : planes(static_cast<std::size_t>(channels), Raster<T>(w, h, fill)) {}
    // One plane: a grey image.
    explicit Planes(Raster<T> grey) { planes.push_back(std::move(grey)); }

    int channels() const { return static_cast<int>(planes.size()); }
    int width() const { return planes.empty() ? 0 : planes.front().width; }
    int height() const { return planes.empty() ? 0 : planes.front().height; }
    Raster<T>& operator[](int c) { return planes[static_cast<std::size_t>(c)]; }
    const Raster<T>& operator[](int c) const { return planes[static_cast<std::size_t>(c)]; }
};

using ImagePlanes = Planes<float>;
using CoveragePlanes = Planes<double>;

}  // namespace aabench
