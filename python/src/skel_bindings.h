#pragma once
// The skeleton part of the module (bind_skeletons), split by topic: one bind_skel_*.cpp each,
// called in this order by bind_skeletons.cpp, plus the conversions the topics share.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <string>
#include <string_view>
#include <vector>

#include "animkit/core/types.h"
#include "animkit/kinematics/joint_limits.h"
#include "animkit/kinematics/skeletal_motion.h"
#include "animkit/kinematics/skeleton.h"

namespace animkit::python {

namespace py = pybind11;

void bind_skel_core(py::module_& m);       ///< Skeleton, SkeletonPose, Motion, FK
void bind_skel_limits(py::module_& m);     ///< FreeJoint, HingeLimit, BallLimit, limit files
void bind_skel_bvh(py::module_& m);        ///< BvhClip, read/parse/write
void bind_skel_foot_lock(py::module_& m);  ///< FootLockSettings, lock_feet
void bind_skel_tree_ik(py::module_& m);    ///< Effector, TreeIkSolver, solve_tree

/// One unit quaternion (w, x, y, z): finite and of norm 1 within 1e-6 (the library's
/// tolerance), else animkit.Error naming `what`.
Quat to_unit_quat(const py::object& value, std::string_view what);

/// Raises animkit.Error unless every quaternion is finite and unit (the message names `what`
/// and the first bad index).
void check_unit_quats(const std::vector<Quat>& rotations, std::string_view what);
/// Raises animkit.Error unless every vector is finite.
void check_finite(const std::vector<Vec3>& points, std::string_view what);

/// The joint `joint` names: an int index (checked against the skeleton's range) or a str
/// name (found by Skeleton::find_joint). animkit.Error naming `what` otherwise.
int joint_index(const Skeleton& skeleton, const py::object& joint, std::string_view what);

/// A motion's frames as one (frames, joints, 3|4) array, a copy.
py::array_t<double> motion_rotations_array(const SkeletalMotion& motion);
py::array_t<double> motion_translations_array(const SkeletalMotion& motion);

/// One limit per joint from a Python list of FreeJoint / HingeLimit / BallLimit (None is a
/// FreeJoint), each validated; animkit.Error for a wrong length or an invalid limit.
std::vector<JointLimit> to_joint_limits(const py::object& limits, const Skeleton& skeleton);
/// A limit as its Python object.
py::object joint_limit_to_python(const JointLimit& limit);

}  // namespace animkit::python
