// The aliasing symptoms (harness/measure/symptoms.h; definitions in docs/metrics.md).
//
// Two things here are more than a loop:
//
// - The edge band. Testing every pixel against every edge costs pixels x edges (a zone plate
//   has ~10^5 edges). Instead each edge visits only the pixels near it
//   (harness/measure/segment_band.h): the band is exact and the work is O(length x band).
// - The alias spectrum. Parseval makes the total energy a plain sum of squares; only the
//   split below half of Nyquist needs the DFT. The windowed error is zero-padded to an
//   efficient DFT size: the Hann window already brings it to zero at the borders, so padding
//   only samples the same spectrum more finely and leaves the energies unchanged.
#include "harness/measure/symptoms.h"

#include <glm/glm.hpp>

#include "harness/measure/segment_band.h"
#include "harness/world/frame.h"
#include "patterns/scene/curves.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>
#include <opencv2/quality/qualityssim.hpp>
#include <stdexcept>
#include <tbb/parallel_for.h>

namespace aabench {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

void check_same_size(const Image& rendered, const Coverage& reference, const char* what) {
    if (rendered.width != reference.width || rendered.height != reference.height) {
        throw std::invalid_argument(std::string(what) + ": image sizes differ");
    }
}

// Marks the pixels of `mask` whose centre is within d of the segment [a, b].
void mark_segment_band(Point a, Point b, double d, Raster<std::uint8_t>& mask) {
    segment_band::for_each_pixel_near(
        a, b, d, mask.width, mask.height, [&](int i, int j) { return mask.at(i, j) != 0; },
        [&](int i, int j) { mask.at(i, j) = 1; });
}

// Sum over the image of (value - background), in double.
double mass_of(const Image& image, double background) {
    double sum = 0.0;
    for (float v : image.data) sum += static_cast<double>(v) - background;
    return sum;
}

double mass_of(const Coverage& coverage, double background) {
    double sum = 0.0;
    for (double v : coverage.data) sum += v - background;
    return sum;
}

}  // namespace

// ---- 1. Jagged edges ----

Raster<std::uint8_t> edge_band_mask(const Scene& scene, double distance_px) {
    if (!(distance_px >= 0.0) || !std::isfinite(distance_px)) {
        throw std::invalid_argument("edge_band_mask: distance must be finite and >= 0");
    }
    require_window_frame(scene, "edge_band_mask");
    Raster<std::uint8_t> mask(scene.width, scene.height, 0);
    for (const Shape& shape : scene.shapes) {
        for (const Contour& contour : shape.contours) {
            for (std::size_t k = 0; k < contour.size(); ++k) {
                const Point a = contour[k];
                const Point b = contour[(k + 1) % contour.size()];
                mark_segment_band(a, b, distance_px, mask);
            }
        }
    }
    return mask;
}

double edge_rmse(const Image& rendered, const Coverage& reference,
                 const Raster<std::uint8_t>& mask) {
    check_same_size(rendered, reference, "edge_rmse");
    if (mask.width != rendered.width || mask.height != rendered.height) {
        throw std::invalid_argument("edge_rmse: mask size differs from the image");
    }
    double sum = 0.0;
    long long count = 0;
    for (std::size_t k = 0; k < mask.data.size(); ++k) {
        if (!mask.data[k]) continue;
        const double e = static_cast<double>(rendered.data[k]) - reference.data[k];
        sum += e * e;  // a NaN pixel makes the sum NaN: it must never look small
        ++count;
    }
    return count > 0 ? std::sqrt(sum / static_cast<double>(count)) : 0.0;
}

// ---- 2. Captured mass ----

MassReference prepare_mass_reference(const Scene& scene) {
    require_window_frame(scene, "prepare_mass_reference");
    MassReference reference;
    reference.objects.reserve(scene.thin_objects.size());
    for (const ThinObject& object : scene.thin_objects) {
        double x_min = kInf, y_min = kInf, x_max = -kInf, y_max = -kInf;
        for (const Contour& contour : object.shape.contours) {
            for (const Point& p : contour) {
                x_min = std::min(x_min, p.x);
                x_max = std::max(x_max, p.x);
                y_min = std::min(y_min, p.y);
                y_max = std::max(y_max, p.y);
            }
        }
        MassWindow window;
        window.label = object.label;
        window.scene.background = scene.background;
        window.scene.metadata = {{"thin_object", object.label}};
        if (!(x_min <= x_max && y_min <= y_max)) {  // no points: nothing to measure
            window.scene.width = window.scene.height = 1;
            window.exact_mass = 0.0;
            reference.objects.push_back(std::move(window));
            continue;
        }
        // The window starts at whole pixels: moving a scene by an integer changes no
        // coordinate's fraction, so each method draws the object exactly as it would in place.
        const double x0 = std::floor(x_min) - kMassWindowMarginPx;
        const double y0 = std::floor(y_min) - kMassWindowMarginPx;
        const double width = std::ceil(x_max) + kMassWindowMarginPx - x0;
        const double height = std::ceil(y_max) + kMassWindowMarginPx - y0;
        // Capped before the cast (any finite coordinate is allowed); the check then refuses it.
        constexpr double kCap = 2.0 * kMaxImageSide;
        check_image_size(static_cast<long long>(std::min(width, kCap)),
                         static_cast<long long>(std::min(height, kCap)),
                         "thin object '" + object.label + "'");
        window.scene.width = static_cast<int>(width);
        window.scene.height = static_cast<int>(height);
        Shape shape = object.shape;
        // Its contours and, for a curved shape, its Bezier outline (curves.h).
        translate_shape(shape, -x0, -y0);
        window.scene.shapes.push_back(std::move(shape));
        window.exact_mass = mass_of(box_reference(window.scene), scene.background);
        reference.objects.push_back(std::move(window));
    }
    return reference;
}

std::vector<double> captured_masses(const Method& method, const MassReference& reference) {
    std::vector<double> masses;
    masses.reserve(reference.objects.size());
    for (const MassWindow& window : reference.objects) {
        if (!(std::abs(window.exact_mass) > 0.0)) {
            masses.push_back(kNaN);
            continue;
        }
        Image out(window.scene.width, window.scene.height);
        method.render(window.scene, out);
        masses.push_back(mass_of(out, window.scene.background) / window.exact_mass);
    }
    return masses;
}

std::vector<double> captured_masses(const Method& method, const Scene& scene) {
    return captured_masses(method, prepare_mass_reference(scene));
}

MassStats summarise_masses(const MassReference& reference, const std::vector<double>& masses) {
    if (masses.size() != reference.objects.size()) {
        throw std::invalid_argument("summarise_masses: one mass per thin object expected");
    }
    MassStats stats;
    stats.count = static_cast<int>(masses.size());
    if (masses.empty()) {
        stats.worst = stats.max = stats.mean = kNaN;
        return stats;
    }
    stats.worst = kInf;
    stats.max = -kInf;
    double sum = 0.0;
    bool any_nan = false;
    for (std::size_t k = 0; k < masses.size(); ++k) {
        const double m = masses[k];
        if (std::isnan(m)) {
            any_nan = true;
            continue;
        }
        sum += m;
        if (m < stats.worst) {
            stats.worst = m;
            stats.worst_label = reference.objects[k].label;
        }
        if (m > stats.max) {
            stats.max = m;
            stats.max_label = reference.objects[k].label;
        }
    }
    stats.mean = sum / static_cast<double>(masses.size());
    if (any_nan) stats.worst = stats.max = stats.mean = kNaN;
    return stats;
}

// ---- 3. Alias energy ----

AliasEnergy alias_energy(const Image& rendered, const Coverage& reference) {
    check_same_size(rendered, reference, "alias_energy");
    const int w = rendered.width, h = rendered.height;
    // A Hann window of 1 or 2 samples is all zeros: no energy to compare.
    if (w < 3 || h < 3) return {kNaN, kNaN};

    cv::Mat window;
    cv::createHanningWindow(window, cv::Size(w, h), CV_64F);
    const cv::Mat ref(h, w, CV_64F, const_cast<double*>(reference.data.data()));
    const cv::Mat rendered_f(h, w, CV_32F, const_cast<float*>(rendered.data.data()));
    cv::Mat error;
    rendered_f.convertTo(error, CV_64F);
    error -= ref;

    // Remove the error's window-weighted mean (the bias): the windowed error then has an
    // exactly zero DC term, and what remains is the error's pattern.
    const double weighted_mean = window.dot(error) / cv::sum(window)[0];
    error -= weighted_mean;
    error = error.mul(window);
    const cv::Mat ref_windowed = ref.mul(window);
    const double ref_energy = ref_windowed.dot(ref_windowed);

    const int pw = cv::getOptimalDFTSize(w), ph = cv::getOptimalDFTSize(h);
    cv::Mat padded = cv::Mat::zeros(ph, pw, CV_64F);
    error.copyTo(padded(cv::Rect(0, 0, w, h)));
    cv::Mat spectrum;
    cv::dft(padded, spectrum, cv::DFT_COMPLEX_OUTPUT);

    // Parseval: sum |X|^2 = (pw * ph) * sum x^2, so dividing by pw * ph gives energies on the
    // same scale as ref_energy.
    const double limit2 = kLowFrequencyCyclesPerPx * kLowFrequencyCyclesPerPx;
    double total = 0.0, low = 0.0;
    for (int ky = 0; ky < ph; ++ky) {
        const double fy = static_cast<double>(ky <= ph / 2 ? ky : ky - ph) / ph;
        const cv::Vec2d* row = spectrum.ptr<cv::Vec2d>(ky);
        for (int kx = 0; kx < pw; ++kx) {
            const double fx = static_cast<double>(kx <= pw / 2 ? kx : kx - pw) / pw;
            const double power = row[kx][0] * row[kx][0] + row[kx][1] * row[kx][1];
            total += power;
            if (fx * fx + fy * fy < limit2) low += power;
        }
    }
    const double scale = static_cast<double>(pw) * ph;
    total /= scale;
    low /= scale;
    if (!(ref_energy > 0.0)) return {kNaN, kNaN};
    // log10(0) = -inf: an exactly flat error has no pattern at all.
    return {10.0 * std::log10(total / ref_energy), 10.0 * std::log10(low / ref_energy)};
}

// ---- SSIM ----

double ssim(const Image& rendered, const Coverage& reference, double dynamic_range) {
    check_same_size(rendered, reference, "ssim");
    if (!(dynamic_range > 0.0) || !std::isfinite(dynamic_range)) {
        throw std::invalid_argument("ssim: dynamic range must be finite and > 0");
    }
    // OpenCV's SSIM constants are those of 8-bit data, C1 = (0.01 * 255)^2 and
    // C2 = (0.03 * 255)^2: scaling the images so that dynamic_range maps to 255 gives the
    // standard K1 = 0.01, K2 = 0.03 of our range. Both are passed as CV_64F (OpenCV computes
    // in double for 32- and 64-bit input).
    const double scale = 255.0 / dynamic_range;
    const cv::Mat ref(reference.height, reference.width, CV_64F,
                      const_cast<double*>(reference.data.data()));
    const cv::Mat rendered_f(rendered.height, rendered.width, CV_32F,
                             const_cast<float*>(rendered.data.data()));
    cv::Mat ref_scaled, rendered_scaled;
    ref.convertTo(ref_scaled, CV_64F, scale);
    rendered_f.convertTo(rendered_scaled, CV_64F, scale);
    return cv::quality::QualitySSIM::compute(ref_scaled, rendered_scaled, cv::noArray())[0];
}

// ---- 4 and 5. Motion ----

MotionReference prepare_motion_reference(const Scene& scene, int frames,
                                         const ReferenceFn& reference) {
    if (frames < 1) throw std::invalid_argument("prepare_motion_reference: frames must be >= 1");
    MotionReference motion;
    motion.frames = frames;
    // The frames are independent: prepared in parallel (TBB), each at its index.
    std::vector<std::optional<PreparedFrame>> prepared(static_cast<std::size_t>(frames));
    motion.references.resize(static_cast<std::size_t>(frames));
    motion.masses.resize(static_cast<std::size_t>(frames));
    tbb::parallel_for(0, frames, [&](int t) {
        const double offset = static_cast<double>(t) / frames;
        // 3-D: the camera moves, and each frame is prepared anew (its own visible pieces).
        const Scene moved =
            scene.world ? camera_moved(scene, offset, offset) : translated(scene, offset, offset);
        const auto k = static_cast<std::size_t>(t);
        prepared[k].emplace(PreparedFrame::prepare(moved, {.frame_index = t, .time = offset}));
        const SceneInput pieces = prepared[k]->pieces();
        motion.references[k] = reference(pieces);
        motion.masses[k] = prepare_mass_reference(pieces.scene());
    });
    motion.prepared.reserve(static_cast<std::size_t>(frames));
    for (auto& frame : prepared) motion.prepared.push_back(std::move(*frame));
    return motion;
}

MotionStats motion_symptoms(const Method& method, const MotionReference& reference) {
    const int frames = reference.frames;
    if (frames < 1 || reference.prepared.size() != static_cast<std::size_t>(frames) ||
        reference.references.size() != reference.prepared.size() ||
        reference.masses.size() != reference.prepared.size()) {
        throw std::invalid_argument("motion_symptoms: incomplete motion reference");
    }
    const Scene& first = reference.prepared.front().pieces().scene();
    const std::size_t pixels = static_cast<std::size_t>(first.width) * first.height;
    const std::size_t objects = reference.masses.front().objects.size();

    // Welford's running mean and sum of squared deviations per pixel: no cancellation when
    // the error is large and steady and its variation tiny (exact methods).
    std::vector<double> mean(pixels, 0.0), m2(pixels, 0.0);
    std::vector<double> mass_min(objects, kInf), mass_max(objects, -kInf);
    std::vector<bool> mass_nan(objects, false);
    Image out(first.width, first.height);
    for (int t = 0; t < frames; ++t) {
        method.render(reference.prepared[t].input_for(method), out);
        const Coverage& exact = reference.references[t];
        const double n = t + 1;
        for (std::size_t k = 0; k < pixels; ++k) {
            const double e = static_cast<double>(out.data[k]) - exact.data[k];
            const double delta = e - mean[k];
            mean[k] += delta / n;
            m2[k] += delta * (e - mean[k]);
        }
        const std::vector<double> masses = captured_masses(method, reference.masses[t]);
        for (std::size_t o = 0; o < objects; ++o) {
            if (std::isnan(masses[o])) mass_nan[o] = true;
            mass_min[o] = std::min(mass_min[o], masses[o]);
            mass_max[o] = std::max(mass_max[o], masses[o]);
        }
    }

    MotionStats stats;
    stats.frames = frames;
    stats.thin_objects = static_cast<int>(objects);
    double crawl_sum = 0.0;
    for (std::size_t k = 0; k < pixels; ++k) crawl_sum += std::sqrt(m2[k] / frames);
    stats.crawl = crawl_sum / static_cast<double>(pixels);

    if (objects == 0) {
        stats.popping = kNaN;
        return stats;
    }
    stats.popping = 0.0;  // every finite ratio is >= 1, so the first object sets it
    for (std::size_t o = 0; o < objects; ++o) {
        const std::string& label = reference.masses.front().objects[o].label;
        if (mass_nan[o]) {  // never let an unmeasurable object look steady
            stats.popping = kNaN;
            stats.popping_infinite = false;
            stats.popping_worst_label = label;
            return stats;
        }
        if (!(mass_min[o] > 0.0)) {  // vanished in some frame
            if (!stats.popping_infinite) {
                stats.popping_infinite = true;
                stats.popping = kInf;
                stats.popping_worst_label = label;
            }
            continue;
        }
        const double ratio = mass_max[o] / mass_min[o];
        if (!stats.popping_infinite && ratio > stats.popping) {
            stats.popping = ratio;
            stats.popping_worst_label = label;
        }
    }
    return stats;
}

MotionStats motion_symptoms(const Method& method, const Scene& scene, int frames,
                            const ReferenceFn& reference) {
    return motion_symptoms(method, prepare_motion_reference(scene, frames, reference));
}

Raster<std::uint8_t> seam_mask(const SceneInput& in,
                               const std::vector<std::array<Point, 2>>& shared_edges) {
    const Scene& pieces = in.scene();
    Raster<std::uint8_t> mask(pieces.width, pieces.height, 0);
    if (shared_edges.empty()) return mask;
    Scene unit = pieces;
    unit.background = 0.0;
    for (Shape& s : unit.shapes) {
        s.value = 1.0;
        s.value_plane.reset();
    }
    const Coverage covered = box_reference(in.same_kind(unit));  // revalued: still disjoint
    for (const auto& [a, b] : shared_edges) {
        const double len = std::hypot(b.x - a.x, b.y - a.y);
        const long long steps = std::min<long long>(
            static_cast<long long>(std::ceil(len / kSeamStepPx)), 1LL << 24);
        for (long long k = 0; k <= steps; ++k) {
            const double t = steps == 0 ? 0.0 : static_cast<double>(k) / steps;
            const double x = a.x + t * (b.x - a.x), y = a.y + t * (b.y - a.y);
            if (!(x >= 0.0 && y >= 0.0 && x < pieces.width && y < pieces.height)) continue;
            const int i = static_cast<int>(x), j = static_cast<int>(y);
            if (covered.at(i, j) >= 1.0 - kFullCoverageTolerance) mask.at(i, j) = 1;
        }
    }
    return mask;
}

SeamStats seam_error(const Image& rendered, const Coverage& reference,
                     const Raster<std::uint8_t>& mask) {
    SeamStats s;
    double sum = 0.0;
    for (std::size_t p = 0; p < mask.data.size(); ++p) {
        if (!mask.data[p]) continue;
        const double e = std::abs(static_cast<double>(rendered.data[p]) - reference.data[p]);
        // NaN propagates: a non-finite pixel on a seam must not read as "no seam".
        s.worst = (e > s.worst || std::isnan(e)) ? e : s.worst;
        sum += e;
        ++s.pixels;
    }
    if (s.pixels == 0) return {std::nan(""), std::nan(""), 0};
    s.mean = sum / static_cast<double>(s.pixels);
    return s;
}

}  // namespace aabench
