"""A Blender mesh as the arrays unwrap() takes, and its result written back.

Polygons are split into Blender's loop triangles; the diagonals that split
them are no Blender edge, so they are given as forbidden edges: each
polygon stays in one chart and each loop gets one UV. All through
foreach_get / foreach_set, so that a 20k-face mesh converts in milliseconds."""
import numpy as np


def _edge_keys(pairs, n):
    pairs = np.sort(pairs.reshape(-1, 2), axis=1).astype(np.int64)
    return pairs[:, 0] * n + pairs[:, 1]


def _edge_flags(mesh, name):
    """A boolean per edge: a property of MeshEdge (Blender 3.x) or an edge attribute (4.x)."""
    flags = np.zeros(len(mesh.edges), dtype=bool)
    attribute = mesh.attributes.get(name) if name else None
    if attribute is not None and attribute.domain == 'EDGE' and attribute.data_type == 'BOOLEAN':
        attribute.data.foreach_get("value", flags)
    elif name in ("use_seam", "use_edge_sharp") and hasattr(mesh.edges[0] if len(mesh.edges) else None, name):
        mesh.edges.foreach_get(name, flags)
    elif name == "sharp_edge" and len(mesh.edges) and hasattr(mesh.edges[0], "use_edge_sharp"):
        mesh.edges.foreach_get("use_edge_sharp", flags)
    return flags


class MeshArrays:
    """What unwrap() needs from one Blender mesh, and how to map its result back."""

    def __init__(self, mesh, keep_seams=True, protect=None):
        mesh.calc_loop_triangles()
        n = len(mesh.vertices)
        self.V = np.empty(3 * n, dtype=np.float64)
        mesh.vertices.foreach_get("co", self.V)
        self.V = self.V.reshape(n, 3)
        t = len(mesh.loop_triangles)
        self.F = np.empty(3 * t, dtype=np.int64)
        mesh.loop_triangles.foreach_get("vertices", self.F)
        self.F = self.F.reshape(t, 3)
        self.loops = np.empty(3 * t, dtype=np.int64)
        mesh.loop_triangles.foreach_get("loops", self.loops)
        self.loops = self.loops.reshape(t, 3)
        self.number_of_loops = len(mesh.loops)

        e = len(mesh.edges)
        edge_vertices = np.empty(2 * e, dtype=np.int64)
        mesh.edges.foreach_get("vertices", edge_vertices)
        self.edge_vertices = edge_vertices.reshape(e, 2)
        self.edge_keys = _edge_keys(self.edge_vertices, n)
        self.edge_order = np.argsort(self.edge_keys)
        self.sorted_keys = self.edge_keys[self.edge_order]

        self.seams = self.edge_vertices[_edge_flags(mesh, "use_seam")] if keep_seams else np.empty((0, 2), np.int64)
        protected = self.edge_vertices[_edge_flags(mesh, protect)] if protect else np.empty((0, 2), np.int64)
        # the triangles' sides that are no edge of the mesh: inside a polygon
        sides = np.stack([self.F, np.roll(self.F, -1, axis=1)], axis=2).reshape(-1, 2)
        side_keys = _edge_keys(sides, n)
        diagonal = ~np.isin(side_keys, self.edge_keys)
        diagonals = np.unique(np.sort(sides[diagonal], axis=1), axis=0)
        self.forbidden = np.vstack([protected, diagonals]) if len(protected) or len(diagonals) else None
        self.fingerprint = (n, e, self.number_of_loops, len(mesh.polygons))

    def edge_indices(self, pairs):
        """The Blender edge of each vertex pair (all of them edges of the mesh)."""
        keys = _edge_keys(np.asarray(pairs), len(self.V))
        at = np.searchsorted(self.sorted_keys, keys)
        return self.edge_order[at]

    def loop_uvs(self, result):
        """(number of loops, 2): the UV of each loop."""
        uv = np.zeros((self.number_of_loops, 2), dtype=np.float64)
        corners = result.faces_uv
        kept = corners[:, 0] >= 0
        uv[self.loops[kept].ravel()] = result.uv[corners[kept].ravel()]
        return uv

    def write(self, mesh, result, uv_map_name=None):
        """The result into `mesh`: UVs into the UV map `uv_map_name` (created if
        missing; None: the active one, created if there is none), seams marked."""
        if tuple(self.fingerprint) != (len(mesh.vertices), len(mesh.edges), len(mesh.loops), len(mesh.polygons)):
            raise RuntimeError("the mesh changed while it was unwrapped")
        layer = mesh.uv_layers.get(uv_map_name) if uv_map_name else mesh.uv_layers.active
        if layer is None:
            layer = mesh.uv_layers.new(name=uv_map_name or "UVMap")
        mesh.uv_layers.active = layer
        layer.data.foreach_set("uv", self.loop_uvs(result).astype(np.float32).ravel())
        seam = np.zeros(len(mesh.edges), dtype=bool)
        if len(result.seams):
            seam[self.edge_indices(result.seams)] = True
        mesh.edges.foreach_set("use_seam", seam)
        mesh.update()
