#pragma once
/// Every limit tecido puts on its input, in one table (docs/limits.md, "Limits"). Each is far above any
/// real file and is enforced before the work it bounds starts, so that no accepted input takes
/// memory or time out of proportion to its size. Past a limit: io::InputError (the file and the
/// JSON pointer or line) or io::UsageError (the option), exit 2, the limit named in the message.
/// Readers and commands added later (CCD queries, obstacles, experiment seeds) use these too.
#include <cstddef>
#include <cstdint>

namespace tecido::io {

// ---- Every input file -------------------------------------------------------------------
/// Largest input file [bytes] (JSON or OBJ); a longer file or stream (/dev/zero, a pipe) is
/// rejected after reading one byte more, never read whole. A parsed JSON document takes about 4
/// times its text for real files and at most about 33 times for the densest ([{},{},...]:
/// nlohmann::json's nodes), so this bounds a reader's memory.
constexpr std::size_t kMaxInputBytes = std::size_t{64} << 20;
/// Deepest JSON nesting (arrays and objects) of any JSON input: rejected while parsing, at the
/// first level past it. Real files nest at most about 8 levels.
constexpr int kMaxJsonDepth = 256;

// ---- Scenes (tecido run, the experiment's --scene) ---------------------------------------
constexpr double kMaxCoordinate = 1e12;  ///< |position| components [m]
constexpr double kMaxSpeed = 1e8;        ///< |velocity| components [m/s]
constexpr double kMaxMass = 1e12;        ///< [kg]
/// Smallest mass of a free particle or cloth node [kg]: its inverse, which the engine steps with,
/// must be a finite double (1 / 1e-310 overflows; fuzz_scene: regress_subnormal_mass).
constexpr double kMinMass = 1e-300;
constexpr double kMaxDt = 10.0;          ///< [s]
/// Steps of one run (the scene's "steps", `run --steps`); the work limit below usually binds first.
constexpr long long kMaxSteps = 1000000000LL;
/// Particles of a scene: listed ones plus cloth nodes.
constexpr std::size_t kMaxParticles = std::size_t{1} << 20;
/// Nodes of one cloth grid (rows x cols); each side is at most kMaxClothSide.
constexpr long long kMaxClothNodes = 1LL << 20;
constexpr int kMaxClothSide = 4096;
/// Springs of a scene: listed ones plus a cloth's (fewer than 8 per node, so a cloth of
/// kMaxClothNodes always fits).
constexpr std::size_t kMaxSprings = std::size_t{1} << 23;
/// Triangles of a scene (a cloth has fewer than 2 per node) and of an obstacle mesh.
constexpr std::size_t kMaxTriangles = std::size_t{1} << 21;
/// Bounded planes of a scene (every particle is tested against every plane, every step).
constexpr std::size_t kMaxPlanes = 1024;
/// Obstacles of a scene (spheres, boxes, meshes; every particle against every one, every step).
constexpr std::size_t kMaxObstacles = 1024;
/// Work of one run: steps x elements per step (io/work_limit.h: a step's overhead, particles,
/// springs, particles x (planes + obstacles), self-collision triangles by their cost), in
/// element-steps; a few minutes of one core. `--max-work N` raises it up to kMaxWorkCeiling.
constexpr double kDefaultMaxWork = 1e11;
constexpr double kMaxWorkCeiling = 1e16;
/// Frames of one `tecido run --out` (one OBJ file each, and one VTK file with --vtk), and what
/// they hold in all: frames x (particles + triangles), about 40 bytes each (40 GB at the limit;
/// the default of about 100 frames of the largest scene is a third of it).
constexpr long long kMaxFrames = 100000;
constexpr double kMaxFrameElements = 1e9;

// ---- Query files (tecido tritri, plane, ccd) and meshes (selfcollide, obstacles) ---------
constexpr std::size_t kMaxPairs = std::size_t{1} << 20;       ///< entries of a pairs file
constexpr std::size_t kMaxCases = std::size_t{1} << 20;       ///< entries of a plane cases file
constexpr std::size_t kMaxCcdQueries = std::size_t{1} << 20;  ///< entries of a CCD queries file
/// Vertices and triangles (after splitting polygons into fans) of an OBJ mesh.
constexpr std::size_t kMaxMeshVertices = std::size_t{1} << 20;
constexpr std::size_t kMaxMeshTriangles = std::size_t{1} << 21;
/// Triangles an all-pairs engine (core-brute, exact) accepts: n (n - 1) / 2 = 1.3e8 pair tests.
constexpr std::size_t kMaxBruteForceTriangles = std::size_t{1} << 14;

// ---- Outside engines (--engine-cmd) ------------------------------------------------------
/// Longest reply line of a JSON-lines engine [bytes]: the largest real reply, a step of a scene at
/// kMaxParticles with positions and velocities (6 numbers of up to 25 characters each, about
/// 150 MB), fits; a process that writes more without a newline is stopped there, and one that
/// writes slower is stopped at the timeout, which bounds the whole reply.
constexpr std::size_t kMaxReplyBytes = std::size_t{256} << 20;

// ---- Command-line options ----------------------------------------------------------------
constexpr int kMaxThreads = 1024;     ///< --threads (0 = all cores)
constexpr int kMaxShards = 65536;     ///< n of --shard i/n
constexpr int kMaxSeeds = 1000;       ///< --seeds N of an experiment (repetitions per cell)

}  // namespace tecido::io
