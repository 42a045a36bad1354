"""petersen's networkx-style matchings: networkx's own test cases run against them (read from the
installed networkx, through the Python functions and through `petersen match`), random
differential tests against networkx, and the array and scipy.sparse forms. Every answer the
library gives has had its dual certificate checked by the independent verifier before it is
returned (cheapest_matching_any_graph raises otherwise)."""

import importlib.util
import inspect
import math
import pathlib
import random
import subprocess

import numpy as np
import pytest

import petersen

nx = pytest.importorskip("networkx")

NX_TESTS = pathlib.Path(nx.__file__).parent / "algorithms" / "tests" / "test_matching.py"


def networkx_test_module():
    """networkx's own test_matching.py, imported from the installed package (not copied)."""
    if not NX_TESTS.exists():
        pytest.skip(f"{NX_TESTS} is absent")
    spec = importlib.util.spec_from_file_location("networkx_test_matching", NX_TESTS)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def weight_cases():
    """The names of the test methods of networkx's TestMaxWeightMatching."""
    if not NX_TESTS.exists():
        return []
    cls = networkx_test_module().TestMaxWeightMatching
    return [name for name, _ in inspect.getmembers(cls, inspect.isfunction)
            if name.startswith("test_")]


def run_networkx_case(name, monkeypatch, max_weight, min_weight):
    """Runs networkx's test `name` with nx.max_weight_matching and nx.min_weight_matching
    replaced; returns how many times they were called (so that a case that ran neither is
    seen). networkx 2.8's min_weight_matching takes a deprecated positional maxcardinality
    (True or 1 only) before weight; the adapter maps it, as networkx 3 dropped it."""
    calls = []

    def max_weight_matching(G, maxcardinality=False, weight="weight"):
        calls.append("max")
        return max_weight(G, maxcardinality=maxcardinality, weight=weight)

    def min_weight_matching(G, maxcardinality=None, weight="weight"):
        assert maxcardinality in (None, True, 1)
        calls.append("min")
        return min_weight(G, weight=weight)

    module = networkx_test_module()
    monkeypatch.setattr(module.nx, "max_weight_matching", max_weight_matching)
    monkeypatch.setattr(module.nx, "min_weight_matching", min_weight_matching)
    case = module.TestMaxWeightMatching()
    getattr(case, name)()
    return len(calls)


@pytest.mark.parametrize("name", weight_cases())
def test_networkx_cases_through_the_python_functions(name, monkeypatch):
    calls = run_networkx_case(name, monkeypatch, petersen.max_weight_matching,
                              petersen.min_weight_matching)
    assert calls > 0


# ---- the same cases through `petersen match`

def cli_matching(cli, tmp_path, G, objective, weight, negate=False):
    """`petersen match --objective OBJECTIVE` on G written as an edge list (labels to indices,
    weights with 17 significant digits, so a float is the file's number exactly), the matched
    pairs read back as labels."""
    if G.is_directed() or G.is_multigraph():
        raise nx.NetworkXNotImplemented("not implemented for directed or multigraph type")
    nodes = list(G)
    index = {v: i for i, v in enumerate(nodes)}
    lines = [f"# nodes {len(nodes)}"]
    for u, v, w in G.edges(data=weight, default=1):
        w = -w if negate else w
        lines.append(f"{index[u]} {index[v]} {w!r}" if isinstance(w, float) else
                     f"{index[u]} {index[v]} {w}")
    graph, out = tmp_path / "g.txt", tmp_path / "m.txt"
    graph.write_text("\n".join(lines) + "\n")
    subprocess.run([cli, "match", str(graph), str(out), "--objective", objective], check=True,
                   capture_output=True)
    pairs = set()
    for line in out.read_text().split("\n"):
        if line:
            a, b = map(int, line.split())
            pairs.add((nodes[a], nodes[b]))
    return pairs


@pytest.mark.parametrize("name", weight_cases())
def test_networkx_cases_through_the_cli(name, monkeypatch, tmp_path, cli):
    def max_weight(G, maxcardinality=False, weight="weight"):
        return cli_matching(cli, tmp_path, G, "weight-maximum" if maxcardinality else "weight",
                            weight)

    def min_weight(G, weight="weight"):
        return cli_matching(cli, tmp_path, G, "cost", weight)

    assert run_networkx_case(name, monkeypatch, max_weight, min_weight) > 0


# ---- random differential tests against networkx

def weight_of(G, pairs, weight="weight"):
    return sum(G[u][v].get(weight, 1) for u, v in pairs)


def is_matching(G, pairs):
    seen = set()
    for u, v in pairs:
        if not G.has_edge(u, v) or u == v or u in seen or v in seen:
            return False
        seen |= {u, v}
    return True


def random_graph(rng, real):
    """A small random graph: labels of mixed types, integer weights from a narrow range (ties)
    or real ones, some negative."""
    n = rng.randint(1, 16)
    labels = [rng.choice([i, f"v{i}", (i, "t")]) for i in range(n)]
    G = nx.Graph()
    G.add_nodes_from(labels)
    for _ in range(rng.randint(0, 3 * n)):
        u, v = rng.choice(labels), rng.choice(labels)
        if u == v:
            continue
        w = rng.uniform(-2, 10) if real else rng.randint(-2, 6)
        G.add_edge(u, v, weight=w)
    return G


@pytest.mark.parametrize("real", [False, True])
def test_random_graphs_agree_with_networkx(real):
    rng = random.Random(43 + real)
    graphs = 1100
    for trial in range(graphs):
        G = random_graph(rng, real)
        for maxcardinality in (False, True):
            ours = petersen.max_weight_matching(G, maxcardinality=maxcardinality)
            theirs = nx.max_weight_matching(G, maxcardinality=maxcardinality)
            assert is_matching(G, ours), (trial, ours)
            if maxcardinality:
                assert len(ours) == len(theirs), (trial, ours, theirs)
            ours_w, theirs_w = weight_of(G, ours), weight_of(G, theirs)
            if real:
                # networkx sums floats as it goes; petersen's rounding is stated (gap_bound).
                assert ours_w >= theirs_w - 1e-9, (trial, ours_w, theirs_w)
                assert abs(ours_w - theirs_w) <= 1e-9, (trial, ours_w, theirs_w)
            else:
                assert ours_w == theirs_w, (trial, ours, theirs)
        ours, theirs = petersen.min_weight_matching(G), nx.min_weight_matching(G)
        assert is_matching(G, ours) and len(ours) == len(theirs), (trial, ours, theirs)
        if real:
            assert abs(weight_of(G, ours) - weight_of(G, theirs)) <= 1e-9, trial
        else:
            assert weight_of(G, ours) == weight_of(G, theirs), (trial, ours, theirs)


# ---- the array and sparse forms

def test_array_form_states_exactness_and_tolerance():
    edges = np.array([[0, 1], [1, 2], [2, 3], [3, 0]])
    exact = petersen.weighted_matching(4, edges, [2, 3, 2, 1])
    assert exact.edges.tolist() == [0, 2] and exact.weight == 4 and exact.exact
    assert exact.gap_bound == 0 and exact.perfect
    halves = petersen.weighted_matching(4, edges, np.array([2.5, 0.5, 0.25, 1.0]))
    assert halves.exact and halves.weight == 2.75
    reals = [math.pi, math.e, math.sqrt(2), 0.1]
    rounded = petersen.weighted_matching(4, edges, reals)
    assert rounded.edges.tolist() == [0, 2] and not rounded.exact
    assert 0 < rounded.gap_bound < 1e-10
    assert rounded.weight == math.fsum([math.pi, math.sqrt(2)])
    # The lightest perfect matching, and its refusal with a Tutte-Berge set.
    assert petersen.weighted_matching(4, edges, reals, "min_weight_perfect").edges.tolist() == [1, 3]
    with pytest.raises(petersen.NoPerfectMatching) as refused:
        petersen.weighted_matching(4, [[0, 1], [0, 2], [0, 3]], [1, 1, 1], "min_weight_perfect")
    assert refused.value.tutte_set.tolist() == [0] and refused.value.unmatched == 2
    # Integers past 2^40 are rounded too (here 2^50 and 2^50 + 1 to the same), within the gap.
    big = petersen.weighted_matching(3, [[0, 1], [1, 2]], [2**50, 2**50 + 1])
    assert len(big.edges) == 1 and not big.exact and big.gap_bound >= 1
    assert big.weight >= 2**50 + 1 - big.gap_bound
    with pytest.raises(ValueError, match="not finite"):
        petersen.weighted_matching(2, [[0, 1]], [math.nan])
    with pytest.raises(ValueError, match="one per edge"):
        petersen.weighted_matching(2, [[0, 1]], [1, 2])
    with pytest.raises(ValueError, match="unknown objective"):
        petersen.weighted_matching(2, [[0, 1]], [1], "heaviest")


def test_scipy_sparse_matrices():
    sp = pytest.importorskip("scipy.sparse")
    rng = np.random.default_rng(5)
    for _ in range(50):
        n = int(rng.integers(2, 30))
        dense = np.triu(rng.integers(0, 9, size=(n, n)) * (rng.random((n, n)) < 0.3), k=1)
        A = sp.csr_matrix(dense + dense.T)
        G = nx.Graph()
        G.add_nodes_from(range(n))
        for i, j in zip(*np.nonzero(dense)):
            G.add_edge(int(i), int(j), weight=int(dense[i, j]))
        ours = petersen.max_weight_matching(A)
        assert is_matching(G, ours)
        assert weight_of(G, ours) == weight_of(G, nx.max_weight_matching(G))
        assert weight_of(G, petersen.min_weight_matching(A)) == \
            weight_of(G, nx.min_weight_matching(G))
    with pytest.raises(ValueError, match="square"):
        petersen.max_weight_matching(sp.csr_matrix(np.ones((2, 3))))
