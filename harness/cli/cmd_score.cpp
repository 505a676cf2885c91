// aabench score: an image rendered elsewhere (any renderer) scored against the exact answer of
// the scene it shows, with the figures compare gives a method's render that need only one image
// (harness/measure/score.h). --json prints them under results.json's column names.
#include <fmt/format.h>

#include <filesystem>

#include "harness/cli/command.h"
#include "harness/measure/score.h"
#include "harness/report/image_read.h"
#include "harness/report/score_report.h"
#include "patterns/pattern.h"

namespace aabench {
namespace {

class ScoreCommand : public Command {
public:
    CLI::App* add_to(CLI::App& app) override {
        auto* cmd = app.add_subcommand(
            "score", "score an image from any renderer against the scene's exact reference");
        cmd->add_option("image", image_, "the image: .exr, .pfm (linear float), .png (8/16-bit)")
            ->required();
        add_scene_options(cmd, src_);
        cmd->add_option("--filter", filter_,
                        "the renderer's own filter, for own_rmse, edge_rmse and alias: box, "
                        "gaussian[:sigma=S,radius=R] or cone[:radius=R]")
            ->capture_default_str();
        auto* srgb = cmd->add_flag("--srgb", srgb_,
                                   "decode the codes with the sRGB transfer function (default: as "
                                   "the file says; untagged 8-bit: sRGB, untagged 16-bit: linear)");
        cmd->add_flag("--linear", linear_, "take the codes as linear light (default: as --srgb says)")
            ->excludes(srgb);
        cmd->add_flag("--json", json_, "print the figures as JSON (results.json column names)");
        return cmd;
    }

    int run(const Invocation&) override {
        const Scene scene = load_scene(src_);
        const ScoredImage read = read_image_to_score(
            image_, srgb_ ? Encoding::kSrgb : linear_ ? Encoding::kLinear : Encoding::kAuto);
        // An RGB file whose channels are equal is a grey image stored as RGB (scored as grey
        // against a grey scene); against a colour scene its three channels are scored.
        const bool colour = read.colour && (scene.channels == 3 || read.channels_differ);
        ResultRow row = colour ? score_image(*read.colour, scene, filter_, image_)
                               : score_image(read.image, scene, filter_, image_);
        // Which decoding was assumed, and why: a wrong guess is the commonest silent error.
        const std::string encoding = fmt::format(
            "{}: read as {} ({})\n", image_,
            read.gamma > 0.0 ? fmt::format("gamma {:.5f}", read.gamma)
            : read.used == Encoding::kSrgb ? "sRGB"
                                           : "linear",
            read.why);
        if (json_) {
            fmt::print(stderr, "{}", encoding);
        } else {
            fmt::print("{}", encoding);
        }
        if (src_.scene_file.empty()) {
            row.pattern = resolve_pattern(src_.pattern).spec;
            row.pattern_id = resolve_pattern(src_.pattern).info->id;
        } else {
            row.pattern = row.pattern_id = std::filesystem::path(src_.scene_file).stem().string();
            row.scene_file = src_.scene_file;
        }
        fmt::print("{}", json_ ? score_json(row, image_) : format_score(row, image_));
        return 0;
    }

private:
    SceneSource src_;
    std::string image_, filter_ = "box";
    bool srgb_ = false, linear_ = false, json_ = false;
};

}  // namespace

std::unique_ptr<Command> make_score_command() { return std::make_unique<ScoreCommand>(); }

}  // namespace aabench
