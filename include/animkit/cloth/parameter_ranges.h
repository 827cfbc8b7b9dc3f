#pragma once
// The physical parameters a cloth accepts, and why there are bounds at all. The incremental
// potential multiplies them together: M / h^2 (1e6 kg / (1e-6 s)^2 = 1e18), k h^2 / m, squared
// lengths and energies summed over a million springs. Inside these ranges every such term stays
// far from overflow and from drowning the others in rounding; outside them a step computes
// infinities or noise (stiffness 1e300 gave infinite gradients and a frozen cloth that reported
// convergence). So values beyond them are refused up front, naming the range, rather than
// simulated wrong. The ranges span far more than any real cloth (and the lab's sliders).
#include "animkit/core/validation.h"

namespace animkit {

inline constexpr ParameterRange kMassRange{1e-6, 1e6};        ///< per particle, kg
inline constexpr ParameterRange kStiffnessRange{1e-6, 1e9};   ///< per spring, N/m
inline constexpr ParameterRange kDampingRange{0.0, 1e6};      ///< dashpot, N s/m
inline constexpr ParameterRange kGravityRange{-1e4, 1e4};     ///< along -y, m/s^2
inline constexpr ParameterRange kTimeStepRange{1e-6, 10.0};   ///< per step, s
// Positions, velocities, times and friction coefficients: kCoordinateRange and its kin in
// core/validation.h, shared with the colliders.
/// Substeps per step: enough for explicit Euler at any stable setting the lab's sliders allow
/// (the lab's 1000) and more, while a run still ends.
inline constexpr int kMaxSubsteps = 100'000;

}  // namespace animkit
