// The sequence run and the temporal measures (harness/measure/sequence_run.h; definitions in
// docs/metrics.md, "Sequences").
#include "harness/measure/sequence_run.h"

#include <fmt/format.h>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <map>
#include <memory>

#include "harness/measure/metric_input.h"
#include "harness/measure/sequence_metrics.h"
#include "harness/measure/symptoms.h"
#include "harness/reference/box_reference.h"
#include "harness/reference/filter_reference.h"
#include "methods/method.h"

namespace aabench {
namespace {

// The ghost/rest ratio is left empty when the rest's rmse is below this: the float32 image
// rounds values in [0, 1] to about 6e-8, so an exact method's two errors are rounding noise and
// their ratio (1.17 on blocks-orbit) would read as a finding.
constexpr double kGhostRatioFloorRmse = 1e-6;

double rmse_of(const std::vector<double>& e) {
    if (e.empty()) return kNaN;
    double sum = 0.0;
    for (double v : e) sum += v * v;
    return std::sqrt(sum / static_cast<double>(e.size()));
}

double median_of(std::vector<double> v) {
    if (v.empty()) return kNaN;
    std::sort(v.begin(), v.end());
    const std::size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

// A colour frame's three planes as one raster of three times the height, R above G above B:
// the temporal measures read their inputs value by value, so over this raster they are taken
// over every channel (docs/temporal.md, "Colour").
template <class T, class Planes>
Raster<T> stacked(const Planes& planes) {
    const int w = planes[0].width, h = planes[0].height;
    Raster<T> out(w, 3 * h);
    for (int c = 0; c < 3; ++c) {
        std::copy(planes[c].data.begin(), planes[c].data.end(),
                  out.data.begin() + static_cast<std::ptrdiff_t>(c) * w * h);
    }
    return out;
}

// Everything about one sequence that does not depend on the method.
struct PreparedSequence {
    Sequence sequence;
    std::vector<PreparedFrame> prepared;
    // Per frame: the box reference (a colour sequence's: of its luminance, for the report).
    std::vector<Coverage> box;
    // A colour sequence (channels 3): per frame, the box reference of every channel stacked
    // (stacked()), and the own references of every filter likewise; `own` and `edge_sign`
    // below are then stacked too. Empty in a grey sequence.
    int channels = 1;
    std::vector<Coverage> box_stacked;
    // Per own filter (Filter::text(); "box" included): its exact reference and edge-blur
    // signs per frame.
    std::map<std::string, std::vector<Coverage>> own;
    std::map<std::string, std::vector<Raster<std::int8_t>>> edge_sign;
    std::vector<FrameMotion> motion;
    std::vector<Raster<std::uint8_t>> recent;
};

PreparedSequence prepare_sequence(Sequence sequence, const std::vector<Filter>& filters) {
    PreparedSequence ps;
    const int frames = sequence.frames;
    ps.sequence = std::move(sequence);
    ps.channels = ps.sequence.scene.channels;
    std::vector<std::optional<PreparedFrame>> prepared(frames);
    ps.box.resize(frames);
    if (ps.channels == 3) ps.box_stacked.resize(frames);
    for (const Filter& f : filters) {
        ps.own[f.text()].resize(frames);
        ps.edge_sign[f.text()].resize(frames);
    }
    tbb::parallel_for(0, frames, [&](int t) {
        prepared[t].emplace(PreparedFrame::prepare(frame_scene(ps.sequence, t),
                                                   {.frame_index = t, .time = double(t)}));
        const SceneInput pieces = prepared[t]->pieces();
        ps.box[t] = box_reference(pieces);
        const Raster<std::uint8_t> band = edge_band_mask(pieces.scene());
        if (ps.channels == 3) {
            // Each channel's references (exact_reference_planes), and the edge-blur signs of
            // each channel's own reference on the scene's edge band.
            const SceneInput& measured = pieces;
            const CoveragePlanes box = exact_reference_planes(measured, Filter::box());
            ps.box_stacked[t] = stacked<double>(box);
            for (const Filter& f : filters) {
                const CoveragePlanes own =
                    f.is_box() ? box : exact_reference_planes(measured, f);
                std::array<Raster<std::int8_t>, 3> sign;
                for (int c = 0; c < 3; ++c) sign[c] = edge_blur_sign(own[c], band);
                ps.own[f.text()][t] = stacked<double>(own);
                ps.edge_sign[f.text()][t] = stacked<std::int8_t>(sign);
            }
            return;
        }
        for (const Filter& f : filters) {
            Coverage& own = ps.own[f.text()][t];
            own = f.is_box() ? ps.box[t] : exact_reference(pieces, f);
            ps.edge_sign[f.text()][t] = edge_blur_sign(own, band);
        }
    });
    for (auto& p : prepared) ps.prepared.push_back(std::move(*p));
    ps.motion.resize(frames);
    tbb::parallel_for(0, frames, [&](int t) {
        ps.motion[t] = frame_motion(ps.sequence, ps.prepared[t > 0 ? t - 1 : 0], ps.prepared[t], t);
    });
    ps.recent = recent_disocclusions(ps.motion);
    return ps;
}

std::vector<int> filmstrip_indices(int frames, int wanted) {
    std::vector<int> kept;
    const int n = std::max(1, std::min(wanted, frames));
    for (int k = 0; k < n; ++k) {
        const int t =
            n == 1 ? frames - 1 : static_cast<int>(std::lround(double(k) * (frames - 1) / (n - 1)));
        if (kept.empty() || kept.back() != t) kept.push_back(t);
    }
    return kept;
}

}  // namespace

int convergence_frame(const std::vector<double>& frame_rmse, double steady) {
    int c = static_cast<int>(frame_rmse.size());
    for (int t = c - 1; t >= 0; --t) {
        if (!(std::abs(frame_rmse[t] - steady) <= kConvergenceBand * steady)) break;
        c = t;
    }
    return c;
}

std::vector<Raster<std::uint8_t>> recent_disocclusions(const std::vector<FrameMotion>& motion) {
    std::vector<Raster<std::uint8_t>> recent;
    if (motion.empty()) return recent;
    const int w = motion.front().disoccluded.width, h = motion.front().disoccluded.height;
    // Frames since the surface at each pixel was disoccluded; frame 0 starts "long ago".
    std::vector<int> age(static_cast<std::size_t>(w) * h, kGhostFrames), next(age.size());
    for (std::size_t t = 0; t < motion.size(); ++t) {
        const FrameMotion& m = motion[t];
        for (int j = 0; j < h; ++j) {
            for (int i = 0; i < w; ++i) {
                const std::size_t k = static_cast<std::size_t>(j) * w + i;
                if (t == 0) {
                    next[k] = kGhostFrames;
                } else if (m.disoccluded.data[k]) {
                    next[k] = 0;
                } else {
                    // Followed back to the nearest pixel centre of the previous frame.
                    int pi = i, pj = j;
                    if (!m.vectors.empty()) {
                        pi = static_cast<int>(std::floor(i + 0.5 - m.vectors.dx[k]));
                        pj = static_cast<int>(std::floor(j + 0.5 - m.vectors.dy[k]));
                    }
                    const bool inside = pi >= 0 && pi < w && pj >= 0 && pj < h;
                    next[k] =
                        inside ? std::min(kGhostFrames, age[std::size_t(pj) * w + pi] + 1) : 0;
                }
            }
        }
        age.swap(next);
        Raster<std::uint8_t>& r = recent.emplace_back(w, h, 0);
        for (std::size_t k = 0; k < age.size(); ++k) r.data[k] = age[k] < kGhostFrames ? 1 : 0;
    }
    return recent;
}

Raster<std::int8_t> edge_blur_sign(const Coverage& reference, const Raster<std::uint8_t>& band) {
    const int w = reference.width, h = reference.height;
    Raster<std::int8_t> sign(w, h, 0);
    // Below this a pixel is level with its neighbours (the references are exact to ~1e-12):
    // a blur does not move it.
    constexpr double kLevel = 1e-9;
    for (int j = 0; j < h; ++j) {
        for (int i = 0; i < w; ++i) {
            if (!band.at(i, j)) continue;
            double sum = 0.0;
            int n = 0;
            for (int b = std::max(0, j - 1); b <= std::min(h - 1, j + 1); ++b) {
                for (int a = std::max(0, i - 1); a <= std::min(w - 1, i + 1); ++a) {
                    sum += reference.at(a, b);
                    ++n;
                }
            }
            const double d = reference.at(i, j) - sum / n;
            sign.at(i, j) = d > kLevel ? 1 : d < -kLevel ? -1 : 0;
        }
    }
    return sign;
}

TemporalMeasures temporal_measures(const TemporalInputs& in) {
    TemporalMeasures m;
    const int frames = static_cast<int>(in.errors.size());
    for (const auto& e : in.errors) m.frame_rmse.push_back(rmse_of(e));
    const int first_steady = frames / 2;  // the second half
    double sum = 0.0;
    for (int t = first_steady; t < frames; ++t) sum += m.frame_rmse[t];
    m.steady_rmse = sum / std::max(1, frames - first_steady);
    m.convergence = in.still ? convergence_frame(m.frame_rmse, m.steady_rmse) : kNaN;

    // Flicker over the steady frames: Welford per pixel, as crawl (harness/measure/symptoms.h).
    const std::size_t pixels = frames ? in.own_errors.front().size() : 0;
    std::vector<double> mean(pixels, 0.0), m2(pixels, 0.0);
    for (int t = first_steady; t < frames; ++t) {
        const double n = t - first_steady + 1;
        for (std::size_t k = 0; k < pixels; ++k) {
            const double e = in.own_errors[t][k];
            const double delta = e - mean[k];
            mean[k] += delta / n;
            m2[k] += delta * (e - mean[k]);
        }
    }
    const double n_steady = std::max(1, frames - first_steady);
    double flicker = 0.0;
    for (std::size_t k = 0; k < pixels; ++k) flicker += std::sqrt(m2[k] / n_steady);
    m.flicker = pixels ? flicker / static_cast<double>(pixels) : kNaN;

    // Ghosting over every frame with a previous one.
    double ghost_sum = 0.0, rest_sum = 0.0;
    long long ghost_n = 0, rest_n = 0;
    for (int t = 1; t < frames; ++t) {
        for (std::size_t k = 0; k < pixels; ++k) {
            const double e2 = in.errors[t][k] * in.errors[t][k];
            if (in.recent[t].data[k]) {
                ghost_sum += e2;
                ++ghost_n;
            } else {
                rest_sum += e2;
                ++rest_n;
            }
        }
    }
    m.ghost_rmse = ghost_n ? std::sqrt(ghost_sum / double(ghost_n)) : kNaN;
    m.rest_rmse = rest_n ? std::sqrt(rest_sum / double(rest_n)) : kNaN;
    m.ghost_ratio = m.rest_rmse >= kGhostRatioFloorRmse ? m.ghost_rmse / m.rest_rmse : kNaN;

    // Edge blur over the steady frames: the own-filter error against the direction a blur
    // moves each edge pixel, so > 0 is mass smeared toward the neighbours.
    double blur_sum = 0.0;
    long long blur_n = 0;
    for (int t = first_steady; t < frames; ++t) {
        for (std::size_t k = 0; k < pixels; ++k) {
            const int s = in.edge_sign[t].data[k];
            if (s == 0) continue;
            blur_sum += -s * in.own_errors[t][k];
            ++blur_n;
        }
    }
    m.edge_blur = blur_n ? blur_sum / double(blur_n) : kNaN;
    return m;
}

SequenceRunResult run_sequences(const SequenceRunOptions& options,
                                const SequenceProgressFn& progress) {
    // Every input checked before any work.
    std::vector<const SequenceSpec*> specs;
    if (options.sequences.empty() && options.scene_files.empty()) {
        for (const SequenceSpec& s : sequence_registry()) {
            if (s.in_default_run) specs.push_back(&s);  // the others run when named
        }
    } else {
        for (const std::string& name : options.sequences) specs.push_back(&find_sequence(name));
    }
    check_image_size(options.width, options.height, "--size");
    if (options.frames < kMinSequenceFrames || options.frames > kMaxSequenceFrames) {
        throw InputError(fmt::format("--frames: {} is not in {}..{}", options.frames,
                                     kMinSequenceFrames, kMaxSequenceFrames));
    }
    // The files' sequences made (and so checked) before any work; their frames prepared one
    // sequence at a time, like the built-ins'.
    std::vector<Sequence> sequences;
    for (const SequenceSpec* spec : specs) sequences.push_back({*spec, Scene{}, options.frames});
    for (const SceneFileInput& file : options.scene_files) {
        // Rows, report sections and frames.csv are keyed by the name: it must be the run's only.
        const std::string stem = std::filesystem::path(file.path).stem().string();
        for (std::size_t q = 0; q < sequences.size(); ++q) {
            if (sequences[q].spec.name != stem) continue;
            const bool built_in = q < specs.size();  // files come after the built-ins
            throw InputError(fmt::format(
                "--scenes: {}: its name '{}' (the file stem) is taken by {} in this run; rename "
                "the file",
                file.path, stem,
                built_in ? "the built-in sequence " + stem : sequences[q].spec.pattern));
        }
        sequences.push_back(file_sequence(file.scene, stem, file.path, options.frames));
    }
    std::vector<MethodInstance> methods;
    if (options.method_specs.empty()) {
        for (const MethodInfo& info : method_registry()) methods.push_back(make_method(info.id));
    } else {
        for (const std::string& spec : options.method_specs) methods.push_back(make_method(spec));
    }
    std::vector<Filter> filters;
    for (const MethodInstance& m : methods) {
        const Filter& f = m.method->filter();
        if (std::find(filters.begin(), filters.end(), f) == filters.end()) filters.push_back(f);
    }
    tbb::global_control threads(tbb::global_control::max_allowed_parallelism,
                                static_cast<std::size_t>(std::max(1, options.jobs)));

    SequenceRunResult result;
    const std::size_t total = sequences.size() * methods.size();
    std::size_t done = 0;
    long long task = 0;
    for (std::size_t q = 0; q < sequences.size(); ++q) {
        const bool from_file = q >= specs.size();
        const SequenceSpec* spec = &sequences[q].spec;
        // A built-in's scene is made here, at the run's size: one sequence's frames at a time.
        const PreparedSequence ps = prepare_sequence(
            from_file ? std::move(sequences[q])
                      : make_sequence(*spec, options.width, options.height, options.frames),
            filters);
        spec = &ps.sequence.spec;
        const int frames = ps.sequence.frames;
        const int w = ps.sequence.scene.width, h = ps.sequence.scene.height;
        SequenceFigures& fig = result.figures.emplace_back();
        fig.sequence = spec->name;
        fig.summary = spec->summary;
        fig.still = spec->motion == SequenceMotion::kStill;
        fig.frames = frames;
        fig.kept_frames = filmstrip_indices(frames, options.filmstrip_frames);
        for (int t : fig.kept_frames) fig.kept_reference.push_back(ps.box[t]);
        for (const FrameMotion& m : ps.motion) {
            long long n = 0;
            for (std::uint8_t d : m.disoccluded.data) n += d;
            fig.disoccluded_share.push_back(double(n) / double(std::size_t(w) * h));
        }
        // A colour sequence: the recently disoccluded masks repeated for every channel.
        const bool colour = ps.channels == 3;
        std::vector<Raster<std::uint8_t>> recent_stacked;
        if (colour) {
            for (const Raster<std::uint8_t>& r : ps.recent) {
                recent_stacked.push_back(stacked<std::uint8_t>(std::array{r, r, r}));
            }
        }
        for (const MethodInstance& mi : methods) {
            const Method& method = *mi.method;
            ResultRow& row = result.rows.emplace_back();
            row.task = task++;
            row.pattern = row.pattern_id = spec->name;
            if (from_file) row.scene_file = spec->pattern;
            row.method = mi.spec;
            row.method_id = mi.id;
            row.width = w;
            row.height = h;
            row.edges = static_cast<long long>(ps.prepared.front().pieces().scene().edge_count());
            row.reference_filter = method.filter().text();
            row.time_runs = 1;
            row.not_applicable = method.not_applicable(ps.prepared.front().input_for(method).scene());
            if (progress) progress(++done, total, spec->name + " " + mi.spec);
            if (!row.not_applicable.empty()) continue;

            SequenceMethodRun& run = fig.runs.emplace_back();
            run.method = mi.spec;
            TemporalInputs in;
            in.still = fig.still;
            in.recent = colour ? recent_stacked : ps.recent;
            in.edge_sign = ps.edge_sign.at(row.reference_filter);
            const std::vector<Coverage>& own = ps.own.at(row.reference_filter);
            // A colour sequence's errors are over its stacked planes (R, G, B: every channel),
            // a grey one's over its one plane.
            const std::vector<Coverage>& box = colour ? ps.box_stacked : ps.box;
            std::unique_ptr<TemporalState> state = method.begin(w, h);
            Image out(w, h);
            ImagePlanes planes = colour ? ImagePlanes(3, w, h) : ImagePlanes();
            Image drawn;  // a colour frame's planes stacked, as its references are
            for (int t = 0; t < frames; ++t) {
                // Built before the clock starts: a world's overlay or pieces are stages, not
                // the method's work (relied_stage_ms is the stages' share, not timed here).
                const SceneInput input = ps.prepared[t].input_for(method);
                const auto start = std::chrono::steady_clock::now();
                if (colour) {
                    method.render_frame(input, ps.motion[t].vectors, t, state.get(), planes);
                } else {
                    method.render_frame(input, ps.motion[t].vectors, t, state.get(), out);
                }
                run.frame_ms.push_back(std::chrono::duration<double, std::milli>(
                                           std::chrono::steady_clock::now() - start)
                                           .count());
                if (colour) {
                    drawn = stacked<float>(planes);
                    luminance_image(planes, out);  // what the report shows (docs/colour.md)
                }
                const Image& measured = colour ? drawn : out;
                std::vector<double>& e = in.errors.emplace_back(measured.data.size());
                std::vector<double>& eo = in.own_errors.emplace_back(measured.data.size());
                for (std::size_t k = 0; k < measured.data.size(); ++k) {
                    e[k] = double(measured.data[k]) - box[t].data[k];
                    eo[k] = double(measured.data[k]) - own[t].data[k];
                }
                if (std::find(fig.kept_frames.begin(), fig.kept_frames.end(), t) !=
                    fig.kept_frames.end()) {
                    run.kept.push_back(out);
                }
                if (t == frames - 1) {
                    run.last_error = Image(w, h);
                    // A colour frame's error map is its luminance's.
                    for (std::size_t k = 0; k < run.last_error.data.size(); ++k) {
                        run.last_error.data[k] =
                            colour ? static_cast<float>(double(out.data[k]) - ps.box[t].data[k])
                                   : static_cast<float>(e[k]);
                    }
                }
            }
            const TemporalMeasures m = temporal_measures(in);
            run.frame_rmse = m.frame_rmse;
            row[sequence_metric(SequenceMetric::kSteadyRmse)] = m.steady_rmse;
            row[sequence_metric(SequenceMetric::kConvergence)] = m.convergence;
            row[sequence_metric(SequenceMetric::kFlicker)] = m.flicker;
            row[sequence_metric(SequenceMetric::kGhostRmse)] = m.ghost_rmse;
            row[sequence_metric(SequenceMetric::kRestRmse)] = m.rest_rmse;
            row[sequence_metric(SequenceMetric::kGhostRatio)] = m.ghost_ratio;
            row[sequence_metric(SequenceMetric::kEdgeBlur)] = m.edge_blur;
            row[sequence_metric(SequenceMetric::kFrameMs)] = median_of(run.frame_ms);
        }
    }
    return result;
}

}  // namespace aabench
