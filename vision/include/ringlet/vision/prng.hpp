#pragma once
// The vision PRNG is the project's splitmix64 (hal/), seeded per frame: a frame's result depends
// on (seed, frame number) only.
#include "ringlet/hal/splitmix64.hpp"

namespace ringlet::vision {

using hal::SplitMix64;

}  // namespace ringlet::vision
