// aabench render, reference and export: one scene through one method, the exact reference, or
// a built-in pattern or sequence written as a scene file.
#include <fmt/format.h>

#include <cmath>
#include <optional>
#include <tuple>

#include "harness/cli/command.h"
#include "harness/measure/limits.h"
#include "harness/reference/filter_reference.h"
#include "harness/report/image_io.h"
#include "harness/report/scene_svg.h"
#include "harness/world/frame.h"
#include "harness/world/sequence.h"
#include "methods/method.h"
#include "patterns/pattern.h"
#include "patterns/scene/scene_io.h"

namespace aabench {
namespace {

// A render whose estimate passes this announces itself and shows its progress (about the
// time after which a silent command starts to look hung).
constexpr double kAnnounceAfterMs = 2000.0;
// Bands of rows for the progress bar: steps of 2 %. Each band reads the scene's edges again
// (a fraction of a millisecond on the largest patterns), nothing next to a render this long.
constexpr int kProgressBands = 50;

// "850 ms", "12.3 s", "2 min 5 s".
std::string format_duration(double ms) {
    if (ms < 1000.0) return fmt::format("{:.0f} ms", ms);
    if (ms < 60000.0) return fmt::format("{:.1f} s", ms / 1000.0);
    const long long s = std::llround(ms / 1000.0);
    return fmt::format("{} min {} s", s / 60, s % 60);
}

class RenderCommand : public Command {
public:
    CLI::App* add_to(CLI::App& app) override {
        auto* cmd = app.add_subcommand("render", "render a scene with one method to an image");
        add_scene_options(cmd, src_);
        cmd->add_option("--method", method_, "method ID[:key=value,...]")->required();
        cmd->add_option("--out", out_, "output image: .exr (float32), .pfm, .png (16-bit)")
            ->required();
        cmd->add_option("--depth-out", depth_out_,
                        "also write the depth image z_s = f*d/z_v (f px, d = eye to target) "
                        "drawn by the method (3-D scenes)");
        cmd->add_option("--edges-out", edges_out_,
                        "also write the line image of the edge stage (scenes with an edges "
                        "block); --out then gets the composite");
        cmd->add_option("--threads", threads_,
                        "threads, 1..256: the image split in horizontal bands rendered in "
                        "parallel (TBB)")
            ->capture_default_str()
            ->check(CLI::Range(1, 256));
        cmd->add_flag("--stats", stats_,
                      "print the plan and each stage's time and bytes allocated (3-D scenes)");
        return cmd;
    }
    int run(const Invocation&) override {
        const MethodInstance method = make_method(method_);  // check before work
        for (const std::string* path : {&out_, &depth_out_, &edges_out_}) {
            if (!path->empty()) check_image_output_path(*path);
        }
        const Scene scene = load_scene(src_);
        // The options are checked against the plan before any stage runs.
        check_effect_options(scene, make_plan(scene, {.depth_image = !depth_out_.empty()}),
                             *method.method, method.spec);
        const PreparedFrame frame =
            PreparedFrame::prepare(scene, {.depth_image = !depth_out_.empty()});
        const Plan& plan = frame.plan();
        // What the method draws: the ScreenScene for a method with its own visibility, the
        // exact visible pieces for the others (harness/world/frame.h).
        const SceneInput input = frame.input_for(*method.method);
        const Scene& drawn = input.scene();
        const SceneSize size = measure_scene(drawn);
        const std::size_t bytes = estimate_job_bytes(size, {method.spec}, {});
        check_job_memory(bytes, kDefaultMemoryBudgetBytes, "render");
        // A method that cannot draw the scene says why, and nothing is written.
        const std::string reason = method.method->not_applicable(drawn);
        if (!reason.empty()) throw InputError(fmt::format("{}: not applicable: {}", method.spec, reason));
        if (drawn.channels == 3) {
            // A colour scene: every plane, in bands. A colour world has no edge stage (the
            // reader refuses one), so what runs after the method is its grey depth image.
            ImagePlanes planes(3, drawn.width, drawn.height);
            render_in_bands(*method.method, input, planes, threads_);
            write_image(out_, planes);
            if (!depth_out_.empty()) {
                write_image(
                    depth_out_,
                    *frame.after_method(*method.method, method.spec, planes[0], true).depth);
            }
            return 0;
        }
        Image shaded(drawn.width, drawn.height);
        // A long render says what it will take before it starts, and how far it is (a render
        // that runs for minutes in silence looks hung). Short ones stay quiet.
        const double estimate_ms = estimate_render_ms(method, size);
        if (estimate_ms > kAnnounceAfterMs || stats_) {
            fmt::print(stderr, "render: {} at {}x{}: about {} on {} (estimate), {}\n", method.spec,
                       drawn.width, drawn.height, format_duration(estimate_ms / threads_),
                       threads_ == 1 ? "one thread" : fmt::format("{} threads", threads_),
                       format_bytes(bytes));
        }
        if (estimate_ms > kAnnounceAfterMs && stderr_is_terminal()) {
            ProgressBar bar(true);
            bar(0, drawn.height, fmt::format("rows of {}", method.spec));  // at once, not at 2 %
            render_with_progress(*method.method, input, shaded, threads_, kProgressBands,
                                 [&](int rows_done, int rows) {
                                     bar(rows_done, rows, fmt::format("rows of {}", method.spec));
                                 });
        } else {
            render_in_bands(*method.method, input, shaded, threads_);
        }
        const AfterMethod after =
            frame.after_method(*method.method, method.spec, shaded, !depth_out_.empty());
        write_image(out_, after.edges ? after.edges->composite : shaded);
        if (after.edges && !edges_out_.empty()) write_image(edges_out_, after.edges->lines);
        if (!depth_out_.empty()) write_image(depth_out_, *after.depth);
        if (stats_) {
            StageCosts costs = frame.costs();
            costs[static_cast<int>(Stage::kDepthImage)].add(after.depth_cost);
            costs[static_cast<int>(Stage::kEdges)].add(after.edge_cost);
            fmt::print("{}", format_stage_costs(plan, costs));
        }
        return 0;
    }

private:
    // Everything the options ask of the scene and the method, before any work is done.
    void check_effect_options(const Scene& scene, const Plan& plan, const Method& method,
                              const std::string& spec) const {
        if (!depth_out_.empty() && !scene.world) {
            throw InputError("--depth-out: a 2-D scene has no depth (give a 3-D scene or pattern)");
        }
        if (!edges_out_.empty() && !plan.in(Stage::kEdges)) {
            throw InputError("--edges-out: the scene calls for no edge stage (" +
                             plan[Stage::kEdges].reason + ")");
        }
        if (plan.in(Stage::kDepthImage) && !method.affine_values()) {
            throw InputError(fmt::format(
                "--method: {} draws no depth image (affine values), which {} needs", spec,
                plan.in(Stage::kEdges) ? "the scene's edges block" : "--depth-out"));
        }
    }

    SceneSource src_;
    std::string method_, out_, depth_out_, edges_out_;
    int threads_ = 1;
    bool stats_ = false;
};

class ReferenceCommand : public Command {
public:
    CLI::App* add_to(CLI::App& app) override {
        auto* cmd = app.add_subcommand("reference", "write the exact reference image");
        add_scene_options(cmd, src_);
        cmd->add_option("--filter", filter_, "box, gaussian[:sigma=S,radius=R] or cone[:radius=R]")
            ->capture_default_str();
        cmd->add_option("--out", out_, "output image: .exr, .pfm, .png")->required();
        cmd->add_flag("--depth", depth_,
                      "the exact box reference of the depth image z_s = f*d/z_v (3-D scenes; "
                      "box filter only)");
        return cmd;
    }
    int run(const Invocation&) override {
        Filter filter;
        try {
            filter = Filter::parse(filter_);  // check before any work
        } catch (const InputError& e) {
            throw InputError(std::string("--filter: ") + e.what());
        }
        if (depth_ && !filter.is_box()) {
            throw InputError("--depth: only the box reference of depth exists (--filter box)");
        }
        check_image_output_path(out_);
        const Scene scene = load_scene(src_);
        if (depth_ && !scene.world) {
            throw InputError("--depth: a 2-D scene has no depth (give a 3-D scene or pattern)");
        }
        const PreparedFrame frame = PreparedFrame::prepare(scene, {.depth_image = depth_});
        const SceneInput measured = depth_ ? frame.depth_pieces() : frame.pieces();
        check_job_memory(estimate_job_bytes(measure_scene(measured.scene()), {}, {filter_}),
                         kDefaultMemoryBudgetBytes, "reference");
        // Every plane of a colour scene, the one of a grey scene; rounded once to float32.
        const CoveragePlanes cov = exact_reference_planes(measured, filter);
        ImagePlanes image(cov.channels(), cov.width(), cov.height());
        for (int c = 0; c < cov.channels(); ++c) {
            for (std::size_t k = 0; k < cov[c].data.size(); ++k) {
                image[c].data[k] = static_cast<float>(cov[c].data[k]);
            }
        }
        write_image(out_, image);
        return 0;
    }

private:
    SceneSource src_;
    std::string filter_ = "box", out_;
    bool depth_ = false;
};

class ExportCommand : public Command {
public:
    CLI::App* add_to(CLI::App& app) override {
        auto* cmd = app.add_subcommand(
            "export", "write a built-in pattern or sequence as a scene file, or any scene as SVG");
        // --scene, --pattern, --size as add_scene_options() has them, but --size also sizes
        // a sequence: the either-or is checked in run().
        auto* scene =
            cmd->add_option("--scene", src_.scene_file, "scene file (JSON, docs/scene-format.md)");
        auto* pattern =
            cmd->add_option("--pattern", src_.pattern, "built-in pattern ID[:key=value,...]");
        auto* sequence = cmd->add_option(
            "--sequence", sequence_,
            "built-in sequence NAME (aabench list): its pattern carrying its motion, a scene "
            "file of version 3 (docs/sequences.md)");
        auto* size = cmd->add_option("--size", src_.size,
                                     fmt::format("image size WxH, with --pattern or --sequence "
                                                 "(the sequence's default {0}x{0})",
                                                 kDefaultSequenceSide));
        frames_option_ = cmd->add_option("--frames", frames_,
                                         "with --sequence: the file's \"frames\", 2..10000 "
                                         "(left out: the runner's, compare --frames)");
        scene->excludes(pattern)->excludes(size)->excludes(sequence);
        pattern->excludes(sequence);
        frames_option_->needs(sequence);
        cmd->add_option("--out", out_,
                        "output: .json (the scene file) or .svg (what methods draw: 2-D paths, "
                        "fill-rule nonzero, values as linear 8-bit greys; docs/external.md)")
            ->required();
        return cmd;
    }
    int run(const Invocation&) override {
        const bool svg = out_.size() > 4 && out_.compare(out_.size() - 4, 4, ".svg") == 0;
        const bool json = out_.size() > 5 && out_.compare(out_.size() - 5, 5, ".json") == 0;
        if (!svg && !json) {
            throw InputError(
                fmt::format("--out: {}: unsupported format (use .json or .svg)", out_));
        }
        Scene scene;
        if (!sequence_.empty()) {
            const SequenceSpec& spec = find_sequence(sequence_);
            auto [w, h] = std::pair(kDefaultSequenceSide, kDefaultSequenceSide);
            if (!src_.size.empty()) std::tie(w, h) = parse_size(src_.size, "--size");
            std::optional<int> frames;
            if (frames_option_->count() > 0) {
                if (frames_ < kMinSequenceFrames || frames_ > kMaxSequenceFrames) {
                    throw InputError(fmt::format("--frames: {} is not in {}..{}", frames_,
                                                 kMinSequenceFrames, kMaxSequenceFrames));
                }
                frames = frames_;
            }
            scene = sequence_scene(spec, w, h, frames);
        } else {
            if (!src_.size.empty() && src_.pattern.empty()) {
                throw InputError("--size: applies to --pattern or --sequence");
            }
            if (!src_.pattern.empty() && src_.size.empty()) {
                throw InputError("--pattern: needs --size WxH");
            }
            scene = load_scene(src_);
        }
        write_text_file(out_, svg ? scene_to_svg(PreparedFrame::prepare(scene).pieces().scene()) : scene_to_json(scene));
        return 0;
    }

private:
    SceneSource src_;
    std::string out_;
    std::string sequence_;
    int frames_ = 0;
    CLI::Option* frames_option_ = nullptr;
};

}  // namespace

std::unique_ptr<Command> make_render_command() { return std::make_unique<RenderCommand>(); }
std::unique_ptr<Command> make_reference_command() { return std::make_unique<ReferenceCommand>(); }
std::unique_ptr<Command> make_export_command() { return std::make_unique<ExportCommand>(); }

}  // namespace aabench
