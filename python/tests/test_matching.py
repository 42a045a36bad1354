"""petersen.perfect_matching on graphs, checked here (every node covered exactly once)."""

import numpy as np
import pytest

import petersen

GRAPH_ALGORITHMS = [a for a in petersen.ALGORITHMS if a != "lrs"]


def petersen_graph():
    outer = [(i, (i + 1) % 5) for i in range(5)]
    spokes = [(i, i + 5) for i in range(5)]
    inner = [(5 + i, 5 + (i + 2) % 5) for i in range(5)]
    return 10, np.array(outer + spokes + inner)


def prism(k):
    edges = [(i, (i + 1) % k) for i in range(k)] + [(k + i, k + (i + 1) % k) for i in range(k)]
    edges += [(i, k + i) for i in range(k)]
    return 2 * k, np.array(edges)


def assert_perfect(n, edges, matched):
    assert matched.dtype == np.int64 and len(matched) == n // 2
    assert np.all(np.diff(matched) > 0)
    ends = np.asarray(edges)[matched].ravel()
    assert sorted(ends.tolist()) == list(range(n))


@pytest.mark.parametrize("algorithm", GRAPH_ALGORITHMS)
def test_every_algorithm_matches_perfectly(algorithm):
    for n, edges in (petersen_graph(), prism(7), prism(200)):
        assert_perfect(n, edges, petersen.perfect_matching(n, edges, algorithm=algorithm))


def test_parallel_edges_and_any_dtype():
    # Two nodes joined by three parallel edges, twice (two components).
    edges = np.array([[0, 1], [0, 1], [1, 0], [2, 3], [3, 2], [2, 3]], dtype=np.uint8)
    assert_perfect(4, edges, petersen.perfect_matching(4, edges))
    assert_perfect(4, edges, petersen.perfect_matching(4, edges.tolist()))
    assert_perfect(4, edges, petersen.perfect_matching(4, np.asfortranarray(edges)))


def test_graphs_that_are_not_cubic_bridgeless_raise_value_error():
    with pytest.raises(ValueError, match="degree|node"):
        petersen.perfect_matching(4, [[0, 1], [1, 2], [2, 3]])
    # Two K4s minus an edge, joined by two edges: a 2-edge cut, no bridge, so it matches.
    edges = [(0, 1), (0, 2), (1, 2), (1, 3), (2, 3), (4, 5), (4, 6), (5, 6), (5, 7), (6, 7),
             (0, 4), (3, 7)]
    assert_perfect(8, edges, petersen.perfect_matching(8, edges))
    # A bridge: two K4s each with edge 1-3 subdivided by node 4, the two node 4s joined.
    one = [(0, 1), (0, 2), (0, 3), (1, 2), (1, 4), (2, 3), (3, 4)]
    bridged = one + [(a + 5, b + 5) for a, b in one] + [(4, 9)]
    with pytest.raises(ValueError, match="bridge"):
        petersen.perfect_matching(10, bridged)
    with pytest.raises(ValueError, match="out of range"):
        petersen.perfect_matching(2, [[0, 5]])
    with pytest.raises(ValueError, match="mesh|lrs"):
        petersen.perfect_matching(10, petersen_graph()[1], algorithm="lrs")
    with pytest.raises(ValueError, match=r"\(e, 2\)"):
        petersen.perfect_matching(10, [1, 2, 3])
