#pragma once

#include <ctime>

namespace inlay {

// User and system CPU seconds of the process, every thread (0 when the clock cannot be read).
inline double processCpuSeconds() {
  timespec ts{};
  if (clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts) != 0) return 0;
  return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

}  // namespace inlay
