"""Matchings of graphs as graph people have them: networkx graphs, scipy.sparse matrices, arrays.

``max_weight_matching`` and ``min_weight_matching`` answer networkx's questions (the same
arguments, the same set of node pairs), exactly and with each answer's certificate checked by the
library's independent verifier: Edmonds' primal-dual blossom algorithm in C++ on a doubled graph
(a matching of any size) or on the graph itself. ``weighted_matching`` is the array form, which
returns edge indices and says how exact the answer is.

Weights may be integers or floats. Integers within 2^40 are exact, and so are floats that a power
of two makes integers within 2^40 (such as 2.5 or 3.0); other floats are rounded at the largest
power of two that keeps them within 2^40, the optimum of the rounded weights is certified, and
``WeightedMatching.gap_bound`` says how far from the exact optimum it may be (about 2^-40 of the
largest weight per matched edge). networkx and scipy are needed only for their own inputs.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any, Hashable, List, Set, Tuple

import numpy as np
import numpy.typing as npt

from . import _petersen

__all__ = [
    "NoPerfectMatching",
    "WeightedMatching",
    "max_weight_matching",
    "min_weight_matching",
    "weighted_matching",
]

#: The objectives of ``weighted_matching``: what is optimized, over which matchings.
OBJECTIVES = {
    # name: (the library's set of matchings, weights negated into costs)
    "max_weight": ("any_size", True),
    "max_weight_maximum": ("maximum", True),
    "min_weight_maximum": ("maximum", False),
    "min_weight_perfect": ("perfect", False),
}


class NoPerfectMatching(ValueError):
    """``weighted_matching(..., objective="min_weight_perfect")`` on a graph without a perfect
    matching. ``tutte_set`` is the proof: removing those nodes leaves more odd components than
    it has nodes, so every matching leaves ``unmatched`` nodes free."""

    def __init__(self, tutte_set: np.ndarray, unmatched: int):
        super().__init__(
            f"no perfect matching: removing the {len(tutte_set)} nodes of the Tutte-Berge set "
            f"leaves {len(tutte_set) + unmatched} odd components, so every matching leaves "
            f"{unmatched} nodes unmatched")
        self.tutte_set = tutte_set
        self.unmatched = unmatched


@dataclass
class WeightedMatching:
    """What ``weighted_matching`` returns."""

    #: The sorted indices of the matched edges.
    edges: np.ndarray
    #: Their total weight (an int for integer weights, else a float summed exactly, then rounded).
    weight: Any
    #: Whether the weights went to the solver without rounding: then the answer is optimal
    #: exactly.
    exact: bool
    #: How much better than ``weight`` the exact optimum may be (0 when exact): the weights were
    #: rounded by at most ``gap_bound / (2 * matching edges)`` each.
    gap_bound: float
    #: Whether every node is matched.
    perfect: bool


def _weight_array(weights: npt.ArrayLike, m: int) -> np.ndarray:
    """Weights as int64 when they are integers that fit 64 bits, else float64."""
    array = np.asarray(weights)
    if array.dtype == object:  # integers past 64 bits, fractions, decimals: as floats
        array = array.astype(np.float64)
    kind = array.dtype.kind
    if kind == "b" or (kind == "u" and (array.size == 0 or array.max() < 2**63)):
        array = array.astype(np.int64)
    elif kind in "uf":
        array = array.astype(np.float64, copy=False)
    elif kind == "i":
        array = array.astype(np.int64, copy=False)
        if array.size and array.min() == np.iinfo(np.int64).min:  # -w would wrap
            array = array.astype(np.float64)
    else:
        raise TypeError(f"weights must be numbers, not {array.dtype}")
    if array.shape != (m,):
        raise ValueError(f"weights: one per edge, {m}, in a flat array, not shape {array.shape}")
    if kind == "f" and not np.all(np.isfinite(array)):
        raise ValueError(f"weights: the weight of edge {int(np.argmin(np.isfinite(array)))} is "
                         "not finite")
    return array


def weighted_matching(n: int, edges: npt.ArrayLike, weights: npt.ArrayLike,
                      objective: str = "max_weight", threads: int = 1) -> WeightedMatching:
    """The best matching of any (multi)graph by ``objective``, certified.

    ``edges`` is an (m, 2) integer array over nodes 0..n-1 (parallel edges and loops allowed; a
    loop is never matched), ``weights`` one number per edge (int or float, any sign).
    ``objective``: ``max_weight`` (the heaviest matching of any size, networkx's
    ``max_weight_matching``), ``max_weight_maximum`` (the heaviest among the maximum-cardinality
    ones, ``maxcardinality=True``), ``min_weight_maximum`` (the lightest among those, networkx's
    ``min_weight_matching``) or ``min_weight_perfect`` (the lightest perfect matching; raises
    ``NoPerfectMatching`` with a Tutte-Berge set when there is none). Exact for integer weights
    and short binary fractions; otherwise see ``gap_bound``. Worst case O(n^2 m), near-linear on
    sparse graphs in practice; the GIL is released while the library works.
    """
    if objective not in OBJECTIVES:
        raise ValueError(f"unknown objective {objective!r}: {', '.join(OBJECTIVES)}")
    which, negate = OBJECTIVES[objective]
    edge_array = np.asarray(edges)
    if edge_array.size == 0:
        edge_array = np.zeros((0, 2), np.int64)
    w = _weight_array(weights, len(edge_array))
    costs = -w if negate else w
    matched, exact, exponent, rounding, perfect, tutte = _petersen.weighted_matching(
        int(n), edge_array, costs, which, int(threads))
    if which == "perfect" and not perfect:
        raise NoPerfectMatching(tutte, int(n) - 2 * len(matched))
    if w.dtype.kind == "i":
        weight: Any = int(w[matched].sum(dtype=object)) if len(matched) else 0
    else:
        weight = math.fsum(w[matched].tolist())
    gap = 0.0
    if not exact:
        # The solver's rounding, and the weights' own conversion to doubles (half an ulp).
        largest = float(np.max(np.abs(w))) if len(w) else 0.0
        per_edge = rounding + (largest * 2.0**-53 if w.dtype.kind == "i" else 0.0)
        gap = 2.0 * (len(matched) + int(n) // 2) * per_edge
    return WeightedMatching(matched, weight, bool(exact), gap, bool(perfect))


def _graph_arrays(G: Any, weight: str) -> Tuple[List[Hashable], np.ndarray, List[Any], bool]:
    """A networkx graph or a scipy.sparse matrix as (nodes, edges (m, 2), weights, is_sparse)."""
    if hasattr(G, "is_directed") and hasattr(G, "edges"):
        import networkx as nx  # noqa: PLC0415 (optional: only for networkx graphs)

        if G.is_directed():
            raise nx.NetworkXNotImplemented("not implemented for directed type")
        if G.is_multigraph():
            raise nx.NetworkXNotImplemented("not implemented for multigraph type")
        nodes = list(G)
        index = {node: i for i, node in enumerate(nodes)}
        pairs, weights = [], []
        for u, v, w in G.edges(data=weight, default=1):
            pairs.append((index[u], index[v]))
            weights.append(w)
        edges = np.array(pairs, np.int64).reshape(-1, 2)
        return nodes, edges, weights, False
    try:
        import scipy.sparse as sp  # noqa: PLC0415 (optional: only for sparse matrices)
    except ImportError:  # pragma: no cover - scipy is installed where sparse input exists
        sp = None
    if sp is not None and sp.issparse(G):
        if G.shape[0] != G.shape[1]:
            raise ValueError(f"a sparse adjacency matrix is square, not {G.shape}")
        upper = sp.triu(sp.coo_matrix(G), k=1)
        edges = np.stack([upper.row, upper.col], axis=1).astype(np.int64)
        return list(range(G.shape[0])), edges, upper.data, True
    raise TypeError("a networkx graph or a scipy.sparse matrix, not " + type(G).__name__)


def _pairs(nodes: List[Hashable], edges: np.ndarray, matched: np.ndarray) -> Set[Tuple[Any, Any]]:
    return {(nodes[edges[e, 0]], nodes[edges[e, 1]]) for e in matched.tolist()}


def max_weight_matching(G: Any, maxcardinality: bool = False,
                        weight: str = "weight") -> Set[Tuple[Any, Any]]:
    """networkx's ``max_weight_matching``, exact and certified: a matching of largest total
    weight, of any size (or, with ``maxcardinality``, among the maximum-cardinality ones).

    ``G`` is a networkx Graph (node labels of any hashable type; an edge without the ``weight``
    attribute weighs 1; self-loops are never matched; directed graphs and multigraphs raise
    ``networkx.NetworkXNotImplemented`` as networkx does) or a square scipy.sparse matrix, whose
    strict upper triangle's stored entries are the edges and their values the weights (nodes
    0..n-1). Returns the matched pairs as a set of tuples, as networkx does. Ties between optima
    may be broken differently from networkx; the weight is the same. For the weights' exactness
    and edge indices, use ``weighted_matching``.
    """
    nodes, edges, weights, _ = _graph_arrays(G, weight)
    objective = "max_weight_maximum" if maxcardinality else "max_weight"
    result = weighted_matching(len(nodes), edges, weights, objective)
    return _pairs(nodes, edges, result.edges)


def min_weight_matching(G: Any, weight: str = "weight") -> Set[Tuple[Any, Any]]:
    """networkx's ``min_weight_matching``, exact and certified: among the maximum-cardinality
    matchings, one of least total weight (a perfect one when the graph has one).

    ``G`` and the result as in ``max_weight_matching``.
    """
    nodes, edges, weights, _ = _graph_arrays(G, weight)
    result = weighted_matching(len(nodes), edges, weights, "min_weight_maximum")
    return _pairs(nodes, edges, result.edges)
