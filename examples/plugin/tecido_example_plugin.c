/* An example tecido plug-in in plain C: three engines behind the ABI of include/tecido/plugin.h.
 *
 *   mt-plugin     the seed's triangle-triangle test: Moller-Trumbore (1997) on each edge of one
 *                 triangle against the other, with the paper's absolute epsilon 1e-6 on the
 *                 determinant, and the seed's rule "an edge of A hits B AND an edge of B hits A".
 *                 Known misses: coplanar (touching) pairs, a small triangle stabbing a large one.
 *   euler-plugin  explicit (forward) Euler on particles and springs with gravity and linear drag:
 *                 x += h v(t), v += h a(x(t), v(t)). Global order 1, which it claims.
 *   sampled-ccd   a naive continuous collision test (vertex-face and edge-edge): it samples the
 *                 coplanarity of the four points at SAMPLES + 1 instants and looks for a contact
 *                 only where the sign changes, at the linearly interpolated time. Known misses:
 *                 fast contacts, where the plane passes the point and back (or touches it)
 *                 between two instants; contacts near an edge, where the interpolated time is off.
 *
 * Build: cc -shared -fPIC -O2 -I<tecido>/include tecido_example_plugin.c -o libtecido_example_plugin.so -lm
 * Use:   tecido tritri --pairs P.json --plugin ./libtecido_example_plugin.so --engines mt-plugin,exact --json
 *        tecido suite order --plugin ./libtecido_example_plugin.so --engines euler-plugin
 *        tecido ccd --queries Q.json --plugin ./libtecido_example_plugin.so --engines exact,sampled-ccd --json
 *
 * EXAMPLE_EULER_NAME and EXAMPLE_EULER_CLAIMS rename the Euler engine and change the order it claims
 * (tecido's tests build a lying copy, "euler-liar", that claims 2 and must be caught);
 * EXAMPLE_SAMPLED_EDGE_EDGE=NULL leaves sampled-ccd without an edge-edge test (the same copy: a
 * kind it does not model). */
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
#ifndef EXAMPLE_SAMPLED_EDGE_EDGE
#define EXAMPLE_SAMPLED_EDGE_EDGE sampled_edge_edge
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
  if (s->m > 0) { /* the spring arrays may be NULL when there are none (plugin.h) */
    memcpy(s->k, sc->spring_stiffness, s->m * sizeof(double));
    memcpy(s->rest, sc->spring_rest_length, s->m * sizeof(double));
    memcpy(s->ends, sc->spring_ends, 2 * s->m * sizeof(uint32_t));
  }
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

/* ---- sampled continuous collision ---- */

#define SAMPLES 4

/* The four points at time t: p[3k..3k+2] = (1 - t) t0 + t t1 for point k. */
static void at_time(const double t0[12], const double t1[12], double t, double p[12]) {
  for (int q = 0; q < 12; ++q) p[q] = (1.0 - t) * t0[q] + t * t1[q];
}

/* (p1 - p0) . ((p2 - p0) x (p3 - p0)): zero when the four points are coplanar. */
static double coplanarity(const double p[12]) {
  double u[3], v[3], w[3], n[3];
  sub(p + 3, p, u), sub(p + 6, p, v), sub(p + 9, p, w);
  cross(v, w, n);
  return dot(u, n);
}

/* Vertex p[0..2] in the closed triangle p[3..11] (coplanar): barycentric signs by area vectors. */
static int vertex_in_face(const double p[12]) {
  double e1[3], e2[3], d[3], n[3], c[3];
  sub(p + 6, p + 3, e1), sub(p + 9, p + 3, e2), sub(p, p + 3, d);
  cross(e1, e2, n);
  const double nn = dot(n, n);
  if (nn == 0.0) return 0;
  cross(d, e2, c);
  const double u = dot(c, n) / nn;
  cross(e1, d, c);
  const double v = dot(c, n) / nn;
  return u >= 0.0 && v >= 0.0 && u + v <= 1.0;
}

/* Segments p0p1 and p2p3 (coplanar) meet: the parameters of their closest points in [0, 1]. */
static int edges_meet(const double p[12]) {
  double a[3], b[3], r[3];
  sub(p + 3, p, a), sub(p + 9, p + 6, b), sub(p, p + 6, r);
  const double aa = dot(a, a), ab = dot(a, b), bb = dot(b, b), ar = dot(a, r), br = dot(b, r);
  const double den = aa * bb - ab * ab;
  if (den == 0.0) return 0; /* parallel: not handled */
  const double s = (ab * br - bb * ar) / den, u = (aa * br - ab * ar) / den;
  return s >= 0.0 && s <= 1.0 && u >= 0.0 && u <= 1.0;
}

static int sampled(const double t0[12], const double t1[12], double* toi, int (*meets)(const double*)) {
  double p[12], prev = 0.0;
  for (int k = 0; k <= SAMPLES; ++k) {
    const double t = (double)k / SAMPLES;
    at_time(t0, t1, t, p);
    const double f = coplanarity(p);
    if (k > 0 && ((prev <= 0.0 && f >= 0.0) || (prev >= 0.0 && f <= 0.0))) {
      const double tc = prev == f ? t : t - (1.0 / SAMPLES) * f / (f - prev); /* linear interpolation */
      at_time(t0, t1, tc, p);
      if (meets(p)) {
        *toi = tc;
        return 1;
      }
    }
    prev = f;
  }
  return 0;
}

static int sampled_vertex_face(const double t0[12], const double t1[12], double* toi) {
  return sampled(t0, t1, toi, vertex_in_face);
}

static int sampled_edge_edge(const double t0[12], const double t1[12], double* toi) {
  return sampled(t0, t1, toi, edges_meet);
}

/* ---- the table ---- */

static const tecido_engine engines[] = {
    {"mt-plugin", 0.0, TECIDO_ENGINE_THREAD_SAFE, mt_tri_tri, NULL, NULL, NULL, NULL, NULL, NULL, NULL},
    {EXAMPLE_EULER_NAME, EXAMPLE_EULER_CLAIMS, TECIDO_ENGINE_THREAD_SAFE, NULL, NULL, NULL, NULL, euler_create,
     euler_step, euler_read, euler_destroy},
    {"sampled-ccd", 0.0, TECIDO_ENGINE_THREAD_SAFE, NULL, NULL, sampled_vertex_face, EXAMPLE_SAMPLED_EDGE_EDGE, NULL,
     NULL, NULL, NULL},
};

static const tecido_plugin plugin = {TECIDO_PLUGIN_ABI_VERSION, sizeof engines / sizeof engines[0], engines};

const tecido_plugin* tecido_plugin_entry(void) {
  (void)sampled_edge_edge; /* referenced even when EXAMPLE_SAMPLED_EDGE_EDGE leaves it out of the table */
  return &plugin;
}
