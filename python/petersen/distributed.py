"""petersen.distributed: a binary PLY triangle mesh quadrangulated on a Dask cluster, in parts.

    >>> from distributed import Client
    >>> import petersen.distributed
    >>> stats = petersen.distributed.quadrangulate("in.ply", "out.ply", Client(), parts=8)

The stages (docs/dask.md), each the library's step of petersen/partition/partition.hpp:

1. **Parts** (``pair_part``). The client reads the PLY header once and gives each task a
   contiguous range of faces; the worker reads its own range from the file (a shared path),
   pairs it by a certified maximum pairing of the part's pairable graph, moves the triangles it
   left unpaired along alternating paths to the part's border, and keeps the part on the worker.
   It sends on its open-edge records (an edge with one triangle in the part: vertex pair,
   triangle, third corner) and its band (the triangles near the open edges, with their partners).
2. **Cut** (``pair_open_edges``). One task pairs the records by vertex pair: the pairable
   adjacencies across the cuts, and whether the mesh is closed.
3. **Repair** (``repair_cuts``). One task joins the bands and the cut adjacencies and pairs the
   triangles the parts left by augmenting paths there. On a closed mesh a triangle still
   unpaired means the bands were too narrow: the parts run again with bands four times as wide,
   until a band is its whole part.
4. **Write.** Each part checks its own triangles (each pair names its partner back, the two
   triangles of each quad share an edge) and writes its faces into the output at offsets the
   client computed; the client copies the vertex block unchanged and renames the temporary file
   into place when every part has written.

With ``all_quad`` the write is the all-quad steps of petersen/partition/all_quad.hpp, as out of
core runs them: each part's output faces and their parity on its worker (``part_parity``), the
seam graph once (``split_seams``), each part's plan as a chain in part order, each given the cut
midpoints of the parts before it (``plan_part_all_quad``), then the header with the exact counts,
the input's vertex block, the added vertices' records (``blended_records``) and each part's quads
(``part_all_quads``) at offsets the client computes.

Only small arrays move between tasks (records, bands, the repair's partners); the parts'
triangles and partners stay on their workers. Retries are Dask's: every task is submitted with
``retries``, and a task whose worker died is run again by the scheduler (from the file), as is
any part whose result was lost with its worker.
"""

from __future__ import annotations

import math
import os
import time
from dataclasses import dataclass
from typing import Any, Dict, Optional, Sequence, Tuple, Union

import numpy as np

from . import _degrees, _number, _petersen

__all__ = ["PlyLayout", "read_layout", "quadrangulate"]

@dataclass(frozen=True)
class PlyLayout:
    """Where a binary little-endian triangle PLY keeps its vertices and faces, as the library's
    PLY header reader (petersen/io/ply_stream.hpp) found them: what the client needs to split the
    faces into parts and to copy the vertex block into the output."""

    path: str
    vertex_count: int
    face_count: int
    vertex_offset: int
    face_offset: int
    #: The vertex element's header lines, copied into the output's header.
    vertex_header: Tuple[str, ...]


def read_layout(path: str) -> PlyLayout:
    """Reads the header of a binary little-endian PLY whose faces are triangles (a vertex element
    of scalar properties with x, y and z, then a face element of one list with 32-bit indices).
    Raises ValueError naming the file and header line for any other file, and for a file shorter
    than its header says. O(header)."""
    layout = _petersen.ply_triangle_layout(str(path))
    return PlyLayout(path=str(path), vertex_count=layout["vertex_count"],
                     face_count=layout["face_count"], vertex_offset=layout["vertex_offset"],
                     face_offset=layout["face_offset"],
                     vertex_header=tuple(layout["vertex_declaration"].splitlines()))


def _read_faces(layout: PlyLayout, lo: int, hi: int) -> np.ndarray:
    """Faces lo..hi-1 as an (hi - lo, 3) int64 array of vertex ids; ValueError naming the face for
    one that is not a triangle or has a vertex out of range."""
    return _petersen.read_triangles(layout.path, lo, hi)


def _corner_positions(layout: PlyLayout, F: np.ndarray) -> np.ndarray:
    """The positions of the corners of faces F ((m, k) vertex ids), (m, k, 3) float64, as the
    in-memory reader gives them: only the vertex records F names are read."""
    return _petersen.read_corner_positions(layout.path, F)


@dataclass
class _Part:
    """A part as its worker keeps it between the stages (petersen/partition/partition.hpp)."""

    lo: int
    F: np.ndarray  # (m, 3) global vertex ids
    partner: np.ndarray  # per triangle, its partner's global face id, -1 when unpaired
    open_edges: np.ndarray  # (r, 4): low, high, face, apex
    #: objective pairs: its band (faces, corners, sides, distance, partner); the cost objectives:
    #: its seam (faces, corners, positions, paired, dual)
    band: Dict[str, np.ndarray]
    figures: Dict[str, Any]


def _pair_part(layout: PlyLayout, lo: int, hi: int, augment: str, band_radius: int) -> _Part:
    """Stage 1 on a worker: reads faces lo..hi-1 and pairs them (pair_part: a certified maximum
    pairing of the part, its unpaired triangles moved to the border, its open edges and band)."""
    F = _read_faces(layout, lo, hi)
    r = _petersen.pair_part(lo, F, augment, band_radius, 1)
    figures = {k: r[k] for k in ("pairs", "moved_to_border", "stranded", "maximum_certified",
                                 "inner_structural_cuts", "seconds")}
    figures["unpaired"] = len(r["unpaired"])
    figures["band_faces"] = len(r["band"]["faces"])
    figures["whole"] = figures["band_faces"] == len(F)
    return _Part(lo, F, r["partner"], r["open_edges"], r["band"], figures)


def _pair_part_at_cost(layout: PlyLayout, lo: int, hi: int, band_radius: int,
                       costs: Dict[str, Any]) -> _Part:
    """Stage 1 of the cost objectives on a worker: reads faces lo..hi-1 and their corners'
    positions and pairs them by the minimum-cost matching of quadrangulate (pair_part), its
    certificate checked; keeps its band (band_radius steps from its open sides) for stage 3."""
    F = _read_faces(layout, lo, hi)
    r = _petersen.pair_part(lo, F, "local", band_radius, 1, positions=_corner_positions(layout, F),
                            **costs)
    figures = {k: r[k] for k in ("pairs", "maximum_certified", "optimality_certified",
                                 "objective_units", "inner_structural_cuts", "seconds")}
    figures["unpaired"] = len(r["unpaired"])
    figures["band_faces"] = len(r["seam"]["faces"])
    return _Part(lo, F, r["partner"], r["open_edges"], r["seam"], figures)


def _open_edges(part: _Part) -> Dict[str, Any]:
    """What stage 1 sends to the cut: the open-edge records and the figures (small)."""
    return {"open_edges": part.open_edges, "figures": part.figures}


def _band(part: _Part) -> Dict[str, np.ndarray]:
    return part.band


def _cut(inputs: Sequence[Dict[str, Any]]) -> Dict[str, Any]:
    """Stage 2: the open edges of every part paired by vertex key (pair_open_edges)."""
    cut = _petersen.pair_open_edges(np.concatenate([i["open_edges"] for i in inputs]))
    cut["figures"] = [i["figures"] for i in inputs]
    return cut


def _cut_figures(cut: Dict[str, Any]) -> Dict[str, Any]:
    figures = {k: v for k, v in cut.items() if k != "adjacencies"}
    figures["adjacencies"] = len(cut["adjacencies"])
    return figures


def _checked_partners(faces: np.ndarray, corners: np.ndarray, partner: np.ndarray,
                      figures: Dict[str, Any], step: str) -> Dict[str, Any]:
    """The band faces' new partners, checked to name each other back, with each partner's corners
    where the partner is a band face (a quad across a cut needs them): what the write stage
    reads of stage 3."""
    order = np.argsort(faces)
    at = np.searchsorted(faces, partner, sorter=order)
    at = order[np.minimum(at, len(faces) - 1)]
    inside = (partner >= 0) & (faces[at] == partner)
    if (partner[at[inside]] != faces[inside]).any():
        bad = np.flatnonzero(inside & (partner[at] != faces))[0]
        raise RuntimeError(f"verification failed: the {step} paired triangle {faces[bad]} with "
                           f"{partner[bad]}, which is paired with {partner[at[bad]]}")
    partner_corners = np.where(inside[:, None], corners[at], -1)
    return {"faces": faces, "partner": partner, "partner_corners": partner_corners,
            "figures": figures}


def _repair(cut: Dict[str, Any], bands: Sequence[Dict[str, np.ndarray]], augment: str,
            first_radius: int) -> Dict[str, Any]:
    """Stage 3: augmenting paths in the bands and the cut adjacencies (repair_cuts), checked by
    _checked_partners."""
    band = {k: np.concatenate([b[k] for b in bands]) for k in bands[0]}
    r = _petersen.repair_cuts(band["faces"], band["corners"], band["sides"], band["distance"],
                              band["partner"], cut["adjacencies"], augment, first_radius)
    figures = {k: v for k, v in r.items() if k != "partner"}
    return _checked_partners(band["faces"], band["corners"], r["partner"], figures, "repair")


def _seams(cut: Dict[str, Any], seams: Sequence[Dict[str, np.ndarray]],
           costs: Dict[str, Any]) -> Dict[str, Any]:
    """Stage 3 of the cost objectives: the parts' bands and the cut adjacencies paired again by a
    minimum-cost matching, and the parts' duals stitched into a lower bound (pair_seams); checked
    by _checked_partners."""
    seam = {k: np.concatenate([s[k] for s in seams]) for k in seams[0]}
    units = sum(f["objective_units"] for f in cut["figures"])
    r = _petersen.pair_seams(seam["faces"], seam["corners"], seam["positions"], seam["sides"],
                             seam["distance"], seam["partner"], seam["dual"], seam["price"],
                             seam["stay_dual"], cut["adjacencies"], units, **costs)
    figures = {k: v for k, v in r.items() if k != "partner"}
    return _checked_partners(seam["faces"], seam["corners"], r["partner"], figures, "seam step")


def _repair_for(repair: Dict[str, Any], lo: int, hi: int) -> Dict[str, Any]:
    """The rows of the repair on faces lo..hi-1: what one part's write needs."""
    mine = (repair["faces"] >= lo) & (repair["faces"] < hi)
    return {k: repair[k][mine] for k in ("faces", "partner", "partner_corners")}


def _repair_figures(repair: Dict[str, Any]) -> Dict[str, Any]:
    return repair["figures"]


def _plan(part: _Part, repair: Dict[str, Any]) -> Dict[str, np.ndarray]:
    """The part's output, kept on its worker for the write: the quad of each pair whose first
    triangle is the part's (ascending by that triangle) and the triangles left (local ids,
    ascending). Verifies, from the partners alone, that every triangle of
    the part is in exactly one quad or left: each pair inside the part names its partner back
    (the repair checked those across cuts). O(part)."""
    m, lo = len(part.F), part.lo
    partner = part.partner.copy()
    partner[repair["faces"] - lo] = repair["partner"]
    ids = np.arange(m)
    inside = (partner >= lo) & (partner < lo + m)
    back = partner[np.where(inside, partner - lo, 0)]
    if (inside & (back != ids + lo)).any():
        bad = np.flatnonzero(inside & (back != ids + lo))[0]
        raise RuntimeError(f"verification failed: triangle {lo + bad} is paired with "
                           f"{partner[bad]}, which is paired with {back[bad]}")
    if ((partner == ids + lo)).any():
        raise RuntimeError("verification failed: a triangle paired with itself")
    first = np.flatnonzero(partner > ids + lo)
    corners = np.empty((len(first), 3), np.int64)
    local = inside[first]
    corners[local] = part.F[partner[first[local]] - lo]
    across = np.searchsorted(repair["faces"], first[~local] + lo)
    if len(across) and not (repair["faces"][np.minimum(across, len(repair["faces"]) - 1)]
                            == first[~local] + lo).all():
        raise RuntimeError("verification failed: a pair across a cut the repair did not make")
    corners[~local] = repair["partner_corners"][across]
    return {"heads": first, "quads": _petersen.quads_of_pairs(part.F[first], corners),
            "lefts": np.flatnonzero(partner < 0)}


def _plan_counts(plan: Dict[str, np.ndarray]) -> Tuple[int, int]:
    """The quads and triangles a part writes."""
    return len(plan["heads"]), len(plan["lefts"])


def _face_bytes(corners: np.ndarray) -> bytes:
    """Faces of k corners as PLY records: a uchar k, then k little-endian uint32."""
    k = corners.shape[1]
    record = np.empty(len(corners), np.dtype([("n", "u1"), ("v", "<u4", (k,))]))
    record["n"], record["v"] = k, corners
    return record.tobytes()


def _write_part(part: _Part, plan: Dict[str, np.ndarray], out_tmp: str, offset: int) -> int:
    """Stage 4 on a worker: the part's faces in input order (each quad at its first triangle,
    each left triangle at its place), written at `offset`. The quads between two left triangles
    are one run of records, so the cost is O(part) plus O(1) per left triangle. Idempotent: a
    retried write writes the same bytes. Returns the bytes written."""
    quads, lefts = plan["quads"], plan["lefts"]
    before = np.searchsorted(plan["heads"], lefts)
    pieces, done = [], 0
    for left, quads_before in zip(lefts, before):
        pieces += [_face_bytes(quads[done:quads_before]), _face_bytes(part.F[left:left + 1])]
        done = quads_before
    pieces.append(_face_bytes(quads[done:]))
    return _pwrite(b"".join(pieces), out_tmp, offset)


def _pwrite(data, out_tmp: str, offset: int) -> int:
    """`data` written into `out_tmp` at `offset` (idempotent). Returns the bytes written."""
    fd = os.open(out_tmp, os.O_WRONLY)
    try:
        os.pwrite(fd, data, offset)
    finally:
        os.close(fd)
    return len(data)


# The written quads' worst corners as `petersen quad --memory-limit` counts them
# (partition/src/quality_histogram.hpp): per 1/1024 degree, 0 to 270, summed over the parts.
_QUALITY_BINS_PER_DEGREE = 1024
_QUALITY_BINS = 270 * _QUALITY_BINS_PER_DEGREE + 1


def _quality_counts(layout: PlyLayout, plan: Dict[str, np.ndarray]) -> Tuple[np.ndarray, int]:
    """On a part's worker: its quads' worst corners (petersen.quad_quality) counted per bin,
    and how many are non-convex (over 90 degrees). O(part) besides the positions' reads."""
    quads = plan["quads"]
    if len(quads) == 0:
        return np.zeros(_QUALITY_BINS, np.int64), 0
    corners = _corner_positions(layout, quads).reshape(-1, 3)
    cost = _petersen.quad_quality(corners, np.arange(len(corners), dtype=np.int64).reshape(-1, 4))
    clamped = np.clip(np.nan_to_num(cost, nan=270.0), 0, 270)  # as out of core: NaN the worst
    bins = np.floor(clamped * _QUALITY_BINS_PER_DEGREE).astype(np.int64)
    return np.bincount(bins, minlength=_QUALITY_BINS), int((cost > 90).sum())


def _quality(client, layout, plans, retries) -> Dict[str, Any]:
    """The output's quality keys from the parts' counts: the median and 95th percentile by nearest
    rank over the binned costs (as out of core: within 0.001 degree below the exact figures), the
    non-convex count exact."""
    counts = client.gather([_submit(client, _quality_counts, layout, plan, retries=retries)
                            for plan in plans])
    total = np.sum([c[0] for c in counts], axis=0)
    cumulative = np.cumsum(total)
    quads = int(cumulative[-1])

    def rank(p):
        if quads == 0:
            return 0.0
        k = max(1, math.ceil(p * quads))
        return float(np.searchsorted(cumulative, k)) / _QUALITY_BINS_PER_DEGREE

    return {"quality_median": rank(0.5), "quality_p95": rank(0.95),
            "nonconvex_quads": sum(c[1] for c in counts)}


def _mixed_face_bytes(corners: np.ndarray, arity: np.ndarray) -> bytes:
    """Faces of 3 or 4 corners (flat corners, one arity per face) as PLY records. O(corners)."""
    if (arity == 4).all():
        return _face_bytes(corners.reshape(-1, 4))
    size = 1 + 4 * arity.astype(np.int64)
    start = np.cumsum(size) - size
    out = np.empty(int(size.sum()), np.uint8)
    out[start] = arity
    face_of = np.repeat(np.arange(len(arity)), arity)
    first_corner = np.cumsum(arity.astype(np.int64)) - arity
    at = start[face_of] + 1 + 4 * (np.arange(len(corners)) - first_corner[face_of])
    out[at[:, None] + np.arange(4)] = corners.astype("<u4").view(np.uint8).reshape(-1, 4)
    return out.tobytes()


# All quads part by part (all_quad.hpp), after the pairing, on the parts' workers.

def _all_quad_faces(part: _Part, plan: Dict[str, np.ndarray]) -> Dict[str, np.ndarray]:
    """The part's output faces as all_quad.hpp's PartFaces: each quad at its first triangle and
    each triangle left at its place, in face order (as the plain write stage writes them), as
    flat corners and arities. Kept on the worker for the all-quad stages. O(part)."""
    heads, quads, lefts = plan["heads"], plan["quads"], plan["lefts"]
    rows = np.full((len(heads) + len(lefts), 4), -1, np.int64)
    rows[:len(heads)] = quads
    rows[len(heads):, :3] = part.F[lefts]
    rows = rows[np.argsort(np.concatenate([heads, lefts]), kind="stable")]
    return {"corners": rows[rows >= 0], "arity": np.where(rows[:, 3] >= 0, 4, 3).astype(np.uint8)}


def _parity(faces: Dict[str, np.ndarray]) -> Dict[str, Any]:
    """All-quad step 1 on a part's worker (part_parity): its open edges and components' parity."""
    return _petersen.part_parity(faces["corners"], faces["arity"])


def _split_seams(parities: Sequence[Dict[str, Any]]) -> Dict[str, Any]:
    """All-quad step 2, once (split_seams): the seam graph of every part's open edges."""
    seams = _petersen.split_seams([p["border"] for p in parities],
                                  [p["component_odd"] for p in parities])
    seams["kept_faces"] = sum(p["kept_faces"] for p in parities)
    return seams


def _seams_figures(seams: Dict[str, Any]) -> Dict[str, int]:
    return {k: seams[k] for k in ("cut_edges", "boundary_edges", "whole_edges", "kept_faces")}


_NO_EDGES = np.zeros((0, 2), np.int64)


def _plan_all_quad(path: str, faces: Dict[str, np.ndarray], index: int, seams: Dict[str, Any],
                   earlier: Optional[np.ndarray], objective: str,
                   keep_polygons: bool) -> Dict[str, Any]:
    """All-quad step 3 for part `index` (plan_part_all_quad), given the cut midpoints the parts
    before it chose (ascending): its T-join and cut. Adds `cut_so_far`, the cut midpoints of the
    parts up to this one, ascending: what the next part's plan needs."""
    earlier = _NO_EDGES if earlier is None else earlier
    plan = _petersen.plan_part_all_quad(path, faces["corners"], faces["arity"], index,
                                        seams["edges"], seams["node_start"], seams["node_odd"],
                                        earlier, objective, keep_polygons, 1)
    both = np.concatenate([earlier, plan["cut_midpoints"]])
    plan["cut_so_far"] = both[np.lexsort((both[:, 1], both[:, 0]))]
    return plan


def _cut_so_far(plan: Dict[str, Any]) -> np.ndarray:
    return plan["cut_so_far"]


def _merge_plans(plans: Sequence[Dict[str, Any]]) -> Dict[str, Any]:
    """Every part's midpoints, ascending and once each (the output's vertices after the input's),
    and the figures: per part its faces, centres and certificate; the split pieces' quality."""
    edges = np.concatenate([p["midpoints"] for p in plans])
    midpoints = np.unique(edges, axis=0) if len(edges) else _NO_EDGES
    median, p95 = _petersen.split_quality_figures(
        np.concatenate([p["split_quality"] for p in plans]))
    return {"midpoints": midpoints, "figures": {
        "split_edges": len(midpoints), "faces": [int(p["faces"]) for p in plans],
        "centres": [len(p["centre_corners"]) for p in plans],
        "certified": [bool(p["certified"]) for p in plans],
        "split_quads": int(sum(len(p["split_quality"]) for p in plans)),
        "split_quality_median": median, "split_quality_p95": p95}}


def _merged_figures(merged: Dict[str, Any]) -> Dict[str, Any]:
    return merged["figures"]


def _write_added(path: str, merged: Dict[str, Any], plans: Sequence[Dict[str, Any]],
                 out_tmp: str, offset: int) -> int:
    """The records of the added vertices, blended from the input's (blended_records: each
    midpoint's two ends, then each part's centres in part order), written at `offset`."""
    centres = np.concatenate([p["centre_corners"] for p in plans]).reshape(-1, 4)
    return _pwrite(_petersen.blended_records(path, merged["midpoints"], centres), out_tmp, offset)


def _all_quads(path: str, faces: Dict[str, np.ndarray], merged: Dict[str, Any],
               vertex_count: int, first_centre: int, objective: str,
               keep_polygons: bool) -> Dict[str, Any]:
    """All-quad step 4 on a part's worker (part_all_quads): its faces cut into quads over the
    output's vertex ids, as PLY face records kept for the write, with their counts."""
    corners, arity = _petersen.part_all_quads(path, faces["corners"], faces["arity"],
                                              merged["midpoints"], vertex_count, first_centre,
                                              objective, keep_polygons, 1)
    return {"records": _mixed_face_bytes(corners, arity), "faces": len(arity),
            "triangles": int((arity == 3).sum())}


def _records_counts(records: Dict[str, Any]) -> Tuple[int, int, int]:
    return len(records["records"]), records["faces"], records["triangles"]


def _write_records(records: Dict[str, Any], out_tmp: str, offset: int) -> int:
    return _pwrite(records["records"], out_tmp, offset)


def _write_all_quad(client, layout, parts, bounds, repair, out_path, retries, objective,
                    keep_polygons) -> Tuple[int, int, Dict[str, Any]]:
    """The all-quad stages and the write: each part's output faces and parity on its worker,
    the seams once, the plans as a chain in part order (each given the cut midpoints of the parts
    before it), then the header with the exact counts, the input's vertex block, the added
    vertices' records and each part's quads at offsets the client computes. Returns the pairing's
    quads and triangles left and the all-quad figures."""
    plans, counts = _plans(client, parts, bounds, repair, retries)
    quality = _quality(client, layout, plans, retries)
    faces = [_submit(client, _all_quad_faces, p, plan, retries=retries)
             for p, plan in zip(parts, plans)]
    seams = _submit(client, _split_seams,
                    [_submit(client, _parity, f, retries=retries) for f in faces],
                    retries=retries)
    split, earlier = [], None
    for index, f in enumerate(faces):
        split.append(_submit(client, _plan_all_quad, layout.path, f, index, seams, earlier,
                             objective, keep_polygons, retries=retries))
        earlier = _submit(client, _cut_so_far, split[-1], retries=retries)
    merged = _submit(client, _merge_plans, split, retries=retries)
    figures = _submit(client, _merged_figures, merged, retries=retries).result()
    figures.update(_submit(client, _seams_figures, seams, retries=retries).result())
    added = figures["split_edges"] + sum(figures["centres"])
    vertices = layout.vertex_count + added
    if vertices >= 0xFFFFFFFF:
        raise ValueError(f"all_quad: {vertices} vertices; vertex ids are 32-bit")
    first_centre = np.cumsum([0] + figures["centres"])[:-1] + layout.vertex_count + \
        figures["split_edges"]
    records = [_submit(client, _all_quads, layout.path, f, merged, layout.vertex_count, int(c),
                       objective, keep_polygons, retries=retries)
               for f, c in zip(faces, first_centre)]
    sizes = client.gather([_submit(client, _records_counts, r, retries=retries)
                           for r in records])
    faces_out = sum(s[1] for s in sizes)
    if faces_out != sum(figures["faces"]):
        raise RuntimeError(f"verification failed: the parts wrote {faces_out} faces, their plans "
                           f"counted {sum(figures['faces'])}")
    record_bytes = (layout.face_offset - layout.vertex_offset) // max(1, layout.vertex_count)
    tmp = f"{out_path}.tmp-{os.getpid()}"
    try:
        start = _start_output(layout, tmp, vertices, faces_out,
                              added * record_bytes + sum(s[0] for s in sizes))
        offsets = np.cumsum([0] + [s[0] for s in sizes])[:-1] + start + added * record_bytes
        written = [_submit(client, _write_added, layout.path, merged, split, tmp, start,
                           retries=retries)]
        written += [_submit(client, _write_records, r, tmp, int(o), retries=retries)
                    for r, o in zip(records, offsets)]
        if client.gather(written)[0] != added * record_bytes:
            raise RuntimeError("verification failed: the added vertices' records are not "
                               f"{added} of {record_bytes} bytes")
        os.replace(tmp, out_path)
    finally:
        if os.path.exists(tmp):
            os.remove(tmp)
    figures.update(faces_out=faces_out, added_vertices=added,
                   kept_triangles=sum(s[2] for s in sizes), quality=quality)
    return sum(c[0] for c in counts), sum(c[1] for c in counts), figures


def _all_quad_stats(stats: Dict[str, Any], figures: Dict[str, Any], seconds: float) -> None:
    """The all-quad keys of `petersen quad --memory-limit --all-quad --stats-json`:
    ``all_quad_certified`` is False as there, since each part's T-join is minimal for its own
    parity only (``all_quad_parts_certified``); the whole mesh's minimum is not proved."""
    stats.update({
        "added_vertices": figures["added_vertices"], "split_edges": figures["split_edges"],
        "degenerate_faces": figures["kept_faces"], "centre_vertices": sum(figures["centres"]),
        "all_quad_certified": False, "all_quad_parts_certified": all(figures["certified"]),
        "all_quad_parts": len(figures["faces"]), "split_quads": figures["split_quads"],
        "split_quality_median": figures["split_quality_median"],
        "split_quality_p95": figures["split_quality_p95"], "faces_out": figures["faces_out"],
        "seam_cut_edges": figures["cut_edges"], "all_quad_seconds": seconds,
    })


_OPTIONS = ("augment", "objective", "triangle_cost", "max_corner_deviation", "sharp_angle",
            "all_quad", "keep_polygons")


def _costs_of(options: Dict[str, Any]) -> Dict[str, Any]:
    """The objective and its costs, as pair_part and pair_seams take them; TypeError for an option
    the objective does not use."""
    objective = options.get("objective", "quads")
    if objective not in ("quads", "quality", "pairs"):
        raise ValueError(f"unknown objective '{objective}': quads, quality or pairs")
    if options.get("all_quad") and "triangle_cost" in options:
        raise TypeError("petersen.distributed.quadrangulate: option 'triangle_cost' does not go "
                        "with all_quad: every triangle left is split into quads, so the parts "
                        "pair the cheapest maximum, which prices no triangle")
    refused = {
        "triangle_cost": objective != "quads",
        "max_corner_deviation": objective == "pairs", "sharp_angle": objective == "pairs",
        "augment": objective != "pairs",
    }
    for key, no in refused.items():
        if no and key in options:
            raise TypeError(f"petersen.distributed.quadrangulate: option '{key}' does not go with "
                            f"objective {objective}: the parts pair by "
                            + ("the maximum matching, measuring no quad" if objective == "pairs"
                               else "the minimum-cost matching"))
    costs: Dict[str, Any] = {"objective": objective}
    if "triangle_cost" in options:
        costs["triangle_cost"] = _number("triangle_cost", options["triangle_cost"], 10000.0)
    for key, high in (("max_corner_deviation", 270.0), ("sharp_angle", 180.0)):
        if key in options:
            costs[key] = _degrees(key, options[key], high)
    return costs


def _submit(client, fn, *args, retries: int):
    return client.submit(fn, *args, retries=retries, pure=False)


def _pair_and_repair(client, layout, bounds, augment, band_radius, first_radius, retries):
    """Stages 1 to 3; on a closed mesh left imperfect, stage 1 again with bands four times as
    wide, until a band is its whole part (the repair is then the whole mesh's augmentation)."""
    rounds = 0
    while True:
        rounds += 1
        clock = time.perf_counter()
        parts = [_submit(client, _pair_part, layout, int(lo), int(hi), augment, band_radius,
                         retries=retries) for lo, hi in zip(bounds[:-1], bounds[1:])]
        cut = _submit(client, _cut, [_submit(client, _open_edges, p, retries=retries)
                                     for p in parts], retries=retries)
        cut_figures = _submit(client, _cut_figures, cut, retries=retries).result()
        parts_seconds = time.perf_counter() - clock
        clock = time.perf_counter()
        bands = [_submit(client, _band, p, retries=retries) for p in parts]
        repair = _submit(client, _repair, cut, bands, augment, first_radius, retries=retries)
        repaired = _submit(client, _repair_figures, repair, retries=retries).result()
        repaired.update(rounds=rounds, band_radius=band_radius, parts_seconds=parts_seconds,
                        repair_seconds=time.perf_counter() - clock)
        whole = all(f["whole"] for f in cut_figures["figures"])
        if not (cut_figures["closed"] and repaired["unpaired_after"] and not whole):
            return parts, cut_figures, repaired, repair
        band_radius *= 4


def _pair_and_seam(client, layout, bounds, band_radius, costs, retries):
    """Stages 1 to 3 of the cost objectives: each part alone, then the seams."""
    clock = time.perf_counter()
    parts = [_submit(client, _pair_part_at_cost, layout, int(lo), int(hi), band_radius, costs,
                     retries=retries) for lo, hi in zip(bounds[:-1], bounds[1:])]
    cut = _submit(client, _cut, [_submit(client, _open_edges, p, retries=retries)
                                 for p in parts], retries=retries)
    cut_figures = _submit(client, _cut_figures, cut, retries=retries).result()
    parts_seconds = time.perf_counter() - clock
    clock = time.perf_counter()
    seams = [_submit(client, _band, p, retries=retries) for p in parts]
    seam = _submit(client, _seams, cut, seams, costs, retries=retries)
    figures = _submit(client, _repair_figures, seam, retries=retries).result()
    figures.update(parts_seconds=parts_seconds, seam_seconds=time.perf_counter() - clock)
    return parts, cut_figures, figures, seam


def _cost_stats(costs, layout, bounds, cut, seamed, quads, left) -> Dict[str, Any]:
    """The figures of a cost objective's run: petersen.quadrangulate's keys where they mean the
    same, the lower bound and gap (objective quads), the parts' and the seams' own."""
    per_part = cut["figures"]
    objective = costs["objective"]
    stats: Dict[str, Any] = {"objective": objective, "algorithm": "min-cost"}
    if objective == "quads":
        stats["triangle_cost"] = seamed["triangle_cost"]
        stats["flow_weight"] = 0.0  # shape alone: flow_weight is refused on parts
    for key in ("max_corner_deviation", "sharp_angle"):
        if key in costs:
            stats[key] = costs[key]
    costs_certified = seamed["certified"] and all(f["optimality_certified"] for f in per_part)
    stats.update({
        "vertices": layout.vertex_count, "faces_in": layout.face_count,
        "triangles": layout.face_count, "polygons_kept": 0, "maximum_certified": left == 0,
        "pairs": quads, "triangles_left": left, "added_vertices": 0,
        "objective_total": seamed["objective_total"], "costs_certified": costs_certified,
    })
    if objective == "quads":
        gap = max(0.0, seamed["objective_total"] - seamed["lower_bound"])
        stats.update({"lower_bound": seamed["lower_bound"], "gap": gap,
                      "gap_relative": gap / seamed["objective_total"]
                      if seamed["objective_total"] > 0 else 0.0})
    stats["optimality_certified"] = bool(costs_certified and objective == "quads"
                                         and seamed["optimality_certified"])
    stats.update({
        "parts": len(bounds) - 1, "part_cut_edges": cut["adjacencies"],
        "boundary_edges": cut["boundary_edges"], "non_manifold_edges": cut["non_manifold_edges"],
        "duplicate_edges": cut["duplicate_edges"],
        "parts_certified": all(f["optimality_certified"] for f in per_part),
        "unpaired_after_parts": sum(f["unpaired"] for f in per_part),
        "band_faces": sum(f["band_faces"] for f in per_part),
        "seam_pairs": seamed["pairs_across"], "seam_graph_faces": seamed["seam_graph_faces"],
        "part_seconds_max": max(f["seconds"] for f in per_part),
        "seam_matching_seconds": seamed["seconds"],
        "parts_seconds": seamed["parts_seconds"], "seam_seconds": seamed["seam_seconds"],
    })
    return stats


def _plans(client, parts, bounds, repair, retries):
    """Each part's output as _plan makes it (kept on its worker) and its (quads, triangles)."""
    slices = [_submit(client, _repair_for, repair, int(bounds[i]), int(bounds[i + 1]),
                      retries=retries) for i in range(len(parts))]
    plans = [_submit(client, _plan, p, r, retries=retries) for p, r in zip(parts, slices)]
    counts = client.gather([_submit(client, _plan_counts, p, retries=retries) for p in plans])
    return plans, counts


def _start_output(layout: PlyLayout, tmp: str, vertex_count: int, face_count: int,
                  size_after_vertices: int) -> int:
    """The header (the input's vertex element with `vertex_count` vertices, then `face_count`
    faces) and the input's vertex block copied into `tmp`, sized for `size_after_vertices` more
    bytes. Returns where the input's vertex block ends in `tmp`."""
    lines = list(layout.vertex_header)
    lines[0] = f"element vertex {vertex_count}"
    header = ("ply\nformat binary_little_endian 1.0\ncomment written by petersen.distributed\n"
              + "\n".join(lines) + f"\nelement face {face_count}\n"
              "property list uchar uint vertex_indices\nend_header\n").encode("ascii")
    vertex_bytes = layout.face_offset - layout.vertex_offset
    with open(tmp, "wb") as out, open(layout.path, "rb") as src:
        out.write(header)
        out.flush()
        src.seek(layout.vertex_offset)
        copied = 0
        while copied < vertex_bytes:
            copied += os.copy_file_range(src.fileno(), out.fileno(), vertex_bytes - copied)
        out.truncate(len(header) + vertex_bytes + size_after_vertices)
    return len(header) + vertex_bytes


def _write_output(client, layout, parts, bounds, repair, out_path, retries
                  ) -> Tuple[int, int, Dict[str, Any]]:
    """Stage 4: the header and vertex block by the client, each part's faces by its worker.
    Returns the quads, the triangles left and the quads' quality keys."""
    plans, counts = _plans(client, parts, bounds, repair, retries)
    quality = _quality(client, layout, plans, retries)
    quads = sum(c[0] for c in counts)
    left = sum(c[1] for c in counts)
    tmp = f"{out_path}.tmp-{os.getpid()}"
    try:
        start = _start_output(layout, tmp, layout.vertex_count, quads + left,
                              17 * quads + 13 * left)
        offsets = np.cumsum([0] + [17 * q + 13 * t for q, t in counts])[:-1] + start
        client.gather([_submit(client, _write_part, p, plan, tmp, int(o), retries=retries)
                       for p, plan, o in zip(parts, plans, offsets)])
        os.replace(tmp, out_path)
    finally:
        if os.path.exists(tmp):
            os.remove(tmp)
    return quads, left, quality


def _part_bounds(face_count: int, parts: Union[int, Sequence[int]]) -> np.ndarray:
    """The parts' first faces and the face count: `parts` even-sized ranges (a connected part of
    a closed mesh then pairs perfectly by itself), or the boundaries given."""
    if isinstance(parts, (int, np.integer)):
        bounds = np.linspace(0, face_count, max(1, int(parts)) + 1).astype(np.int64) // 2 * 2
        bounds[-1] = face_count
        return np.unique(bounds)  # no empty part when there are more parts than face pairs
    bounds = np.asarray(parts, np.int64)
    if bounds.ndim != 1 or len(bounds) < 2 or bounds[0] != 0 or bounds[-1] != face_count or (
            np.diff(bounds) <= 0).any():
        raise ValueError(f"parts: boundaries rising from 0 to the face count {face_count}, "
                         f"not {parts}")
    return bounds


def quadrangulate(in_path: str, out_path: str, client: Any,
                  parts: Union[int, Sequence[int]] = 0, band_radius: int = 16,
                  first_radius: int = 2, retries: int = 3, **options: Any) -> Dict[str, Any]:
    """Pairs the triangles of the binary PLY ``in_path`` into quads on a Dask cluster and writes
    them to ``out_path`` (binary PLY, the input's vertex block unchanged, faces in input order:
    each quad where its first triangle was, left triangles as they were), as
    ``petersen.quadrangulate`` would. ``client`` is a ``distributed.Client``; the file must be at
    the same path on every worker. ``parts`` face ranges of even sizes (default: one per worker),
    or the ranges' boundaries ``[0, b1, ..., face count]``; ``band_radius`` how far from its cut
    a part's band reaches and ``first_radius`` the repair's first band graph (it doubles up to
    ``band_radius``); ``retries`` Dask's retries of each task; ``options`` as
    ``petersen.quadrangulate``'s: ``objective`` ("quads", the default: each part by the same
    certified minimum-cost matching, then the triangles left beside the cuts across them;
    "quality": each part's cheapest maximum pairing, its cost not certified for the whole mesh;
    "pairs": the maximum, fastest, with the band repair), ``triangle_cost`` (quads),
    ``max_corner_deviation`` and ``sharp_angle`` (quads and quality), ``augment`` (pairs),
    ``all_quad`` (every face a quad by midpoints and centres added after the input's vertices,
    part by part as ``petersen quad --memory-limit --all-quad``; the pairing the cheapest
    maximum, so not with ``triangle_cost``) and ``keep_polygons`` (taken; the input is all
    triangles).

    With objective quads the statistics hold ``objective_total``, a ``lower_bound`` on the whole
    mesh's optimum (the parts' certified duals stitched across the cuts), ``gap`` and
    ``gap_relative``, and ``optimality_certified`` when the gap is 0.

    Returns the statistics: the keys of ``petersen.quadrangulate``'s that apply (``input``,
    ``output``, ``faces_in``, ``vertices``, ``triangles``, ``pairs``, ``triangles_left``,
    ``quality_median`` and ``quality_p95``, as out of core of the costs binned per 1/1024 degree,
    ``nonconvex_quads``, ``maximum_certified``, ``total_seconds``, ...) and the distributed
    figures (``parts``, ``part_cut_edges``, ``unpaired_after_parts``, ``repair_*``, each stage's
    seconds); with ``all_quad`` the keys of
    the out-of-core ``--stats-json`` (``added_vertices``, ``split_edges``, ``centre_vertices``,
    ``faces_out``, ``all_quad_parts_certified``, ``all_quad_certified`` False: no whole-mesh
    minimum is proved part by part). ``maximum_certified`` is True
    when every triangle is paired (checked); a mesh with boundary whose pairing leaves triangles
    gets no whole-mesh Tutte-Berge witness here (``petersen.quadrangulate`` gives one). Raises
    ValueError naming the file and header line, or face, for input it cannot read, TypeError for
    an option the parts do not take.
    """
    for key in options:
        if key not in _OPTIONS:
            raise TypeError(f"petersen.distributed.quadrangulate: option '{key}' is not one the "
                            f"parts take ({', '.join(_OPTIONS)})")
    all_quad = bool(options.pop("all_quad", False))
    keep_polygons = bool(options.pop("keep_polygons", False))  # the input is all triangles
    costs = _costs_of(dict(options, all_quad=all_quad))
    if all_quad and costs["objective"] == "quads":
        # Every triangle left is split into quads anyway: the cheapest maximum pairing, as
        # petersen.quadrangulate and `petersen quad --memory-limit` pair with all_quad.
        costs = dict(costs, objective="quality")
    if costs["objective"] == "quads" and band_radius < 3:
        # The seams price a face beside a cut from its two rings, which must lie in the bands.
        raise ValueError(f"petersen.distributed.quadrangulate: objective quads needs band_radius "
                         f">= 3, not {band_radius}")
    clock = time.perf_counter()
    layout = read_layout(in_path)
    if layout.face_count == 0:
        raise ValueError(f"{in_path}: no faces")
    bounds = _part_bounds(layout.face_count, parts or len(client.scheduler_info()["workers"]))

    def write(part_futures, repair):
        """The output (plain, or all quads); the pairing's quads and triangles left, checked."""
        lap = time.perf_counter()
        if all_quad:
            quads, left, figures = _write_all_quad(client, layout, part_futures, bounds, repair,
                                                   out_path, retries, costs["objective"],
                                                   keep_polygons)
        else:
            quads, left, quality = _write_output(client, layout, part_futures, bounds, repair,
                                                 out_path, retries)
            figures = {"quality": quality}
        if quads * 2 + left != layout.face_count:
            raise RuntimeError("verification failed: the parts' faces do not add up to the "
                               "input's")
        return quads, left, figures, time.perf_counter() - lap

    if costs["objective"] != "pairs":
        part_futures, cut, seamed, seam = _pair_and_seam(client, layout, bounds, band_radius,
                                                         costs, retries)
        quads, left, figures, seconds = write(part_futures, seam)
        stats = {"input": in_path, "output": out_path,
                 **_cost_stats(costs, layout, bounds, cut, seamed, quads, left),
                 **figures["quality"]}
        if all_quad:
            stats["objective"] = options.get("objective", "quads")
            _all_quad_stats(stats, figures, seconds)
        stats.update(write_seconds=seconds, total_seconds=time.perf_counter() - clock)
        return stats
    part_futures, cut, repaired, repair = _pair_and_repair(
        client, layout, bounds, options.get("augment", "local"), band_radius, first_radius,
        retries)
    quads, left, figures, write_seconds = write(part_futures, repair)
    per_part = cut["figures"]
    stats = {
        "input": in_path, "output": out_path,
        "objective": "pairs", "algorithm": "auto", "augment": options.get("augment", "local"),
        "vertices": layout.vertex_count, "faces_in": layout.face_count,
        "triangles": layout.face_count, "polygons_kept": 0, "maximum_certified": left == 0,
        "pairs": quads, "triangles_left": left, "added_vertices": 0,
        "parts": len(bounds) - 1, "part_cut_edges": cut["adjacencies"],
        "boundary_edges": cut["boundary_edges"], "non_manifold_edges": cut["non_manifold_edges"],
        "duplicate_edges": cut["duplicate_edges"],
        "parts_certified": all(f["maximum_certified"] for f in per_part),
        "unpaired_after_parts": sum(f["unpaired"] for f in per_part),
        "moved_to_border": sum(f["moved_to_border"] for f in per_part),
        "stranded": sum(f["stranded"] for f in per_part),
        "band_faces": sum(f["band_faces"] for f in per_part),
        "part_seconds_max": max(f["seconds"] for f in per_part),
        "repair_rounds": repaired["rounds"], "repair_band_radius": repaired["band_radius"],
        "repair_radius": repaired["radius"],
        "repair_band_graph_faces": repaired["band_graph_faces"],
        "repair_augmenting_paths": repaired["augmenting_paths"],
        "repair_unpaired_before": repaired["unpaired_before"],
        "repair_unpaired_after": repaired["unpaired_after"],
        "repair_maximum_in_band_certified": repaired["maximum_in_band_certified"],
        "repair_matching_seconds": repaired["seconds"],
        "parts_seconds": repaired["parts_seconds"], "repair_seconds": repaired["repair_seconds"],
        "write_seconds": write_seconds, **figures["quality"],
    }
    if all_quad:
        _all_quad_stats(stats, figures, write_seconds)
    stats["total_seconds"] = time.perf_counter() - clock
    return stats
