#pragma once
// Conservative continuous collision detection for primitives moving linearly over a step:
// Additive CCD (Li, Kaufman, Jiang, "Codimensional Incremental Potential Contact", SIGGRAPH 2021,
// Algorithm 1). IPC's line search never takes a step past the time this returns, so the
// primitives never touch or cross (Li et al. 2020, section 5).
//
// Vertex i moves as x_i(t) = x_i + t (x'_i - x_i) for t in [0, max_time]. Remove the mean
// displacement (a common translation moves no point relative to another) and let l_p be the
// largest displacement on one primitive plus the largest on the other. Any point of one
// primitive then moves relative to any point of the other by at most l_p per unit time, so the
// distance d(t) is l_p-Lipschitz, and so is the gap d(t) - xi (xi: thickness). From a gap G at
// time t, no contact can happen before t + G / l_p. Additive CCD walks in such safe steps:
//   g = s G_0;  t_1 = (1 - s) G_0 / l_p  (safe: G(t_1) >= s G_0 by the Lipschitz bound);
//   then t_{k+1} = t_k + 0.9 G(t_k) / l_p, stopping at the first t_{k+1} with G(t_{k+1}) < g
//   and returning t* = t_k (the last time whose gap was measured >= g), or max_time when the
//   walk gets there (this implementation also measures the gap at max_time before accepting it).
//
// Guarantee (exact arithmetic): G(t*) >= s G_0 and G(t) >= 0.55 s G_0 for all t in [0, t*].
// Between accepted samples t_k, t_{k+1} (step at most 0.9 G_k / l_p, both gaps >= g), the two
// Lipschitz cones give G >= (G_k + G_{k+1} - 0.9 G_k) / 2 >= 0.55 g; on [0, t_1], G >= s G_0.
// In floating point the gaps are computed from rounded distances (relative error ~1e-15 of the
// coordinates' scale squared); the guarantee holds as long as 0.55 s G_0 is well above that, i.e.
// for any gap the barrier can resolve. The returned time is never past the first contact.
// Cost: one distance per step; about l_p / (0.9 g) steps at worst, capped by max_iterations
// (then the time reached so far is returned, still safe).
//
// Sliding. l_p counts motion across the gap as fully as motion closing it, so a point sliding
// over a face at a small gap (cloth on a ball) takes a thousand steps. Once a walk has taken 32
// steps, each step that stops short of max_time is weighed against another: with n the
// separating direction at the current positions (from the second primitive's closest point to
// the first's), the time for which min_i n.x_i(t) - max_j n.y_j(t), over the first
// primitive's vertices i and the second's j, stays above g + xi. The primitives are the convex
// hulls of their vertices, so their distance is at least that, and it is a minimum of
// functions linear in t (exact roots). The walk takes the longer step; on this one the gap
// stays >= g throughout, which keeps the guarantee above. Motion across n leaves the bound
// untouched: the rest of a slide is one step.
#include <array>
#include <optional>

#include "animkit/core/result.h"
#include "animkit/core/types.h"

namespace animkit {

/// Parameters of Additive CCD (the walk described at the top of this header).
struct AdditiveCcdSettings {
  /// s in (0, 1): the fraction of the initial gap kept at the returned time. Default 0.1 (C-IPC's
  /// choice; ipc-toolkit's conservative rescaling 0.9).
  double separation_fraction = 0.1;
  /// xi >= 0: the thickness (position units); the gap is distance - xi. Default 0 (IPC).
  double thickness = 0.0;
  /// The end of the motion to check, in (0, 1]. Default 1: the whole step.
  double max_time = 1.0;
  /// Cap on the number of distance evaluations, >= 1. Default one million.
  int max_iterations = 1'000'000;
  /// Also step along the separating direction (see "Sliding" above). Default true; false
  /// leaves Additive CCD's Lipschitz walk alone, whose times fall short of the exact ones.
  bool along_separation = true;

  /// The first problem, e.g. "CCD separation fraction must be in (0, 1), got 1".
  std::optional<Error> validate() const;
};

/// What a CCD query found: how far along the motion is safe and whether it was cut short.
struct CcdResult {
  /// t* in [0, max_time]: the motion is safe up to this time (see the guarantee above).
  double time_of_impact = 1.0;
  /// True when the motion was cut short (t* < max_time): a possible contact, the iteration cap,
  /// or primitives already within the thickness at t = 0 (then t* = 0).
  bool collides = false;
  /// Distance evaluations done.
  int iterations = 0;
};

/// Point p against triangle (a, b, c): `start` and `end` hold (p, a, b, c) at t = 0 and t = 1.
/// Fails on invalid settings or a non-finite coordinate.
Result<CcdResult> point_triangle_ccd(const std::array<Vec3, 4>& start,
                                     const std::array<Vec3, 4>& end,
                                     const AdditiveCcdSettings& settings = {});

/// Edge (a0, a1) against edge (b0, b1): `start` and `end` hold (a0, a1, b0, b1).
Result<CcdResult> edge_edge_ccd(const std::array<Vec3, 4>& start, const std::array<Vec3, 4>& end,
                                const AdditiveCcdSettings& settings = {});

/// Point p against segment (a, b): `start` and `end` hold (p, a, b). For codimensional contact
/// (rods, points) and tests.
Result<CcdResult> point_edge_ccd(const std::array<Vec3, 3>& start, const std::array<Vec3, 3>& end,
                                 const AdditiveCcdSettings& settings = {});

/// Point p against point q: `start` and `end` hold (p, q).
Result<CcdResult> point_point_ccd(const std::array<Vec3, 2>& start, const std::array<Vec3, 2>& end,
                                  const AdditiveCcdSettings& settings = {});

}  // namespace animkit
