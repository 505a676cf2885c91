#include "patterns/scene.h"

#include <algorithm>

#include <fmt/format.h>

namespace aabench {

std::size_t Scene::edge_count() const {
    std::size_t count = 0;
    for (const Shape& shape : shapes) {
        for (const Contour& contour : shape.contours) count += contour.size();
    }
    return count;
}

std::pair<double, double> Scene::value_range() const {
    double lo = background, hi = background;
    for (const Shape& shape : shapes) {
        lo = std::min(lo, shape.value);
        hi = std::max(hi, shape.value);
    }
    return {lo, hi};
}

void check_image_size(long long width, long long height, const std::string& where) {
    if (width < 1 || height < 1 || width > kMaxImageSide || height > kMaxImageSide) {
        throw InputError(fmt::format("{}: size {}x{} is out of range (each side 1..{})", where,
                                     width, height, kMaxImageSide));
    }
    if (width * height > kMaxImagePixels) {
        throw InputError(fmt::format("{}: size {}x{} has {} pixels, more than the limit of {}",
                                     where, width, height, width * height, kMaxImagePixels));
    }
}

}  // namespace aabench
