// Sequences (harness/world/sequence.h) and the sequence run (harness/measure/sequence_run.h):
// motion vectors and disocclusion masks against an independent computation (Embree ray casting
// of both frames for worlds, the frames' own vertices for 2-D scenes) on seeded random worlds
// and every built-in sequence; properties of the temporal measures and of the runner.
#include "harness/world/sequence.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <glm/gtc/matrix_transform.hpp>
#include <optional>
#include <random>

#include "cli_runner.h"
#include "tests/random_world.h"
#include "harness/measure/sequence_metrics.h"
#include "harness/measure/sequence_run.h"
#include "harness/world/reflections.h"
#include "harness/world/stages.h"
#include "methods/method.h"
#include "patterns/pattern.h"

namespace aabench {
namespace {

// Motion vectors are stored as float: a vector of up to ~100 px carries 100 * 6e-8 = 6e-6 px
// of rounding; the double computations on both sides add ~1e-10. 1e-4 px is far above both and
// far below anything a method could see.
constexpr double kVectorTolerancePx = 1e-4;
// Embree casts in single precision: near an edge between two faces (within ~1e-6 of the
// coordinates' magnitude) its ray may take the other face (reflections.h says so; the exact
// visibility of tests/world_visibility_test.cpp measures the same). Such pixels disagree on the
// face seen or on the disocclusion; at the sizes here they are at most a few in a thousand.
constexpr double kMaxDisagreeingShare = 0.005;

struct Agreement {
    long long pixels = 0;
    long long face_disagree = 0;   // Embree saw another face at the pixel centre now
    long long mask_disagree = 0;   // disocclusion differs (on pixels where the faces agree)
    double worst_vector_px = 0.0;  // over pixels where the faces agree
};

glm::dvec3 ray_direction(const ViewSetup& view, double x, double y) {
    // View depth component 1: the ray parameter is z_v (harness/world/reflections.h).
    const glm::dvec3 v((x - 0.5 * view.width) / view.focal_px,
                       (0.5 * view.height - y) / view.focal_px, 1.0);
    return glm::dvec3(glm::inverse(view.view) * glm::dvec4(v.x, v.y, -v.z, 0.0));
}

// The motion of frame t by ray casting: the surface hit through each pixel centre now, taken
// to the previous camera, and a ray from the previous eye to it: disoccluded unless it meets
// the same face first.
Agreement check_world_frame(const Sequence& seq, int t, const FrameMotion& motion) {
    const Scene& scene = seq.scene;
    const int w = scene.width, h = scene.height;
    const RayCaster caster(*scene.world);
    const ViewSetup now = ViewSetup::from(frame_camera(seq, t), w, h);
    const ViewSetup before = ViewSetup::from(frame_camera(seq, t - 1), w, h);
    const PreparedFrame frame = PreparedFrame::prepare(frame_scene(seq, t));
    Agreement a;
    for (int j = 0; j < h; ++j) {
        for (int i = 0; i < w; ++i) {
            const double x = i + 0.5, y = j + 0.5;
            const std::size_t k = std::size_t(j) * w + i;
            ++a.pixels;
            const RayHit hit = caster.cast(now.eye, ray_direction(now, x, y), now.near);
            const int ours = visible_shape_at(frame.screen(), x, y);
            const int our_face = ours < 0 ? -1 : frame.screen().shapes[std::size_t(ours)].face;
            if (our_face != hit.face) {
                ++a.face_disagree;
                continue;
            }
            bool disoccluded = false;
            double dx = 0.0, dy = 0.0;
            if (hit.face < 0) {
                const RayHit was =
                    caster.cast(before.eye, ray_direction(before, x, y), before.near);
                disoccluded = was.face >= 0;
            } else {
                const glm::dvec3 p = now.eye + hit.t * ray_direction(now, x, y);
                const glm::dvec3 q = before.to_view(p);
                const double px = 0.5 * w + before.focal_px * q.x / q.z;
                const double py = 0.5 * h - before.focal_px * q.y / q.z;
                dx = x - px;
                dy = y - py;
                if (q.z <= before.near || !(px >= 0 && px < w && py >= 0 && py < h)) {
                    disoccluded = true;
                } else {
                    const RayHit was = caster.cast(before.eye, (p - before.eye) / q.z, before.near);
                    disoccluded = was.face != hit.face;
                }
            }
            if (disoccluded != (motion.disoccluded.data[k] != 0)) ++a.mask_disagree;
            if (!disoccluded) {
                a.worst_vector_px =
                    std::max({a.worst_vector_px, std::abs(dx - motion.vectors.dx[k]),
                              std::abs(dy - motion.vectors.dy[k])});
            }
        }
    }
    return a;
}


FrameMotion motion_of(const Sequence& seq, int t) {
    const PreparedFrame previous = PreparedFrame::prepare(frame_scene(seq, t - 1));
    const PreparedFrame current = PreparedFrame::prepare(frame_scene(seq, t));
    return frame_motion(seq, previous, current, t);
}

void expect_agreement(const Agreement& a, const std::string& what) {
    EXPECT_LE(a.face_disagree + a.mask_disagree, kMaxDisagreeingShare * a.pixels)
        << what << ": faces disagree at " << a.face_disagree << ", masks at " << a.mask_disagree
        << " of " << a.pixels;
    EXPECT_LE(a.worst_vector_px, kVectorTolerancePx) << what;
    std::printf("%s: worst vector difference %.3g px, face disagreements %lld, mask %lld of %lld\n",
                what.c_str(), a.worst_vector_px, a.face_disagree, a.mask_disagree, a.pixels);
}

constexpr int kRandomWorlds = 12;

TEST(SequenceMotion, RandomWorldsAgreeWithRayCastingUnderEveryCameraMotion) {
    long long disoccluded = 0;
    for (int k = 0; k < kRandomWorlds; ++k) {
        SequenceSpec spec;
        spec.name = fmt::format("random-{}", k);
        switch (k % 3) {
            case 0:
                spec.motion = SequenceMotion::kOrbit;
                spec.orbit_deg = 3.0;
                break;
            case 1:
                spec.motion = SequenceMotion::kPath;
                spec.eye_step = {0.15, -0.05, -0.2};  // a dolly with a drift
                spec.target_step = {0.05, 0.02, 0.0};
                break;
            default:
                spec.motion = SequenceMotion::kTranslate;
                spec.dx_px = 2.3;
                spec.dy_px = -1.1;
        }
        const Sequence seq = make_sequence(spec, random_world(0x5e90000 + k, 5), 2);
        const FrameMotion motion = motion_of(seq, 1);
        for (std::uint8_t d : motion.disoccluded.data) disoccluded += d;
        expect_agreement(check_world_frame(seq, 1, motion), spec.name);
    }
    // The motions must uncover something, or the masks were never tested.
    EXPECT_GT(disoccluded, 0);
}

// The first vertex of the scene's first shape that has one (a scene may begin with shapes
// without contours: the vertex read must exist in both frames).
Point first_vertex(const Scene& scene) {
    for (const Shape& shape : scene.shapes) {
        for (const Contour& contour : shape.contours) {
            if (!contour.empty()) return contour.front();
        }
    }
    ADD_FAILURE() << "a 2-D sequence's scene has no vertex";
    return {};
}

// A mesh model's sequence (SequenceSpec::model_file) made, or, where its Debian package is not
// installed (or the build has no Assimp), nothing: the pattern's one-line refusal is printed.
std::optional<Sequence> model_sequence(const SequenceSpec& spec, int side, int frames) {
    try {
        return make_sequence(spec, side, side, frames);
    } catch (const InputError& e) {
        if (!spec.model_file) throw;
        std::printf("%s left out: %s\n", spec.name.c_str(), e.what());
        return std::nullopt;
    }
}

TEST(SequenceMotion, EveryBuiltInSequenceAgreesWithAnIndependentComputation) {
    constexpr int kSide = 48;
    for (const SequenceSpec& spec : sequence_registry()) {
        const std::optional<Sequence> made = model_sequence(spec, kSide, 3);
        if (!made) continue;
        const Sequence& seq = *made;
        for (int t = 1; t < 3; ++t) {
            const FrameMotion motion = motion_of(seq, t);
            if (spec.motion == SequenceMotion::kStill) {
                EXPECT_TRUE(motion.vectors.empty()) << spec.name;
                for (std::uint8_t d : motion.disoccluded.data) ASSERT_EQ(d, 0) << spec.name;
                continue;
            }
            if (seq.scene.world) {
                expect_agreement(check_world_frame(seq, t, motion),
                                 fmt::format("{} frame {}", spec.name, t));
                continue;
            }
            // 2-D: the frames' own vertices say how far the scene moved.
            const Point before = first_vertex(frame_scene(seq, t - 1));
            const Point now = first_vertex(frame_scene(seq, t));
            for (int j = 0; j < kSide; ++j) {
                for (int i = 0; i < kSide; ++i) {
                    const std::size_t k = std::size_t(j) * kSide + i;
                    ASSERT_NEAR(motion.vectors.dx[k], now.x - before.x, kVectorTolerancePx);
                    ASSERT_NEAR(motion.vectors.dy[k], now.y - before.y, kVectorTolerancePx);
                    const double px = i + 0.5 - (now.x - before.x);
                    const double py = j + 0.5 - (now.y - before.y);
                    const bool outside = px < 0 || px >= kSide || py < 0 || py >= kSide;
                    ASSERT_EQ(motion.disoccluded.data[k] != 0, outside) << spec.name << " " << i;
                }
            }
        }
    }
}

TEST(SequenceMotion, FrameZeroHasNoMotionAndNoDisocclusion) {
    const Sequence seq = make_sequence(find_sequence("fast-pan"), 32, 32, 2);
    const PreparedFrame frame = PreparedFrame::prepare(frame_scene(seq, 0));
    const FrameMotion motion = frame_motion(seq, frame, frame, 0);
    EXPECT_TRUE(motion.vectors.empty());
    for (std::uint8_t d : motion.disoccluded.data) ASSERT_EQ(d, 0);
}

TEST(SequenceRegistry, UnknownNamesAndBadFrameCountsAreInputErrors) {
    EXPECT_THROW(find_sequence("no-such"), InputError);
    EXPECT_THROW(make_sequence(find_sequence("star-still"), 16, 16, 0), InputError);
    SequenceSpec orbit_2d = find_sequence("star-still");
    orbit_2d.motion = SequenceMotion::kOrbit;
    EXPECT_THROW(make_sequence(orbit_2d, 16, 16, 4), InputError);
}

// ---- The measures ----

TEST(TemporalMeasures, ConvergenceIsTheFirstFrameThatStaysWithinTheBand) {
    // 1.0 and 0.5 are outside 10 % of 0.1; 0.105 is inside, 0.2 outside again at frame 3.
    EXPECT_EQ(convergence_frame({1.0, 0.5, 0.105, 0.2, 0.1, 0.1, 0.1}, 0.1), 4);
    EXPECT_EQ(convergence_frame({0.1, 0.1}, 0.1), 0);
    EXPECT_EQ(convergence_frame({0.1, 0.5}, 0.1), 2);  // never settles: the frame count
}

TEST(TemporalMeasures, RecentDisocclusionFollowsTheMotionForEightFrames) {
    constexpr int kFrames = 12;
    std::vector<FrameMotion> motion(kFrames);
    for (int t = 0; t < kFrames; ++t) {
        motion[t].disoccluded = Raster<std::uint8_t>(8, 1, 0);
        if (t == 0) continue;
        MotionVectors& v = motion[t].vectors;
        v.width = 8;
        v.height = 1;
        v.dx.assign(8, t <= 4 ? 1.0f : 0.0f);  // one pixel right per frame, then still
        v.dy.assign(8, 0.0f);
    }
    motion[1].disoccluded.at(0, 0) = 1;
    const auto recent = recent_disocclusions(motion);
    // Frames 1..4 move the surface right: the one uncovered at frame 1 and those entering
    // through the left border (no history there) are at pixels 0..t-1, pixel i having been
    // uncovered i frames ago; then they stand still and age one frame per frame.
    for (int t = 0; t < kFrames; ++t) {
        for (int i = 0; i < 8; ++i) {
            const int age = i + std::max(0, t - 4);
            const bool expected = t >= 1 && i <= std::min(t, 4) - 1 && age < kGhostFrames;
            EXPECT_EQ(recent[t].at(i, 0) != 0, expected) << "frame " << t << " pixel " << i;
        }
    }
}

TEST(TemporalMeasures, GhostingAndFlickerOnAConstructedSequence) {
    TemporalInputs in;
    constexpr int kFrames = 4;
    for (int t = 0; t < kFrames; ++t) {
        in.errors.push_back({t % 2 ? 0.2 : 0.0, 0.1});  // pixel 0 alternates, pixel 1 steady
        in.own_errors.push_back(in.errors.back());
        Raster<std::uint8_t> r(2, 1, 0);
        r.at(0, 0) = t >= 1 ? 1 : 0;
        in.recent.push_back(r);
        Raster<std::int8_t> s(2, 1, 0);
        s.at(1, 0) = 1;  // pixel 1 is above its neighbours: +0.1 there is a sharpening
        in.edge_sign.push_back(s);
    }
    const TemporalMeasures m = temporal_measures(in);
    // Frames 2, 3 (the second half): pixel 0 is 0.0 then 0.2, deviation 0.1; pixel 1 none.
    EXPECT_NEAR(m.flicker, 0.05, 1e-12);
    // Ghost pixels of frames 1..3: 0.2, 0.0, 0.2; the rest 0.1 throughout.
    EXPECT_NEAR(m.ghost_rmse, std::sqrt(0.08 / 3), 1e-12);
    EXPECT_NEAR(m.rest_rmse, 0.1, 1e-12);
    EXPECT_NEAR(m.ghost_ratio, std::sqrt(0.08 / 3) / 0.1, 1e-12);
    EXPECT_NEAR(m.edge_blur, -0.1, 1e-12);
    EXPECT_TRUE(std::isnan(m.convergence));  // not a still sequence
}

TEST(TemporalMeasures, TheGhostRatioOfRoundingNoiseIsEmpty) {
    // Errors of float32 rounding size (an exact method): both rmse are kept, their ratio is not.
    TemporalInputs in;
    for (int t = 0; t < 3; ++t) {
        in.errors.push_back({6e-8, 3e-8});
        in.own_errors.push_back(in.errors.back());
        Raster<std::uint8_t> r(2, 1, 0);
        r.at(0, 0) = 1;
        in.recent.push_back(r);
        in.edge_sign.push_back(Raster<std::int8_t>(2, 1, 0));
    }
    const TemporalMeasures m = temporal_measures(in);
    EXPECT_NEAR(m.ghost_rmse, 6e-8, 1e-20);
    EXPECT_NEAR(m.rest_rmse, 3e-8, 1e-20);
    EXPECT_TRUE(std::isnan(m.ghost_ratio));
}

// ---- The runner ----

SequenceRunOptions small_run(std::vector<std::string> sequences, std::vector<std::string> methods) {
    SequenceRunOptions o;
    o.sequences = std::move(sequences);
    o.method_specs = std::move(methods);
    o.width = o.height = 24;
    o.frames = 6;
    o.filmstrip_frames = 3;
    return o;
}

const ResultRow& row_of(const SequenceRunResult& r, const std::string& seq, const std::string& id) {
    for (const ResultRow& row : r.rows) {
        if (row.pattern == seq && row.method_id == id) return row;
    }
    throw std::logic_error("no row " + seq + " " + id);
}

TEST(SequenceRun, ASpatialMethodOnAStillSequenceHasZeroFlickerAndConvergesAtOnce) {
    const SequenceRunResult r = run_sequences(small_run({"star-still"}, {"none", "ssaa"}));
    for (const char* id : {"none", "ssaa"}) {
        const ResultRow& row = row_of(r, "star-still", id);
        EXPECT_EQ(row[sequence_metric(SequenceMetric::kFlicker)], 0.0) << id;
        EXPECT_EQ(row[sequence_metric(SequenceMetric::kConvergence)], 0.0) << id;
        EXPECT_GT(row[sequence_metric(SequenceMetric::kSteadyRmse)], 0.0) << id;
        EXPECT_TRUE(std::isnan(row[sequence_metric(SequenceMetric::kGhostRmse)]))
            << id;  // nothing is uncovered
    }
}

TEST(SequenceRun, TheExactMethodIsExactOnEveryFrameOfAMovingSequence) {
    // exact renders the box reference in float32: errors are rounding, ~6e-8 per pixel.
    constexpr double kFloat32Rounding = 1e-6;
    const SequenceRunResult r = run_sequences(small_run({"star-drift", "room-pan"}, {"exact"}));
    for (const char* seq : {"star-drift", "room-pan"}) {
        const ResultRow& row = row_of(r, seq, "exact");
        EXPECT_LT(row[sequence_metric(SequenceMetric::kSteadyRmse)], kFloat32Rounding) << seq;
        EXPECT_LT(row[sequence_metric(SequenceMetric::kFlicker)], kFloat32Rounding) << seq;
        EXPECT_GT(row[sequence_metric(SequenceMetric::kFrameMs)], 0.0) << seq;
    }
}

TEST(SequenceRun, IsDeterministicAndKeepsTheFilmstripFrames) {
    const SequenceRunOptions o = small_run({"fast-pan"}, {"none", "box-multiscan"});
    const SequenceRunResult a = run_sequences(o), b = run_sequences(o);
    ASSERT_EQ(a.figures.size(), 1u);
    ASSERT_EQ(a.figures[0].runs.size(), 2u);
    for (std::size_t k = 0; k < 2; ++k) {
        EXPECT_EQ(a.figures[0].runs[k].frame_rmse, b.figures[0].runs[k].frame_rmse);
        EXPECT_EQ(a.figures[0].runs[k].kept.size(), a.figures[0].kept_frames.size());
    }
    EXPECT_EQ(a.figures[0].kept_frames.back(), o.frames - 1);
    // A fast pan uncovers the screen's edge every frame: ghosting is measured.
    EXPECT_FALSE(
        std::isnan(row_of(a, "fast-pan", "none")[sequence_metric(SequenceMetric::kGhostRmse)]));
}

// The mesh models' sequences are those whose pattern reads a model file, and every other one
// runs without any (a run of every built-in leaves the first out: run_sequences).
TEST(SequenceRegistry, TheModelSequencesAreThoseOnMeshModels) {
    std::vector<std::string> models;
    for (const SequenceSpec& spec : sequence_registry()) {
        const std::string id = spec.pattern.substr(0, spec.pattern.find(':'));
        int found = 0;
        for (const PatternInfo& info : pattern_registry()) {
            if (info.id != id) continue;
            EXPECT_EQ(spec.model_file, info.model_file) << spec.name;
            ++found;
        }
        EXPECT_EQ(found, 1) << spec.name;
        if (spec.model_file) models.push_back(spec.name);
    }
    EXPECT_EQ(models, (std::vector<std::string>{"bunny-orbit", "truck-pan"}));
}

// Two frames of each mesh model's sequence at a small size through the sequence run: `exact`
// is the box reference on both frames, and the motion uncovers something (the orbit turns the
// bunny, the pan moves the truck over the ground).
TEST(SequenceRun, TheMeshModelSequencesRunTwoFramesAtASmallSize) {
    constexpr double kFloat32Rounding = 1e-6;  // exact in float32, as above
    for (const char* name : {"bunny-orbit", "truck-pan"}) {
        if (!model_sequence(find_sequence(name), 8, 1)) continue;
        SequenceRunOptions o = small_run({name}, {"exact", "none"});
        o.width = o.height = 32;
        o.frames = 2;
        o.filmstrip_frames = 2;
        const SequenceRunResult r = run_sequences(o);
        ASSERT_EQ(r.figures.size(), 1u) << name;
        const SequenceFigures& f = r.figures[0];
        ASSERT_EQ(f.runs.size(), 2u) << name;
        for (const double e : f.runs[0].frame_rmse) EXPECT_LT(e, kFloat32Rounding) << name;
        for (const double e : f.runs[1].frame_rmse) EXPECT_GT(e, 0.0) << name;  // none aliases
        ASSERT_EQ(f.disoccluded_share.size(), 2u) << name;
        EXPECT_GT(f.disoccluded_share[1], 0.0) << name;
    }
}

TEST(SequenceRun, BadInputIsRefusedBeforeAnyWork) {
    EXPECT_THROW(run_sequences(small_run({"nope"}, {"none"})), InputError);
    EXPECT_THROW(run_sequences(small_run({"star-still"}, {"nope"})), InputError);
    SequenceRunOptions one_frame = small_run({"star-still"}, {"none"});
    one_frame.frames = 1;
    EXPECT_THROW(run_sequences(one_frame), InputError);
}

class SequenceCli : public CliRunner {
protected:
    SequenceCli() : CliRunner("seq") {}
};

TEST_F(SequenceCli, CompareSequencesWritesTheTablesFilesAndReport) {
    const CliOutput r = run(
        fmt::format("compare --sequences star-still,strips-crawl --methods none,exact --size 20x20 "
                    "--frames 4 --out {}",
                    path("run")));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("flicker"), std::string::npos) << r.out;
    for (const char* f :
         {"table.txt", "results.csv", "results.json", "frames.csv", "frames.json", "index.html"}) {
        EXPECT_TRUE(std::filesystem::exists(dir_ / "run" / f)) << f;
    }
    std::ifstream csv(dir_ / "run" / "frames.csv");
    const std::string text((std::istreambuf_iterator<char>(csv)), std::istreambuf_iterator<char>());
    // Header plus 2 sequences x 2 methods x 4 frames.
    EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 1 + 2 * 2 * 4);
}

TEST_F(SequenceCli, UnknownSequenceIsAOneLineInputError) {
    const CliOutput r = run(fmt::format("compare --sequences nope --out {}", path("run")));
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("unknown sequence 'nope'"), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir_ / "run"));
}

}  // namespace
}  // namespace aabench
