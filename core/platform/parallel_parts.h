#pragma once
/// Runs one job in `parts` shares on as many threads (the calling thread runs share 0; the
/// others are started for the call and joined before it returns). Callers cut their work into
/// contiguous shares by index and merge the shares' results in share order (or by sorting), so
/// the result does not depend on the number of threads. An exception thrown by any share is
/// rethrown after every thread has joined (the lowest share's first).
#include <cstddef>
#include <functional>

namespace tecido {

void run_parts(int parts, const std::function<void(int part)>& job);

/// The first index of share `part` of `parts` over n items: n * part / parts.
inline std::size_t share_begin(std::size_t n, int part, int parts) {
  return n * static_cast<std::size_t>(part) / static_cast<std::size_t>(parts);
}

}  // namespace tecido
