#pragma once
/// The first stages of core's continuous collision test (ccd/ccd.h: swept boxes, kinetic boxes, the
/// coplanarity cubic on [0, 1]) and the root of its time search decided for many queries at
/// once, several per SIMD register, for a caller that holds the queries as point indices into
/// two position arrays (a mesh's frames: continuous self-collision,
/// core/cloth/continuous_self_collision.h).
///
/// Each decision is the one ccd's own stage takes on the same query, computed by the same
/// operations on the same doubles in the same order, lane by lane (IEEE-754 round-to-nearest,
/// no fused multiply-add: the vector functions are compiled with fp-contract off), so it is
/// bit for bit that stage's, whatever the vector width:
///  - swept boxes (ccd/pipeline.cpp, stage 2): each primitive's box over both frames, compared
///    exactly; disjoint means ccd answers miss;
///  - kinetic boxes (ccd/kinetic_boxes.h): its 1-D linear program, the same operations (the
///    divisions included: IEEE division is correctly rounded in every width), its early
///    returns turned into lane masks;
///  - the coplanarity cubic (ccd/coplanarity_cubic.h, stage 4) with its cheap bound
///    6 mx my mz: coefficients all beyond the bound mean ccd answers miss (ccd keeps the cheap
///    bound exactly when it certifies, and then rejects). It is applied only where ccd would
///    not rescale the query (ccd/system.h): the largest component of X, Y, Z over both frames
///    in [2^-128, 2^125] (then P and Q stay below 2^127 and the sum of all components is
///    finite, so ccd's scale is 1 and its differences are these). Elsewhere, and where the
///    cheap bound does not certify (ccd would then try the permanents), no cubic verdict.
/// The stages commute: ccd answers miss when any of them certifies (for finite input the
/// system's "all points coincide" case has f = 0, which no bound certifies), so a caller may
/// act on any verdict in any order and still give ccd's answer.
/// The queries they leave open where ccd's scale is 1 are gathered into full blocks and the
/// root of ccd's time search is decided on them (batch/root.inl, with the arithmetic of
/// decisions.inl that the scalar search runs at width 1: the cubic's permanent
/// bound, the projected quadratics, rule 2, rule J with its Newton iteration and bracket): where
/// ccd decides there, the verdict says miss or hit, ccd's answer; elsewhere nothing (the caller
/// runs ccd, which decides deeper). Decided there only for core's default settings.
///
/// Widths (core/simd/): 1 (the scalar instantiation, on request), 2 (SSE2, part of x86-64, and
/// the generic build), 4 (AVX) and 8 (AVX-512F), chosen at run time from what the CPU has and
/// TECIDO_SIMD allows; the verdicts do not depend on the width (tests compare).
#include "core/geometry/ccd/query.h"

#include <array>
#include <cstddef>
#include <cstdint>

namespace tecido {

/// Verdict bits, per query.
enum CcdBatchVerdict : std::uint8_t {
  kCcdBoxesDisjoint = 1,  ///< swept or kinetic boxes disjoint: ccd answers miss at its stage 2
  kCcdCubicMiss = 2,      ///< boxes not disjoint, the cubic certainly nonzero on [0, 1] (cheap bound, unscaled): ccd answers miss
  kCcdRootMiss = 4,       ///< neither, and ccd's time search answers miss at its root (batch/root.inl)
  kCcdRootHit = 8,        ///< neither, and ccd's time search answers hit at its root
};

/// The widest vector width this CPU runs (8, 4 or 2), and whether a width (1, 2, 4, 8) can run here.
int ccd_batch_widest();
bool ccd_batch_width_available(int width);

/// For each of the n queries (points queries[k][0..3] in the order of ccd/query.h), the
/// verdict bits above into verdict[k]; the cubic and the root are evaluated only when `cubic`
/// is true (core's test with its default settings). Point
/// p is x0[stride p + c] at t = 0 and x1[stride p + c] at t = 1 (c = 0, 1, 2: x, y, z): stride
/// 3 for two arrays of Vec3, or both frames interleaved in one array. Finite positions.
/// width 0: the widest available; otherwise one of 1, 2, 4, 8 that is available.
void ccd_batch_first_stages(CcdKind kind, const double* x0, const double* x1, std::size_t stride,
                            const std::array<int, 4>* queries, int n, bool cubic, std::uint8_t* verdict, int width = 0);

}  // namespace tecido
