"""petersen.max_weight_matching against networkx's on the same networkx graphs (one run each).

    python3 bench/networkx_speed.py [--nodes 10000] [--weights integer,real]
                                    [--maxcardinality false,true]

networkx takes about ten minutes per call at 10^4 nodes on the reference machine.

Random graphs of n nodes and 3n edges, integer weights 1..1000 and real ones in [0, 1); ours is
timed from the networkx graph to the set of pairs (conversion included), its certificate checked
inside; the two optima are checked equal (exactly for integers, to 1e-9 for reals).
"""

import argparse
import random
import time

import networkx as nx

import petersen


def graph(n, real, seed):
    rng = random.Random(seed)
    G = nx.Graph()
    G.add_nodes_from(range(n))
    while G.number_of_edges() < 3 * n:
        u, v = rng.randrange(n), rng.randrange(n)
        if u != v:
            G.add_edge(u, v, weight=rng.random() if real else rng.randint(1, 1000))
    return G


def weight(G, pairs):
    return sum(G[u][v]["weight"] for u, v in pairs)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--nodes", type=int, default=10_000)
    parser.add_argument("--weights", default="integer,real")
    parser.add_argument("--maxcardinality", default="false,true")
    args = parser.parse_args()
    kinds = [kind == "real" for kind in args.weights.split(",")]
    cardinalities = [flag == "true" for flag in args.maxcardinality.split(",")]
    print("| weights | maxcardinality | nodes | edges | petersen s | networkx s | networkx ÷ petersen "
          "| optimum |")
    print("|---|---|---:|---:|---:|---:|---:|---|")
    for real in kinds:
        G = graph(args.nodes, real, 7)
        for maxcardinality in cardinalities:
            start = time.perf_counter()
            ours = petersen.max_weight_matching(G, maxcardinality=maxcardinality)
            ours_s = time.perf_counter() - start
            start = time.perf_counter()
            theirs = nx.max_weight_matching(G, maxcardinality=maxcardinality)
            theirs_s = time.perf_counter() - start
            same = abs(weight(G, ours) - weight(G, theirs)) <= (1e-9 if real else 0)
            print(f"| {'real' if real else 'integer'} | {maxcardinality} | {args.nodes} | "
                  f"{G.number_of_edges()} | {ours_s:.3f} | {theirs_s:.1f} | "
                  f"{theirs_s / ours_s:.0f} | {'equal' if same else 'MISMATCH'} |", flush=True)


if __name__ == "__main__":
    main()
