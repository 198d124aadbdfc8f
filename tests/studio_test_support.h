// Helpers shared by the studio QtTests.
#pragma once

namespace inlay::test {

// Sanitizer builds run several times slower (TSan 5-15x, ASan about 2-3x), so every wait a
// studio test makes for a worker, a frame or a child process is scaled by the factor that
// cmake/Sanitizers.cmake chooses (1 in an ordinary build). Only the deadline grows: each test
// still waits for the same condition.
constexpr int kWaitScale = INLAY_TEST_WAIT_SCALE;

constexpr int waitMs(int ms) { return ms * kWaitScale; }

}  // namespace inlay::test
