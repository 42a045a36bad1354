"""petersen.distributed: a binary PLY triangle mesh quadrangulated on a Dask cluster, in parts.

    >>> from distributed import Client
    >>> import petersen.distributed
    >>> stats = petersen.distributed.quadrangulate("in.ply", "out.ply", Client(), parts=8)

The stages (docs/dask.md):

1. **Parts.** The client reads the PLY header once and gives each task a contiguous range of
   faces; the worker reads its own range from the file (a shared path) and the positions of the
   vertices it uses, pairs the range with ``petersen.quadrangulate`` (a certified maximum pairing of
   the part's pairable graph), moves each triangle it left unpaired along an alternating path to
   the part's frontier (a triangle with an edge no other triangle of the part has), and keeps the
   part on the worker. It returns only its open-edge records (one per such edge: the vertex key,
   the triangle, the opposite vertex) and the keys the cut step must watch.
2. **Cut.** One task pairs the records by vertex key: two records of different triangles whose
   opposite vertices differ make a cut edge (pairable, as on one machine); one record is a mesh
   boundary; an edge with more than two faces across parts is a cut no pair crosses.
3. **Repair.** Each part hands over its band (the triangles within ``rings`` steps of its
   frontier, closed under its pairs) with the band's pairable edges; one task takes the bands and
   the cut edges and replaces their pairs by a maximum matching of that graph
   (``petersen.maximum_matching``), which joins the triangles the parts left across the cuts by
   augmenting paths. On a closed mesh (no boundary) a triangle still unpaired means the bands
   were too narrow: the bands are taken again with four times the rings, until the bands are
   the whole parts, where the repair is the whole mesh's maximum matching.
4. **Write.** Each part checks its own triangles (every one in exactly one quad or left, the two
   triangles of each quad sharing an edge with four distinct vertices) and writes its faces into
   the output at offsets the client computed, a temporary file renamed into place when every part
   has written; the vertex block is copied unchanged.

Only small arrays move between tasks (records, bands, the repair's pairs); the parts' triangles and
pairs stay on their workers. Retries are Dask's: every task is submitted with ``retries``, and a
task whose worker died is run again by the scheduler (from the file), as is any part whose result
was lost with its worker.
"""

from __future__ import annotations

import os
import time
from dataclasses import dataclass
from typing import Any, Dict, List, Sequence, Tuple, Union

import numpy as np

import petersen

__all__ = ["PlyLayout", "read_layout", "quadrangulate"]

_PLY_TYPES = {
    "char": "i1", "int8": "i1", "uchar": "u1", "uint8": "u1", "short": "i2", "int16": "i2",
    "ushort": "u2", "uint16": "u2", "int": "i4", "int32": "i4", "uint": "u4", "uint32": "u4",
    "float": "f4", "float32": "f4", "double": "f8", "float64": "f8",
}
_HEADER_LIMIT = 1 << 16
_NO_FACE = -1


@dataclass(frozen=True)
class PlyLayout:
    """Where a binary little-endian triangle PLY keeps its vertices and faces: enough for any
    worker to read a range of either without the header."""

    path: str
    vertex_count: int
    face_count: int
    vertex_offset: int
    vertex_dtype: Tuple[Tuple[str, str], ...]
    face_offset: int
    face_dtype: Tuple[Tuple[Any, ...], ...]
    #: The vertex element's header lines, copied into the output's header.
    vertex_header: Tuple[str, ...]

    @property
    def face_stride(self) -> int:
        return np.dtype(list(self.face_dtype)).itemsize


def _header_lines(path: str) -> Tuple[List[str], int]:
    with open(path, "rb") as f:
        head = f.read(_HEADER_LIMIT)
    end = head.find(b"end_header\n")
    if not head.startswith(b"ply\n") or end < 0:
        raise ValueError(f"{path}: not a PLY file (no 'ply' line, or no 'end_header' in the "
                         f"first {_HEADER_LIMIT} bytes)")
    return head[:end].decode("ascii", "replace").split("\n")[:-1], end + len("end_header\n")


def _ply_type(path: str, line: int, name: str) -> str:
    if name not in _PLY_TYPES:
        raise ValueError(f"{path}: header line {line}: unknown PLY type '{name}'")
    return "<" + _PLY_TYPES[name]


def read_layout(path: str) -> PlyLayout:
    """Reads the header of a binary little-endian PLY whose faces are triangles. Raises
    ValueError naming the file and header line for any other file: ascii or big-endian, an
    element before the vertices or between vertices and faces, a face property list that is not
    vertex_indices, a list in the vertex element, x, y or z missing. O(header)."""
    lines, data_offset = _header_lines(path)
    elements: List[Tuple[str, int, List[Tuple[Any, ...]], List[str], int]] = []
    for number, line in enumerate(lines, start=1):
        words = line.split()
        if not words or words[0] in ("ply", "comment", "obj_info"):
            continue
        if words[0] == "format":
            if words[1:2] != ["binary_little_endian"]:
                raise ValueError(f"{path}: header line {number}: format {' '.join(words[1:])}; "
                                 "the distributed pipeline reads binary_little_endian PLY")
        elif words[0] == "element" and len(words) == 3:
            elements.append((words[1], int(words[2]), [], [line], number))
        elif words[0] == "property" and elements:
            elements[-1][3].append(line)
            if words[1] == "list" and len(words) == 5:
                fields = (words[4], _ply_type(path, number, words[2]),
                          _ply_type(path, number, words[3]))
            elif len(words) == 3:
                fields = (words[2], _ply_type(path, number, words[1]))
            else:
                raise ValueError(f"{path}: header line {number}: malformed property")
            elements[-1][2].append(fields)
        else:
            raise ValueError(f"{path}: header line {number}: unexpected '{line}'")
    names = [e[0] for e in elements]
    if names[:2] != ["vertex", "face"]:
        raise ValueError(f"{path}: elements {names}: the distributed pipeline reads a vertex "
                         "element followed by a face element")
    (_, n, vprops, vlines, vline), (_, m, fprops, _, fline) = elements[:2]
    if any(len(p) == 3 for p in vprops) or not {"x", "y", "z"} <= {p[0] for p in vprops}:
        raise ValueError(f"{path}: header line {vline}: vertex element needs x, y, z and no list")
    lists = [p for p in fprops if len(p) == 3]
    if len(lists) != 1 or lists[0][0] not in ("vertex_indices", "vertex_index"):
        raise ValueError(f"{path}: header line {fline}: face element needs one list, "
                         "vertex_indices")
    if n >= 2**32:
        raise ValueError(f"{path}: {n} vertices; at most 2^32 - 1")
    face_dtype = tuple(
        (("count", p[1]), ("corners", p[2], (3,))) if len(p) == 3 else ((p[0], p[1]),)
        for p in fprops)
    layout = PlyLayout(
        path=str(path), vertex_count=n, face_count=m, vertex_offset=data_offset,
        vertex_dtype=tuple((p[0], p[1]) for p in vprops),
        face_offset=data_offset + n * np.dtype(list((p[0], p[1]) for p in vprops)).itemsize,
        face_dtype=tuple(field for group in face_dtype for field in group),
        vertex_header=tuple(vlines))
    end = layout.face_offset + m * layout.face_stride
    if os.path.getsize(path) < end:
        raise ValueError(f"{path}: {os.path.getsize(path)} bytes, shorter than the {end} its "
                         "header needs for triangles (a face of another arity?)")
    return layout


def _read_faces(layout: PlyLayout, lo: int, hi: int) -> np.ndarray:
    """Faces lo..hi-1 as an (hi - lo, 3) int64 array of vertex ids; ValueError naming the face for
    one that is not a triangle or has a vertex out of range."""
    dtype = np.dtype(list(layout.face_dtype))
    rows = np.memmap(layout.path, dtype=dtype, mode="r",
                     offset=layout.face_offset + lo * dtype.itemsize, shape=(hi - lo,))
    bad = np.flatnonzero(rows["count"] != 3)
    if bad.size:
        raise ValueError(f"{layout.path}: face {lo + bad[0]}: {rows['count'][bad[0]]} corners; "
                         "the distributed pipeline reads triangle meshes")
    F = rows["corners"].astype(np.int64)
    out = np.flatnonzero(((F < 0) | (F >= layout.vertex_count)).any(axis=1))
    if out.size:
        raise ValueError(f"{layout.path}: face {lo + out[0]}: a vertex index out of range "
                         f"({layout.vertex_count} vertices): {F[out[0]].tolist()}")
    return F


def _read_positions(layout: PlyLayout, vertices: np.ndarray) -> np.ndarray:
    rows = np.memmap(layout.path, dtype=np.dtype(list(layout.vertex_dtype)), mode="r",
                     offset=layout.vertex_offset, shape=(layout.vertex_count,))
    picked = rows[vertices]
    return np.stack([picked["x"], picked["y"], picked["z"]], axis=1).astype(np.float64)


def _edge_keys(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """The key of the edges a-b: (min << 32) | max, one uint64 per edge (vertex ids < 2^32)."""
    lo, hi = np.minimum(a, b).astype(np.uint64), np.maximum(a, b).astype(np.uint64)
    return (lo << np.uint64(32)) | hi


@dataclass
class _Edges:
    """The edges of a part's triangles grouped by key: per group its key, how many of the part's
    triangles have it, and (for groups of one or two) the triangles and opposite vertices."""

    keys: np.ndarray
    counts: np.ndarray
    faces: np.ndarray  # (groups, 2) local triangle ids, -1 past the count
    opposite: np.ndarray  # (groups, 2) vertex ids, -1 past the count


def _group_edges(F: np.ndarray) -> _Edges:
    """O(m log m): one sort of the 3m halfedges by key."""
    m = len(F)
    a, b, w = F.T.ravel(), np.roll(F, -1, axis=1).T.ravel(), np.roll(F, -2, axis=1).T.ravel()
    face = np.tile(np.arange(m), 3)
    proper = a != b  # a degenerate triangle's edge from a vertex to itself is no edge
    keys, face, w = _edge_keys(a, b)[proper], face[proper], w[proper]
    order = np.argsort(keys, kind="stable")
    keys, face, w = keys[order], face[order], w[order]
    start = np.flatnonzero(np.r_[True, keys[1:] != keys[:-1]])
    counts = np.diff(np.r_[start, len(keys)])
    faces = np.full((len(start), 2), -1, np.int64)
    opposite = np.full((len(start), 2), -1, np.int64)
    faces[:, 0], opposite[:, 0] = face[start], w[start]
    two = counts >= 2
    faces[two, 1], opposite[two, 1] = face[start[two] + 1], w[start[two] + 1]
    return _Edges(keys[start], counts, faces, opposite)


def _pairable(F: np.ndarray, edges: _Edges) -> np.ndarray:
    """The groups that are pairable edges (dualize/pairable_graph.hpp): exactly two triangles,
    neither degenerate, whose union has four distinct vertices."""
    degenerate = (F[:, 0] == F[:, 1]) | (F[:, 1] == F[:, 2]) | (F[:, 0] == F[:, 2])
    ok = edges.counts == 2
    ok &= edges.opposite[:, 0] != edges.opposite[:, 1]
    f = np.where(ok[:, None], edges.faces, 0)
    return ok & ~degenerate[f[:, 0]] & ~degenerate[f[:, 1]]


def _csr(m: int, pairs: np.ndarray) -> Tuple[np.ndarray, np.ndarray]:
    """Adjacency of m nodes from (e, 2) pairs: indptr, neighbours. O(m + e log e)."""
    src = np.concatenate([pairs[:, 0], pairs[:, 1]])
    dst = np.concatenate([pairs[:, 1], pairs[:, 0]])
    order = np.argsort(src, kind="stable")
    indptr = np.zeros(m + 1, np.int64)
    np.cumsum(np.bincount(src, minlength=m), out=indptr[1:])
    return indptr, dst[order]


def _neighbours(indptr: np.ndarray, nbr: np.ndarray, nodes: np.ndarray):
    """(source, neighbour) for every edge at `nodes`, vectorised."""
    starts, ends = indptr[nodes], indptr[nodes + 1]
    sizes = ends - starts
    src = np.repeat(nodes, sizes)
    offsets = np.arange(sizes.sum()) - np.repeat(np.cumsum(sizes) - sizes, sizes)
    return src, nbr[np.repeat(starts, sizes) + offsets]


def _move_to_frontier(mate, indptr, nbr, frontier, free) -> int:
    """Moves each free triangle to the frontier along an even alternating path (free u, then
    non-pair edge, pair edge, ...), flipping the pairs on it: the pairing keeps its size and the
    free triangle becomes the path's end, a frontier triangle, where the repair reaches it. A
    breadth-first alternating tree (each node entered once, so each path is simple); blossoms are
    not shrunk, so a path through one may be missed, leaving that triangle where it is (the repair
    then widens its bands). O(part) per free triangle. Returns how many moved."""
    moved = 0
    for u in free:
        if frontier[u]:
            continue
        parent = np.full(len(mate), -1, np.int64)
        seen = np.zeros(len(mate), bool)
        seen[u] = True
        even = np.array([u])
        while even.size:
            src, dst = _neighbours(indptr, nbr, even)
            keep = ~seen[dst] & (mate[dst] >= 0)
            dst, first = np.unique(dst[keep], return_index=True)
            src = src[keep][first]
            seen[dst], parent[dst] = True, src
            nxt = mate[dst]
            keep = ~seen[nxt]
            nxt, odd = nxt[keep], dst[keep]
            seen[nxt], parent[nxt] = True, odd
            hit = nxt[frontier[nxt]]
            if hit.size:
                z = hit[0]
                node = z
                mate[z] = -1
                while node != u:
                    y = parent[node]
                    x = parent[y]
                    mate[x], mate[y] = y, x
                    node = x
                moved += 1
                break
            even = nxt
    return moved


@dataclass
class _Part:
    """A part as its worker keeps it between the stages."""

    index: int
    lo: int
    F: np.ndarray  # (m, 3) global vertex ids
    mate: np.ndarray  # local triangle id of each triangle's partner, -1 when unpaired
    indptr: np.ndarray  # the pairable graph of the part (CSR over local ids)
    nbr: np.ndarray
    pair_keys: np.ndarray  # (pairable edges,) keys, for the cut's spanning non-manifold edges
    pair_faces: np.ndarray  # (pairable edges, 2) local ids
    frontier: np.ndarray  # bool per triangle: has an edge no other triangle of the part has
    records: Dict[str, np.ndarray]
    watch: np.ndarray  # keys of edges of 2+ part triangles the other parts may also have
    figures: Dict[str, Any]


def _pair_part(layout: PlyLayout, index: int, lo: int, hi: int, options: dict) -> _Part:
    """Stage 1 on a worker: reads faces lo..hi-1, pairs them and prepares the records."""
    clock = time.perf_counter()
    F = _read_faces(layout, lo, hi)
    used, local = np.unique(F, return_inverse=True)
    result = petersen.quadrangulate(_read_positions(layout, used), local.reshape(-1, 3),
                                    threads=1, **options)
    mate = np.full(len(F), -1, np.int64)
    s = result.sources[: len(result.quads)]
    mate[s[:, 0]], mate[s[:, 1]] = s[:, 1], s[:, 0]
    edges = _group_edges(F)
    pairable = _pairable(F, edges)
    indptr, nbr = _csr(len(F), edges.faces[pairable])
    one = edges.counts == 1
    frontier = np.zeros(len(F), bool)
    frontier[edges.faces[one, 0]] = True
    ends = np.concatenate([edges.keys[one] >> np.uint64(32),
                           edges.keys[one] & np.uint64(0xFFFFFFFF)])
    frontier_vertices = np.unique(ends)
    lo_v, hi_v = edges.keys >> np.uint64(32), edges.keys & np.uint64(0xFFFFFFFF)
    watched = (edges.counts >= 3) | ((edges.counts == 2) & np.isin(lo_v, frontier_vertices)
                                     & np.isin(hi_v, frontier_vertices))
    free_before = int((mate < 0).sum())
    moved = _move_to_frontier(mate, indptr, nbr, frontier, np.flatnonzero(mate < 0))
    return _Part(
        index=index, lo=lo, F=F, mate=mate, indptr=indptr, nbr=nbr,
        pair_keys=edges.keys[pairable], pair_faces=edges.faces[pairable], frontier=frontier,
        records={"keys": edges.keys[one], "faces": edges.faces[one, 0] + lo,
                 "opposite": edges.opposite[one, 0]},
        watch=np.stack([edges.keys[watched].view(np.int64),
                        edges.counts[watched]], axis=1),
        figures={"triangles": len(F), "pairs": int(len(result.quads)),
                 "left": free_before, "moved_to_frontier": moved,
                 "maximum_certified": bool(result.stats["maximum_certified"]),
                 "interior_edges": int((edges.counts >= 2).sum()),
                 "seconds": time.perf_counter() - clock})


def _cut_inputs(part: _Part) -> Dict[str, Any]:
    """What stage 1 sends to the cut: records, watched keys, figures (all small)."""
    return {"records": part.records, "watch": part.watch, "figures": part.figures}


def _cut(inputs: Sequence[Dict[str, Any]]) -> Dict[str, Any]:
    """Stage 2: the records of every part paired by key. O(r log r) in the records."""
    keys = np.concatenate([i["records"]["keys"] for i in inputs])
    faces = np.concatenate([i["records"]["faces"] for i in inputs])
    opposite = np.concatenate([i["records"]["opposite"] for i in inputs])
    watch = np.concatenate([i["watch"] for i in inputs])
    order = np.argsort(keys, kind="stable")
    keys, faces, opposite = keys[order], faces[order], opposite[order]
    start = np.flatnonzero(np.r_[True, keys[1:] != keys[:-1]])
    counts = np.diff(np.r_[start, len(keys)])
    # Faces on each key beyond the records: the parts' own triangles on a watched edge.
    group_keys = keys[start]
    watch_keys = watch[:, 0].view(np.uint64)
    extra = np.zeros(len(start), np.int64)
    where = np.searchsorted(group_keys, watch_keys)
    hit = where < len(group_keys)
    hit[hit] &= group_keys[where[hit]] == watch_keys[hit]
    np.add.at(extra, where[hit], watch[hit, 1])
    total = counts + extra
    # A watched key of two parts' interiors shares no record: its count is their sum.
    wk, wcount = np.unique(watch_keys[~hit], return_counts=True)
    spanning = np.concatenate([group_keys[(total >= 3) & (extra > 0)], wk[wcount >= 2]])
    # Each part counted its watched edges among its own; counted once here.
    hit_groups = int((extra > 0).sum())
    repeats = (int(hit.sum()) - hit_groups) + (int((~hit).sum()) - len(wk))
    two = (counts == 2) & (extra == 0)
    s = start[two]
    cut = two.copy()
    cut[two] = opposite[s] != opposite[s + 1]
    s = start[cut]
    return {"edges": np.stack([faces[s], faces[s + 1]], axis=1),
            "spanning_nonmanifold": np.unique(spanning),
            "boundary_edges": int(((counts == 1) & (extra == 0)).sum()),
            "record_edges": len(start) - hit_groups - repeats,
            "figures": [i["figures"] for i in inputs]}


def _band(part: _Part, spanning: np.ndarray, rings: int) -> Dict[str, np.ndarray]:
    """Stage 3 on a worker: the triangles within `rings` pairable steps of the frontier (and of
    the part's free triangles and the spanning non-manifold edges), closed under the part's pairs,
    with their pairable edges. O(band) per ring."""
    m = len(part.F)
    bad = np.isin(part.pair_keys, spanning)
    seeds = part.frontier | (part.mate < 0)
    seeds[part.pair_faces[bad].ravel()] = True
    in_band = seeds.copy()
    ring = np.flatnonzero(seeds)
    for _ in range(rings):
        if not ring.size:
            break
        _, dst = _neighbours(part.indptr, part.nbr, ring)
        ring = np.unique(dst[~in_band[dst]])
        in_band[ring] = True
    paired = in_band & (part.mate >= 0)
    in_band[part.mate[paired]] = True
    ok = ~bad & in_band[part.pair_faces[:, 0]] & in_band[part.pair_faces[:, 1]]
    local = np.flatnonzero(in_band)
    mate = part.mate[local]
    return {"faces": local + part.lo, "triangles": part.F[local],
            "mates": np.where(mate >= 0, mate + part.lo, -1),
            "edges": part.pair_faces[ok] + part.lo, "whole": bool(in_band.all() or m == 0)}


def _quads_of(first: np.ndarray, second: np.ndarray) -> np.ndarray:
    """The quad of each pair of triangles sharing an edge, following the first's orientation
    (dualize/quad_of.hpp): the first's corners with the second's opposite vertex inserted in the
    shared edge. Raises RuntimeError when two triangles do not share exactly one edge."""
    in_first = (second[:, :, None] == first[:, None, :]).any(axis=2)
    if not (in_first.sum(axis=1) == 2).all():
        bad = np.flatnonzero(in_first.sum(axis=1) != 2)[0]
        raise RuntimeError(f"verification failed: triangles {first[bad].tolist()} and "
                           f"{second[bad].tolist()} share no single edge")
    w = second[np.arange(len(second)), np.argmin(in_first, axis=1)]
    # The first's corner i starts the shared edge when corners i and i+1 are in the second.
    shared = (first[:, :, None] == second[:, None, :]).any(axis=2)
    i = np.argmax(shared & np.roll(shared, -1, axis=1), axis=1)
    rows = np.arange(len(first))
    return np.stack([first[rows, i], w, first[rows, (i + 1) % 3], first[rows, (i + 2) % 3]], 1)


def _repair(cut: Dict[str, Any], bands: Sequence[Dict[str, np.ndarray]]) -> Dict[str, Any]:
    """Stage 3: a maximum matching of the bands and the cut edges replaces the bands' pairs.
    Checked: each new pair an edge of the graph, each triangle in one pair at most, the two
    triangles of each sharing an edge. O(band) plus the matching's cost."""
    clock = time.perf_counter()
    faces = np.concatenate([b["faces"] for b in bands])
    order = np.argsort(faces)
    faces = faces[order]
    triangles = np.concatenate([b["triangles"] for b in bands])[order]
    mates = np.concatenate([b["mates"] for b in bands])[order]
    edges = np.concatenate([b["edges"] for b in bands] + [cut["edges"]])
    ids = np.searchsorted(faces, edges)
    if not (faces[np.minimum(ids, len(faces) - 1)] == edges).all():
        raise RuntimeError("a cut edge's triangle is in no band")
    found = petersen.maximum_matching(len(faces), ids)
    pairs = np.sort(ids[found.edges], axis=1)
    used = np.bincount(pairs.ravel(), minlength=len(faces))
    if used.max(initial=0) > 1:
        raise RuntimeError("verification failed: a triangle in two pairs of the repair")
    quads = _quads_of(triangles[pairs[:, 0]], triangles[pairs[:, 1]])
    return {"faces": faces, "pairs": faces[pairs], "quads": quads,
            "left": faces[used == 0], "free_before": int((mates < 0).sum()),
            "pairs_before": int((mates >= 0).sum()) // 2, "nodes": len(faces),
            "edges": len(edges), "whole": all(b["whole"] for b in bands),
            "seconds": time.perf_counter() - clock}


def _plan(part: _Part, repair: Dict[str, Any]):
    """The part's output: its own pairs outside the band (first, second local ids), the repair's
    pairs whose first triangle is its (a mask of the repair's rows) and its triangles left.
    Verifies that every triangle of the part is in exactly one quad or left. O(part)."""
    m, lo = len(part.F), part.lo
    ids = np.arange(m)
    in_band = np.zeros(m, bool)
    in_band[repair["faces"] - lo] = True
    own = ~in_band & (part.mate > ids)
    first, second = ids[own], part.mate[own]
    pairs = repair["pairs"]
    mine = (pairs >= lo) & (pairs < lo + m)
    lefts = np.sort(np.concatenate([repair["left"] - lo, np.flatnonzero(~in_band & (part.mate < 0))]))
    cover = np.bincount(np.concatenate([first, second, pairs[mine] - lo, lefts]), minlength=m)
    if not (cover == 1).all():
        bad = np.flatnonzero(cover != 1)[0]
        raise RuntimeError(f"verification failed: triangle {lo + bad} is in {cover[bad]} faces")
    return first, second, mine[:, 0], lefts


def _part_counts(part: _Part, repair: Dict[str, Any]) -> Tuple[int, int]:
    """The quads and triangles this part writes."""
    first, _, theirs, lefts = _plan(part, repair)
    return len(first) + int(theirs.sum()), len(lefts)


def _write_part(part: _Part, repair: Dict[str, Any], out_tmp: str, offset: int) -> int:
    """Stage 4 on a worker: the part's faces, in input order, written at `offset` (uchar count,
    uint32 corners). Idempotent, so a retried write is harmless. Returns the bytes written."""
    first, second, theirs, lefts = _plan(part, repair)
    quads = np.concatenate([_quads_of(part.F[first], part.F[second]), repair["quads"][theirs]])
    heads = np.concatenate([first, repair["pairs"][theirs, 0] - part.lo])
    starts = np.concatenate([heads, lefts])
    sizes = np.concatenate([np.full(len(heads), 17), np.full(len(lefts), 13)])
    order = np.argsort(starts, kind="stable")
    at = np.zeros(len(order), np.int64)
    np.cumsum(sizes[order][:-1], out=at[1:]) if len(order) else None
    where = np.empty(len(order), np.int64)
    where[order] = at
    out = np.empty(int(sizes.sum()), np.uint8)
    for rows, k, base in ((quads, 4, where[: len(heads)]), (part.F[lefts], 3, where[len(heads):])):
        record = np.empty(len(rows), np.dtype([("n", "u1"), ("v", "<u4", (k,))]))
        record["n"], record["v"] = k, rows
        out[base[:, None] + np.arange(1 + 4 * k)] = record.view(np.uint8).reshape(-1, 1 + 4 * k)
    fd = os.open(out_tmp, os.O_WRONLY)
    try:
        os.pwrite(fd, out.tobytes(), offset)
    finally:
        os.close(fd)
    return len(out)


_OPTIONS = ("algorithm", "seed", "augment")


def _submit(client, fn, *args, retries: int):
    return client.submit(fn, *args, retries=retries, pure=False)


def _repair_for(repair: Dict[str, Any], lo: int, hi: int) -> Dict[str, Any]:
    """The rows of the repair that concern faces lo..hi-1: what one part's write needs."""
    def within(ids):
        return (ids >= lo) & (ids < hi)

    touching = within(repair["pairs"]).any(axis=1)
    return {"faces": repair["faces"][within(repair["faces"])], "pairs": repair["pairs"][touching],
            "quads": repair["quads"][touching], "left": repair["left"][within(repair["left"])]}


def _repair_figures(repair: Dict[str, Any]) -> Dict[str, Any]:
    return {k: v for k, v in repair.items() if np.isscalar(v)} | {"left": len(repair["left"])}


def _repair_rounds(client, parts, cut, face_count, rings: int, retries: int):
    """Stage 3, widened until a closed mesh's pairing is perfect (or the bands are the parts).
    The repair stays on its worker; the client gets its figures."""
    rounds = 0
    while True:
        rounds += 1
        bands = [_submit(client, _band, p, cut["spanning_nonmanifold"], rings, retries=retries)
                 for p in parts]
        repair = _submit(client, _repair, cut, bands, retries=retries)
        figures = _submit(client, _repair_figures, repair, retries=retries).result()
        closed = cut["boundary_edges"] == 0
        if not (closed and figures["left"] and not figures["whole"]):
            figures.update(rounds=rounds, rings=rings)
            return repair, figures
        rings = min(rings * 4, face_count)


def _write_output(client, layout, parts, bounds, repair, out_path, retries) -> Tuple[int, int]:
    """Stage 4: the header and vertex block by the client, each part's faces by its worker."""
    slices = [_submit(client, _repair_for, repair, int(bounds[i]), int(bounds[i + 1]),
                      retries=retries) for i in range(len(parts))]
    counts = client.gather([_submit(client, _part_counts, p, r, retries=retries)
                            for p, r in zip(parts, slices)])
    quads = sum(c[0] for c in counts)
    left = sum(c[1] for c in counts)
    header = ("ply\nformat binary_little_endian 1.0\ncomment written by petersen.distributed\n"
              + "\n".join(layout.vertex_header) + f"\nelement face {quads + left}\n"
              "property list uchar uint vertex_indices\nend_header\n").encode("ascii")
    vertex_bytes = layout.face_offset - layout.vertex_offset
    tmp = f"{out_path}.tmp-{os.getpid()}"
    try:
        with open(tmp, "wb") as out, open(layout.path, "rb") as src:
            out.write(header)
            out.flush()
            src.seek(layout.vertex_offset)
            copied = 0
            while copied < vertex_bytes:
                copied += os.copy_file_range(src.fileno(), out.fileno(), vertex_bytes - copied)
            out.truncate(len(header) + vertex_bytes + 17 * quads + 13 * left)
        offsets = np.cumsum([0] + [17 * q + 13 * t for q, t in counts])[:-1]
        offsets += len(header) + vertex_bytes
        client.gather([_submit(client, _write_part, p, r, tmp, int(o), retries=retries)
                       for p, r, o in zip(parts, slices, offsets)])
        os.replace(tmp, out_path)
    finally:
        if os.path.exists(tmp):
            os.remove(tmp)
    return quads, left


def _part_bounds(face_count: int, parts: Union[int, Sequence[int]]) -> np.ndarray:
    """The parts' first faces and the face count: `parts` even-sized ranges (a connected part of
    a closed mesh then pairs perfectly by itself), or the boundaries given."""
    if isinstance(parts, (int, np.integer)):
        bounds = np.linspace(0, face_count, max(1, int(parts)) + 1).astype(np.int64) // 2 * 2
        bounds[-1] = face_count
        return bounds
    bounds = np.asarray(parts, np.int64)
    if bounds.ndim != 1 or len(bounds) < 2 or bounds[0] != 0 or bounds[-1] != face_count or (
            np.diff(bounds) <= 0).any():
        raise ValueError(f"parts: boundaries rising from 0 to the face count {face_count}, "
                         f"not {parts}")
    return bounds


def quadrangulate(in_path: str, out_path: str, client: Any,
                  parts: Union[int, Sequence[int]] = 0, rings: int = 8,
                  retries: int = 3, **options: Any) -> Dict[str, Any]:
    """Pairs the triangles of the binary PLY ``in_path`` into quads on a Dask cluster and writes
    them to ``out_path`` (binary PLY, the input's vertex block unchanged, faces in input order:
    each quad where its first triangle was, left triangles as they were), as
    ``petersen.quadrangulate`` would. ``client`` is a ``distributed.Client``; the file must be at
    the same path on every worker. ``parts`` face ranges of even sizes (default: one per worker),
    or the ranges' boundaries ``[0, b1, ..., face count]``; ``rings`` the
    repair bands' first width, ``retries`` Dask's retries of each task; ``options`` those of
    ``petersen.quadrangulate`` that apply to parts: ``algorithm``, ``seed``, ``augment``.

    Returns the statistics: the keys of ``petersen.quadrangulate``'s that apply (``faces_in``,
    ``vertices``, ``triangles``, ``mesh_edges``, ``pairs``, ``triangles_left``,
    ``maximum_certified``, ``total_seconds``, ...) and the distributed figures (``parts``,
    ``part_cut_edges``, ``left_after_parts``, ``repair_*``, each stage's seconds).
    ``maximum_certified`` is True when every triangle is paired (checked); a mesh with boundary
    whose pairing leaves triangles gets no Tutte-Berge witness here (``petersen.quadrangulate``
    gives one). Raises ValueError naming the file and header line, or face, for input it cannot
    read, TypeError for an option parts do not take.
    """
    for key in options:
        if key not in _OPTIONS:
            raise TypeError(f"petersen.distributed.quadrangulate: option '{key}' is not one the "
                            f"parts take ({', '.join(_OPTIONS)})")
    clock = time.perf_counter()
    figures: Dict[str, Any] = {}
    layout = read_layout(in_path)
    bounds = _part_bounds(layout.face_count, parts or len(client.scheduler_info()["workers"]))
    parts = len(bounds) - 1
    lap = time.perf_counter()
    part_futures = [_submit(client, _pair_part, layout, i, int(bounds[i]), int(bounds[i + 1]),
                            options, retries=retries) for i in range(parts)]
    cut = _submit(client, _cut, [_submit(client, _cut_inputs, p, retries=retries)
                                 for p in part_futures], retries=retries).result()
    figures["parts_seconds"] = time.perf_counter() - lap
    lap = time.perf_counter()
    repair, repaired = _repair_rounds(client, part_futures, cut, layout.face_count, rings,
                                      retries)
    figures["repair_seconds"] = time.perf_counter() - lap
    lap = time.perf_counter()
    quads, left = _write_output(client, layout, part_futures, bounds, repair, out_path, retries)
    figures["write_seconds"] = time.perf_counter() - lap
    per_part = cut["figures"]
    interior = sum(f["interior_edges"] for f in per_part)
    if quads * 2 + left != layout.face_count:
        raise RuntimeError("verification failed: the parts' faces do not add up to the input's")
    stats = {
        "objective": "pairs", "algorithm": options.get("algorithm", "auto"),
        "augment": options.get("augment", "local"), "vertices": layout.vertex_count,
        "faces_in": layout.face_count, "triangles": layout.face_count, "polygons_kept": 0,
        "mesh_edges": interior + cut["record_edges"],
        "maximum_certified": left == 0, "pairs": quads, "triangles_left": left,
        "added_vertices": 0, "parts": parts, "part_cut_edges": len(cut["edges"]),
        "boundary_edges": cut["boundary_edges"],
        "spanning_nonmanifold_edges": len(cut["spanning_nonmanifold"]),
        "left_after_parts": sum(f["left"] for f in per_part),
        "moved_to_frontier": sum(f["moved_to_frontier"] for f in per_part),
        "part_seconds_max": max(f["seconds"] for f in per_part),
        "repair_rounds": repaired["rounds"], "repair_rings": repaired["rings"],
        "repair_nodes": repaired["nodes"], "repair_edges": repaired["edges"],
        "repair_free_before": repaired["free_before"], "repair_left": repaired["left"],
        "repair_matching_seconds": repaired["seconds"],
    }
    stats.update(figures)
    stats["total_seconds"] = time.perf_counter() - clock
    return stats
