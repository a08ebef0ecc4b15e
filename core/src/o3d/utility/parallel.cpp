// SPDX-License-Identifier: MIT
#include "o3d/utility/parallel.h"

#include <omp.h>
#include <pthread.h>
#include <unistd.h>

#include <atomic>

namespace o3d::utility {
namespace {
std::atomic<int> g_default_threads{0};
std::atomic<bool> g_forked{false};

void mark_forked_child() { g_forked.store(true); }

struct ForkWatch {
    ForkWatch() { pthread_atfork(nullptr, nullptr, &mark_forked_child); }
};
const ForkWatch g_fork_watch;
}  // namespace

void set_default_num_threads(int num_threads) { g_default_threads.store(num_threads < 0 ? 0 : num_threads); }

int resolve_num_threads(int requested) {
    if (g_forked.load()) return 1;
    int n = requested > 0 ? requested : g_default_threads.load();
    if (n <= 0) n = omp_get_max_threads();
    return n < 1 ? 1 : n;
}

}  // namespace o3d::utility
