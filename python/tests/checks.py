"""An independent check of a quadrangulate result, from the input faces alone."""

import numpy as np


def check_result(V, faces, result, all_quad=False, lrs=False):
    """faces: the input faces as a list of tuples. Asserts what every answer must satisfy."""
    n_in = len(faces)
    triangles = [f for f in faces if len(f) == 3]
    out = result.faces
    assert len(out) == len(result.sources)
    assert result.quads.shape[1:] == (4,) and result.triangles.shape[1:] == (3,)
    assert result.quads.dtype == np.int64 and result.sources.dtype == np.int64
    assert result.V.shape[1] == 3 and np.array_equal(result.V[: len(V)], np.asarray(V, float))
    # Kept polygons are the input's faces of other arity, unchanged and in order.
    kept = [tuple(f) for f in faces if len(f) != 3]
    assert [tuple(p) for p in result.polygons] == kept
    for k, p in enumerate(result.polygons):
        src = result.sources[len(result.quads) + len(result.triangles) + k]
        assert tuple(faces[src[0]]) == tuple(p) and src[1] == -1
    # Each input triangle is used once: by a pair's quad, or left (or split, with all_quad).
    used = np.zeros(n_in, int)
    pairs = 0
    for k, q in enumerate(result.quads):
        s0, s1 = result.sources[k]
        assert len(set(q.tolist())) == 4
        if all_quad:  # split faces name the faces they were split from, maybe several times
            continue
        if lrs:  # a triangle lrs's flips made names no input face
            for s in (s0, s1):
                if s >= 0:
                    used[s] += 1
            continue
        assert s0 >= 0 and s1 >= 0
        pairs += 1
        t1, t2 = faces[s0], faces[s1]
        assert len(t1) == 3 and len(t2) == 3
        assert len(set(t1) & set(t2)) == 2, "the two triangles share an edge"
        assert set(q.tolist()) == set(t1) | set(t2)
        # The quad follows t1's orientation: t1's two edges that stay are edges of q, same way.
        q_edges = {(int(q[i]), int(q[(i + 1) % 4])) for i in range(4)}
        t1_edges = [(t1[i], t1[(i + 1) % 3]) for i in range(3)]
        assert sum(e in q_edges for e in t1_edges) == 2
        used[s0] += 1
        used[s1] += 1
    for k, t in enumerate(result.triangles):
        s0, s1 = result.sources[len(result.quads) + k]
        assert s1 == -1 and tuple(faces[s0]) == tuple(t)
        used[s0] += 1
    if not all_quad:
        assert used.max(initial=0) <= 1
    if not all_quad and not lrs:
        assert all(used[i] == 1 for i, f in enumerate(faces) if len(f) == 3)
        assert pairs == result.stats["pairs"]
    assert len(result.triangles) == (0 if all_quad else result.stats["triangles_left"])
    if all_quad:
        assert result.stats["added_vertices"] == len(result.V) - len(V)
    assert result.stats["triangles"] == len(triangles)
    assert result.stats["faces_in"] == n_in
    assert result.stats["maximum_certified"] is True
    # The Tutte set names input triangles, one per node at most.
    assert len(set(result.tutte_set.tolist())) == len(result.tutte_set)
    assert all(len(faces[t]) == 3 for t in result.tutte_set)
