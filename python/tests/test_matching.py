"""petersen.perfect_matching and min_cost_matching on graphs, checked here (every node covered
exactly once; the cheapest maximum matching against brute force)."""

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
    with pytest.raises(ValueError, match="unknown algorithm 'lemon'"):
        petersen.maximum_matching(10, petersen_graph()[1], algorithm="lemon")
    with pytest.raises(ValueError, match=r"\(e, 2\)"):
        petersen.perfect_matching(10, [1, 2, 3])


def brute_force_cheapest(n, edges, costs):
    """(size, cost) of the cheapest maximum matching, by trying every subset of edges."""
    best = (0, 0)
    for mask in range(1 << len(edges)):
        used, size, cost, ok = set(), 0, 0, True
        for e in range(len(edges)):
            if mask >> e & 1:
                a, b = edges[e]
                if a == b or a in used or b in used:
                    ok = False
                    break
                used |= {a, b}
                size += 1
                cost += costs[e]
        if ok and (size > best[0] or (size == best[0] and cost < best[1])):
            best = (size, cost)
    return best


def test_min_cost_matching_equals_brute_force():
    rng = np.random.default_rng(11)
    for trial in range(60):
        n = int(rng.integers(1, 9))
        m = int(rng.integers(0, 11))
        edges = rng.integers(0, n, size=(m, 2))  # loops included: never matched
        costs = rng.integers(-20, 50, size=m)
        r = petersen.min_cost_matching(n, edges, costs)
        size, cost = brute_force_cheapest(n, edges.tolist(), costs.tolist())
        assert len(r.edges) == size and r.total_cost == cost, (trial, edges, costs)
        assert int(costs[r.edges].sum()) == r.total_cost
        ends = edges[r.edges].ravel()
        assert len(set(ends.tolist())) == len(ends)  # no node twice
        assert r.perfect == (2 * size == n)
        again = petersen.min_cost_matching(n, edges, costs, threads=1)
        assert np.array_equal(again.edges, r.edges)


def test_min_cost_matching_refuses_bad_costs():
    edges = np.array([[0, 1], [1, 2], [2, 3]])
    with pytest.raises(TypeError, match="integers"):
        petersen.min_cost_matching(4, edges, [1.5, 2.0, 3.0])
    with pytest.raises(ValueError, match="one per edge"):
        petersen.min_cost_matching(4, edges, [1, 2])
    with pytest.raises(ValueError, match="out of range"):
        petersen.min_cost_matching(4, edges, [1, 2, 2**41])
    with pytest.raises(ValueError, match="out of range"):
        petersen.min_cost_matching(4, edges, np.array([1, 2, 2**64 - 1], dtype=np.uint64))
    with pytest.raises(ValueError, match="node 7 is out of range"):
        petersen.min_cost_matching(4, [[0, 7]], [1])
    # A loop is never matched, however cheap.
    loop = petersen.min_cost_matching(2, [[0, 0], [0, 1]], [-100, 5])
    assert loop.edges.tolist() == [1] and loop.total_cost == 5 and loop.perfect


def test_maximum_matching_of_any_graph_with_its_witness():
    # A path of five nodes and a triangle: three edges at most; the witness proves it.
    edges = np.array([[0, 1], [1, 2], [2, 3], [3, 4], [5, 6], [6, 7], [7, 5], [4, 4]])
    r = petersen.maximum_matching(8, edges)
    assert len(r.edges) == brute_force_cheapest(8, edges.tolist(), [0] * len(edges))[0] == 3
    ends = edges[r.edges].ravel()
    assert len(set(ends.tolist())) == len(ends) and not r.perfect
    # Tutte-Berge: with A removed, the odd components leave odd(G - A) - |A| nodes unmatched.
    a = set(r.tutte_set.tolist())
    parent = list(range(8))

    def find(x):
        while parent[x] != x:
            parent[x] = parent[parent[x]]
            x = parent[x]
        return x

    for u, v in edges.tolist():
        if u not in a and v not in a:
            parent[find(u)] = find(v)
    sizes = {}
    for v in range(8):
        if v not in a:
            sizes[find(v)] = sizes.get(find(v), 0) + 1
    odd = sum(1 for s in sizes.values() if s % 2)
    assert 8 - 2 * len(r.edges) == odd - len(a)
    # A cubic bridgeless graph: perfect, by the algorithm asked for, and no witness needed.
    n, graph = petersen_graph()
    p = petersen.maximum_matching(n, graph, algorithm="sg", seed=3)
    assert p.perfect and len(p.edges) == 5 and len(p.tutte_set) == 0
