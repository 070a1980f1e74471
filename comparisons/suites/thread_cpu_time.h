#pragma once
/// CPU time of the calling thread, for the suites that time work inside a sweep's case: unlike
/// wall time it does not count the time other threads and processes take from this one on a
/// shared machine.
#include <ctime>

namespace tecido::suites {

/// CPU seconds consumed by the calling thread so far (CLOCK_THREAD_CPUTIME_ID).
inline double thread_cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

}  // namespace tecido::suites
