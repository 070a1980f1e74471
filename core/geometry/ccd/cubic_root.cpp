#include "core/geometry/ccd/cubic_root.h"

#include "core/geometry/ccd/decisions.h"

namespace tecido {

double ccd_cubic_root(const double b[4], double tol) {
  return ccd_scalar::cubic_root<ccd_scalar::Lanes>(b, tol);
}

}  // namespace tecido
