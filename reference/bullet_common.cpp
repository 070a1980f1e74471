// The pieces both Bullet cloth adapters share (bullet_common.h). Includes Bullet's soft-body and
// rigid-body headers; built in the tecido_bullet library with the float64 Bullet
// (BT_USE_DOUBLE_PRECISION, private to that library).
#include "reference/bullet_common.h"

#include <BulletCollision/CollisionShapes/btBoxShape.h>
#include <BulletDynamics/Dynamics/btDiscreteDynamicsWorld.h>
#include <BulletDynamics/Dynamics/btRigidBody.h>
#include <BulletSoftBody/btSoftBody.h>
#include <LinearMath/btDefaultMotionState.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <sstream>
#include <stdexcept>

static_assert(sizeof(btScalar) == sizeof(double), "the Bullet adapters need the float64 Bullet build");

namespace tecido::reference {

std::string note_number(double x) {
  std::ostringstream s;
  s.precision(6);
  s << x;
  return s.str();
}

// ---- plane boxes ---------------------------------------------------------------------------------

PlaneBox plane_box(const Scene& scene, std::size_t k, double thickness, double collision_margin) {
  const BoundedPlane& pl = scene.planes[k];
  const Particles& p = scene.particles;
  bool pos = false, neg = false;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.pinned[i]) continue;
    const double s = pl.side(p.x[i]);
    pos = pos || s > 0.0;
    neg = neg || s < 0.0;
  }
  PlaneBox b;
  const double t = thickness;
  double centre_offset = 0.0;  // along the normal
  b.contact_offset = collision_margin;
  if (pos && !neg) {
    centre_offset = -0.5 * t;
  } else if (neg && !pos) {
    centre_offset = 0.5 * t;
  } else {
    b.contact_offset = 0.5 * t + collision_margin;
    b.note = "two-sided plane " + std::to_string(k) + ": free particles start on both sides, so the static box (thickness " +
             note_number(t) + " m) is centred on the plane and its faces stand " + note_number(0.5 * t) + " m off it";
  }
  const double hx = std::max(pl.half_extents.x(), 1e-9), hy = std::max(pl.half_extents.y(), 1e-9);
  b.half_extents = Vec3(hx, hy, 0.5 * t);
  // btBoxShape keeps its outer faces at the half extents whatever the margin; a margin larger
  // than a half extent would round the box, so keep it below every half extent.
  b.shape_margin = std::min({0.04, 0.5 * hx, 0.5 * hy, 0.25 * t});
  b.axes = {pl.forward, pl.right(), pl.normal};
  b.centre = pl.position + centre_offset * pl.normal;
  return b;
}

// ---- spring families -----------------------------------------------------------------------------

namespace {

/// 1 when particles i and j are cloth nodes one grid edge apart along one of the builder's four
/// directions (type B), 2 when two edges apart (type A), 0 otherwise (not both cloth nodes, or
/// another offset).
int cloth_reach(const Scene& scene, int i, int j) {
  if (!scene.cloth) return 0;
  const ClothGridSpec& g = *scene.cloth;
  const int first = scene.cloth_first_particle, count = g.rows * g.cols;
  if (i < first || j < first || i >= first + count || j >= first + count) return 0;
  int dr = (j - first) / g.cols - (i - first) / g.cols, dc = (j - first) % g.cols - (i - first) % g.cols;
  if (dr < 0 || (dr == 0 && dc < 0)) dr = -dr, dc = -dc;  // the builder's orientation: dr >= 0
  for (int reach : {1, 2})
    for (const auto& o : {std::array<int, 2>{0, 1}, {1, 0}, {1, 1}, {1, -1}})
      if (dr == reach * o[0] && dc == reach * o[1]) return reach;
  return 0;
}

/// The elastic and bending k: the cloth spec's, or the first spring's and the first other value.
void family_constants(const Scene& scene, SpringFamilies& f) {
  const auto& springs = scene.forces.springs;
  f.damping = springs.empty() ? 0.0 : springs.front().damping;
  if (scene.cloth) {
    f.k_elastic = scene.cloth->stiffness_b;
    f.k_bending = scene.cloth->stiffness_a > 0.0 ? scene.cloth->stiffness_a : f.k_elastic;
    return;
  }
  f.k_elastic = springs.empty() ? 0.0 : springs.front().stiffness;
  f.k_bending = f.k_elastic;
  for (const Spring& s : springs) {
    if (s.stiffness != f.k_elastic) {
      f.k_bending = s.stiffness;
      break;
    }
  }
}

}  // namespace

SpringFamilies spring_families(const Scene& scene) {
  SpringFamilies f;
  family_constants(scene, f);
  const auto& springs = scene.forces.springs;
  const int n = static_cast<int>(scene.particles.size());
  std::size_t off_k = 0, off_damping = 0;
  f.bending.assign(springs.size(), 0);
  for (std::size_t s = 0; s < springs.size(); ++s) {
    const Spring& sp = springs[s];
    if (sp.i < 0 || sp.j < 0 || sp.i >= n || sp.j >= n || sp.i == sp.j)
      throw std::invalid_argument("spring " + std::to_string(s) + " has an invalid end");
    const int reach = cloth_reach(scene, sp.i, sp.j);
    bool bending = reach == 2;
    if (reach == 0) bending = std::abs(sp.stiffness - f.k_bending) < std::abs(sp.stiffness - f.k_elastic);
    const double own = bending ? f.k_bending : f.k_elastic, other = bending ? f.k_elastic : f.k_bending;
    if (sp.stiffness != own && sp.stiffness == other) {
      bending = !bending;  // exact in the other family
    } else if (sp.stiffness != own) {
      ++off_k;
    }
    f.bending[s] = bending ? 1 : 0;
    off_damping += sp.damping != f.damping ? 1 : 0;
  }
  const std::string source = scene.cloth ? "the cloth spec's type B and type A stiffnesses" : "the springs' first two values";
  if (off_k > 0)
    f.notes.push_back("per-spring stiffness: " + std::to_string(off_k) + " of " + std::to_string(springs.size()) +
                      " springs have a stiffness other than their family's (" + source + ": elastic " +
                      note_number(f.k_elastic) + " N/m, bending " + note_number(f.k_bending) +
                      " N/m); Bullet's btDeformableMassSpringForce has one k per family, so they use it");
  if (off_damping > 0)
    f.notes.push_back("per-spring damping: Bullet's mass-spring force has one damping coefficient for all links; " +
                      note_number(f.damping) + " N s/m (the first spring's) is used for every spring, " +
                      std::to_string(off_damping) + " springs differ");
  return f;
}

// ---- Bullet-side pieces --------------------------------------------------------------------------

btVector3 to_bt(const Vec3& v) { return btVector3(v.x(), v.y(), v.z()); }
Vec3 from_bt(const btVector3& v) { return Vec3(v.x(), v.y(), v.z()); }

void append_nodes(btSoftBody& body, const Particles& p) {
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double w = p.inv_mass[i];
    body.appendNode(to_bt(p.x[i]), w > 0.0 ? 1.0 / w : 0.0);
    btSoftBody::Node& n = body.m_nodes[body.m_nodes.size() - 1];
    n.m_im = w;
    n.m_v = to_bt(p.v[i]);
    n.m_vn = n.m_v;
  }
}

void freeze_rest_lengths(btSoftBody& body, const std::vector<double>& rest_lengths) {
  body.updateConstants();
  body.m_bUpdateRtCst = false;
  if (static_cast<int>(rest_lengths.size()) > body.m_links.size())
    throw std::logic_error("freeze_rest_lengths: more rest lengths than links");
  for (std::size_t k = 0; k < rest_lengths.size(); ++k) {
    btSoftBody::Link& l = body.m_links[static_cast<int>(k)];
    l.m_rl = rest_lengths[k];
    l.m_c1 = l.m_rl * l.m_rl;
  }
}

bool nodes_finite(const btSoftBody& body, std::size_t count) {
  for (std::size_t i = 0; i < count; ++i) {
    const btSoftBody::Node& n = body.m_nodes[static_cast<int>(i)];
    for (int c = 0; c < 3; ++c)
      if (!std::isfinite(n.m_x[c]) || !std::isfinite(n.m_v[c])) return false;
  }
  return true;
}

std::vector<Vec3> node_positions(const btSoftBody& body, std::size_t count) {
  std::vector<Vec3> out;
  out.reserve(count);
  for (std::size_t i = 0; i < count; ++i) out.push_back(from_bt(body.m_nodes[static_cast<int>(i)].m_x));
  return out;
}

std::vector<Vec3> node_velocities(const btSoftBody& body, std::size_t count) {
  std::vector<Vec3> out;
  out.reserve(count);
  for (std::size_t i = 0; i < count; ++i) out.push_back(from_bt(body.m_nodes[static_cast<int>(i)].m_v));
  return out;
}

// ---- plane boxes in a world ----------------------------------------------------------------------

struct PlaneBoxes::Bodies {
  std::vector<std::unique_ptr<btBoxShape>> shapes;
  std::vector<std::unique_ptr<btDefaultMotionState>> states;
  std::vector<std::unique_ptr<btRigidBody>> bodies;
};

PlaneBoxes::PlaneBoxes() : bodies_(std::make_unique<Bodies>()) {}
PlaneBoxes::~PlaneBoxes() = default;
PlaneBoxes::PlaneBoxes(PlaneBoxes&&) noexcept = default;
PlaneBoxes& PlaneBoxes::operator=(PlaneBoxes&&) noexcept = default;

void PlaneBoxes::add(btDiscreteDynamicsWorld& world, const Scene& scene, double thickness, double collision_margin,
                     std::vector<std::string>& notes) {
  contact_offset_ = collision_margin;
  for (std::size_t k = 0; k < scene.planes.size(); ++k) {
    const PlaneBox box = plane_box(scene, k, thickness, collision_margin);
    contact_offset_ = std::max(contact_offset_, box.contact_offset);
    if (!box.note.empty()) notes.push_back(box.note);
    auto shape = std::make_unique<btBoxShape>(to_bt(box.half_extents));
    shape->setMargin(box.shape_margin);
    const Vec3 &f = box.axes[0], &r = box.axes[1], &n = box.axes[2];
    btTransform tr;
    tr.setBasis(btMatrix3x3(f.x(), r.x(), n.x(), f.y(), r.y(), n.y(), f.z(), r.z(), n.z()));
    tr.setOrigin(to_bt(box.centre));
    auto state = std::make_unique<btDefaultMotionState>(tr);
    btRigidBody::btRigidBodyConstructionInfo info(0.0, state.get(), shape.get(), btVector3(0, 0, 0));
    info.m_friction = scene.planes[k].friction;
    info.m_restitution = 0.0;
    auto rb = std::make_unique<btRigidBody>(info);
    world.addRigidBody(rb.get());
    bodies_->shapes.push_back(std::move(shape));
    bodies_->states.push_back(std::move(state));
    bodies_->bodies.push_back(std::move(rb));
  }
}

void PlaneBoxes::remove(btDiscreteDynamicsWorld& world) {
  if (!bodies_) return;  // moved from
  for (auto& rb : bodies_->bodies) world.removeRigidBody(rb.get());
}

}  // namespace tecido::reference
