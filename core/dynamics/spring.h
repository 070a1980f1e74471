#pragma once
/// A spring between two particles (seed eq. 10): f_i = ks (|x_ij| - l) x_ij/|x_ij| with
/// x_ij = x_j - x_i, and the opposite force on j. Optional linear damping along the spring:
/// f_i += c ((v_j - v_i) . u) u with u = x_ij/|x_ij|.
namespace tecido {

struct Spring {
  int i = 0;
  int j = 0;
  double stiffness = 0.0;    ///< ks [N/m]
  double rest_length = 0.0;  ///< l [m]
  double damping = 0.0;      ///< c [N s/m], 0 = undamped
};

}  // namespace tecido
