#pragma once
/// Closed forms of the `obstacles` suite's analytic cases.
namespace tecido::suites::obstacles {

/// Time [s] for a particle released at rest to fall `height` [m] under gravity g: sqrt(2 h / g).
double fall_time(double height, double g);

/// Height [m] a particle dropped from `height` above a surface rises to after one bounce with
/// restitution k (velocity k v after the contact): k^2 h (energy (k v)^2 / 2 = k^2 g h).
double rebound_apex(double height, double k);

/// Distance [m] slid in n steps of h [s] from rest down a face with tangential acceleration a
/// [m/s^2] under the seed's friction law (seed section 3.1.1: each step the tangential velocity is
/// scaled by (1 - mu), then symplectic Euler adds a h and moves by the new velocity):
/// v_k = a h (1 - (1 - mu)^k) / mu, x_n = h sum_{k=1..n} v_k
///     = a h^2 / mu (n - (1 - mu)(1 - (1 - mu)^n) / mu); for mu = 0, a h^2 n (n + 1) / 2.
double slide_distance(double a, double mu, double h, long long n);

/// The speed the seed's friction law tends to on an incline: a h / mu [m/s] (v = (1 - mu) v + a h;
/// it depends on the step, unlike Coulomb friction). Infinite for mu = 0.
double slide_terminal_speed(double a, double mu, double h);

}  // namespace tecido::suites::obstacles
