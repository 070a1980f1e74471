/* An example tecido plug-in in plain C: two engines behind the ABI of include/tecido/plugin.h.
 *
 *   mt-plugin     the seed's triangle-triangle test: Moller-Trumbore (1997) on each edge of one
 *                 triangle against the other, with the paper's absolute epsilon 1e-6 on the
 *                 determinant, and the seed's rule "an edge of A hits B AND an edge of B hits A".
 *                 Known misses: coplanar (touching) pairs, a small triangle stabbing a large one.
 *   euler-plugin  explicit (forward) Euler on particles and springs with gravity and linear drag:
 *                 x += h v(t), v += h a(x(t), v(t)). Global order 1, which it claims.
 *
 * Build: cc -shared -fPIC -O2 -I<tecido>/include tecido_example_plugin.c -o libtecido_example_plugin.so -lm
 * Use:   tecido tritri --pairs P.json --plugin ./libtecido_example_plugin.so --engines mt-plugin,exact --json
 *        tecido suite order --plugin ./libtecido_example_plugin.so --engines euler-plugin
 *
 * EXAMPLE_EULER_NAME and EXAMPLE_EULER_CLAIMS rename the Euler engine and change the order it claims
 * (tecido's tests build a lying copy, "euler-liar", that claims 2 and must be caught). */
#include <tecido/plugin.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#ifndef EXAMPLE_EULER_NAME
#define EXAMPLE_EULER_NAME "euler-plugin"
#endif
#ifndef EXAMPLE_EULER_CLAIMS
#define EXAMPLE_EULER_CLAIMS 1.0
#endif

/* ---- Moller-Trumbore on triangle edges ---- */

static void sub(const double* a, const double* b, double* r) { r[0] = a[0] - b[0]; r[1] = a[1] - b[1]; r[2] = a[2] - b[2]; }
static double dot(const double* a, const double* b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
static void cross(const double* a, const double* b, double* r) {
  r[0] = a[1] * b[2] - a[2] * b[1];
  r[1] = a[2] * b[0] - a[0] * b[2];
  r[2] = a[0] * b[1] - a[1] * b[0];
}

/* The segment o -> o + dir against triangle t (9 doubles), borders included. */
static int segment_hits(const double* o, const double* dir, const double* t) {
  double e1[3], e2[3], p[3], tv[3], q[3];
  sub(t + 3, t, e1);
  sub(t + 6, t, e2);
  cross(dir, e2, p);
  const double det = dot(e1, p);
  if (det > -1e-6 && det < 1e-6) return 0; /* the paper's EPSILON */
  const double inv = 1.0 / det;
  sub(o, t, tv);
  const double u = dot(tv, p) * inv;
  if (u < 0.0 || u > 1.0) return 0;
  cross(tv, e1, q);
  const double v = dot(dir, q) * inv;
  if (v < 0.0 || u + v > 1.0) return 0;
  const double s = dot(e2, q) * inv;
  return s >= 0.0 && s <= 1.0;
}

static int some_edge_hits(const double* a, const double* b) {
  for (int i = 0; i < 3; ++i) {
    double dir[3];
    sub(a + 3 * ((i + 1) % 3), a + 3 * i, dir);
    if (segment_hits(a + 3 * i, dir, b)) return 1;
  }
  return 0;
}

static int mt_tri_tri(const double a[9], const double b[9]) { return some_edge_hits(a, b) && some_edge_hits(b, a); }

/* ---- explicit Euler on particles and springs ---- */

typedef struct euler_sim {
  size_t n, m;
  double *x, *v, *a, *inv_mass, *k, *rest;
  uint32_t* ends;
  double g[3], drag;
} euler_sim;

static void euler_destroy(void* p) {
  euler_sim* s = (euler_sim*)p;
  if (!s) return;
  free(s->x), free(s->v), free(s->a), free(s->inv_mass), free(s->k), free(s->rest), free(s->ends);
  free(s);
}

static void* euler_create(const tecido_scene* sc, char* why, size_t why_size) {
  if (sc->features != 0) { /* wind, planes, damping, self-collision, obstacles: none modelled */
    snprintf(why, why_size, "only particles, springs, gravity and linear drag (feature bits 0x%llx)",
             (unsigned long long)sc->features);
    return NULL;
  }
  euler_sim* s = (euler_sim*)calloc(1, sizeof *s);
  if (!s) return NULL;
  s->n = sc->particle_count, s->m = sc->spring_count;
  s->x = malloc(3 * s->n * sizeof(double)), s->v = malloc(3 * s->n * sizeof(double));
  s->a = malloc(3 * s->n * sizeof(double)), s->inv_mass = malloc(s->n * sizeof(double));
  s->k = malloc(s->m * sizeof(double) + 1), s->rest = malloc(s->m * sizeof(double) + 1);
  s->ends = malloc(2 * s->m * sizeof(uint32_t) + 1);
  if (!s->x || !s->v || !s->a || !s->inv_mass || !s->k || !s->rest || !s->ends) {
    euler_destroy(s);
    snprintf(why, why_size, "out of memory");
    return NULL;
  }
  memcpy(s->x, sc->positions, 3 * s->n * sizeof(double));
  memcpy(s->v, sc->velocities, 3 * s->n * sizeof(double));
  memcpy(s->inv_mass, sc->inverse_masses, s->n * sizeof(double));
  memcpy(s->k, sc->spring_stiffness, s->m * sizeof(double));
  memcpy(s->rest, sc->spring_rest_length, s->m * sizeof(double));
  memcpy(s->ends, sc->spring_ends, 2 * s->m * sizeof(uint32_t));
  memcpy(s->g, sc->gravity, sizeof s->g);
  s->drag = sc->linear_drag;
  return s;
}

/* a = g - (c/m) v + (1/m) sum of spring forces; 0 for pinned particles. */
static void accelerations(euler_sim* s) {
  memset(s->a, 0, 3 * s->n * sizeof(double));
  for (size_t k = 0; k < s->m; ++k) { /* forces first, divided by mass below */
    const size_t i = s->ends[2 * k], j = s->ends[2 * k + 1];
    double d[3];
    sub(s->x + 3 * j, s->x + 3 * i, d);
    const double len = sqrt(dot(d, d));
    if (len == 0.0) continue;
    const double f = s->k[k] * (len - s->rest[k]) / len;
    for (int c = 0; c < 3; ++c) s->a[3 * i + c] += f * d[c], s->a[3 * j + c] -= f * d[c];
  }
  for (size_t i = 0; i < s->n; ++i)
    for (int c = 0; c < 3; ++c) {
      const double w = s->inv_mass[i];
      s->a[3 * i + c] = w == 0.0 ? 0.0 : s->g[c] + w * (s->a[3 * i + c] - s->drag * s->v[3 * i + c]);
    }
}

static int euler_step(void* p, double h, int64_t steps) {
  euler_sim* s = (euler_sim*)p;
  for (int64_t t = 0; t < steps; ++t) {
    accelerations(s);
    for (size_t q = 0; q < 3 * s->n; ++q) {
      s->x[q] += h * s->v[q];
      s->v[q] += h * s->a[q];
    }
  }
  for (size_t q = 0; q < 3 * s->n; ++q)
    if (!isfinite(s->x[q]) || !isfinite(s->v[q])) return 1;
  return 0;
}

static void euler_read(const void* p, double* x, double* v) {
  const euler_sim* s = (const euler_sim*)p;
  memcpy(x, s->x, 3 * s->n * sizeof(double));
  memcpy(v, s->v, 3 * s->n * sizeof(double));
}

/* ---- the table ---- */

static const tecido_engine engines[] = {
    {"mt-plugin", 0.0, TECIDO_ENGINE_THREAD_SAFE, mt_tri_tri, NULL, NULL, NULL, NULL, NULL, NULL, NULL},
    {EXAMPLE_EULER_NAME, EXAMPLE_EULER_CLAIMS, TECIDO_ENGINE_THREAD_SAFE, NULL, NULL, NULL, NULL, euler_create,
     euler_step, euler_read, euler_destroy},
};

static const tecido_plugin plugin = {TECIDO_PLUGIN_ABI_VERSION, sizeof engines / sizeof engines[0], engines};

const tecido_plugin* tecido_plugin_entry(void) { return &plugin; }
