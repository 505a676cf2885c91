// The five aliasing symptoms Nishita & Nakamae (1984) name, and SSIM, as figures of a rendered
// image (or a method) against the exact reference. Pure functions: no I/O. The definitions,
// constants and how to read each figure are in docs/metrics.md ("The aliasing symptoms").
//
//   1 jagged edges        edge_rmse over edge_band_mask: the error where antialiasing acts
//   2 thin objects vanish dropout (harness/measure/metrics.h) and captured_masses / summarise_masses
//   3 moire               alias_energy: the error's power spectrum, all of it and below half
//                         of Nyquist, in dB relative to the reference's energy
//   4 crawling edges      motion_symptoms().crawl: per-pixel standard deviation over sub-pixel
//                         offsets of (method - reference), averaged over the image
//   5 popping             motion_symptoms().popping: each thin object's captured mass over the
//                         offsets, worst max/min ratio (infinite when it vanishes in a frame)
//   SSIM                  ssim: cv::quality::QualitySSIM with 8-bit constants rescaled
//   seams (3-D)           seam_error over seam_mask: the error on edges two visible faces of
//                         one object share, where the exact answer has no background at all
//
// Costly parts come in two steps so that a comparison of many methods on one pattern pays for
// the exact answers once: prepare_mass_reference and prepare_motion_reference hold what does
// not depend on the method (translated scenes, their references, exact masses).
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "harness/reference/box_reference.h"
#include "harness/world/frame.h"
#include "harness/world/sequence.h"
#include "methods/method.h"
#include "methods/scan/kernel/image.h"
#include "patterns/scene/scene.h"

namespace aabench {

// ---- Seams (conflation, 3-D scenes) ----

// A pixel counts as wholly covered when the exact coverage of the visible pieces is within
// this of 1: the box reference is exact to ~1e-12 per pixel, so 1e-9 keeps every pixel that
// is covered and no pixel with a real gap (a gap of 1e-9 px^2 could not show in any method).
inline constexpr double kFullCoverageTolerance = 1e-9;
// Shared edges are walked in steps of this length (px) to find the pixels they cross: 1/16 px
// reaches every pixel the edge passes through by more than a 1/16-px corner.
inline constexpr double kSeamStepPx = 1.0 / 16.0;

// 1 where a shared edge crosses the pixel and the pieces cover the pixel wholly (so the exact
// answer there has no background: any background in a method's pixel is conflation).
Raster<std::uint8_t> seam_mask(const SceneInput& pieces,
                               const std::vector<std::array<Point, 2>>& shared_edges);

struct SeamStats {
    double worst = 0.0;  // max |rendered - reference| over the mask
    double mean = 0.0;   // mean |rendered - reference| over the mask
    long long pixels = 0;
};
// NaN worst and mean when the mask is empty (no shared edge in view).
SeamStats seam_error(const Image& rendered, const Coverage& reference,
                     const Raster<std::uint8_t>& mask);

// ---- 1. Jagged edges ----

// Half-width of the edge band: pixels whose centre lies within 1.5 px of an edge. A one-pixel
// filter changes pixels up to about 1 px from an edge; 1.5 px adds the half pixel between a
// pixel's centre and its side, so every pixel an edge touches is in the band, and interiors
// (which say nothing about antialiasing) are out.
inline constexpr double kEdgeBandPx = 1.5;

// 1 where the pixel centre (i + 0.5, j + 0.5) is within `distance_px` (inclusive) of some
// contour edge of some shape (closing edges included), else 0. Distances are exact
// point-segment distances; the cost is O(edge length x band width), not O(pixels x edges).
// Every contour edge counts, also one hidden under a later shape (no built-in pattern has one).
Raster<std::uint8_t> edge_band_mask(const Scene& scene, double distance_px = kEdgeBandPx);

// sqrt(mean over the masked pixels of (rendered - reference)^2), summed in double. 0 when the
// mask is empty (a scene without edges has nothing to be jagged); NaN when a masked pixel is.
double edge_rmse(const Image& rendered, const Coverage& reference,
                 const Raster<std::uint8_t>& mask);

// ---- 2. Vanishing thin objects: captured mass ----

// Margin around each thin object's bounding box in its measuring window: more than any
// method's reach (every registered filter has a radius of 1 px), so the window holds all that
// the object contributes to, with room for a wider filter.
inline constexpr int kMassWindowMarginPx = 4;

// One thin object alone, translated by whole pixels into a small window of its own.
struct MassWindow {
    std::string label;
    Scene scene;        // the object as the only shape, on the original background
    double exact_mass;  // sum over the window of (box reference - background)
};

// What captured_masses needs that does not depend on the method: one window per thin object.
struct MassReference {
    std::vector<MassWindow> objects;
};

MassReference prepare_mass_reference(const Scene& scene);

// For each thin object in order: sum over its window of (rendered - background) / exact_mass.
// 1 is a perfect capture, 0 a vanished object; NaN when the object has no exact mass (value
// equal to the background, or no area).
std::vector<double> captured_masses(const Method& method, const MassReference& reference);
std::vector<double> captured_masses(const Method& method, const Scene& scene);

// Summary of captured masses. `worst` is the smallest ratio (the symptom is vanishing, so the
// object that kept least is the one to look at), `max` the largest (an object drawn too heavy
// shows there), `mean` the plain mean. count = 0 gives NaN figures and empty labels; any NaN
// mass makes worst, max and mean NaN (a NaN must never look like a good capture).
struct MassStats {
    double worst = 0.0;
    std::string worst_label;
    double max = 0.0;
    std::string max_label;
    double mean = 0.0;
    int count = 0;
};
MassStats summarise_masses(const MassReference& reference, const std::vector<double>& masses);

// ---- 3. Moire: alias energy ----

// Half of Nyquist (0.5 cycles/px): error energy at radial frequencies below this is the slow,
// large-scale pattern the eye reads as moire.
inline constexpr double kLowFrequencyCyclesPerPx = 0.25;

// total_db = 10 log10(E_err / E_ref), low_db = 10 log10(E_low / E_ref), where, with w the 2-D
// Hann window (cv::createHanningWindow) and e = rendered - reference:
//   E_err = energy of w * (e - weighted mean of e): the error pattern; the error's mean is
//           the bias, reported by compare_to_reference, and a uniform offset is no pattern;
//   E_low = the part of E_err at radial frequencies |f| < kLowFrequencyCyclesPerPx (cv::dft);
//   E_ref = energy of w * reference, mean included: the image's own energy, which never
//           vanishes for a non-black reference (a box-filtered grating at the pixel pitch is
//           nearly flat, so its mean-free energy would be a degenerate yardstick).
// -inf when the error is exactly flat; NaN when E_ref = 0 (an all-zero reference).
struct AliasEnergy {
    double total_db = 0.0;
    double low_db = 0.0;
};
AliasEnergy alias_energy(const Image& rendered, const Coverage& reference);

// ---- SSIM ----

// Mean SSIM (11x11 Gaussian window, sigma 1.5; K1 = 0.01, K2 = 0.03 of `dynamic_range`) by
// cv::quality::QualitySSIM. OpenCV hard-codes the constants for 8-bit data (C1 = (0.01*255)^2),
// so both images are scaled by 255 / dynamic_range first; the built-in patterns' range is 1.
// 1 for identical images, lower otherwise.
double ssim(const Image& rendered, const Coverage& reference, double dynamic_range = 1.0);

// ---- 4 and 5. Motion: crawling edges and popping ----

// Default number of frames: 16 offsets over one pixel, finer than any method's sub-pixel
// pattern at the defaults (ssaa k = 4, nishita-d 3x3, multiscan n <= 12 in y), so a method's
// error is seen at many phases of its grid.
inline constexpr int kMotionFrames = 16;

// translated() and camera_moved(), the motions of the crawl and popping frames, are
// harness/world/sequence.h's (a sequence moves scenes the same way).

using ReferenceFn = std::function<Coverage(const SceneInput&)>;

// What motion_symptoms needs that does not depend on the method. Frame t (t = 0 .. frames-1)
// is the scene moved by (t / frames, t / frames): a diagonal path over one pixel. A 2-D scene
// is translated; a 3-D scene (scene.world) is filmed with its camera moved (camera_moved) and
// each frame goes through the world stages again: its visible pieces in `scenes`, its
// ScreenScene in `screens` (what methods with their own visibility draw).
struct MotionReference {
    int frames = 0;
    // One prepared frame per offset: the translated scene (2-D) or the world seen by the moved
    // camera (3-D); a method draws frames[t].input_for(method), references measure pieces().
    std::vector<PreparedFrame> prepared;
    std::vector<Coverage> references;   // reference(prepared[t].pieces())
    std::vector<MassReference> masses;  // the thin objects' windows, per frame
};

// `reference` is the exact answer the method is judged against: box_reference by default; a
// filtered_reference for a method whose filter is not the box (else its consistent filter
// difference, which slides with the scene, counts as crawl). The frames are prepared in
// parallel (TBB): `reference` is called from several threads at once.
MotionReference prepare_motion_reference(const Scene& scene, int frames = kMotionFrames,
                                         const ReferenceFn& reference = box_reference);

struct MotionStats {
    int frames = 0;
    // mean over pixels of the standard deviation over frames of (rendered - reference)
    // (population deviation, divided by frames).
    double crawl = 0.0;
    // Over thin objects, the largest max/min ratio of captured mass across frames; infinite
    // (and popping_infinite set) when some object's mass is <= 0 in some frame. NaN when the
    // scene has no thin objects.
    double popping = 0.0;
    bool popping_infinite = false;
    std::string popping_worst_label;
    int thin_objects = 0;
};

MotionStats motion_symptoms(const Method& method, const MotionReference& reference);
MotionStats motion_symptoms(const Method& method, const Scene& scene, int frames = kMotionFrames,
                            const ReferenceFn& reference = box_reference);

}  // namespace aabench
