// External renderers in the comparison (harness/cli/external.h, docs/external.md).
//
// Each run is `/bin/sh -c` of the command with its placeholders replaced by single-quoted
// paths, stdout and stderr to files in a scratch directory. The wall time of the whole process
// (shell included) is what a user of the renderer pays per image; its startup, the same
// command on an empty scene of the same size, is measured and reported beside it, never
// subtracted: the two are separate figures, and their difference is the user's to take.
#include "harness/cli/external.h"

#include <fmt/format.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>

#include "harness/measure/metric_input.h"
#include "harness/measure/score.h"
#include "harness/report/image_io.h"
#include "harness/report/image_read.h"
#include "harness/report/scene_svg.h"
#include "harness/world/frame.h"
#include "patterns/pattern.h"
#include "patterns/scene/scene_io.h"

namespace aabench {
namespace {

namespace fs = std::filesystem;

// A directory of its own for one renderer's files, removed when done.
class ScratchDir {
public:
    ScratchDir() {
        static std::atomic<int> counter{0};
        path_ = fs::temp_directory_path() /
                fmt::format("aabench-external-{}-{}", ::getpid(), counter++);
        fs::create_directories(path_);
    }
    ~ScratchDir() {
        std::error_code ignored;
        fs::remove_all(path_, ignored);
    }
    ScratchDir(const ScratchDir&) = delete;
    ScratchDir& operator=(const ScratchDir&) = delete;
    const fs::path& path() const { return path_; }

private:
    fs::path path_;
};

std::string slurp(const fs::path& path) {
    std::ifstream in(path);
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

std::string first_line(const std::string& text) {
    const std::string line = text.substr(0, text.find('\n'));
    return line.empty() ? "(nothing on stderr)" : line;
}

struct ProcessRun {
    int exit_code = 0;  // -1: killed by a signal
    double wall_ns = 0.0;
    std::string out, err;
};

ProcessRun run_shell(const std::string& command, const fs::path& dir) {
    const fs::path out = dir / "stdout", err = dir / "stderr";
    // Braces, not a subshell: the redirections apply to the whole command list.
    const std::string line = fmt::format("{{ {}\n}} >{} 2>{} </dev/null", command,
                                         shell_quote(out.string()), shell_quote(err.string()));
    const auto start = std::chrono::steady_clock::now();
    const int status = std::system(line.c_str());
    const auto stop = std::chrono::steady_clock::now();
    ProcessRun run;
    run.wall_ns = std::chrono::duration<double, std::nano>(stop - start).count();
    run.exit_code = status != -1 && WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    run.out = slurp(out);
    run.err = slurp(err);
    return run;
}

// The last "aabench-time-ms: X" the command printed, or NaN.
double reported_ms(const std::string& out) {
    static const std::regex line(R"((?:^|\n)aabench-time-ms:[ \t]*([-+0-9.eE]+))");
    double value = kNaN;
    for (auto it = std::sregex_iterator(out.begin(), out.end(), line); it != std::sregex_iterator();
         ++it) {
        char* end = nullptr;
        const std::string text = (*it)[1].str();
        const double v = std::strtod(text.c_str(), &end);
        if (end == text.c_str() + text.size() && std::isfinite(v)) value = v;
    }
    return value;
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    const std::size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

// One renderer on one scene: the files its command names, written in `dir`.
class Job {
public:
    Job(const ExternalRenderer& renderer, const Scene& scene, const std::string& label,
        const fs::path& dir)
        : renderer_(renderer),
          label_(label),
          dir_(dir),
          out_(dir / "out.png"),
          colour_scene_(scene.channels == 3) {
        const std::string& c = renderer.command;
        const PreparedFrame frame = PreparedFrame::prepare(scene);
        const Scene& pieces = frame.pieces().scene();  // what the files hold
        std::string command = c;
        auto put = [&command](const std::string& key, const std::string& value) {
            for (std::size_t at; (at = command.find(key)) != std::string::npos;) {
                command.replace(at, key.size(), value);
            }
        };
        if (c.find("{scene}") != std::string::npos) {
            write_text_file((dir / "scene.json").string(), scene_to_json(scene));
            put("{scene}", shell_quote((dir / "scene.json").string()));
        }
        if (c.find("{pieces}") != std::string::npos) {
            write_text_file((dir / "pieces.json").string(), scene_to_json(pieces));
            put("{pieces}", shell_quote((dir / "pieces.json").string()));
        }
        if (c.find("{svg}") != std::string::npos) {
            write_text_file((dir / "scene.svg").string(), scene_to_svg(pieces));
            put("{svg}", shell_quote((dir / "scene.svg").string()));
        }
        put("{out}", shell_quote(out_.string()));
        put("{width}", std::to_string(scene.width));
        put("{height}", std::to_string(scene.height));
        command_ = command;
    }

    // One run; the image it wrote is checked to exist (a stale one is removed first).
    ProcessRun run() const {
        std::error_code ignored;
        fs::remove(out_, ignored);
        ProcessRun r = run_shell(command_, dir_);
        if (r.exit_code != 0) {
            throw InputError(fmt::format(
                "--external {}: the command {} on {}: {}", renderer_.name,
                r.exit_code < 0 ? std::string("was killed") : fmt::format("exited {}", r.exit_code),
                label_, first_line(r.err)));
        }
        if (!fs::exists(out_)) {
            throw InputError(fmt::format("--external {}: the command wrote no image {{out}} on {}",
                                         renderer_.name, label_));
        }
        return r;
    }

    // Every channel: a colour scene's RGB {out} is scored in colour (score_image).
    ImagePlanes image() const {
        ScoredImage read = read_image_to_score(
            out_.string(), renderer_.srgb ? Encoding::kSrgb : Encoding::kLinear);
        // A grey scene's image is its first channel, as it always was (a peer's RGBA of grey
        // fills), whatever rounding its other channels carry.
        if (read.colour && colour_scene_) return std::move(*read.colour);
        return ImagePlanes(std::move(read.image));
    }

private:
    const ExternalRenderer& renderer_;
    std::string label_;
    fs::path dir_, out_;
    bool colour_scene_ = false;
    std::string command_;
};

// R timed runs after one untimed one: (stats of the wall times, median reported ms).
std::pair<TimingStats, double> time_job(const Job& job, int runs) {
    std::vector<double> wall, reported;
    for (int r = 0; r < runs; ++r) {
        const ProcessRun run = job.run();
        wall.push_back(run.wall_ns);
        const double ms = reported_ms(run.out);
        if (!std::isnan(ms)) reported.push_back(ms);
    }
    TimingStats t{median(wall), *std::min_element(wall.begin(), wall.end()),
                  *std::max_element(wall.begin(), wall.end()), runs};
    return {t, reported.empty() ? kNaN : median(reported)};
}

// The run's scenes, one per pattern (in row order), with the index of its last row.
struct RunScene {
    const ResultRow* row;  // the pattern's first row: spec, id, file, size
    std::size_t last_row;
    Scene scene;
};

std::vector<RunScene> run_scenes(const CompareOptions& options, const CompareResult& result) {
    std::vector<RunScene> scenes;
    for (std::size_t k = 0; k < result.rows.size(); ++k) {
        const ResultRow& r = result.rows[k];
        auto it = std::find_if(scenes.begin(), scenes.end(), [&](const RunScene& s) {
            return s.row->pattern == r.pattern && s.row->scene_file == r.scene_file;
        });
        if (it != scenes.end()) {
            it->last_row = k;
            continue;
        }
        Scene scene;
        if (r.scene_file.empty()) {
            scene = make_pattern(r.pattern, r.width, r.height);
        } else {
            for (const SceneFileInput& f : options.scene_files) {
                if (f.path == r.scene_file) scene = f.scene;
            }
        }
        scenes.push_back({&r, k, std::move(scene)});
    }
    return scenes;
}

}  // namespace

std::string shell_quote(const std::string& text) {
    std::string out = "'";
    for (char c : text) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return out + "'";
}

ExternalRenderer parse_external(const std::string& text) {
    static const std::regex name_re("[A-Za-z0-9_.-]+");
    const auto eq = text.find('=');
    ExternalRenderer r;
    std::string name = text.substr(0, eq);
    if (name.size() > 5 && name.compare(name.size() - 5, 5, ":srgb") == 0) {
        r.srgb = true;
        name.resize(name.size() - 5);
    }
    if (eq == std::string::npos || !std::regex_match(name, name_re)) {
        throw InputError(fmt::format(
            "--external: '{}' is not NAME[:srgb]='COMMAND {{svg}} {{out}}' (NAME of letters, "
            "digits, _ . -)",
            text));
    }
    r.name = name;
    r.command = text.substr(eq + 1);
    if (r.command.find("{out}") == std::string::npos) {
        throw InputError(fmt::format(
            "--external {}: the command never names {{out}}, the image it must write", r.name));
    }
    return r;
}

void add_external_rows(const std::vector<ExternalRenderer>& renderers,
                       const CompareOptions& options, CompareResult& result,
                       const ProgressFn& progress) {
    if (renderers.empty()) return;
    const std::vector<RunScene> scenes = run_scenes(options, result);
    // New rows go after each pattern's last row: inserted from the back, indices stay valid.
    std::vector<std::pair<std::size_t, ResultRow>> added;
    std::size_t done = 0;
    for (const ExternalRenderer& renderer : renderers) {
        ScratchDir dir;
        std::map<std::pair<int, int>, double> startup_ns;  // by size
        for (const RunScene& s : scenes) {
            const std::string label = s.row->pattern_id;
            const std::pair<int, int> size{s.scene.width, s.scene.height};
            if (!startup_ns.count(size)) {
                Scene empty;
                empty.width = size.first;
                empty.height = size.second;
                const Job job(renderer, empty, "an empty scene", dir.path());
                job.run();  // untimed, as for the scenes
                startup_ns[size] = time_job(job, options.runs).first.median_ns;
            }
            const Job job(renderer, s.scene, label, dir.path());
            job.run();
            ResultRow row = score_image(job.image(), s.scene, "box",
                                        fmt::format("--external {} on {}", renderer.name, label));
            const auto [time, reported] = time_job(job, options.runs);
            row.task = result.task_count + static_cast<long long>(added.size());
            row.pattern = s.row->pattern;
            row.pattern_id = s.row->pattern_id;
            row.scene_file = s.row->scene_file;
            row.method = external_method(renderer);
            row.method_id = external_method(renderer.name);
            // A renderer handed the visible pieces or their SVG relies on the world stages that
            // made them (all of them, visibility included); one handed the scene does its own.
            const bool given_scene =
                renderer.command.find("{scene}") != std::string::npos;
            const double world_ms = row[metric::kWorldMs];
            set_timing(row, time, given_scene || std::isnan(world_ms) ? 0.0 : world_ms);
            row.time_source = "process";
            row[metric::kExternalStartupNs] = startup_ns[size];
            row[metric::kExternalReportedMs] = reported;
            for (ComparisonFigures& fig : result.figures) {
                if (fig.pattern_spec != row.pattern) continue;
                fig.methods.push_back(row.method);
                // The report's figures are grey: a colour image's luminance.
                Image luma;
                luminance_image(job.image(), luma);
                fig.images.push_back(std::move(luma));
            }
            added.emplace_back(s.last_row, std::move(row));
            if (progress) {
                progress(++done, renderers.size() * scenes.size(),
                         "external " + renderer.name + " / " + label);
            }
        }
    }
    // From the back, so the earlier positions stay valid; among one pattern's rows the last
    // renderer goes in first, so they end up in the renderers' order.
    std::stable_sort(added.begin(), added.end(),
                     [](const auto& a, const auto& b) { return a.first < b.first; });
    for (auto it = added.rbegin(); it != added.rend(); ++it) {
        result.rows.insert(result.rows.begin() + static_cast<std::ptrdiff_t>(it->first) + 1,
                           std::move(it->second));
    }
    result.task_count += static_cast<long long>(added.size());
}

}  // namespace aabench
