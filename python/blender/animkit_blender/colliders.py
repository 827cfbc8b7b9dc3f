"""Telling what shape a Blender mesh object is, so a collider can use animkit's exact shapes:
a sphere (every vertex equidistant from the centre: a UV or ico sphere), a box (8 vertices at
the corners of a rectangular box, any rotation), or else the mesh's own triangles. Everything
here is in Blender's world space; the cloth operator converts to animkit's axes.
"""
import itertools
import math

import numpy as np

# Relative spread allowed in the vertices' distances from the centre (a sphere) or in a box's
# edges (rounding in a mesh saved as float32).
SHAPE_TOLERANCE = 1e-4


def detect_sphere(points):
    """(centre (3,), radius) if the points all lie on one sphere around their bounding box's
    centre (at least 12 points, as an icosahedron has), else None."""
    if len(points) < 12:
        return None
    centre = 0.5 * (points.min(axis=0) + points.max(axis=0))
    distances = np.linalg.norm(points - centre, axis=1)
    radius = float(distances.mean())
    if radius <= 0.0 or np.ptp(distances) > SHAPE_TOLERANCE * radius:
        return None
    return centre, radius


def detect_box(points):
    """(centre (3,), half_extents (3,), rotation 3x3 with the box's axes as columns, det +1)
    if the points are the 8 corners of a box (any orientation, any proportions), else None."""
    unique = np.unique(np.round(points, 9), axis=0)
    if len(unique) != 8:
        return None
    centre = unique.mean(axis=0)
    others = unique[1:] - unique[0]
    size = float(np.linalg.norm(others, axis=1).max())
    if size <= 0.0:
        return None
    # The corner's three edges: three of the other corners' offsets, mutually perpendicular,
    # whose subset sums give all seven offsets.
    targets = {tuple(np.round(v / size, 6)) for v in others}
    for triple in itertools.combinations(range(7), 3):
        edges = others[list(triple)]
        norms = np.linalg.norm(edges, axis=1)
        if np.any(norms < SHAPE_TOLERANCE * size):
            continue
        axes = edges / norms[:, None]
        if np.max(np.abs(axes @ axes.T - np.eye(3))) > SHAPE_TOLERANCE:
            continue
        sums = {tuple(np.round((a * edges[0] + b * edges[1] + c * edges[2]) / size, 6))
                for a in (0, 1) for b in (0, 1) for c in (0, 1) if a or b or c}
        if sums != targets:
            continue
        rotation = axes.T.copy()
        if np.linalg.det(rotation) < 0.0:
            rotation[:, 2] *= -1.0
        return centre, 0.5 * norms, rotation
    return None


def icosphere_inradius_ratio(level):
    """The smallest distance from the centre to a face of animkit's sphere collider surface
    (an icosahedron subdivided `level` times, vertices on the unit sphere), divided by the
    radius. The collider's contact surface is that inscribed mesh, so a collider of radius
    r / ratio keeps the cloth outside the true sphere of radius r."""
    t = (1.0 + math.sqrt(5.0)) / 2.0
    vertices = [(-1, t, 0), (1, t, 0), (-1, -t, 0), (1, -t, 0), (0, -1, t), (0, 1, t),
                (0, -1, -t), (0, 1, -t), (t, 0, -1), (t, 0, 1), (-t, 0, -1), (-t, 0, 1)]
    vertices = [np.array(v, dtype=np.float64) / np.linalg.norm(v) for v in vertices]
    faces = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9), (5, 11, 4),
             (11, 10, 2), (10, 7, 6), (7, 1, 8), (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8),
             (3, 8, 9), (4, 9, 5), (2, 4, 11), (6, 2, 10), (8, 6, 7), (9, 8, 1)]
    for _ in range(level):
        midpoints = {}

        def midpoint(a, b):
            key = (min(a, b), max(a, b))
            if key not in midpoints:
                m = vertices[a] + vertices[b]
                vertices.append(m / np.linalg.norm(m))
                midpoints[key] = len(vertices) - 1
            return midpoints[key]

        refined = []
        for a, b, c in faces:
            ab, bc, ca = midpoint(a, b), midpoint(b, c), midpoint(c, a)
            refined += [(a, ab, ca), (b, bc, ab), (c, ca, bc), (ab, bc, ca)]
        faces = refined
    v = np.array(vertices)
    f = np.array(faces)
    normals = np.cross(v[f[:, 1]] - v[f[:, 0]], v[f[:, 2]] - v[f[:, 0]])
    normals /= np.linalg.norm(normals, axis=1, keepdims=True)
    return float(np.min(np.abs(np.sum(normals * v[f[:, 0]], axis=1))))
