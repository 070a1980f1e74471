/* tecido's plug-in ABI: an engine written in any language that can export C functions, loaded by
 * `tecido tritri|plane|ccd|suite --plugin PATH.so` and validated like a built-in engine.
 *
 * Plain C (C99 and C++), no C++ types. A plug-in is a shared library exporting one function,
 *
 *     const tecido_plugin* tecido_plugin_entry(void);
 *
 * returning a table that lives as long as the library (a static const object). The table's first
 * member is the ABI version the plug-in was built against (TECIDO_PLUGIN_ABI_VERSION of this
 * header); tecido refuses a table of another version with a one-line error and exit 2, so the
 * layout below may change only together with the version.
 *
 * A plug-in names one or more engines. Each engine fills in only what it can answer; every other
 * function pointer is NULL and tecido does not offer that engine there:
 *   tri_tri          closed triangles (touching counts as intersecting)         tecido tritri, suites tritri, selfcollision
 *   segment_plane    a segment against a bounded (rectangular, closed) plane    tecido plane
 *   ccd_vertex_face  a vertex against a triangle, both moving linearly, t in [0,1]   tecido ccd, suite ccd
 *   ccd_edge_edge    an edge against an edge, likewise
 *   create/step/read/destroy   a particle-and-spring dynamics engine            suites order, stability, drift, tradeoff
 *
 * Threads: tecido's suites run cases on several threads. An engine whose flags include
 * TECIDO_ENGINE_THREAD_SAFE may have its query functions (tri_tri, segment_plane, ccd_*) and
 * distinct simulations called at the same time; without the flag tecido calls that engine from one
 * thread at a time. A simulation handle is never used by two threads at once.
 *
 * Errors: a query answers -1 when it cannot decide (tecido prints null). create() refuses a scene
 * it does not model by returning NULL with a one-line reason in `why` (tecido reports "not
 * modelled by <engine>: <why>" and skips the engine on that scene). Strings are NUL-terminated
 * UTF-8; tecido owns every buffer it passes and never frees what the plug-in returns.
 */
#ifndef TECIDO_PLUGIN_H
#define TECIDO_PLUGIN_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

#define TECIDO_PLUGIN_ABI_VERSION 1

/* The name of the one exported function, for dlsym. */
#define TECIDO_PLUGIN_ENTRY_SYMBOL "tecido_plugin_entry"

#if defined(_WIN32)
#define TECIDO_PLUGIN_EXPORT __declspec(dllexport)
#else
#define TECIDO_PLUGIN_EXPORT __attribute__((visibility("default")))
#endif

/* tecido_engine.flags */
#define TECIDO_ENGINE_THREAD_SAFE 1u /* queries and distinct simulations may run concurrently */

/* tecido_scene.features: what a scene asks for beyond its particles, springs, gravity and linear
 * drag. A dynamics engine must refuse (create() returns NULL) a scene with any bit it does not
 * model; tecido never drops a feature silently. The details of these features are not in the flat
 * arrays (a process engine gets them in the scene's JSON). Unknown bits must be refused too. */
#define TECIDO_FEATURE_WIND 1u              /* a constant or swirling wind force per particle */
#define TECIDO_FEATURE_PLANES 2u            /* bounded planes the particles collide with */
#define TECIDO_FEATURE_SPRING_DAMPING 4u    /* some spring has damping along its axis */
#define TECIDO_FEATURE_SELF_COLLISION 8u    /* cloth self-collision detection and response */
#define TECIDO_FEATURE_OBSTACLES 16u        /* spheres, boxes or meshes the particles collide with */
#define TECIDO_FEATURE_EDGE_CONTACTS 32u    /* edge contacts against obstacles */

/* A bounded plane: the rectangle's centre, unit normal, unit forward (orthogonal to the normal),
 * and half extents along forward and along right = normal x forward. Closed: the border counts. */
typedef struct tecido_plane {
  double position[3];
  double normal[3];
  double forward[3];
  double half_extents[2];
} tecido_plane;

/* The scene a dynamics engine is created on, as flat arrays (n particles, m springs), SI units.
 * Particle i is at positions[3i..3i+2]. inverse_masses[i] == 0 marks a pinned particle: it never
 * moves. Spring k joins spring_ends[2k] and spring_ends[2k+1] with force
 * stiffness (|xij| - rest_length) xij / |xij| on both ends. Forces per free particle: m g, -c v
 * (linear drag, c = linear_drag, 0 = none), springs. The arrays are valid during create() only;
 * an array of zero entries (m = 0: no springs) may be NULL. */
typedef struct tecido_scene {
  size_t particle_count;
  const double* positions;       /* 3n [m] */
  const double* velocities;      /* 3n [m/s] */
  const double* inverse_masses;  /* n [1/kg]; 0 = pinned */
  size_t spring_count;
  const uint32_t* spring_ends;        /* 2m particle indices */
  const double* spring_stiffness;     /* m [N/m] */
  const double* spring_rest_length;   /* m [m] */
  double gravity[3];                  /* [m/s^2]; zero when the scene has none */
  double linear_drag;                 /* c [kg/s] */
  double dt;                          /* the scene's step [s]; step() says the one to take */
  uint64_t features;                  /* TECIDO_FEATURE_* bits; refuse any you do not model */
} tecido_scene;

typedef struct tecido_engine {
  const char* name;        /* the engine's name on tecido's command line: [A-Za-z0-9_.-]+ */
  double claimed_order;    /* the global order its integrator claims (the order suite checks it); 0 = none */
  uint32_t flags;          /* TECIDO_ENGINE_* */

  /* Two closed triangles a = 3 corners x (x,y,z), b likewise: 1 intersecting, 0 not, -1 cannot say. */
  int (*tri_tri)(const double a[9], const double b[9]);

  /* The segment from -> to against the plane: 1 hit (*t = fraction along the segment of the
   * crossing, in [0,1]), 0 miss, -1 cannot say. */
  int (*segment_plane)(const tecido_plane* plane, const double from[3], const double to[3], double* t);

  /* Continuous tests over t in [0,1], positions moving linearly from t0 to t1 (4 points x (x,y,z)):
   * vertex-face: the vertex, then the triangle's corners; edge-edge: a0, a1, b0, b1.
   * 1 contact (*toi = the first time of contact), 0 none, -1 cannot say. */
  int (*ccd_vertex_face)(const double t0[12], const double t1[12], double* toi);
  int (*ccd_edge_edge)(const double t0[12], const double t1[12], double* toi);

  /* Dynamics. create() returns a simulation of `scene`, or NULL with a one-line reason written
   * into why[0..why_size-1] (NUL-terminated; e.g. "wind: not modelled"). step() advances `steps`
   * steps of `dt` seconds and returns 0, or nonzero when the state stopped being finite or the
   * engine failed (tecido then stops the run). read() copies the state out: positions and
   * velocities, 3n doubles each, particle i as in the scene. destroy() frees the simulation. */
  void* (*create)(const tecido_scene* scene, char* why, size_t why_size);
  int (*step)(void* simulation, double dt, int64_t steps);
  void (*read)(const void* simulation, double* positions, double* velocities);
  void (*destroy)(void* simulation);
} tecido_engine;

typedef struct tecido_plugin {
  uint32_t abi_version;          /* TECIDO_PLUGIN_ABI_VERSION; must stay the first member */
  size_t engine_count;
  const tecido_engine* engines;  /* engine_count entries */
} tecido_plugin;

/* The one symbol a plug-in exports. */
TECIDO_PLUGIN_EXPORT const tecido_plugin* tecido_plugin_entry(void);

#ifdef __cplusplus
}
#endif

#endif /* TECIDO_PLUGIN_H */
