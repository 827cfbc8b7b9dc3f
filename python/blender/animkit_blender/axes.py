"""Blender's axes and animkit's, both ways, on numpy arrays.

Blender is Z up; animkit's gravity is along -y (Y up). A Blender point (x, y, z) is animkit's
(x, z, -y): a proper rotation by -90 degrees about x, so lengths, handedness and rotations carry
over unchanged. Rotation matrices convert by conjugation: R_animkit = C R_blender C^T.
"""
import numpy as np

# Rows: animkit's x, y, z as combinations of Blender's x, y, z.
BLENDER_TO_ANIMKIT = np.array([[1.0, 0.0, 0.0],
                               [0.0, 0.0, 1.0],
                               [0.0, -1.0, 0.0]])
ANIMKIT_TO_BLENDER = BLENDER_TO_ANIMKIT.T


def points_to_animkit(points):
    """Blender points (..., 3) -> animkit points (..., 3), float64."""
    return np.asarray(points, dtype=np.float64) @ BLENDER_TO_ANIMKIT.T


def points_to_blender(points):
    """animkit points (..., 3) -> Blender points (..., 3), float64."""
    return np.asarray(points, dtype=np.float64) @ ANIMKIT_TO_BLENDER.T


def rotations_to_animkit(matrices):
    """Blender rotation matrices (..., 3, 3) -> the same rotations in animkit's axes."""
    return BLENDER_TO_ANIMKIT @ np.asarray(matrices, dtype=np.float64) @ ANIMKIT_TO_BLENDER


def rotations_to_blender(matrices):
    """animkit rotation matrices (..., 3, 3) -> the same rotations in Blender's axes."""
    return ANIMKIT_TO_BLENDER @ np.asarray(matrices, dtype=np.float64) @ BLENDER_TO_ANIMKIT


def matrices_to_quaternions(matrices):
    """Rotation matrices (..., 3, 3) -> unit quaternions (..., 4) as (w, x, y, z) with w >= 0
    (Shepperd's method: the largest of w, x, y, z is computed first, so no precision is lost
    near 180 degrees)."""
    m = np.asarray(matrices, dtype=np.float64)
    shape = m.shape[:-2]
    m = m.reshape(-1, 3, 3)
    trace = m[:, 0, 0] + m[:, 1, 1] + m[:, 2, 2]
    candidates = np.stack([trace, m[:, 0, 0], m[:, 1, 1], m[:, 2, 2]], axis=1)
    pick = np.argmax(candidates, axis=1)
    q = np.empty((m.shape[0], 4))
    for case in range(4):
        rows = pick == case
        if not np.any(rows):
            continue
        r = m[rows]
        if case == 0:
            s = 2.0 * np.sqrt(np.maximum(1.0 + trace[rows], 0.0))
            q[rows] = np.stack([0.25 * s, (r[:, 2, 1] - r[:, 1, 2]) / s,
                                (r[:, 0, 2] - r[:, 2, 0]) / s, (r[:, 1, 0] - r[:, 0, 1]) / s], 1)
        elif case == 1:
            s = 2.0 * np.sqrt(np.maximum(1.0 + r[:, 0, 0] - r[:, 1, 1] - r[:, 2, 2], 0.0))
            q[rows] = np.stack([(r[:, 2, 1] - r[:, 1, 2]) / s, 0.25 * s,
                                (r[:, 0, 1] + r[:, 1, 0]) / s, (r[:, 0, 2] + r[:, 2, 0]) / s], 1)
        elif case == 2:
            s = 2.0 * np.sqrt(np.maximum(1.0 - r[:, 0, 0] + r[:, 1, 1] - r[:, 2, 2], 0.0))
            q[rows] = np.stack([(r[:, 0, 2] - r[:, 2, 0]) / s, (r[:, 0, 1] + r[:, 1, 0]) / s,
                                0.25 * s, (r[:, 1, 2] + r[:, 2, 1]) / s], 1)
        else:
            s = 2.0 * np.sqrt(np.maximum(1.0 - r[:, 0, 0] - r[:, 1, 1] + r[:, 2, 2], 0.0))
            q[rows] = np.stack([(r[:, 1, 0] - r[:, 0, 1]) / s, (r[:, 0, 2] + r[:, 2, 0]) / s,
                                (r[:, 1, 2] + r[:, 2, 1]) / s, 0.25 * s], 1)
    q[q[:, 0] < 0.0] *= -1.0
    q /= np.linalg.norm(q, axis=1, keepdims=True)
    return q.reshape(shape + (4,))


def quaternions_to_matrices(quaternions):
    """Quaternions (..., 4) as (w, x, y, z), normalized first -> rotation matrices (..., 3, 3)."""
    q = np.asarray(quaternions, dtype=np.float64)
    q = q / np.linalg.norm(q, axis=-1, keepdims=True)
    w, x, y, z = q[..., 0], q[..., 1], q[..., 2], q[..., 3]
    m = np.empty(q.shape[:-1] + (3, 3))
    m[..., 0, 0] = 1.0 - 2.0 * (y * y + z * z)
    m[..., 0, 1] = 2.0 * (x * y - w * z)
    m[..., 0, 2] = 2.0 * (x * z + w * y)
    m[..., 1, 0] = 2.0 * (x * y + w * z)
    m[..., 1, 1] = 1.0 - 2.0 * (x * x + z * z)
    m[..., 1, 2] = 2.0 * (y * z - w * x)
    m[..., 2, 0] = 2.0 * (x * z - w * y)
    m[..., 2, 1] = 2.0 * (y * z + w * x)
    m[..., 2, 2] = 1.0 - 2.0 * (x * x + y * y)
    return m


def continuous_quaternions(quaternions):
    """Flips signs along axis 0 (frames) so consecutive quaternions lie in the same hemisphere:
    keyframes then interpolate the short way. quaternions: (frames, ..., 4)."""
    q = np.array(quaternions, dtype=np.float64)
    for f in range(1, q.shape[0]):
        flip = np.sum(q[f] * q[f - 1], axis=-1) < 0.0
        q[f][flip] *= -1.0
    return q


def orthonormalize(matrices):
    """The nearest rotation to each matrix (..., 3, 3) (polar decomposition by SVD): drops a
    pose bone's scale and any rounding from its rotation part."""
    u, _, vt = np.linalg.svd(np.asarray(matrices, dtype=np.float64))
    r = u @ vt
    flip = np.linalg.det(r) < 0.0
    if np.any(flip):
        u = u.copy()
        u[flip, :, 2] *= -1.0
        r = u @ vt
    return r
