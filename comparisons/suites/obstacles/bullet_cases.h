#pragma once
/// The `obstacles` suite's runs of Bullet's classic soft body with rigid obstacles
/// (reference/bullet_obstacle_world.h) beside core on the same scene (reference build only).
/// Everything about Bullet's state is measured here from its node positions: contact onset,
/// penetration (Bullet keeps a margin, not a hard constraint), rest height, springs through the
/// block.
#include "comparisons/io/json_reader.h"
#include "comparisons/suites/obstacles/settings.h"

#include <string>

namespace tecido::suites::obstacles {

/// The cloth on the sphere (block_scene.h sphere_scene), core and Bullet:
/// {"t_onset_expected" (analytic fall to the surface), "t_contact_core" (core's first bisected
/// contact), "contact_distance" (Bullet's margin), "dt", "core": {...}, "bullet": {...},
/// "not_modelled": [...]}; each engine's object holds "t_onset" (Bullet: the first step end at which
/// a node's velocity leaves free fall by more than 1e-6 m/s, as its cloth falls flat and undragged
/// until it touches; core: its first bisected contact),
/// "max_penetration", "rest_height" (the centre node above the sphere), "max_through" (0 here),
/// "frames" ([[t, springs through, deepest], ...], empty here), "unstable" (step or null).
io::Json bullet_sphere_case(const Settings& s, const std::string& data_dir);

/// The n x n cloth on the block, edges off, core and Bullet, the same fields; "rest_height" is
/// the mean height above the top of the nodes over the top face; frames as block_case.h.
io::Json bullet_block_case(const Settings& s, const std::string& data_dir, int n);

}  // namespace tecido::suites::obstacles
