"""petersen: triangle meshes into quad meshes, and perfect matchings of cubic bridgeless graphs.

A thin layer over the C++ library (``petersen._petersen``): arrays in, owned numpy arrays out, the
GIL released while the library works, and the library's errors (which name the file and line, or
the face, edge or node) raised as ``ValueError``.

    >>> import numpy as np, petersen
    >>> mesh = petersen.read_mesh("bunny.off.gz")
    >>> result = petersen.quadrangulate(mesh.V, mesh.F, algorithm="auto")
    >>> result.quads.shape, result.stats["triangles_left"]
"""

from __future__ import annotations

import math
import numbers
import warnings
from dataclasses import dataclass, field
from typing import Any, Dict, List, Optional, Sequence, Tuple, Union

import numpy as np
import numpy.typing as npt

from . import _petersen, interop
from .graphs import (NoPerfectMatching, WeightedMatching, max_weight_matching,
                     min_weight_matching, weighted_matching)

__all__ = [
    "ALGORITHMS",
    "Attributes",
    "CROSSABLE",
    "CheapestMatching",
    "DroppedWarning",
    "MaximumMatching",
    "NoPerfectMatching",
    "WeightedMatching",
    "Mesh",
    "QuadResult",
    "max_weight_matching",
    "maximum_matching",
    "min_cost_matching",
    "min_weight_matching",
    "perfect_matching",
    "quad_quality",
    "quadrangulate",
    "read_mesh",
    "render",
    "weighted_matching",
    "write_mesh",
]

#: The algorithms of ``quadrangulate`` (all) and ``perfect_matching`` (all but lrs, which needs a
#: mesh): see the README's table.
ALGORITHMS = ("auto", "sg", "ps", "ds", "gw", "frink", "lrs")

#: Faces: an (m, k) integer array (every face k corners) or a sequence of faces of any length >= 3.
Faces = Union[npt.ArrayLike, Sequence[Sequence[int]]]

#: What a mesh carries besides positions and faces, as ``read_mesh`` gives it: a key only where
#: the mesh has that attribute (an empty dict for none).
#:
#: - ``texcoords``: (t, 2) or (t, 3) float64 (OBJ ``vt``); ``normals``: (n, 3) float64 (``vn``).
#: - ``corner_texcoord``, ``corner_normal``: int64, one per corner in face order (the corners of
#:   ``F`` one face after the other), an index into ``texcoords`` / ``normals``, -1 for none.
#: - ``material_names``, ``group_names``, ``object_names``: lists of str (``usemtl``, ``g``,
#:   ``o``); ``face_material``, ``face_group``, ``face_object``: int64 per face, an index into
#:   them, -1 for none; ``face_smoothing``: int64 per face (OBJ ``s``, 0 for off);
#:   ``material_libraries``: list of str (``mtllib``).
#: - ``vertex_properties``, ``face_properties``: ``{name: array}``, one value per vertex / face
#:   (PLY properties such as ``red``, OFF colours), the array's dtype the file's type (uint8,
#:   float32, ...); int64 arrays are written as int32, bool as uint8.
#: - ``position_type``: "float32" (or another PLY type) when a PLY stored x, y, z so; absent for
#:   float64.
Attributes = Dict[str, Any]

#: The attribute causes ``quadrangulate(..., cross=[...])`` may let quads cross; the names are
#: those of ``stats["cut_edges_by_cause"]``.
CROSSABLE = tuple(_petersen.CROSSABLE)


class DroppedWarning(UserWarning):
    """Something of a mesh that ``read_mesh`` read past or ``write_mesh``'s format has no place
    for (the message says what, e.g. "corner normals (vn): PLY has no place for them")."""


def _warn_dropped(path: Any, dropped: List[str], doing: str) -> None:
    for line in dropped:
        warnings.warn(f"{path}: {doing}: {line}", DroppedWarning, stacklevel=3)


@dataclass(frozen=True)
class Mesh:
    """A mesh as read from a file.

    ``V``: (n, 3) float64 positions, every vertex of the file (referenced or not).
    ``F``: an (m, 3) int64 array when every face is a triangle, else a list of int64 arrays, one
    per face, corners in the file's order.
    ``attributes``: texture coordinates, normals, materials, groups, properties (``Attributes``).
    ``dropped``: one line per kind of thing the reader read past (also warned as
    ``DroppedWarning``).
    """

    V: np.ndarray
    F: Union[np.ndarray, List[np.ndarray]]
    attributes: Attributes = field(default_factory=dict)
    dropped: List[str] = field(default_factory=list)

    def to_meshio(self) -> Any:
        """This mesh as a ``meshio.Mesh`` (see ``QuadResult.to_meshio``)."""
        return _to_meshio(self.V, list(self.F), self.attributes)

    def padded_faces(self) -> np.ndarray:
        """The faces as one padded int64 array ``[n, i0, ..., n, ...]``, as pyvista's
        ``PolyData(V, faces)`` takes them."""
        return interop.padded(self.F)


@dataclass(frozen=True)
class QuadResult:
    """What ``quadrangulate`` made.

    ``V``: (n', 3) float64, the input's positions followed by the vertices ``all_quad`` added.
    ``quads``: (k, 4) int64, the quads: one per pair of triangles (following its first triangle's
    orientation) and those ``all_quad`` made by splitting.
    ``triangles``: (t, 3) int64, the triangles left unpaired (with ``all_quad``, only those
    repeating a vertex, kept as they are).
    ``polygons``: list of int64 arrays, the input faces that are not triangles, kept as they were.
    ``sources``: (k + t + p, 2) int64, for each output face *in the order quads, triangles,
    polygons* the input faces it came from: both triangles of a pair's quad, ``[f, -1]`` for a
    face kept or left; -1 where ``lrs``'s flips made a triangle no input face has; a face split by
    ``all_quad`` names the faces of the quad or triangle it was split from.
    ``tutte_set``: int64 input face ids proving that no pairing leaves fewer triangles (empty when
    every triangle is paired).
    ``stats``: the figures of ``petersen quad --stats-json``, same keys and values, without the
    file fields (``input``, ``output``, ``load_seconds``, ``write_seconds``); ``total_seconds`` is
    the library call's.
    """

    V: np.ndarray
    quads: np.ndarray
    triangles: np.ndarray
    polygons: List[np.ndarray]
    sources: np.ndarray
    tutte_set: np.ndarray
    stats: dict
    #: The output's attributes (``Attributes``), faces and corners in the order of ``faces``: each
    #: quad corner has the texture coordinate and normal of the triangle corner it came from, each
    #: face the material, group, ... of its first source; empty when the input had none.
    attributes: Attributes = field(default_factory=dict)

    @property
    def faces(self) -> List[np.ndarray]:
        """Every output face in the order of ``sources``: quads, triangles, polygons."""
        return [*self.quads, *self.triangles, *self.polygons]

    @property
    def first_added_vertex(self) -> int:
        """The index of the first vertex ``all_quad`` added (``len(V)`` when it added none)."""
        return len(self.V) - int(self.stats.get("added_vertices", 0))

    def to_meshio(self) -> Any:
        """The result as a ``meshio.Mesh``: the quads, the triangles and the polygons as separate
        cell blocks ("quad", "triangle", "polygon"; one block per run of faces with the same
        number of corners), in the order of ``faces``; the per-vertex properties as point data,
        the per-face ones (material, group, object, smoothing indices and face properties) as
        cell data. What meshio has no place for (per-corner texture coordinates and normals,
        material names) is warned as ``DroppedWarning``. Needs meshio."""
        return _to_meshio(self.V, self.faces, self.attributes)

    def padded_faces(self) -> np.ndarray:
        """Every output face, in the order of ``faces``, as one padded int64 array
        ``[n, i0, ..., n, ...]``, as pyvista's ``PolyData(r.V, r.padded_faces())`` takes them."""
        return np.concatenate([interop.padded(self.quads), interop.padded(self.triangles),
                               interop.padded(self.polygons)])


def _to_meshio(V: np.ndarray, faces: List[Any], attributes: Attributes) -> Any:
    mesh, dropped = interop.to_meshio(V, faces, attributes)
    for line in dropped:
        warnings.warn(f"to_meshio: not carried: {line}", DroppedWarning, stacklevel=3)
    return mesh


def quadrangulate(
    V: Union[npt.ArrayLike, Mesh],
    F: Optional[Faces] = None,
    algorithm: str = "auto",
    all_quad: bool = False,
    seed: int = 1,
    augment: str = "local",
    objective: str = "quads",
    sharp_angle: Optional[float] = None,
    keep_edges: Optional[npt.ArrayLike] = None,
    max_corner_deviation: Optional[float] = None,
    attributes: Optional[Attributes] = None,
    cross: Sequence[str] = (),
    threads: int = 0,
    keep_polygons: bool = False,
    triangle_cost: Optional[float] = None,
    flow_weight: Optional[float] = None,
    drop_duplicate_faces: bool = False,
) -> QuadResult:
    """Pairs the triangles of any polygon mesh into quads on the same vertices.

    ``V`` is an (n, 3) array of any numeric dtype and memory order (copied only when it is not
    C-ordered float64); ``F`` an (m, k) integer array or a list of faces (sequences of vertex
    indices, any length >= 3, mixed lengths allowed). By default (``objective="quads"``) the
    pairing is the exact least-cost one, certified (``stats["optimality_certified"]``): each quad
    costs its shape (``quad_quality``) plus ``flow_weight`` times its edge flow (how closely the
    edge it removes runs along a smooth cross field; 0, the default, weighs shape alone), and each
    triangle left unpaired ``triangle_cost`` degrees (90 when not given; 0.6 of it for a
    triangle beside good quads each of whose pairs would cost its neighbour 2/3 of it over that
    neighbour's best, a model's own, as a bevel's corner), so a triangle stays where pairing it
    would break better quads; both weights are read by ``objective="quads"``
    only, and ``triangle_cost`` not with ``all_quad`` (which pairs the cheapest maximum), so
    giving one where it would not be read raises ``TypeError``. ``objective="pairs"`` gives a
    certified maximum pairing instead: closed components paired perfectly by ``algorithm`` (auto,
    sg, ps, ds, gw, frink or lrs), the rest by greedy pairing and augmenting paths with a
    Tutte-Berge witness. Faces that are not triangles are kept. ``all_quad`` makes every face a quad by splitting the fewest edges
    (a minimum T-join, certified: ``stats["all_quad_certified"]``, ``stats["added_vertices"]`` and
    ``stats["added_vertices_minimum"]``), polygons included unless ``keep_polygons``; a face
    repeating a vertex is kept as it is (``stats["degenerate_faces"]``). ``augment`` is "local"
    or "faithful", ``seed`` seeds auto, sg and ps. Faces with the same vertices as an earlier face
    are counted in ``stats["duplicate_faces"]`` (no pair crosses their edges);
    ``drop_duplicate_faces=True`` drops them first, keeping the first of each (``sources`` still
    name the faces as given).
    ``objective="quality"`` gives the maximum pairing of least total ``quad_quality`` cost
    (certified: ``stats["optimality_certified"]``); ``algorithm`` is used by "pairs" only.
    ``sharp_angle`` (degrees) cuts edges whose faces' normals differ by more; ``keep_edges``, an
    (e, 2) array of vertex pairs, names edges no quad may remove. ``max_corner_deviation``
    (degrees) allows only pairs whose quad costs at most that (``quad_quality``); the others are
    cuts of cause "shape" and their triangles may stay (the maximum pairing of what is allowed,
    the cheapest with ``objective="quality"``). ``threads`` runs the phases that split into
    independent parts (grouping the edges, measuring the quads, the quality objective's short
    searches) on that many threads, 0 (the default, as ``petersen quad``) on every core; the
    answer does not depend on it. Same options, same seed: same answer as ``petersen quad``. The
    GIL is released while the library works.

    ``V`` may be a mesh object (``F`` then omitted): a ``Mesh``, whose faces and attributes are
    used, a ``meshio.Mesh``, trimesh's shape or pyvista's ``PolyData`` (see ``write_mesh``); ``F``
    may be a padded face array ``[n, i0, ..., n, ...]`` (pyvista's ``faces``). With
    ``attributes`` (``Attributes``, as ``read_mesh`` gives them) no quad crosses a texture or
    normal seam or a border between materials, groups, objects, smoothing groups or face property
    values, unless ``cross`` names that cause (``CROSSABLE``, e.g. ``cross=["uv_seam"]``); the
    result's ``attributes`` carry them to the quads. That is the only difference between
    ``quadrangulate(mesh)`` and ``quadrangulate(mesh.V, mesh.F)``: the same options give the same
    pairs whenever the attributes cut no edge. Flat shading cuts none (a triangle whose corner
    normals all lie along its own normal makes no normal seam with another such triangle), so a
    flat-shaded mesh with no other attributes pairs the same either way. When more than 2 % of
    the triangles are left and attribute cuts exist, ``stats["cross_to_pair"]`` maps those causes
    to their cut edge counts: ``cross=list(r.stats["cross_to_pair"])`` lets pairs cross them.

    Raises ``ValueError`` with the library's message for a bad mesh (a coordinate that is not
    finite, naming the vertex; a vertex index out of range; a face of fewer than three corners; no
    faces at all; with ``all_quad``, a proof that no all-quad mesh exists), for ``max_corner_deviation``
    outside [0, 270], ``sharp_angle`` outside [0, 180], ``triangle_cost`` outside [0, 10000] or
    ``flow_weight`` outside [0, 100] (any not finite), ``threads`` above
    1024, or an unknown algorithm, augment or objective; ``TypeError`` for faces that are not
    integers or an angle that is not a number.
    """
    V, F, attributes = _mesh_parts(V, F, attributes, "quadrangulate")
    _refuse_unread_weights(objective, bool(all_quad), triangle_cost, flow_weight)
    if isinstance(cross, str):
        raise TypeError("cross must be a list of cause names, e.g. cross=['uv_seam']")
    r = _petersen.quadrangulate(
        V, F, algorithm, augment, int(seed), bool(all_quad), objective,
        _degrees("sharp_angle", sharp_angle, 180.0), keep_edges,
        _degrees("max_corner_deviation", max_corner_deviation, 270.0), attributes,
        [str(c) for c in cross], _threads(threads), bool(keep_polygons),
        _number("triangle_cost", _petersen.DEFAULT_TRIANGLE_COST if triangle_cost is None
                else triangle_cost, 10000.0),
        _number("flow_weight", 0.0 if flow_weight is None else flow_weight, 100.0),
        bool(drop_duplicate_faces))
    return QuadResult(**r)


def _refuse_unread_weights(objective: str, all_quad: bool, triangle_cost: Optional[float],
                           flow_weight: Optional[float]) -> None:
    """TypeError for a weight given where the run would not read it, as ``petersen quad``
    refuses the flag."""
    if triangle_cost is not None and objective != "quads":
        raise TypeError(f"triangle_cost prices the triangles objective quads leaves; objective "
                        f"{objective!r} pairs the maximum")
    if triangle_cost is not None and all_quad:
        raise TypeError("triangle_cost: with all_quad every triangle left is split into quads, "
                        "so the pairing is the cheapest maximum, which prices no triangle")
    if flow_weight is not None and objective != "quads":
        raise TypeError(f"flow_weight weighs the edge flow in the costs of objective quads, not "
                        f"{objective!r}")


def _degrees(name: str, value: Optional[float], high: float) -> Optional[float]:
    """An angle option as the library takes it: None, or a finite number of degrees in
    [0, high]; ``ValueError`` naming the keyword otherwise (NaN fails every comparison)."""
    if value is None:
        return None
    if isinstance(value, bool) or not isinstance(value, numbers.Real):
        raise TypeError(f"{name} must be a number of degrees, not {value!r}")
    degrees = float(value)
    if not (math.isfinite(degrees) and 0.0 <= degrees <= high):
        raise ValueError(f"{name} must be a finite number of degrees in [0, {high:g}], "
                         f"not {value!r}")
    return degrees


def _number(name: str, value: float, high: float) -> float:
    """A cost option of the quads objective: a finite number in [0, high], as _degrees checks."""
    if value is None:
        raise TypeError(f"{name} must be a number, not None")
    return _degrees(name, value, high)


def _threads(threads: int) -> int:
    """A ``threads`` option as the library takes it: 0 (every core) or a count."""
    if isinstance(threads, bool) or not isinstance(threads, numbers.Integral):
        raise TypeError(f"threads must be an integer, not {threads!r}")
    if not 0 <= threads < 2**32:
        raise ValueError(f"threads must be 0 (every core) or a count of threads, not {threads}")
    return int(threads)


def _mesh_parts(
    V: Any, F: Any, attributes: Optional[Attributes], what: str
) -> Tuple[Any, Any, Any]:
    """V, F and attributes, from a mesh object in V (whose attributes an explicit
    ``attributes`` replaces) or as given (a padded F unpadded)."""
    if F is not None:
        if isinstance(V, (Mesh, QuadResult)) or interop.mesh_parts(V) is not None:
            raise TypeError(f"{what}: pass a mesh object or V and F, not both")
        return V, interop.faces_from_padded(F) if interop.is_padded(F) else F, attributes
    if isinstance(V, Mesh):
        return V.V, V.F, V.attributes if attributes is None else attributes
    if isinstance(V, QuadResult):
        return V.V, V.faces, V.attributes if attributes is None else attributes
    parts = interop.mesh_parts(V)
    if parts is None:
        raise TypeError(
            f"{what}: F is missing (or V is no mesh: a petersen Mesh or QuadResult, a "
            f"meshio.Mesh, an object with .vertices and .faces or .points and padded .faces; "
            f"got {type(V).__name__})")
    points, faces, own, dropped = parts
    _warn_dropped(type(V).__name__, dropped, "left out")
    return points, faces, own if attributes is None else attributes


def read_mesh(path: str, as_meshio: bool = False, strict: bool = False) -> Any:
    """Reads an OFF, OBJ or PLY mesh (ascii or binary; gzip-compressed too), any face arity,
    with its attributes (``Mesh.attributes``).

    What the reader reads past (OBJ ``l`` lines, other PLY elements) is in ``Mesh.dropped`` and
    warned as ``DroppedWarning``. Raises ``ValueError`` naming the file and line (text) or element
    (binary) for a bad file. A texture coordinate or normal index past those the file has drops
    that attribute of that face, warned once per attribute; ``strict=True`` raises
    ``ValueError`` naming the file and line instead. ``as_meshio=True`` returns a ``meshio.Mesh``
    instead (``Mesh.to_meshio``).
    """
    V, F, attributes, dropped = _petersen.read_mesh(str(path), bool(strict))
    _warn_dropped(path, dropped, "read past")
    mesh = Mesh(V, F, attributes, dropped)
    return mesh.to_meshio() if as_meshio else mesh


def write_mesh(
    path: str,
    V: Union[npt.ArrayLike, Mesh],
    F: Optional[Faces] = None,
    attributes: Optional[Attributes] = None,
) -> List[str]:
    """Writes a mesh as OFF, OBJ or PLY by the extension of ``path`` (``.gz`` compresses).

    ``V`` may be a mesh object (``F`` then omitted): a ``Mesh`` or a ``QuadResult`` (with their
    attributes), a ``meshio.Mesh`` (its "triangle", "quad" and "polygon" blocks; point and cell
    data of one value each as vertex and face properties), anything with ``.vertices`` and
    ``.faces`` (trimesh's shape) or ``.points`` and padded ``.faces`` (pyvista's ``PolyData``);
    ``F`` may be a padded array ``[n, i0, ..., n, ...]``. What of such an object is left out
    (other cell blocks, data of several values per point) is warned as ``DroppedWarning``.
    ``attributes`` (``Attributes``, as ``read_mesh`` gives them) are written as the format can:
    returns one line per kind of thing it has no place for (e.g. corner normals in a PLY), each
    also warned as ``DroppedWarning``; empty when everything was written. Atomic: written to a
    temporary file beside ``path`` and renamed into place, so a failed write leaves no partial
    file and an existing one whole. Reading it back gives the same positions, faces and written
    attributes. Raises ``ValueError`` for a coordinate that is not finite (naming the vertex), an
    unknown extension, an index out of range, attributes of the wrong size or a path that cannot
    be written.
    """
    V, F, attributes = _mesh_parts(V, F, attributes, "write_mesh")
    dropped = _petersen.write_mesh(str(path), V, F, attributes)
    _warn_dropped(path, dropped, "not written")
    return dropped


def perfect_matching(
    n: int,
    edges: npt.ArrayLike,
    algorithm: str = "auto",
    seed: int = 1,
    augment: str = "local",
) -> np.ndarray:
    """A perfect matching of a cubic bridgeless (multi)graph: the sorted indices of its edges.

    ``edges`` is an (e, 2) integer array over nodes 0..n-1 (parallel edges allowed, no loops).
    The answer is checked by the library's verifier before it is returned. A graph that is not
    cubic (a node of degree other than 3, a loop) or has a bridge raises ``ValueError`` with the
    library's message naming the node or edge; no partial or maximum matching is returned then.
    ``lrs`` needs a mesh and raises ``ValueError``. The GIL is released while the library works.
    """
    return _petersen.perfect_matching(int(n), edges, algorithm, augment, int(seed))


@dataclass
class MaximumMatching:
    """What ``maximum_matching`` returns."""

    #: The sorted indices of the matched edges.
    edges: np.ndarray
    #: Whether every node is matched.
    perfect: bool
    #: A Tutte-Berge set A proving the matching maximum (it leaves exactly odd(G - A) - |A|
    #: nodes free); empty when the graph is cubic and bridgeless (the matching is perfect).
    tutte_set: np.ndarray


def maximum_matching(
    n: int,
    edges: npt.ArrayLike,
    algorithm: str = "auto",
    seed: int = 1,
    augment: str = "local",
) -> MaximumMatching:
    """A maximum matching of any (multi)graph, as ``petersen match`` finds it.

    ``edges`` is an (e, 2) integer array over nodes 0..n-1 (parallel edges and loops allowed; a
    loop is never matched). A cubic bridgeless graph gets a perfect matching by ``algorithm``
    (as ``perfect_matching``); any other graph a maximum matching by augmenting paths with its
    Tutte-Berge set. Every answer is checked by the library's verifier (the perfect matching, or
    the maximum one against its set) before it is returned. The GIL is released while the
    library works.
    """
    matched, perfect, tutte = _petersen.maximum_matching(
        int(n), edges, algorithm, augment, int(seed))
    return MaximumMatching(matched, bool(perfect), tutte)


@dataclass
class CheapestMatching:
    """What ``min_cost_matching`` returns."""

    #: The sorted indices of the matched edges.
    edges: np.ndarray
    #: Their total cost: the least among the maximum matchings.
    total_cost: int
    #: Whether every node is matched.
    perfect: bool


def min_cost_matching(
    n: int, edges: npt.ArrayLike, costs: npt.ArrayLike, threads: int = 0
) -> CheapestMatching:
    """The matching of least total cost among the maximum matchings of any (multi)graph.

    ``edges`` is an (e, 2) integer array over nodes 0..n-1 (parallel edges and loops allowed; a
    loop is never matched), ``costs`` one integer per edge (at most 2^40 in absolute value;
    scale and round real costs first). A perfect matching when the graph has one. Exact:
    Edmonds' primal-dual blossom algorithm, as ``petersen match --objective cost`` and
    ``quadrangulate(objective="quality")``; its dual solution is checked by an
    independent verifier before the answer is returned. ``threads`` as in ``quadrangulate``
    (0: every core; the answer does not depend on it). Raises ``ValueError`` for a node out of
    range, or a cost out of range or of the wrong count, ``TypeError`` for costs that are not
    integers. The GIL is released while the library works.
    """
    costs = np.asarray(costs)
    if costs.size and not np.issubdtype(costs.dtype, np.integer):
        raise TypeError(
            f"costs must be integers, not {costs.dtype} (scale and round real costs first)")
    if costs.size and (costs.max() > 2**40 or costs.min() < -(2**40)):
        raise ValueError("costs: a cost out of range (at most 2^40 in absolute value)")
    matched, total, perfect = _petersen.min_cost_matching(
        int(n), edges, costs.astype(np.int64, copy=False), _threads(threads))
    return CheapestMatching(matched, int(total), bool(perfect))


def quad_quality(V: npt.ArrayLike, quads: npt.ArrayLike) -> np.ndarray:
    """The worst-corner deviation of each quad from a right angle, in degrees (float64 array).

    For quad a, b, c, d: n = unit((c - a) x (d - b)); the two quad edges at each corner are
    projected onto the plane orthogonal to n and the interior angle theta taken in [0, 360);
    cost = max over the corners of |90 - theta|. A rectangle costs 0, a non-convex quad more than
    90, a degenerate one 270.
    """
    return _petersen.quad_quality(V, quads)


def render(
    path: str,
    V: Any,
    F: Optional[Faces] = None,
    *,
    first_added_vertex: Optional[int] = None,
    caption: Sequence[str] = (),
    view: Optional[Tuple[float, float, float]] = None,
    width: int = 800,
    height: int = 800,
) -> None:
    """Draws a mesh into a PNG or SVG picture, as ``petersen render``.

    The format is the extension of ``path``. A shaded orthographic view along ``view`` (automatic when None), face edges drawn, quads
    coloured by ``quad_quality`` with a colour bar, triangles highlighted when the mesh has quads,
    vertices from ``first_added_vertex`` on drawn as dots, the ``caption`` lines underneath.
    ``V`` may be a mesh object instead of positions (``F`` then omitted), as in ``write_mesh``;
    for a ``QuadResult`` the vertices ``all_quad`` added are drawn as dots unless
    ``first_added_vertex`` says otherwise.
    """
    if F is None and isinstance(V, QuadResult) and first_added_vertex is None:
        if V.first_added_vertex < len(V.V):
            first_added_vertex = V.first_added_vertex
    V, F, _ = _mesh_parts(V, F, None, "render")
    _petersen.render(
        str(path), V, F, first_added_vertex, list(caption),
        None if view is None else tuple(float(x) for x in view), int(width), int(height))


def __getattr__(name: str) -> Any:
    """``petersen.distributed`` (the Dask pipeline), imported on first use: importing petersen
    imports no cluster code."""
    if name == "distributed":
        import importlib

        return importlib.import_module(".distributed", __name__)
    raise AttributeError(f"module 'petersen' has no attribute '{name}'")
