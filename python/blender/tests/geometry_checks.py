"""Segment / triangle intersection tests in numpy, for checking that baked cloth does not cross
a collider's surface mesh."""
import numpy as np


def segments_cross_triangles(starts, ends, triangles, chunk=4096):
    """Boolean (segments,): does segment k cross any of the triangles (t, 3, 3)?
    Moller-Trumbore on every pair, in chunks of segments; touching within 1e-12 counts."""
    starts = np.asarray(starts, dtype=np.float64)
    ends = np.asarray(ends, dtype=np.float64)
    tri = np.asarray(triangles, dtype=np.float64)
    a = tri[:, 0]
    e1 = tri[:, 1] - a
    e2 = tri[:, 2] - a
    hit = np.zeros(len(starts), dtype=bool)
    for begin in range(0, len(starts), chunk):
        p = starts[begin:begin + chunk, None, :]
        d = ends[begin:begin + chunk, None, :] - p
        h = np.cross(d, e2[None])
        det = np.sum(e1[None] * h, axis=2)
        ok = np.abs(det) > 1e-15
        inv = np.where(ok, 1.0 / np.where(ok, det, 1.0), 0.0)
        s = p - a[None]
        u = np.sum(s * h, axis=2) * inv
        q = np.cross(s, e1[None])
        v = np.sum(d * q, axis=2) * inv
        t = np.sum(e2[None] * q, axis=2) * inv
        eps = 1e-12
        inside = (ok & (u >= -eps) & (v >= -eps) & (u + v <= 1 + eps) & (t >= -eps)
                  & (t <= 1 + eps))
        hit[begin:begin + chunk] = np.any(inside, axis=1)
    return hit


def edges_of(triangles):
    """Unique undirected edges (e, 2) of triangles (m, 3)."""
    tris = np.asarray(triangles)
    edges = np.concatenate([tris[:, [0, 1]], tris[:, [1, 2]], tris[:, [2, 0]]])
    return np.unique(np.sort(edges, axis=1), axis=0)


def meshes_cross(vertices_a, triangles_a, vertices_b, triangles_b):
    """Whether two triangle meshes intersect: an edge of one crosses a triangle of the other
    (two triangles that intersect always have such an edge). Returns (count of crossing edges
    of a, count of crossing edges of b)."""
    va, vb = np.asarray(vertices_a), np.asarray(vertices_b)
    ea, eb = edges_of(triangles_a), edges_of(triangles_b)
    a_hits = segments_cross_triangles(va[ea[:, 0]], va[ea[:, 1]], vb[np.asarray(triangles_b)])
    b_hits = segments_cross_triangles(vb[eb[:, 0]], vb[eb[:, 1]], va[np.asarray(triangles_a)])
    return int(a_hits.sum()), int(b_hits.sum())
