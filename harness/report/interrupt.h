// What a Ctrl-C (SIGINT), SIGTERM or SIGHUP leaves behind: no partial file. Every file aabench
// writes goes to a temporary name first and is renamed into place when complete
// (harness/report/image_io.h); a signal that arrives in between would otherwise leave the
// temporary. The temporaries are registered here while they exist, and the handler removes them
// before the process ends with the signal's default action (so the shell still sees "killed by
// SIGINT").
#pragma once

#include <string>

namespace aabench {

// Installs the handler for SIGINT, SIGTERM and SIGHUP. Once per process (the CLI's main).
void install_interrupt_cleanup();

// A temporary file that the handler removes if a signal comes before unregister_temp_file.
// Returns the slot to unregister, or -1 when every slot is taken (kMaxTempFiles files written
// at once; the file is then not protected, which only matters if a signal comes).
int register_temp_file(const std::string& path);
void unregister_temp_file(int slot);

}  // namespace aabench
