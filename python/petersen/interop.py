"""Meshes of the Python mesh libraries, in and out: meshio's ``Mesh``, trimesh's shape (anything
with ``.vertices`` and ``.faces``) and pyvista's padded face arrays (``[n, i0, ..., n, ...]``,
e.g. a ``PolyData``'s ``.points`` and ``.faces``).

Nothing here imports trimesh or pyvista: their objects are recognised by their attributes.
meshio is imported only to make a ``meshio.Mesh`` (``to_meshio``).
"""

from __future__ import annotations

import numbers
from typing import Any, Dict, List, Optional, Sequence, Tuple

import numpy as np

#: meshio's names of the cell blocks that are faces, by number of corners (others: "polygon").
FACE_CELL_TYPES = {3: "triangle", 4: "quad"}

#: The per-face attributes (``Attributes``) that become meshio cell data under the same name.
_FACE_ATTRIBUTES = ("face_material", "face_group", "face_object", "face_smoothing")


def mesh_parts(mesh: Any) -> Optional[Tuple[np.ndarray, Any, Dict[str, Any], List[str]]]:
    """Positions, faces, attributes and what was left out, of a mesh object of another
    library; None when ``mesh`` is none of them.

    - a ``meshio.Mesh`` (``.points`` and ``.cells``): its "triangle", "quad" and "polygon"
      blocks, in order; one-value-per-point data becomes ``vertex_properties``, one-value-per-cell
      data of those blocks ``face_properties``; other blocks and data are left out (listed).
    - trimesh's shape (``.vertices`` and ``.faces``, an (m, k) array).
    - pyvista's ``PolyData`` (``.points`` and padded ``.faces``).
    """
    points, cells = getattr(mesh, "points", None), getattr(mesh, "cells", None)
    if points is not None and cells is not None and not isinstance(cells, np.ndarray):
        return _from_meshio(mesh)
    vertices, faces = getattr(mesh, "vertices", None), getattr(mesh, "faces", None)
    if vertices is not None and faces is not None:
        return np.asarray(vertices), _faces_of(faces), {}, []
    if points is not None and faces is not None:
        return np.asarray(points), _faces_of(faces), {}, []
    return None


def _faces_of(faces: Any) -> Any:
    """Faces as petersen takes them, a padded array read as such."""
    return faces_from_padded(faces) if is_padded(faces) else faces


def is_padded(faces: Any) -> bool:
    """Whether ``faces`` is one flat sequence of integers: a padded face array, as pyvista's."""
    if isinstance(faces, np.ndarray):
        return faces.ndim == 1 and (faces.size == 0 or np.issubdtype(faces.dtype, np.integer))
    if isinstance(faces, (list, tuple)):
        return len(faces) > 0 and all(isinstance(x, numbers.Integral) for x in faces)
    return False


def faces_from_padded(padded: Any) -> Any:
    """The faces of a padded array ``[n, i0, ..., i(n-1), n, ...]``: an (m, k) int64 array when
    every face has k corners, else a list of int64 arrays. Raises ``ValueError`` naming the
    position of a count below 3 or one that runs past the end."""
    padded = np.asarray(padded, dtype=np.int64).ravel()
    starts = []
    at = 0
    while at < len(padded):
        count = int(padded[at])
        if count < 3:
            raise ValueError(f"padded faces: the count at position {at} is {count} "
                             "(a face has at least 3 corners)")
        if at + 1 + count > len(padded):
            raise ValueError(f"padded faces: the face at position {at} has {count} corners but "
                             f"only {len(padded) - at - 1} values follow")
        starts.append(at)
        at += 1 + count
    if not starts:
        return np.empty((0, 3), np.int64)
    starts = np.array(starts)
    counts = padded[starts]
    if np.all(counts == counts[0]):
        k = int(counts[0])
        return padded.reshape(-1, k + 1)[:, 1:].copy()
    return [padded[s + 1 : s + 1 + c].copy() for s, c in zip(starts.tolist(), counts.tolist())]


def padded(faces: Sequence[Any]) -> np.ndarray:
    """Faces as one padded int64 array ``[n, i0, ..., n, ...]`` (pyvista's ``PolyData.faces``)."""
    if isinstance(faces, np.ndarray) and faces.ndim == 2:
        m, k = faces.shape
        return np.hstack([np.full((m, 1), k, np.int64), faces.astype(np.int64)]).ravel()
    parts = [np.concatenate([[len(f)], np.asarray(f, np.int64)]) for f in faces]
    return np.concatenate(parts).astype(np.int64) if parts else np.empty(0, np.int64)


def _from_meshio(mesh: Any) -> Tuple[np.ndarray, Any, Dict[str, Any], List[str]]:
    blocks = _cell_blocks(mesh.cells)
    faces: List[np.ndarray] = []
    face_block: List[bool] = []
    dropped: List[str] = []
    for kind, data in blocks:
        is_face = kind in ("triangle", "quad") or kind.startswith("polygon")
        face_block.append(is_face)
        if is_face:
            faces.extend(_rows(data))
        else:
            dropped.append(f"meshio cell block '{kind}' ({len(data)} cells): not faces")
    points = np.asarray(mesh.points, dtype=np.float64)
    if points.ndim == 2 and points.shape[1] == 2:  # 2D points: on the plane z = 0
        points = np.hstack([points, np.zeros((len(points), 1))])
    attributes: Dict[str, Any] = {}
    vertex_properties = {}
    for name, values in (getattr(mesh, "point_data", None) or {}).items():
        values = np.asarray(values)
        if values.ndim == 1 and len(values) == len(points):
            vertex_properties[name] = values
        else:
            dropped.append(f"meshio point data '{name}' of shape {values.shape}: "
                           "only one value per point is carried")
    face_properties = {}
    for name, per_block in (getattr(mesh, "cell_data", None) or {}).items():
        arrays = [np.asarray(a) for a, is_face in zip(per_block, face_block) if is_face]
        if arrays and all(a.ndim == 1 for a in arrays):
            face_properties[name] = np.concatenate(arrays)
        elif arrays:
            dropped.append(f"meshio cell data '{name}': only one value per cell is carried")
    if vertex_properties:
        attributes["vertex_properties"] = vertex_properties
    if face_properties:
        attributes["face_properties"] = face_properties
    arities = {len(f) for f in faces}
    F: Any = np.array(faces, dtype=np.int64) if len(arities) == 1 else faces
    if not faces:
        F = np.empty((0, 3), np.int64)
    return points, F, attributes, dropped


def _cell_blocks(cells: Any) -> List[Tuple[str, Any]]:
    """meshio's cells as (type, data) pairs: CellBlocks, (type, data) tuples or a dict."""
    if isinstance(cells, dict):
        return list(cells.items())
    out = []
    for block in cells:
        if hasattr(block, "type") and hasattr(block, "data"):
            out.append((str(block.type), block.data))
        else:
            kind, data = block
            out.append((str(kind), data))
    return out


def _rows(data: Any) -> List[np.ndarray]:
    if isinstance(data, np.ndarray) and data.ndim == 2:
        return list(data.astype(np.int64))
    return [np.asarray(row, dtype=np.int64) for row in data]


def to_meshio(
    V: np.ndarray, faces: Sequence[Any], attributes: Dict[str, Any]
) -> Tuple[Any, List[str]]:
    """A ``meshio.Mesh`` of these faces and what of the attributes it has no place for.

    Runs of faces with the same number of corners become one cell block each, in order
    ("triangle", "quad", "polygon"), so a ``QuadResult``'s quads and triangles are separate
    blocks. ``vertex_properties`` become point data; ``face_properties`` and the per-face
    ``face_material``, ``face_group``, ``face_object``, ``face_smoothing`` cell data. Per-corner
    texture coordinates and normals are left out: meshio holds data per point and per cell.
    """
    try:
        import meshio
    except ImportError as error:
        raise ImportError(
            "to_meshio and read_mesh(..., as_meshio=True) need meshio "
            "(Debian: apt install python3-meshio; else pip install meshio)") from error
    runs: List[Tuple[int, int]] = []  # (first face, end) of each run of one arity
    arities = [len(f) for f in faces]
    for i, k in enumerate(arities):
        if runs and arities[runs[-1][0]] == k:
            runs[-1] = (runs[-1][0], i + 1)
        else:
            runs.append((i, i + 1))
    cells = []
    for first, end in runs:
        k = arities[first]
        block = np.array([np.asarray(f, np.int64) for f in faces[first:end]], dtype=np.int64)
        cells.append(meshio.CellBlock(FACE_CELL_TYPES.get(k, "polygon"), block))
    per_face: Dict[str, np.ndarray] = {}
    for name in _FACE_ATTRIBUTES:
        if name in attributes:
            per_face[name] = np.asarray(attributes[name])
    for name, values in attributes.get("face_properties", {}).items():
        per_face[name] = np.asarray(values)
    cell_data = {name: [values[first:end] for first, end in runs]
                 for name, values in per_face.items()}
    point_data = {name: np.asarray(values)
                  for name, values in attributes.get("vertex_properties", {}).items()}
    dropped = []
    if "corner_texcoord" in attributes or "texcoords" in attributes:
        dropped.append("texture coordinates (per corner): meshio has no per-corner data")
    if "corner_normal" in attributes or "normals" in attributes:
        dropped.append("normals (per corner): meshio has no per-corner data")
    for name in ("material_names", "group_names", "object_names"):
        if attributes.get(name):
            dropped.append(f"{name}: meshio keeps the per-face indices only (cell data)")
    mesh = meshio.Mesh(np.asarray(V, dtype=np.float64), cells, point_data=point_data,
                       cell_data=cell_data)
    return mesh, dropped
