#include "core/geometry/ccd_stats.h"

namespace tecido {

CcdStats& ccd_stats() {
  thread_local CcdStats stats;
  return stats;
}

}  // namespace tecido
