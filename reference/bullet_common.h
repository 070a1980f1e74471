#pragma once
/// What the two Bullet cloth adapters (bullet_deformable.cpp, bullet_softbody.cpp) share:
///  - how a bounded plane becomes a static box (plane_box) and the boxes in a world (PlaneBoxes);
///  - which springs are Bullet's elastic and which its bending links, read from the scene's cloth
///    spec (spring_families);
///  - the Bullet-side pieces both need: core <-> Bullet vectors, the scene's particles as nodes in
///    core's numbering, rest lengths written after Bullet's one-time reset, node states read back.
/// No Bullet header is included here: the Bullet-side functions take Bullet classes declared
/// forward below and are defined in bullet_common.cpp, which includes Bullet (double build, in the
/// tecido_bullet library). Callers of those functions are the adapters' own .cpp files.
#include "core/scene/scene.h"

#include <array>
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

class btVector3;
class btSoftBody;
class btDiscreteDynamicsWorld;

namespace tecido::reference {

/// A number in a "not modelled" note: 6 significant digits, shortest form ("0.1", "1e-06").
std::string note_number(double x);

// ---- Bullet-free pieces --------------------------------------------------------------------------

/// How a bounded plane stands in Bullet: a static box (btStaticPlaneShape cannot be bounded) whose
/// front face is the plane itself, lying behind it on the side away from every free particle.
struct PlaneBox {
  Vec3 centre = Vec3::Zero();        ///< box centre [m]
  Vec3 half_extents = Vec3::Zero();  ///< along forward, right, normal [m]
  std::array<Vec3, 3> axes;          ///< forward, right, normal: the box's local x, y, z
  double shape_margin = 0.0;         ///< Bullet collision margin of the box shape (kept below every half extent)
  double contact_offset = 0.0;       ///< distance from the plane at which Bullet holds a resting node [m]
  std::string note;                  ///< non-empty when the plane is not modelled exactly ("not modelled" line)
};

/// The box for scene.planes[k], `thickness` thick, with the cloth's collision margin. When free
/// particles start on both sides of the plane the box is centred on it and `note` says so.
PlaneBox plane_box(const Scene& scene, std::size_t k, double thickness, double collision_margin);

/// Bullet's deformable mass-spring force has one elastic k and one "bending" k (links flagged
/// m_bbending) and one damping coefficient for every link: which of the scene's springs are which.
struct SpringFamilies {
  double k_elastic = 0.0;  ///< [N/m]
  double k_bending = 0.0;  ///< [N/m]; equal to k_elastic when every spring is elastic
  double damping = 0.0;    ///< [N s/m], the first spring's
  std::vector<char> bending;       ///< per spring, in scene order: 1 = a bending link
  std::vector<std::string> notes;  ///< what Bullet cannot model as given ("per-spring stiffness: ...")
};

/// The families of the scene's springs. With a cloth spec (scene.cloth, appended by append_cloth),
/// the spec says which springs are which: a spring joining two of the cloth's nodes one grid edge
/// apart (the builder's type B: horizontal, vertical, diagonal, anti-diagonal) is elastic with
/// k = stiffness_b, two edges apart (type A) bending with k = stiffness_a (core/scene/cloth_builder.h).
/// Every other spring, and every spring of a scene without a cloth, is explicit per-spring data:
/// it is elastic when its stiffness is the elastic k, bending when it is the bending k; without a
/// cloth the first spring sets the elastic k and the first spring with another stiffness the
/// bending k. A cloth spring whose stiffness is the other family's k moves to that family (Bullet
/// then models it exactly); a spring whose stiffness is neither keeps its family (a spring outside
/// the cloth: the nearer k) and a note says so; so does a damping other than the first spring's. Throws std::invalid_argument for a spring with an end outside the scene.
SpringFamilies spring_families(const Scene& scene);

// ---- Bullet-side pieces (defined in bullet_common.cpp) -------------------------------------------

btVector3 to_bt(const Vec3& v);
Vec3 from_bt(const btVector3& v);

/// Appends the scene's particles to `body` as nodes 0..n-1: position, velocity and inverse mass
/// copied bit for bit (pinned = inverse mass 0; 1/(1/m) may differ from m's inverse in the last
/// bit, so the inverse mass is written directly).
void append_nodes(btSoftBody& body, const Particles& p);

/// Runs Bullet's one-time update of runtime constants now (it would run at the first step and
/// reset every link's rest length to the current distance; Bullet's version also rebuilds the node
/// tree bottom-up, which never ends when links leave nodes unconnected, so the adapters skip it),
/// then writes `rest_lengths` into links 0..n-1.
void freeze_rest_lengths(btSoftBody& body, const std::vector<double>& rest_lengths);

/// True when nodes 0..count-1 have finite positions and velocities.
bool nodes_finite(const btSoftBody& body, std::size_t count);
/// Positions and velocities of nodes 0..count-1 (core's numbering).
std::vector<Vec3> node_positions(const btSoftBody& body, std::size_t count);
std::vector<Vec3> node_velocities(const btSoftBody& body, std::size_t count);

/// The static boxes (plane_box) standing in for a scene's bounded planes in a Bullet world: added
/// by add(), owned here, removed by remove() before the world goes.
class PlaneBoxes {
 public:
  PlaneBoxes();
  ~PlaneBoxes();
  PlaneBoxes(PlaneBoxes&&) noexcept;
  PlaneBoxes& operator=(PlaneBoxes&&) noexcept;

  /// One static box per plane of `scene` (friction = the plane's, no restitution), added to
  /// `world`; a two-sided plane's note goes to `notes`.
  void add(btDiscreteDynamicsWorld& world, const Scene& scene, double thickness, double collision_margin,
           std::vector<std::string>& notes);
  /// Takes the boxes out of `world`.
  void remove(btDiscreteDynamicsWorld& world);
  /// Largest distance from a plane at which Bullet holds a resting node [m] (the collision margin
  /// without planes).
  double contact_offset() const { return contact_offset_; }

 private:
  struct Bodies;
  std::unique_ptr<Bodies> bodies_;
  double contact_offset_ = 0.0;
};

}  // namespace tecido::reference
