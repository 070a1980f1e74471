#include "core/geometry/ccd/stats.h"

namespace tecido {

CcdStats& ccd_stats() {
  thread_local CcdStats stats;
  return stats;
}

}  // namespace tecido
