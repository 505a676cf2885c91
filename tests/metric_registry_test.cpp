// The metric registry (harness/measure/metric_registry.h): a metric added in the test itself
// shows in every consumer (CSV, JSON with its definition, text table, HTML table) and the gate
// catches a regression in it; it is gone when its scope ends. A metric that computes itself
// (a row and its function, nothing else) is computed in compare's rows and by `aabench score`,
// with the preparation it asks for built for it alone. results.json's schema version:
// a schema-1 file (tests/data/results_schema1.json, before the registry) reads and writes back with
// the same figures, an unknown version is refused. docs/metrics.md holds the registry's table.
#include "harness/measure/metric_registry.h"

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "harness/measure/compare.h"
#include "harness/measure/gate.h"
#include "harness/measure/metric_input.h"
#include "harness/measure/score.h"
#include "harness/measure/symptoms.h"
#include "harness/report/html_report.h"
#include "harness/report/metric_docs.h"
#include "harness/report/report.h"
#include "harness/report/score_report.h"
#include "methods/method.h"
#include "patterns/pattern.h"

namespace aabench {
namespace {

namespace fs = std::filesystem;

std::string read_file(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    EXPECT_TRUE(in) << path;
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

// The metric the test adds: a made-up "ringing" figure, gated with a tolerance of its own.
constexpr double kRingingRel = 0.1;  // 10%: any rise above it is a regression in this test
constexpr double kRingingOld = 0.25;
MetricDef ringing_metric() {
    MetricDef def;
    def.key = "test_ringing";
    def.header = "ringing";
    def.definition = "test: overshoot next to edges";
    def.unit = "value";
    def.better = Better::kLower;
    def.gate = Gate::kYes;
    def.tolerance = {kRingingRel, 0.0};
    def.shown_in = kInText | kInHtml;
    def.text_width = 8;
    def.text_decimals = 4;
    return def;
}

ResultRow made_up_row() {
    ResultRow r;
    r.pattern = r.pattern_id = "star";
    r.method = r.method_id = "none";
    r.reference_filter = "box";
    r.width = r.height = 16;
    r[metric::kBoxRmse] = r[metric::kOwnRmse] = 0.01;
    r[metric::kTimeMedianNs] = 1000.0;
    return r;
}

TEST(MetricRegistry, AMetricAddedInATestShowsEverywhereAndIsGated) {
    const int size_before = metric_registry().size();
    {
        const ScopedMetric ringing(ringing_metric());
        ASSERT_EQ(metric_registry().size(), size_before + 1);
        ResultRow row = made_up_row();
        row[ringing.id()] = kRingingOld;
        const std::vector<ResultRow> rows = {row};

        // CSV: a column named by its key, with the row's value.
        const std::string csv = compare_rows_csv(rows);
        const std::string header = csv.substr(0, csv.find('\n'));
        EXPECT_NE(header.find(",test_ringing"), std::string::npos) << header;
        EXPECT_NE(csv.find(",0.25"), std::string::npos) << csv;

        // JSON: its definition, its value, and read back into the row.
        const std::string json = compare_json(rows, RunContext{});
        const nlohmann::json doc = nlohmann::json::parse(json);
        EXPECT_EQ(doc["definitions"]["test_ringing"], "test: overshoot next to edges");
        EXPECT_EQ(doc["rows"][0]["test_ringing"], kRingingOld);
        EXPECT_EQ(rows_from_compare_json(json, "test")[0][ringing.id()], kRingingOld);

        // Text table: its header and the value at its decimals.
        const std::string table = format_compare_tables(rows);
        EXPECT_NE(table.find(" ringing"), std::string::npos) << table;
        EXPECT_NE(table.find(" 0.2500"), std::string::npos) << table;

        // HTML table: a column with the definition as hover text and the exact value.
        const fs::path dir =
            fs::temp_directory_path() / fmt::format("aabench_metric_registry_test-{}", ::getpid());
        ReportData data;
        data.rows = rows;
        write_html_report(dir.string(), data);
        const std::string html = read_file(dir / "index.html");
        fs::remove_all(dir);
        EXPECT_NE(html.find("<th title=\"test: overshoot next to edges\">ringing</th>"),
                  std::string::npos);
        EXPECT_NE(html.find("<td data-v=\"0.25\">0.25</td>"), std::string::npos);

        // The gate: within its own tolerance passes, beyond it fails, named by the key.
        ResultRow slightly = row, much = row;
        slightly[ringing.id()] = kRingingOld * (1 + kRingingRel / 2);
        much[ringing.id()] = kRingingOld * (1 + 2 * kRingingRel);
        const GateResult within = gate_rows(rows, {slightly}, GateTolerance{});
        EXPECT_TRUE(within.passed());
        ASSERT_EQ(within.changes.size(), 1u);
        EXPECT_EQ(within.changes[0].verdict, GateVerdict::kWithin);
        const GateResult worse = gate_rows(rows, {much}, GateTolerance{});
        EXPECT_FALSE(worse.passed());
        ASSERT_EQ(worse.changes.size(), 1u);
        EXPECT_EQ(worse.changes[0].figure, "test_ringing");
        EXPECT_EQ(worse.changes[0].verdict, GateVerdict::kWorse);
    }
    // Gone with its scope: the registry and the files are as before.
    EXPECT_EQ(metric_registry().size(), size_before);
    EXPECT_FALSE(metric_registry().find("test_ringing"));
    EXPECT_EQ(compare_rows_csv({made_up_row()}).find("test_ringing"), std::string::npos);
}

TEST(MetricRegistry, AHigherIsBetterMetricIsWorseWhenItFalls) {
    MetricDef def = ringing_metric();
    def.key = "test_sharpness";
    def.better = Better::kHigher;
    const ScopedMetric sharpness(def);
    ResultRow old_row = made_up_row(), new_row = made_up_row();
    old_row[sharpness.id()] = 1.0;
    new_row[sharpness.id()] = 1.0 - 2 * kRingingRel;
    EXPECT_FALSE(gate_rows({old_row}, {new_row}, GateTolerance{}).passed());
    new_row[sharpness.id()] = 2.0;
    const GateResult better = gate_rows({old_row}, {new_row}, GateTolerance{});
    EXPECT_TRUE(better.passed());
    ASSERT_EQ(better.changes.size(), 1u);
    EXPECT_EQ(better.changes[0].verdict, GateVerdict::kBetter);
}

TEST(MetricRegistry, KeysAreUniqueAndStagesAreAGeneratedFamily) {
    const MetricRegistry& registry = metric_registry();
    for (MetricId id = 0; id < registry.size(); ++id) {
        EXPECT_EQ(registry.find(registry[id].key), id) << registry[id].key;
        EXPECT_FALSE(registry[id].header.empty()) << registry[id].key;
        EXPECT_FALSE(registry[id].unit.empty()) << registry[id].key;
    }
    EXPECT_EQ(registry[stage_ms_metric(0)].key, "stage_projection_ms");
    EXPECT_EQ(registry[stage_bytes_metric(kStageCount - 1)].key, "stage_reflections_bytes");
    EXPECT_EQ(registry[metric::kBoxRmse].key, "box_rmse");
    EXPECT_EQ(registry[metric::kWorldMs].key, "world_ms");
}

// A results file of schema 1 (tests/data/results_schema1.json: the star and room rows of a
// default run at 64x64 written before schema_version) reads, and written back in today's
// schema every column it has keeps its value (figures, names and identity fields).
// A made-up figure computed from the image and its reference: the largest |rendered - box
// reference| over the pixels near edges. It asks for the edge band, which no other metric
// computed here needs (the symptoms are off), so the band is prepared for it alone.
double band_max_abs(const Image& image, const Coverage& box, const Raster<std::uint8_t>& band) {
    if (band.data.size() != image.data.size()) return kNaN;  // the band was not prepared
    double worst = 0.0;
    for (std::size_t k = 0; k < image.data.size(); ++k) {
        if (band.data[k]) worst = std::max(worst, std::abs(image.data[k] - box.data[k]));
    }
    return worst;
}

void measure_band_max_abs(const MetricInput& in, MetricId self, ResultRow& row) {
    row[self] = band_max_abs(in.image, in.box, in.prepared.edge_band);
}

// The whole of adding a metric: one row and its function.
MetricDef band_metric() {
    MetricDef def;
    def.key = "test_band_max_abs";
    def.header = "band_max";
    def.definition = "test: max |rendered - box_reference| within 1.5 px of an edge";
    def.unit = "value";
    def.better = Better::kLower;
    def.shown_in = kInText | kInScore;
    def.compute = measure_band_max_abs;
    def.needs = kNeedsEdgeBand;
    return def;
}

CompareOptions small_run() {
    CompareOptions options;
    options.method_specs = {"none", "box-multiscan:n=3"};
    options.pattern_specs = {"star"};
    options.width = options.height = 32;
    options.runs = 1;
    options.symptoms = false;  // no built-in metric asks for the edge band then
    return options;
}

TEST(MetricRegistry, AMetricThatComputesItselfIsInCompareAndScore) {
    // Without it, nothing in compare's scope (symptoms off) or score's asks for the band...
    MetricScope compare_scope;
    compare_scope.symptoms = false;
    ASSERT_EQ(metric_needs(compare_scope) & kNeedsEdgeBand, 0u);
    const ScopedMetric band(band_metric());
    // ...with it, both do.
    EXPECT_NE(metric_needs(compare_scope) & kNeedsEdgeBand, 0u);

    // compare: every row has the figure of its own image, and the symptoms stay off.
    const CompareResult result = run_comparison(small_run());
    ASSERT_EQ(result.rows.size(), 2u);
    ASSERT_EQ(result.figures.size(), 1u);
    const ComparisonFigures& fig = result.figures[0];
    ASSERT_EQ(fig.images.size(), result.rows.size());
    const Raster<std::uint8_t> edges = edge_band_mask(fig.scene);
    for (std::size_t k = 0; k < result.rows.size(); ++k) {
        const ResultRow& row = result.rows[k];
        EXPECT_TRUE(std::isnan(row[metric::kEdgeRmse])) << row.method;
        // The same function on the same pixels: equal, not near.
        EXPECT_EQ(row[band.id()], band_max_abs(fig.images[k], fig.reference, edges)) << row.method;
    }
    // Point sampling misses coverage on the star's edges; the figure sees it.
    EXPECT_GT(result.rows[0][band.id()], 0.0);
    EXPECT_NE(compare_rows_csv(result.rows).find(",test_band_max_abs"), std::string::npos);

    // score: the figure of the given image, and in both outputs.
    const PatternInstance star = resolve_pattern("star");
    const Scene scene = star.info->generate(star.params, 32, 32);
    const ResultRow scored = score_image(fig.images[0], scene, "box", "star.exr");
    EXPECT_EQ(scored[band.id()], result.rows[0][band.id()]);
    const nlohmann::json doc = nlohmann::json::parse(score_json(scored, "star.exr"));
    ASSERT_TRUE(doc.contains("test_band_max_abs")) << doc.dump();
    EXPECT_EQ(doc["test_band_max_abs"], scored[band.id()]);
    EXPECT_NE(format_score(scored, "star.exr").find("test_band_max_abs"), std::string::npos);
}

TEST(ResultsSchema, ASchema1FileReadsAndWritesBackTheSameFigures) {
    const fs::path path = fs::path(AABENCH_SOURCE_DIR) / "tests/data/results_schema1.json";
    const std::string text = read_file(path);
    const nlohmann::json old_doc = nlohmann::json::parse(text);
    ASSERT_FALSE(old_doc.contains("schema_version"));
    // Leniently, as aabench check reads it: it predates not_applicable.
    const std::vector<ResultRow> rows = rows_from_compare_json(text, path.string(), true);
    ASSERT_EQ(rows.size(), old_doc["rows"].size());
    const nlohmann::json new_doc = nlohmann::json::parse(compare_json(rows, RunContext{}));
    EXPECT_EQ(new_doc["schema_version"], kResultsSchemaVersion);
    for (std::size_t k = 0; k < rows.size(); ++k) {
        for (const auto& [key, value] : old_doc["rows"][k].items()) {
            ASSERT_TRUE(new_doc["rows"][k].contains(key)) << key;
            EXPECT_EQ(new_doc["rows"][k][key], value) << "rows[" << k << "]." << key;
        }
    }
}

TEST(ResultsSchema, AnUnknownVersionIsRefusedWithHowToRegenerate) {
    nlohmann::json doc = nlohmann::json::parse(compare_json({made_up_row()}, RunContext{}));
    doc["schema_version"] = kResultsSchemaVersion + 1;
    try {
        rows_from_compare_json(doc.dump(), "future.json");
        FAIL() << "a newer schema was read";
    } catch (const InputError& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find("future.json"), std::string::npos) << message;
        EXPECT_NE(message.find("regenerate"), std::string::npos) << message;
        EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    }
}

// aabench merge reads shards strictly: a file that lacks a column this build writes (the
// schema-1 file predates not_applicable) is refused in one line that says how to regenerate it.
TEST(ResultsSchema, AStrictReadOfAnOlderFileSaysHowToRegenerate) {
    const fs::path path = fs::path(AABENCH_SOURCE_DIR) / "tests/data/results_schema1.json";
    try {
        rows_from_compare_json(read_file(path), path.string());
        FAIL() << "a file without not_applicable was read strictly";
    } catch (const InputError& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find("missing 'not_applicable'"), std::string::npos) << message;
        EXPECT_NE(message.find("regenerate"), std::string::npos) << message;
        EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    }
}

TEST(MetricDocs, DocsMetricsHoldsTheRegistryTable) {
    const std::string docs = read_file(fs::path(AABENCH_SOURCE_DIR) / "docs/metrics.md");
    const std::size_t begin = docs.find(kRegistryBeginMarker);
    const std::size_t end = docs.find(kRegistryEndMarker);
    ASSERT_NE(begin, std::string::npos);
    ASSERT_NE(end, std::string::npos);
    const std::size_t from = begin + std::string(kRegistryBeginMarker).size() + 1;
    const std::string expected = metric_registry_markdown();
    EXPECT_EQ(docs.substr(from, end - from), expected)
        << "replace docs/metrics.md's block between the markers with:\n"
        << expected;
}

}  // namespace
}  // namespace aabench
