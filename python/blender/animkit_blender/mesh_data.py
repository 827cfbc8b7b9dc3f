"""Reading Blender meshes as numpy arrays: evaluated vertices in world space, triangles,
vertex-group members."""
import numpy as np


def evaluated_mesh(obj, depsgraph):
    """The object's evaluated mesh (modifiers, shape keys) and the evaluated object; free with
    `evaluated_object.to_mesh_clear()`."""
    evaluated = obj.evaluated_get(depsgraph)
    return evaluated, evaluated.to_mesh()


def local_vertices(mesh):
    """Vertex coordinates (n, 3) float64, in the mesh's (object's local) space."""
    co = np.empty(len(mesh.vertices) * 3, dtype=np.float64)
    mesh.vertices.foreach_get("co", co)
    return co.reshape(-1, 3)


def to_world(matrix_world, points):
    """Points (n, 3) through a Blender 4x4 matrix (mathutils.Matrix)."""
    m = np.array(matrix_world, dtype=np.float64)
    return points @ m[:3, :3].T + m[:3, 3]


def to_local(matrix_world, points):
    """World points (n, 3) into the object's local space (inverse of to_world)."""
    m = np.linalg.inv(np.array(matrix_world, dtype=np.float64))
    return points @ m[:3, :3].T + m[:3, 3]


def triangles(mesh):
    """The mesh's polygons as triangles (m, 3) int64 (Blender's own triangulation of each
    polygon, as drawn), vertex indices into mesh.vertices."""
    mesh.calc_loop_triangles()
    tris = np.empty(len(mesh.loop_triangles) * 3, dtype=np.int64)
    mesh.loop_triangles.foreach_get("vertices", tris)
    return tris.reshape(-1, 3)


def group_members(obj, mesh, group_name, min_weight=0.0):
    """Indices of the mesh's vertices in the object's vertex group `group_name` with a weight
    above `min_weight` (empty when there is no such group)."""
    group = obj.vertex_groups.get(group_name)
    if group is None:
        return []
    members = []
    for vertex in mesh.vertices:
        for element in vertex.groups:
            if element.group == group.index and element.weight > min_weight:
                members.append(vertex.index)
                break
    return members
