#pragma once
// A stop flag that is never raised, for recordings that end by their own duration or sources.

#include <atomic>

namespace littermap::test {

inline const std::atomic<bool> kNeverStop{false};

}  // namespace littermap::test
