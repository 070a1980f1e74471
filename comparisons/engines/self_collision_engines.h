#pragma once
/// Triangle-mesh self-collision engines, by name: a name and a function (vertices, triangles)
/// -> the intersecting pairs (i, j), i < j, sorted, of triangles that share no vertex index
/// (closed triangles: touching counts). Adding an engine is one adapter and one line in
/// self_collision_engines.cpp; `tecido selfcollide` picks it up.
#include "core/cloth/self_collision.h"

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace tecido {

struct SelfCollisionEngine {
  std::string name;
  /// nullopt: the engine could not answer (printed as null).
  std::optional<std::vector<TrianglePair>> (*pairs)(const std::vector<Vec3>& vertices,
                                                    const std::vector<std::array<int, 3>>& triangles);
};

/// Every registered engine in a fixed order: core (box tree + exact narrow phase), core-brute
/// (all pairs + exact narrow phase), then the references when they are built.
const std::vector<SelfCollisionEngine>& self_collision_engines();
const SelfCollisionEngine* find_self_collision_engine(const std::string& name);

/// io::UsageError "<option>: <engine> tests every pair of triangles and takes at most N, but
/// <mesh> has M (use core or fcl)" when an all-pairs engine (core-brute, exact) is given more than
/// io::kMaxBruteForceTriangles triangles.
void check_self_collision_size(const std::string& engine, std::size_t triangles, const std::string& mesh,
                               const std::string& option = "--engines");

}  // namespace tecido
