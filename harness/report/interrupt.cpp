// The signal-time cleanup of temporary files (harness/report/interrupt.h).
#include "harness/report/interrupt.h"

#include <signal.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <cstring>

namespace aabench {
namespace {

// Files written at once: one per thread of a --jobs run at most, so 256 covers every --jobs.
constexpr int kMaxTempFiles = 256;
// PATH_MAX on Linux; a longer path is not registered (and could not be opened anyway).
constexpr std::size_t kMaxPathBytes = 4096;

// The handler may only read plain memory and call async-signal-safe functions (unlink, raise):
// the slots are fixed arrays, claimed and released with atomics, never allocated.
struct Slot {
    std::atomic<int> state{0};  // 0 free, 1 being filled, 2 holds a path
    char path[kMaxPathBytes];
};
std::array<Slot, kMaxTempFiles> slots;

void remove_temps_and_die(int signal_number) {
    for (Slot& slot : slots) {
        if (slot.state.load(std::memory_order_acquire) == 2) ::unlink(slot.path);
    }
    // The default action now: the process ends "killed by SIGINT", as the caller expects.
    ::signal(signal_number, SIG_DFL);
    ::raise(signal_number);
}

}  // namespace

void install_interrupt_cleanup() {
    struct sigaction action {};
    action.sa_handler = remove_temps_and_die;
    sigemptyset(&action.sa_mask);
    for (const int s : {SIGINT, SIGTERM, SIGHUP}) sigaddset(&action.sa_mask, s);
    for (const int s : {SIGINT, SIGTERM, SIGHUP}) ::sigaction(s, &action, nullptr);
}

int register_temp_file(const std::string& path) {
    if (path.size() >= kMaxPathBytes) return -1;
    for (int k = 0; k < kMaxTempFiles; ++k) {
        int expected = 0;
        if (!slots[k].state.compare_exchange_strong(expected, 1, std::memory_order_acquire)) {
            continue;
        }
        std::memcpy(slots[k].path, path.c_str(), path.size() + 1);
        slots[k].state.store(2, std::memory_order_release);
        return k;
    }
    return -1;
}

void unregister_temp_file(int slot) {
    if (slot >= 0 && slot < kMaxTempFiles) slots[slot].state.store(0, std::memory_order_release);
}

}  // namespace aabench
