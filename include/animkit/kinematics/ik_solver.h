#pragma once
// One entry point over every IK solver, chosen by an enum (the viewer's and CLI's switch).
#include <optional>
#include <span>
#include <string_view>

#include "animkit/kinematics/ccd.h"
#include "animkit/kinematics/fabrik.h"

namespace animkit {

enum class IkSolverKind { ccd, fabrik };

/// "ccd" or "fabrik".
std::string_view to_string(IkSolverKind kind);
/// Parses "ccd" / "fabrik"; nothing for any other name.
std::optional<IkSolverKind> parse_ik_solver(std::string_view name);
/// Every solver, in menu order.
std::span<const IkSolverKind> all_ik_solvers();

/// "rest" or "previous".
std::string_view to_string(FabrikRotations mode);
/// Parses "rest" / "previous"; nothing for any other name.
std::optional<FabrikRotations> parse_fabrik_rotations(std::string_view name);

/// Runs the chosen solver; see solve_ccd() and solve_fabrik().
Result<IkResult> solve_ik(IkSolverKind kind, const Chain& chain, Pose& pose, const Vec3& target,
                          const IkOptions& options = {});

}  // namespace animkit
