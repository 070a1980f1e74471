// tecido's public functions on worked cases whose answers are known by hand, and the harness's
// errors: what a user relies on before using the referee as an oracle.
#include <gtest/gtest.h>
#include <tecido/core.h>
#include <tecido/harness.h>
#include <tecido/referee.h>
#include <tecido/version.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace {

using tecido::Triangle;
using tecido::Vec3;

// A unit right triangle in the plane z = 0.
const Triangle kFloor = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};

TEST(TecidoApi, VersionMacrosAgree) {
  EXPECT_EQ(std::string(TECIDO_VERSION), std::to_string(TECIDO_VERSION_MAJOR) + "." +
                                             std::to_string(TECIDO_VERSION_MINOR) + "." +
                                             std::to_string(TECIDO_VERSION_PATCH));
}

TEST(TecidoApi, TriangleTestsOnWorkedCases) {
  const Triangle crossing = {Vec3(0.2, 0.2, -1), Vec3(0.2, 0.2, 1), Vec3(0.3, 0.25, 1)};  // pierces the floor
  const Triangle above = {Vec3(0, 0, 1), Vec3(1, 0, 1), Vec3(0, 1, 1)};                   // parallel, 1 m up
  const Triangle touching = {Vec3(1, 0, 0), Vec3(2, 0, 1), Vec3(2, 1, 1)};                // shares the corner (1, 0, 0)
  for (auto [t, truth] : {std::pair{crossing, true}, {above, false}, {touching, true}}) {
    EXPECT_EQ(tecido::referee::tri_tri(kFloor, t), truth);
    EXPECT_EQ(tecido::core::tri_tri(kFloor, t), truth);
  }
}

TEST(TecidoApi, SegmentPlaneHitsHalfwayThroughAUnitSquare) {
  const tecido::Rectangle square;  // centre 0, normal z, half extents 1 x 1
  for (const tecido::PlaneHit h : {tecido::core::segment_plane(square, Vec3(0.5, 0.5, 1), Vec3(0.5, 0.5, -1)),
                                   tecido::referee::segment_plane(square, Vec3(0.5, 0.5, 1), Vec3(0.5, 0.5, -1))}) {
    EXPECT_TRUE(h.hit);
    EXPECT_EQ(h.t, 0.5);
  }
  EXPECT_FALSE(tecido::referee::segment_plane(square, Vec3(1.5, 0, 1), Vec3(1.5, 0, -1)).hit);  // beside it
}

TEST(TecidoApi, VertexThroughAFaceAtAQuarterOfTheStep) {
  tecido::Motion m;  // the vertex falls from z = 0.25 to z = -0.75 through the floor triangle
  m.x0 = {Vec3(0.25, 0.25, 0.25), kFloor[0], kFloor[1], kFloor[2]};
  m.x1 = {Vec3(0.25, 0.25, -0.75), kFloor[0], kFloor[1], kFloor[2]};
  const tecido::referee::ExactContact e = tecido::referee::ccd(m);
  EXPECT_TRUE(e.hit);
  EXPECT_EQ(e.toi, 0.25);
  EXPECT_TRUE(e.toi_exact);
  const tecido::Contact c = tecido::core::ccd(m);
  EXPECT_TRUE(c.hit);
  EXPECT_LE(c.toi, 0.25);  // never after the true contact
  EXPECT_GT(c.toi, 0.25 - 1e-12);
}

TEST(TecidoApi, RefereeRefusesNaN) {
  Triangle t = kFloor;
  t[1].x() = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(tecido::referee::tri_tri(kFloor, t), std::domain_error);
}

TEST(TecidoApi, HarnessRejectsABadTableAndAnUnknownFamily) {
  tecido_engine nameless{};
  nameless.name = "no spaces allowed";
  nameless.tri_tri = [](const double*, const double*) { return 0; };
  EXPECT_THROW(tecido::harness::check_tri_tri(nameless, {}), std::invalid_argument);
  tecido::harness::CaseOptions o;
  o.families = {"no-such-family"};
  EXPECT_THROW(tecido::harness::tri_tri_cases(o), std::invalid_argument);
  EXPECT_THROW(tecido::harness::run_suites({"no-such-suite"}, {}), std::invalid_argument);
}

}  // namespace
