// SPDX-License-Identifier: MIT
#include "o3d/utility/random.h"

#include <mutex>
#include <random>

namespace o3d::utility::random {

namespace {

struct GlobalGenerator {
    std::mutex mutex;
    bool seeded = false;
    SplitMix64 generator{0};
};

GlobalGenerator& global() {
    static GlobalGenerator g;
    return g;
}

}  // namespace

void seed(uint64_t value) {
    auto& g = global();
    std::lock_guard<std::mutex> lock(g.mutex);
    g.generator.state = value;
    g.seeded = true;
}

uint64_t draw_call_seed() {
    auto& g = global();
    std::lock_guard<std::mutex> lock(g.mutex);
    if (!g.seeded) {
        // Seeded lazily, so a program that calls seed() first never touches the random device.
        std::random_device device;
        g.generator.state = (static_cast<uint64_t>(device()) << 32) ^ device();
        g.seeded = true;
    }
    return g.generator.next();
}

}  // namespace o3d::utility::random
