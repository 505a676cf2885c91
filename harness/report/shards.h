// The files of sharded runs: the shard plan as text (compare --plan-shards), the completion
// marker every compare run writes last into its results directory (shard.json), and the
// checks `aabench merge` makes before it joins shards, so that a merge of the wrong folders
// is refused instead of producing a results file that looks whole and is not.
//
// shard.json: {"schema_version", "shard" (K, 1-based), "shard_count" (N), "task_count" (of the
// unsharded run), "rows" (in this shard's results.json), "split" (the split's id, hex),
// "options" (what decides the rows: size, runs, sweep, methods, patterns, scenes, ...),
// "estimate_s" (this shard, on the cost model's machine), "tasks_s" and "wall_s" (measured:
// the tasks alone, the whole command up to the marker)}. docs/cluster.md describes the use.
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "harness/measure/compare.h"

namespace aabench {

inline constexpr const char* kShardMarkerFile = "shard.json";

struct ShardMarker {
    int schema_version = 0;  // of the results.json beside it
    int shard = 1;           // K, 1-based
    int shard_count = 1;     // N
    long long task_count = 0;
    long long rows = 0;
    std::string split_id;            // 16 hex digits
    nlohmann::ordered_json options;  // by the compare option's name
    double estimate_s = 0.0;
    double tasks_s = 0.0;
    double wall_s = 0.0;
};

// The marker of a finished run (`result` of run_comparison with `options`); the caller adds
// the measured times.
ShardMarker make_shard_marker(const CompareOptions& options, const CompareResult& result);
std::string shard_marker_json(const ShardMarker& marker);
// InputError naming `source` for a marker that is not one.
ShardMarker shard_marker_from_json(const std::string& text, const std::string& source);

// compare --plan-shards: every task with its shard and estimate, then one line per shard
// (tasks, estimate, memory), the largest over the mean, and a last line for scripts:
// "largest shard: K/N estimate_s=S memory_bytes=B".
std::string format_shard_plan(const ShardPlan& plan);

// One folder given to merge, as read: its marker (absent: no shard.json) and results.json.
struct ShardFolder {
    std::string dir;
    std::optional<std::string> marker_text;
    std::string results_text;
};

struct MergedShards {
    std::vector<ResultRow> rows;       // in the unsharded order
    std::vector<ShardMarker> markers;  // by K
};

// Checks the folders are the N shards of one run, each finished, then joins their rows.
// Refused with a one-line InputError naming the folder: a shard without its marker
// (unfinished), a results.json of other row count than its marker (half-written or altered),
// another results schema, other options (size, methods, ...), another N or split, the same K
// twice; and, naming the folders given, a K of N that none of them holds.
MergedShards merge_shard_folders(const std::vector<ShardFolder>& folders);

// The error columns: every figure of a row but its times (the metrics before time_median_ns:
// errors, symptoms, line scores), deterministic, unlike the times.
bool is_error_column(MetricId id);

// Where `merged` and `whole` (the unsharded run) differ: the first row or error column that is
// not the same, bit for bit (NaN equals NaN), as one line; empty when none does.
std::string error_column_difference(const std::vector<ResultRow>& merged,
                                    const std::vector<ResultRow>& whole);

// Per shard: tasks, estimate_s, tasks_s, wall_s; then largest/mean of each column.
std::string format_shard_times(const std::vector<ShardMarker>& markers);

}  // namespace aabench
