"""The GIL is released while the library works: Python keeps running beside it."""

import threading
import time

import numpy as np

import petersen
from checks import check_result
from conftest import torus


def test_python_runs_while_quadrangulate_works():
    V, F = torus(800, 400)  # 640,000 triangles: long enough to see the main thread run beside
    result = {}

    def work():
        result["r"] = petersen.quadrangulate(V, F, objective="pairs", algorithm="ps")

    worker = threading.Thread(target=work)
    stamps = []
    worker.start()
    while worker.is_alive():
        stamps.append(time.perf_counter())
    worker.join()
    library_seconds = result["r"].stats["total_seconds"]
    assert library_seconds > 0.05, "the mesh is too small to tell"
    # Holding the GIL through the library call would stop this loop for all of it; released,
    # the loop only waits for the Python parts (array conversion) and the scheduler.
    gaps = np.diff(stamps)
    assert len(stamps) > 100
    assert gaps.max() < 0.5 * library_seconds, (gaps.max(), library_seconds)
    assert result["r"].stats["pairs"] == len(F) // 2


def test_two_conversions_at_once_give_each_its_own_answer():
    meshes = [torus(120, 80), torus(90, 70)]
    results = [None, None]

    def work(i):
        V, F = meshes[i]
        results[i] = petersen.quadrangulate(V, F, objective="pairs", algorithm="ps", seed=i + 1)

    threads = [threading.Thread(target=work, args=(i,)) for i in range(2)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    for i, (V, F) in enumerate(meshes):
        check_result(V, [tuple(f) for f in F.tolist()], results[i])
        alone = petersen.quadrangulate(V, F, objective="pairs", algorithm="ps", seed=i + 1)
        assert np.array_equal(results[i].quads, alone.quads)
