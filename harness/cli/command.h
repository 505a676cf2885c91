// One subcommand of the aabench command line: it declares its options on the CLI11 app and,
// when it is the one parsed, runs. Each subcommand is one file in this room (cmd_*.cpp); cli.cpp
// lists them in the one table below and dispatches. Parsing happens in this room only.
#pragma once

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <CLI/CLI.hpp>

#include "harness/measure/compare.h"
#include "patterns/scene/scene.h"

namespace aabench {

// What every subcommand may need from the invocation itself (for the run context).
struct Invocation {
    int argc;
    char** argv;
};

class Command {
public:
    virtual ~Command() = default;
    // Adds the subcommand and its options to `app`; returns the subcommand.
    virtual CLI::App* add_to(CLI::App& app) = 0;
    // Runs it after a successful parse; returns the exit code. Bad input is an InputError.
    virtual int run(const Invocation& invocation) = 0;
};

// The subcommands, in the order `aabench --help` lists them.
std::unique_ptr<Command> make_list_command();
std::unique_ptr<Command> make_render_command();
std::unique_ptr<Command> make_reference_command();
std::unique_ptr<Command> make_export_command();
std::unique_ptr<Command> make_plan_command();
std::unique_ptr<Command> make_compare_command();
std::unique_ptr<Command> make_merge_command();
std::unique_ptr<Command> make_hardcases_command();
std::unique_ptr<Command> make_claims_command();
std::unique_ptr<Command> make_score_command();
std::unique_ptr<Command> make_check_command();

// ---- Shared by the subcommands ----

// --scene FILE or --pattern ID --size WxH.
struct SceneSource {
    std::string scene_file;
    std::string pattern;
    std::string size;
};
void add_scene_options(CLI::App* cmd, SceneSource& src);
Scene load_scene(const SceneSource& src);

// "WxH" -> (W, H), checked against the size limits; `where` names the option in errors.
std::pair<int, int> parse_size(const std::string& text, const std::string& where);

// Rejects an unsupported output extension before any rendering work is done.
void check_image_output_path(const std::string& path);

// results/<kind>-<UTC date-time>
std::string default_results_dir(const std::string& kind);

// The whole file, or InputError naming it.
std::string read_text(const std::string& path);

// "A.json,B.json" -> its items (an empty item is an InputError naming `where`).
std::vector<std::string> split_path_list(const std::string& text, const std::string& where);
// Each file read with read_scene_file (an error names the file and the JSON path).
std::vector<SceneFileInput> read_scene_files(const std::vector<std::string>& paths);

// A progress bar with an estimate of the time left, on stderr, redrawn in place; off when
// disabled (stderr not a terminal: logs and CI get no control characters).
class ProgressBar {
public:
    explicit ProgressBar(bool enabled);
    void operator()(std::size_t done, std::size_t total, const std::string& what);

private:
    bool enabled_;
    double start_s_;
};

// True when stderr is a terminal (progress bars are drawn only then).
bool stderr_is_terminal();

}  // namespace aabench
