// The regression gate's outcome as text (aabench check): what changed, figure by figure, the
// timing summary, and the verdict line. Pure formatting.
#pragma once

#include <string>

#include "harness/measure/gate.h"

namespace aabench {

std::string format_gate(const GateResult& result, const GateTolerance& tolerance,
                        const std::string& baseline_path);

}  // namespace aabench
