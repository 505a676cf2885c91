// Scene file version 3 (docs/scene-format.md, "Version 3"): a file's "sequence" reads strictly,
// every way it can be wrong is one InputError naming its JSON path, every built-in sequence
// written as a file reads back the same, and a file's sequence gives the built-in's frames,
// references and motion bit for bit. The command line runs and exports file sequences.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "cli_runner.h"
#include "harness/reference/box_reference.h"
#include "harness/world/frame.h"
#include "harness/world/sequence.h"
#include "input_error_of.h"
#include "patterns/pattern.h"
#include "patterns/scene/scene_io.h"

namespace aabench {
namespace {

using Json = nlohmann::ordered_json;
constexpr const char* kSource = "seq.json";

Json two_d() {
    return Json::parse(R"({
      "version": 3, "width": 16, "height": 12,
      "sequence": {"frames": 6, "motion": "translate", "dx_px": 0.6, "dy_px": -0.35},
      "shapes": [{"type": "polygon", "contours": [[[2,2],[12,3],[6,10]]]}]
    })");
}

Json three_d() {
    std::ifstream in(std::filesystem::path(AABENCH_SOURCE_DIR) / "tests/data/box_dolly.json");
    return Json::parse(in);
}

Scene parse(const Json& j) { return parse_scene_json(j.dump(), kSource); }

TEST(SceneFileV3, ReadsEveryMotion) {
    const Scene flat = parse(two_d());
    ASSERT_TRUE(flat.sequence);
    EXPECT_EQ(flat.sequence->motion, SequenceMotion::kTranslate);
    EXPECT_EQ(flat.sequence->dx_px, 0.6);
    EXPECT_EQ(flat.sequence->dy_px, -0.35);
    EXPECT_EQ(flat.sequence->frames, 6);

    const Scene dolly = parse(three_d());
    ASSERT_TRUE(dolly.sequence && dolly.world);
    EXPECT_EQ(dolly.sequence->motion, SequenceMotion::kPath);
    EXPECT_EQ(dolly.sequence->eye_step, glm::dvec3(-0.05, 0.0, -0.1));
    EXPECT_EQ(dolly.sequence->target_step, glm::dvec3(0.0));

    Json pan = three_d();
    pan["sequence"] = {{"motion", "pan"}, {"dx_px", -1.5}};
    const Scene panned = parse(pan);
    EXPECT_EQ(panned.sequence->motion, SequenceMotion::kTranslate);
    EXPECT_EQ(panned.sequence->dx_px, -1.5);
    EXPECT_EQ(panned.sequence->dy_px, 0.0);  // left out: 0
    EXPECT_FALSE(panned.sequence->frames);   // left out: the runner's

    Json orbit = three_d();
    orbit["sequence"] = {{"motion", "orbit"}, {"orbit_deg", 2}};
    EXPECT_EQ(parse(orbit).sequence->orbit_deg, 2.0);

    Json still = two_d();
    still["sequence"] = {{"motion", "still"}};
    EXPECT_EQ(parse(still).sequence->motion, SequenceMotion::kStill);
}

struct Bad {
    const char* what;
    std::function<void(Json&)> edit;
    const char* message;  // the path and the start of the problem
};

TEST(SceneFileV3, EveryBadValueIsOneLineNamingItsPath) {
    auto seq = [](Json& j) -> Json& { return j["sequence"]; };
    const std::vector<Bad> flat = {
        {"sequence in version 2", [](Json& j) { j["version"] = 2; }, "sequence: unknown key"},
        {"sequence in version 1", [](Json& j) { j["version"] = 1; }, "sequence: unknown key"},
        {"not an object", [&](Json& j) { seq(j) = 3; },
         "sequence: expected a sequence object, found 3"},
        {"motion missing", [&](Json& j) { seq(j).erase("motion"); },
         "sequence.motion: required key is missing"},
        {"unknown motion", [&](Json& j) { seq(j)["motion"] = "spin"; },
         "sequence.motion: expected one of \"still\", \"translate\", \"pan\", \"path\", "
         "\"orbit\", found the string \"spin\""},
        {"pan on a 2-D scene", [&](Json& j) { seq(j)["motion"] = "pan"; },
         "sequence.motion: \"pan\" moves a 3-D scene's camera, and this file has no "
         "\"objects\""},
        {"path on a 2-D scene",
         [&](Json& j) {
             seq(j) = {{"motion", "path"}, {"eye_step", {1, 0, 0}}};
         },
         "sequence.motion: \"path\" moves a 3-D scene's camera"},
        {"orbit on a 2-D scene",
         [&](Json& j) {
             seq(j) = {{"motion", "orbit"}, {"orbit_deg", 1}};
         },
         "sequence.motion: \"orbit\" moves a 3-D scene's camera"},
        {"a key of another motion", [&](Json& j) { seq(j)["orbit_deg"] = 1; },
         "sequence.orbit_deg: unknown key for this motion (expected one of: frames, motion, "
         "dx_px, dy_px)"},
        {"a step on a still sequence",
         [&](Json& j) {
             seq(j) = {{"motion", "still"}, {"dx_px", 1}};
         },
         "sequence.dx_px: unknown key for this motion (expected one of: frames, motion)"},
        {"dx_px a string", [&](Json& j) { seq(j)["dx_px"] = "1"; },
         "sequence.dx_px: expected a finite number, found the string \"1\""},
        {"dy_px too large", [&](Json& j) { seq(j)["dy_px"] = 70000; },
         "sequence.dy_px: 70000.0 is beyond the limit of 65536 px per frame"},
        {"frames fractional", [&](Json& j) { seq(j)["frames"] = 2.5; },
         "sequence.frames: expected an integer number of frames, found 2.5"},
        {"frames one", [&](Json& j) { seq(j)["frames"] = 1; },
         "sequence.frames: 1 is not in 2..10000"},
        {"frames too many", [&](Json& j) { seq(j)["frames"] = 10001; },
         "sequence.frames: 10001 is not in 2..10000"},
        {"frames past 64 bits", [&](Json& j) { seq(j)["frames"] = 18446744073709551615ULL; },
         "sequence.frames: 18446744073709551615 is not in 2..10000"},
    };
    const std::vector<Bad> world = {
        {"translate on a 3-D scene",
         [&](Json& j) {
             seq(j) = {{"motion", "translate"}, {"dx_px", 1}};
         },
         "sequence.motion: \"translate\" moves a 2-D scene's shapes; a 3-D scene moves its "
         "camera: \"pan\""},
        {"eye_step of two numbers",
         [&](Json& j) {
             seq(j)["eye_step"] = {1, 2};
         },
         "sequence.eye_step: expected a vector [x, y, z] of three finite numbers, found [1,2]"},
        {"target_step component a string", [&](Json& j) { seq(j)["target_step"][1] = "0"; },
         "sequence.target_step[1]: expected a finite number, found the string \"0\""},
        {"eye_step beyond the limit", [&](Json& j) { seq(j)["eye_step"][2] = 1e97; },
         "sequence.eye_step[2]: 1e+97 is beyond the limit of 1e96 world units per frame"},
        {"orbit_deg missing",
         [&](Json& j) {
             seq(j) = {{"motion", "orbit"}};
         },
         "sequence.orbit_deg: required key is missing"},
        {"orbit_deg past a turn",
         [&](Json& j) {
             seq(j) = {{"motion", "orbit"}, {"orbit_deg", 400}};
         },
         "sequence.orbit_deg: 400.0 is outside [-360, 360] degrees per frame"},
        // The eye (2.5, 2.5, 2.5) reaches the target (0.5, 0.5, 0.5) at frame 4 of these
        // steps (exactly: every number is a binary fraction); with 4 frames (0..3) it never does.
        {"a path into the target",
         [&](Json& j) {
             j["camera"]["eye"] = {2.5, 2.5, 2.5};
             seq(j)["eye_step"] = {-0.5, -0.5, -0.5};
             seq(j)["frames"] = 6;
         },
         "sequence: at frame 4, the eye reaches the target: no view direction"},
        {"a path along up",
         [&](Json& j) {
             // The eye climbs straight above the target at frame 2: the view is along up.
             j["camera"]["eye"] = {0.5, 2.2, 2.5};
             seq(j)["eye_step"] = {0, 0, -1};
             seq(j)["frames"] = 3;
         },
         "sequence: at frame 2, up is parallel to the view direction"},
    };
    for (const auto& [cases, base] : {std::pair(&flat, two_d()), std::pair(&world, three_d())}) {
        for (const Bad& bad : *cases) {
            Json j = base;
            bad.edit(j);
            const std::string message = error_of([&] { parse(j); });
            EXPECT_EQ(message.rfind(std::string(kSource) + ": " + bad.message, 0), 0u)
                << bad.what << ": " << message;
            EXPECT_EQ(message.find('\n'), std::string::npos) << bad.what;
        }
    }
    Json short_path = three_d();
    short_path["camera"]["eye"] = {2.5, 2.5, 2.5};
    short_path["sequence"]["eye_step"] = {-0.5, -0.5, -0.5};
    short_path["sequence"]["frames"] = 4;
    EXPECT_NO_THROW(parse(short_path));
}

TEST(SceneFileV3, ThePathIsCheckedForTheFramesTheRunnerGives) {
    // No frames in the file: the reader cannot know them, make_sequence checks what it is given.
    Json j = three_d();
    j["sequence"].erase("frames");
    j["camera"]["eye"] = {2.5, 2.5, 2.5};
    j["sequence"]["eye_step"] = {-0.5, -0.5, -0.5};
    const Scene scene = parse(j);
    EXPECT_NO_THROW(file_sequence(scene, "dolly", "dolly.json", 4));
    EXPECT_EQ(error_of([&] { file_sequence(scene, "dolly", "dolly.json", 32); }),
              "sequence dolly: at frame 4, the eye reaches the target: no view direction");
    const Scene plain = parse_scene_json(R"({"width": 4, "height": 4, "shapes": []})", "p.json");
    EXPECT_EQ(error_of([&] { file_sequence(plain, "plain", "plain.json", 5); }),
              "plain.json: has no \"sequence\" (a scene file of version 3 carries one; "
              "docs/scene-format.md)");
}

TEST(SceneFileV3, EveryBuiltInSequenceRoundTripsAsAFile) {
    constexpr int kSide = 24;
    for (const SequenceSpec& spec : sequence_registry()) {
        // The mesh models' sequences are an orbit and a pan, as blocks-orbit and room-pan here;
        // written as a file they are their pattern's export (the triangles inline, 7 MB for the
        // bunny), which mesh_file_test checks.
        if (spec.model_file) continue;
        for (const std::optional<int> frames : {std::optional<int>(), std::optional<int>(12)}) {
            const Scene scene = sequence_scene(spec, kSide, kSide, frames);
            const std::string text = scene_to_json(scene);
            // Version 3 carries a sequence; a colour scene's is version 4, which carries one too
            // (docs/scene-format.md).
            const char* version = scene.channels == 3 ? "\"version\": 4" : "\"version\": 3";
            EXPECT_NE(text.find(version), std::string::npos) << spec.name;
            const Scene read = parse_scene_json(text, spec.name);
            ASSERT_TRUE(read.sequence) << spec.name;
            EXPECT_EQ(static_cast<const SequenceSteps&>(*read.sequence),
                      static_cast<const SequenceSteps&>(spec))
                << spec.name;
            EXPECT_EQ(read.sequence->frames, frames) << spec.name;
            const Scene again = parse_scene_json(scene_to_json(read), spec.name);
            EXPECT_EQ(again, read) << spec.name;
        }
    }
    // A scene without a sequence keeps its version.
    EXPECT_NE(scene_to_json(make_pattern("star", 8, 8)).find("\"version\": 1"), std::string::npos);
}

// The same frames, box references and motion, bit for bit, from a built-in and from the file it
// is written as: the file's scene is the pattern's (the writer is exact), and its steps map one
// to one onto the built-in's.
TEST(SceneFileV3, AFileSequenceIsTheBuiltInFrameForFrame) {
    constexpr int kSide = 24;
    constexpr int kFrames = 3;
    for (const char* name : {"star-drift", "room-pan", "blocks-orbit"}) {
        const SequenceSpec& spec = find_sequence(name);
        const Sequence builtin = make_sequence(spec, kSide, kSide, kFrames);
        const Sequence file = file_sequence(
            parse_scene_json(scene_to_json(sequence_scene(spec, kSide, kSide, kFrames)), name),
            name, std::string(name) + ".json", 32);
        ASSERT_EQ(file.frames, kFrames) << name;  // the file's frames, not the default given
        std::vector<PreparedFrame> a, b;
        for (int t = 0; t < kFrames; ++t) {
            a.push_back(PreparedFrame::prepare(frame_scene(builtin, t)));
            b.push_back(PreparedFrame::prepare(frame_scene(file, t)));
            EXPECT_EQ(a[t].pieces().scene().shapes, b[t].pieces().scene().shapes) << name << " frame " << t;
            EXPECT_EQ(box_reference(a[t].pieces()).data, box_reference(b[t].pieces()).data)
                << name << " frame " << t;
            const FrameMotion ma = frame_motion(builtin, a[t > 0 ? t - 1 : 0], a[t], t);
            const FrameMotion mb = frame_motion(file, b[t > 0 ? t - 1 : 0], b[t], t);
            EXPECT_EQ(ma.vectors.dx, mb.vectors.dx) << name << " frame " << t;
            EXPECT_EQ(ma.vectors.dy, mb.vectors.dy) << name << " frame " << t;
            EXPECT_EQ(ma.disoccluded.data, mb.disoccluded.data) << name << " frame " << t;
            if (t > 0) {
                EXPECT_FALSE(ma.vectors.dx.empty()) << name;  // something moved
            }
        }
    }
}

class SequenceFileCli : public CliRunner {
protected:
    SequenceFileCli() : CliRunner("seqfile") {}
};

TEST_F(SequenceFileCli, ExportsAndRunsAFileSequence) {
    const std::string file = path("drift.json");
    CliOutput r = run("export --sequence star-drift --size 16x16 --frames 3 --out " + file);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    ASSERT_TRUE(std::filesystem::exists(file));
    const std::string out = path("out");
    r = run("compare --sequences --scenes " + file + " --methods none --quiet --out " + out);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    std::ifstream csv(std::filesystem::path(out) / "frames.csv");
    const std::string text((std::istreambuf_iterator<char>(csv)), std::istreambuf_iterator<char>());
    EXPECT_NE(text.find("drift"), std::string::npos) << text;
}

TEST_F(SequenceFileCli, RefusesBadFilesAndWritesNothing) {
    const std::string plain = path("plain.json");
    std::ofstream(plain) << R"({"width": 8, "height": 8, "shapes": []})";
    const std::string out = path("out");
    CliOutput r = run("compare --sequences --scenes " + plain + " --quiet --out " + out);
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("plain.json: has no \"sequence\""), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(out));

    const std::string bad = path("bad.json");
    Json j = two_d();
    j["sequence"]["dx_px"] = "fast";
    std::ofstream(bad) << j.dump();
    r = run("compare --sequences --scenes " + bad + " --quiet --out " + out);
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("bad.json: sequence.dx_px: expected a finite number"), std::string::npos)
        << r.err;
    EXPECT_FALSE(std::filesystem::exists(out));
}

TEST_F(SequenceFileCli, RefusesAClashingNameAndASizeForFilesAlone) {
    const std::string out = path("out");
    // The stem names the rows: it may not be a built-in's name in the same run.
    const std::string clash = path("star-still.json");
    std::ofstream(clash) << two_d().dump();
    CliOutput r = run("compare --sequences star-still --scenes " + clash + " --quiet --out " + out);
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("its name 'star-still' (the file stem) is taken by the built-in"),
              std::string::npos)
        << r.err;
    r = run("compare --sequences --scenes " + clash + " --size 8x8 --quiet --out " + out);
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("--size: applies to the built-in sequences only"), std::string::npos)
        << r.err;
    EXPECT_FALSE(std::filesystem::exists(out));
}

}  // namespace
}  // namespace aabench
