// taa (methods/taa.cpp) on sequences built here: a still sequence converges to the mean of its
// jitter positions' point samples; no jitter and alpha = 1 is `none`; an exact integer
// translation with its motion vectors moves the history exactly; the rectifications bound a
// stale history; every run is deterministic and a frame after the first allocates nothing.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "harness/world/alloc_count.h"
#include "methods/method.h"
#include "methods/scan/sampling/point_sampling.h"
#include "patterns/pattern.h"
#include "test_scenes.h"
#include "uniform_motion.h"

namespace aabench {
namespace {

constexpr int kSide = 48;

// The running mean is kept in float (the history) and updated once per frame, where the
// reference sums in double and rounds once: each frame adds at most half a float ulp of a
// value in [0, 1] (6e-8), 16 frames at most 1e-6; 1e-5 leaves room, and a wrong sample
// position or weight moves a pixel on an edge by 1/16 or more.
constexpr double kRunningMeanTolerance = 1e-5;
// The clip formula (centre + offset x half_extent / |offset|) and the clamp reach the same
// bound by different roundings: a few ulp of doubles, rounded to float.
constexpr double kClipEqualsClampTolerance = 1e-6;

// The Halton (2, 3) point of `index` (1-based), written out here independently of the method.
double halton(int index, int base) {
    double f = 1.0, r = 0.0;
    while (index > 0) {
        f /= base;
        r += f * (index % base);
        index /= base;
    }
    return r;
}

// The box mean of the point samples at the Halton points 1..n of every pixel, in double (a
// second reference beside ssaa:pattern=halton, with its own Halton points).
Image halton_mean(const Scene& scene, int n) {
    PointSampler sampler(scene);
    std::vector<double> sums(static_cast<std::size_t>(scene.width) * scene.height, 0.0);
    std::vector<double> xs(scene.width), values(scene.width);
    for (int s = 1; s <= n; ++s) {
        for (int i = 0; i < scene.width; ++i) xs[i] = i + halton(s, 2);
        for (int j = 0; j < scene.height; ++j) {
            sampler.sample_values(j + halton(s, 3), xs, values);
            for (int i = 0; i < scene.width; ++i) sums[j * scene.width + i] += values[i];
        }
    }
    Image out(scene.width, scene.height);
    for (std::size_t p = 0; p < sums.size(); ++p) out.data[p] = static_cast<float>(sums[p] / n);
    return out;
}

Scene translated(Scene scene, double dx, double dy) {
    for (Shape& shape : scene.shapes) {
        for (Contour& contour : shape.contours) {
            for (Point& p : contour) p = {p.x + dx, p.y + dy};
        }
    }
    return scene;
}

using testing::uniform_motion;

// The frames of a sequence: frame t is `scenes[t]` with `motions[t]` (empty for frame 0).
std::vector<Image> run_sequence(const Method& method, const std::vector<Scene>& scenes,
                                const std::vector<MotionVectors>& motions) {
    std::unique_ptr<TemporalState> state = method.begin(scenes[0].width, scenes[0].height);
    std::vector<Image> frames;
    for (std::size_t t = 0; t < scenes.size(); ++t) {
        Image out(scenes[t].width, scenes[t].height);
        method.render_frame(scenes[t], motions[t], static_cast<int>(t), state.get(), out);
        frames.push_back(std::move(out));
    }
    return frames;
}

std::vector<Scene> test_scenes() {
    return {make_pattern("star", kSide, kSide), testing::random_scene(7, kSide, kSide, false),
            testing::random_scene(11, kSide, kSide, true)};
}

TEST(Taa, IsTemporalAndMakesState) {
    const MethodInstance m = make_method("taa");
    EXPECT_TRUE(m.method->traits().temporal);
    EXPECT_NE(m.method->begin(4, 4), nullptr);
    // A spatial method keeps nothing.
    EXPECT_EQ(make_method("none").method->begin(4, 4), nullptr);
}

TEST(Taa, AlphaTakesRunningOrANumber) {
    EXPECT_EQ(make_method("taa:alpha=running").params.get_choice("alpha"), "running");
    EXPECT_NE(make_method("taa:alpha=running").spec.find("alpha=running"), std::string::npos);
    EXPECT_EQ(make_method("taa:alpha=0.25").params.get_real("alpha"), 0.25);
    EXPECT_EQ(make_method("taa:alpha=0.25").params.get_choice("alpha"), "");
    EXPECT_THROW(make_method("taa:alpha=runing"), InputError);
    EXPECT_THROW(make_method("taa:alpha=0"), InputError);
}

TEST(Taa, SpatialRenderIsTheFirstJitterSample) {
    // render() is frame 0: every pixel point-sampled at the Halton point 1, (0.5, 1/3).
    for (const Scene& scene : test_scenes()) {
        const Image taa = render_scene(*make_method("taa:samples=8").method, scene);
        const Image first = halton_mean(scene, 1);
        EXPECT_EQ(taa.data, first.data);
        std::vector<Image> frames =
            run_sequence(*make_method("taa:samples=8").method, {scene}, {MotionVectors{}});
        EXPECT_EQ(frames[0].data, taa.data);
    }
}

TEST(Taa, StillRunningMeanEqualsTheJitterPositionsMean) {
    for (const int n : {8, 16}) {
        const MethodInstance m =
            make_method("taa:samples=" + std::to_string(n) + ",alpha=running,clamp=none");
        for (const Scene& scene : test_scenes()) {
            const std::vector<Image> frames = run_sequence(
                *m.method, std::vector<Scene>(n, scene), std::vector<MotionVectors>(n));
            const Image expected = halton_mean(scene, n);
            const Image ssaa = render_scene(
                *make_method("ssaa:pattern=halton,samples=" + std::to_string(n)).method, scene);
            const Image first = halton_mean(scene, 1);
            double worst = 0.0, spread = 0.0;
            for (std::size_t p = 0; p < expected.data.size(); ++p) {
                worst = std::max(worst, std::abs(double(frames.back().data[p]) - expected.data[p]));
                worst = std::max(worst, std::abs(double(frames.back().data[p]) - ssaa.data[p]));
                spread = std::max(spread, std::abs(double(expected.data[p]) - first.data[p]));
            }
            EXPECT_LE(worst, kRunningMeanTolerance) << m.spec;
            EXPECT_GT(spread, 0.05) << "the scene must have edges for the test to mean anything";
        }
    }
}

TEST(Taa, NoJitterAndAlphaOneIsNone) {
    const MethodInstance taa = make_method("taa:samples=1,alpha=1");
    const MethodInstance none = make_method("none");
    for (const Scene& scene : test_scenes()) {
        // Moving (a stale history must not leak in) and still.
        std::vector<Scene> scenes;
        std::vector<MotionVectors> motions;
        for (int t = 0; t < 4; ++t) {
            scenes.push_back(translated(scene, 0.7 * t, -0.3 * t));
            motions.push_back(t == 0 ? MotionVectors{} : uniform_motion(kSide, kSide, 0.7f, -0.3f));
        }
        const std::vector<Image> frames = run_sequence(*taa.method, scenes, motions);
        for (int t = 0; t < 4; ++t) {
            EXPECT_EQ(frames[t].data, render_scene(*none.method, scenes[t]).data) << "frame " << t;
        }
    }
}

TEST(Taa, IntegerTranslationMovesHistoryExactly) {
    // Frame t is the scene moved by (3t, 2t) px, with motion vectors (3, 2): pixel (x, y) of
    // frame t sees what pixel (x - 3t, y - 2t) sees in the still sequence, and its history
    // came from there. Wherever that whole path (and its 3 x 3 neighbourhoods) stayed inside
    // the image, the moving frame equals the still frame shifted, bit for bit.
    constexpr int kFrames = 6, kStepX = 3, kStepY = 2;
    const Scene scene = testing::random_scene(23, kSide, kSide, false);
    std::vector<Scene> moving, still(kFrames, scene);
    std::vector<MotionVectors> motions, none(kFrames);
    for (int t = 0; t < kFrames; ++t) {
        moving.push_back(translated(scene, kStepX * t, kStepY * t));
        motions.push_back(t == 0 ? MotionVectors{}
                                 : uniform_motion(kSide, kSide, kStepX, kStepY));
    }
    for (const std::string spec :
         {"taa:alpha=running,clamp=none", "taa:history=catmull,clamp=minmax",
          "taa:clamp=variance,gamma=1.5,weight=luma"}) {
        const MethodInstance m = make_method(spec);
        const std::vector<Image> a = run_sequence(*m.method, moving, motions);
        const std::vector<Image> b = run_sequence(*m.method, still, none);
        int compared = 0;
        for (int t = 1; t < kFrames; ++t) {
            for (int y = kStepY * t + 1; y < kSide - 1; ++y) {
                for (int x = kStepX * t + 1; x < kSide - 1; ++x) {
                    ASSERT_EQ(a[t].at(x, y), b[t].at(x - kStepX * t, y - kStepY * t))
                        << spec << " frame " << t << " pixel " << x << "," << y;
                    ++compared;
                }
            }
        }
        EXPECT_GT(compared, 1000);
    }
}

TEST(Taa, RectificationBoundsAStaleHistory) {
    // The background changes from 0.9 to 0.1 between frames 0 and 1, nothing moves. Without
    // rectification frame 1 keeps 90 % of the old value (the ghost); clamped to the current
    // 3 x 3 samples, a flat patch takes the new value at once.
    Scene before;
    before.width = before.height = 16;
    before.background = 0.9;
    Scene after = before;
    after.background = 0.1;
    const std::vector<Scene> scenes = {before, after};
    const std::vector<MotionVectors> motions(2);
    const std::vector<Image> ghost = run_sequence(*make_method("taa:clamp=none").method, scenes,
                                                  motions);
    EXPECT_FLOAT_EQ(ghost[1].at(8, 8), static_cast<float>(0.9 * 0.9 + 0.1 * 0.1));
    for (const std::string clamp : {"minmax", "clip", "variance"}) {
        const std::vector<Image> frames =
            run_sequence(*make_method("taa:clamp=" + clamp).method, scenes, motions);
        for (float v : frames[1].data) EXPECT_FLOAT_EQ(v, 0.1f) << clamp;
    }
}

TEST(Taa, ClipEqualsMinMaxOnOneChannel) {
    const Scene scene = make_pattern("star", kSide, kSide);
    std::vector<Scene> scenes;
    std::vector<MotionVectors> motions;
    for (int t = 0; t < 8; ++t) {
        scenes.push_back(translated(scene, 0.37 * t, 0.21 * t));
        motions.push_back(t == 0 ? MotionVectors{} : uniform_motion(kSide, kSide, 0.37f, 0.21f));
    }
    const std::vector<Image> clip = run_sequence(*make_method("taa:clamp=clip").method, scenes,
                                                 motions);
    const std::vector<Image> minmax =
        run_sequence(*make_method("taa:clamp=minmax").method, scenes, motions);
    const std::vector<Image> none = run_sequence(*make_method("taa:clamp=none").method, scenes,
                                                 motions);
    double worst = 0.0, rectified = 0.0;
    for (std::size_t p = 0; p < clip.back().data.size(); ++p) {
        worst = std::max(worst, std::abs(double(clip.back().data[p]) - minmax.back().data[p]));
        rectified = std::max(rectified, std::abs(double(none.back().data[p]) - minmax.back().data[p]));
    }
    EXPECT_LE(worst, kClipEqualsClampTolerance);
    EXPECT_GT(rectified, 0.01) << "the sequence must make the clamp act";
}

TEST(Taa, RunsAreDeterministic) {
    const Scene scene = testing::random_scene(5, kSide, kSide, true);
    std::vector<Scene> scenes;
    std::vector<MotionVectors> motions;
    for (int t = 0; t < 10; ++t) {
        scenes.push_back(translated(scene, 1.3 * t, 0.4 * t));
        motions.push_back(t == 0 ? MotionVectors{} : uniform_motion(kSide, kSide, 1.3f, 0.4f));
    }
    for (const std::string spec : {"taa", "taa:history=catmull,clamp=variance,samples=16",
                                   "taa:alpha=running,clamp=clip,weight=luma"}) {
        const MethodInstance m = make_method(spec);
        const std::vector<Image> a = run_sequence(*m.method, scenes, motions);
        const std::vector<Image> b = run_sequence(*m.method, scenes, motions);
        for (int t = 0; t < 10; ++t) EXPECT_EQ(a[t].data, b[t].data) << spec << " frame " << t;
    }
}

TEST(Taa, FramesAfterTheFirstAllocateNothing) {
    const Scene scene = make_pattern("star", 64, 64);
    std::vector<Scene> scenes;
    for (int t = 0; t < 6; ++t) scenes.push_back(translated(scene, 0.6 * t, 0.9 * t));
    const MotionVectors motion = uniform_motion(64, 64, 0.6f, 0.9f);
    for (const std::string spec : {"taa", "taa:history=catmull,clamp=variance",
                                   "taa:alpha=running,clamp=clip,weight=luma,samples=16"}) {
        const MethodInstance m = make_method(spec);
        std::unique_ptr<TemporalState> state = m.method->begin(64, 64);
        Image out(64, 64);
        m.method->render_frame(scenes[0], MotionVectors{}, 0, state.get(), out);
        for (int t = 1; t < 6; ++t) {
            const AllocCounts before = thread_alloc_counts();
            m.method->render_frame(scenes[t], motion, t, state.get(), out);
            const AllocCounts after = thread_alloc_counts();
            EXPECT_EQ(after.allocations - before.allocations, 0u) << spec << " frame " << t;
        }
    }
}

}  // namespace
}  // namespace aabench
