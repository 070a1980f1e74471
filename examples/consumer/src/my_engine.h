#pragma once
// The user's engine, as they wrote it: plain functions with the plug-in ABI's signatures
// (tecido/plugin.h), and the tables that name them for tecido's harness.
#include <tecido/plugin.h>

// Closed triangles a, b (3 corners x (x, y, z)): 1 intersecting, 0 not. Floating point: every edge
// of each triangle against the other (Moller-Trumbore with a small tolerance). Coplanar pairs are
// not handled (answered 0).
int my_tri_tri(const double a[9], const double b[9]);

// Continuous collision over t in [0, 1] (plugin.h's layout): the coplanarity cubic sampled at 64
// times, each sign change bisected, the primitives tested at the root with a tolerance of 1e-9.
int my_ccd_vertex_face(const double t0[12], const double t1[12], double* toi);
int my_ccd_edge_edge(const double t0[12], const double t1[12], double* toi);

// A mass-spring cloth stepped by symplectic (semi-implicit) Euler: first order.
void* my_cloth_create(const tecido_scene* scene, char* why, size_t why_size);
int my_cloth_step(void* simulation, double dt, int64_t steps);
void my_cloth_read(const void* simulation, double* positions, double* velocities);
void my_cloth_destroy(void* simulation);

// The user's engine as one table entry per capability.
tecido_engine my_tri_tri_engine();
tecido_engine my_ccd_engine();
tecido_engine my_cloth_engine(const char* name, double claimed_order);
