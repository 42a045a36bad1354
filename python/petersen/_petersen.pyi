# Type stubs of the extension module; the documented API is petersen/__init__.py.
from typing import Any, Dict, List, Optional, Sequence, Tuple

import numpy as np
import numpy.typing as npt

CROSSABLE: List[str]
DEFAULT_TRIANGLE_COST: float

def quadrangulate(
    V: npt.ArrayLike,
    F: Any,
    algorithm: str,
    augment: str,
    seed: int,
    all_quad: bool,
    objective: str,
    sharp_angle: Optional[float],
    keep_edges: Optional[npt.ArrayLike],
    max_corner_deviation: Optional[float],
    attributes: Optional[Dict[str, Any]],
    cross: List[str],
    threads: int,
    keep_polygons: bool = False,
) -> Dict[str, Any]: ...
def maximum_matching(
    n: int, edges: npt.ArrayLike, algorithm: str, augment: str, seed: int
) -> Tuple[np.ndarray, bool, np.ndarray]: ...
def weighted_matching(
    n: int, edges: npt.ArrayLike, costs: np.ndarray, objective: str, threads: int
) -> Tuple[np.ndarray, bool, int, float, bool, np.ndarray]: ...
def min_cost_matching(
    n: int, edges: npt.ArrayLike, costs: np.ndarray, threads: int
) -> Tuple[np.ndarray, int, bool]: ...
def read_mesh(path: str) -> Tuple[np.ndarray, Any, Dict[str, Any], List[str]]: ...
def write_mesh(
    path: str, V: npt.ArrayLike, F: Any, attributes: Optional[Dict[str, Any]]
) -> List[str]: ...
def perfect_matching(
    n: int, edges: npt.ArrayLike, algorithm: str, augment: str, seed: int
) -> np.ndarray: ...
def quad_quality(V: npt.ArrayLike, quads: npt.ArrayLike) -> np.ndarray: ...
def render(
    path: str,
    V: npt.ArrayLike,
    F: Any,
    first_added_vertex: Optional[int],
    caption: List[str],
    view: Optional[Tuple[float, float, float]],
    width: int,
    height: int,
) -> None: ...
def pair_part(
    first_face: int,
    corners: np.ndarray,
    augment: str,
    band_radius: int,
    threads: int,
    objective: str = "pairs",
    triangle_cost: float = 90.0,
    max_corner_deviation: Optional[float] = None,
    sharp_angle: Optional[float] = None,
    positions: Optional[np.ndarray] = None,
) -> Dict[str, Any]: ...
def pair_seams(
    faces: np.ndarray,
    corners: np.ndarray,
    positions: np.ndarray,
    sides: np.ndarray,
    distance: np.ndarray,
    partner: np.ndarray,
    dual: np.ndarray,
    price: np.ndarray,
    stay_dual: np.ndarray,
    adjacencies: np.ndarray,
    parts_units: int,
    objective: str,
    triangle_cost: float = 90.0,
    max_corner_deviation: Optional[float] = None,
    sharp_angle: Optional[float] = None,
    threads: int = 1,
) -> Dict[str, Any]: ...
def pair_open_edges(open_edges: np.ndarray) -> Dict[str, Any]: ...
def repair_cuts(
    faces: np.ndarray,
    corners: np.ndarray,
    sides: np.ndarray,
    distance: np.ndarray,
    partner: np.ndarray,
    adjacencies: np.ndarray,
    augment: str,
    first_radius: int,
) -> Dict[str, Any]: ...
