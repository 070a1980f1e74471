#pragma once
/// Holm's step-down adjustment for a family of tests (Holm 1979, "A simple sequentially rejective
/// multiple test procedure", Scand. J. Statist. 6:65-70): with the m p-values in ascending order
/// p(1) <= ... <= p(m), the adjusted p(i) is max over j <= i of min(1, (m - j + 1) p(j)). Rejecting
/// where the adjusted p < alpha keeps the chance of any false rejection in the family <= alpha.
#include <vector>

namespace tecido::stats {

/// The adjusted p-values, in the input's order. NaN entries (a test that could not be run) are
/// not members of the family: they stay NaN and do not count in m.
std::vector<double> holm_adjust(const std::vector<double>& p);

}  // namespace tecido::stats
