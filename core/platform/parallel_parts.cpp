#include "core/platform/parallel_parts.h"

#include <exception>
#include <thread>
#include <vector>

namespace tecido {

void run_parts(int parts, const std::function<void(int part)>& job) {
  if (parts <= 1) {
    job(0);
    return;
  }
  std::vector<std::exception_ptr> failed(static_cast<std::size_t>(parts));
  const auto guarded = [&](int part) {
    try {
      job(part);
    } catch (...) {
      failed[static_cast<std::size_t>(part)] = std::current_exception();
    }
  };
  std::vector<std::thread> pool;
  pool.reserve(static_cast<std::size_t>(parts - 1));
  for (int part = 1; part < parts; ++part) pool.emplace_back(guarded, part);
  guarded(0);
  for (auto& t : pool) t.join();
  for (const auto& e : failed)
    if (e) std::rethrow_exception(e);
}

}  // namespace tecido
