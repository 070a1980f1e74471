#pragma once
/// A second opinion on contact times (reference build only): FCL's continuous vertex-face test
/// (reference/fcl_adapter.h fcl_ccd) of every cloth vertex's straight path over each step against
/// the block as a triangle mesh (core/geometry/box_mesh.h), on the cloth's free fall.
#include "comparisons/io/json_reader.h"
#include "comparisons/suites/obstacles/settings.h"

#include <string>

namespace tecido::suites::obstacles {

/// The n x n cloth falling towards the block: {"t_fcl" (first step start + toi x dt over every
/// vertex and triangle, "nan" if none), "t_core" (core's first bisected contact on the same scene),
/// "t_exact" (sqrt(2 gap / g), gap the cloth's initial height above the top), "dt"}. Before any contact core's steps are the free fall
/// itself, so both engines see the same motion; FCL takes each step's path as straight, core
/// bisects along the integrator's own sub-steps.
io::Json fcl_block_case(const Settings& s, const std::string& data_dir, int n);

}  // namespace tecido::suites::obstacles
