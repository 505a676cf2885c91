// What a method's times are not, where they could be misread (gl-msaa's are a CPU emulation of
// a GPU, not the cost of MSAA on one). The reports print it under any table holding the method.
// Kept out of MethodTraits so that the one method with a caveat does not touch every method's
// header; methods/registry.cpp maps a row to its method file's caveat.
#pragma once

#include <string>

namespace aabench {

// Empty when the method's times mean what every method's do.
std::string time_caveat(const std::string& method_id);

}  // namespace aabench
