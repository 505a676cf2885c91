// aabench plan: which stages a scene calls for, in or out, and why; with --run, also what
// each stage cost on this scene (time, heap bytes, allocations).
#include <fmt/format.h>

#include <chrono>

#include "harness/cli/command.h"
#include "harness/reference/box_reference.h"
#include "harness/world/frame.h"
#include "harness/world/plan.h"
#include "methods/method.h"

namespace aabench {
namespace {

class PlanCommand : public Command {
public:
    CLI::App* add_to(CLI::App& app) override {
        auto* cmd = app.add_subcommand(
            "plan", "the stages a scene calls for (effects on demand), each in or out and why");
        add_scene_options(cmd, src_);
        cmd->add_flag("--depth", depth_, "as if a depth image were asked for (--depth-out)");
        cmd->add_flag("--run", run_, "also run the stages and print each one's cost");
        return cmd;
    }
    int run(const Invocation&) override {
        const Scene scene = load_scene(src_);
        // The plan alone is cheap (no stage runs); --run prepares the frame.
        fmt::print("plan for {} ({}x{}):\n{}", describe(scene), scene.width, scene.height,
                   format_plan(make_plan(scene, {.depth_image = depth_})));
        if (scene.world) {
            // What each method draws, so which of them wait for the visible pieces.
            std::string own, pieces;
            for (const MethodInfo& info : method_registry()) {
                std::string& list = draws_visible_pieces(scene, *info.traits) ? pieces : own;
                list += (list.empty() ? "" : ", ") + info.id;
            }
            fmt::print("\nwhat each method draws:\n  the ScreenScene (removes hidden surfaces "
                       "itself; never waits for visibility): {}\n  the exact visible pieces "
                       "(charged the visibility stage): {}\n",
                       own, pieces);
        }
        if (run_) {
            const PreparedFrame frame = PreparedFrame::prepare(scene, {.depth_image = depth_});
            // The visible pieces are built on demand: what every comparison of this scene needs
            // next is the exact box reference of them.
            const SceneInput pieces = frame.pieces();
            fmt::print("\ncost of each stage (one run, single thread):\n{}",
                       format_stage_costs(frame.plan(), frame.costs()));
            const auto t0 = std::chrono::steady_clock::now();
            const Coverage reference = box_reference(pieces);
            const double ms = std::chrono::duration<double, std::milli>(
                                  std::chrono::steady_clock::now() - t0)
                                  .count();
            fmt::print("  exact box reference of the {} drawn shapes: {:.3f} ms ({} pixels)\n",
                       pieces.scene().shapes.size(), ms, reference.data.size());
            if (frame.plan().in(Stage::kPatterns) || frame.plan().in(Stage::kShadows)) {
                // Patterns and shadows two ways: the cells every other method and the
                // references take, and the overlay of the scanline methods (docs/world.md).
                (void)frame.overlay();
                const PreparedFrame::LayerCosts c = frame.layer_costs();
                fmt::print("\npatterns and shadows on their faces:\n"
                           "  cells (cut):       {:>7} shapes, cutting  {:.3f} ms\n"
                           "  overlay (laid on): {:>7} shapes, layering {:.3f} ms "
                           "(build with shading and projection {:.3f} ms; {})\n",
                           c.cell_shapes, c.cell_cutting_ms, c.overlay_shapes,
                           c.overlay_layering_ms, c.overlay.time_ms, c.overlay.detail);
            }
        }
        return 0;
    }

private:
    std::string describe(const Scene& scene) const {
        if (!src_.scene_file.empty()) return src_.scene_file;
        for (const auto& [k, v] : scene.metadata) {
            if (k == "pattern") return v;
        }
        return src_.pattern;
    }

    SceneSource src_;
    bool depth_ = false, run_ = false;
};

}  // namespace

std::unique_ptr<Command> make_plan_command() { return std::make_unique<PlanCommand>(); }

}  // namespace aabench
