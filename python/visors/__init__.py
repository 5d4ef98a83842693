"""VISORS GNC from Python: the closed-loop mission simulator, the GNSS simulation and navigation
replay, Monte Carlo campaigns and their results store, and the building blocks (every
``visors tool``, the integer least-squares search).

SI units and the C++ names throughout (``r_gcrf``, ``dv_rtn``, ``*_m``, ``*_s``). Bad input raises
``ValueError`` naming the field, as the command line prints it. See docs/python.md.

Fixed entry points (scripts can rely on them):
    visors.__version__
    visors.tool(name, request: dict) -> dict
    visors.run(scenario, out=None, seed=None) -> dict
"""
from __future__ import annotations

import contextlib
import csv
import json
import math
import os
import pathlib
import sqlite3
import tempfile
from typing import Any, Iterator, Mapping

import numpy as np

from . import _visors

__version__: str = _visors.__version__

__all__ = ["__version__", "tool", "tool_names", "run", "gnss_sim", "nav_replay", "mc", "read_run",
           "read_csv", "read_store", "find_data_file", "integer_least_squares", "control_input_matrix",
           "StochasticMpc", "MU_EARTH"]

MU_EARTH = 3.986004418e14  # [m^3/s^2], the project's default (core::EarthGravityConstants)

DEFAULT_SCENARIO = "scenarios/campaign.toml"


def _jsonable(value: Any) -> Any:
    """numpy arrays and scalars as the JSON the C++ side reads (anything else is refused)."""
    if isinstance(value, np.ndarray):
        return value.tolist()
    if isinstance(value, np.generic):
        return value.item()
    raise TypeError(f"{type(value).__name__} is not JSON serialisable")


def _to_json(value: Mapping[str, Any], field: str) -> str:
    if not isinstance(value, Mapping):
        raise ValueError(f"{field}: must be a dict, not {type(value).__name__}")
    try:
        return json.dumps(value, default=_jsonable, allow_nan=False)
    except (TypeError, ValueError) as error:
        raise ValueError(f"{field}: {error}") from None


def tool_names() -> list[str]:
    """The names ``tool`` accepts (``visors tool --help`` lists the same, with a summary each)."""
    return list(_visors.tool_names())


def tool(name: str, request: Mapping[str, Any]) -> dict:
    """Runs ``visors tool NAME`` in-process: ``request`` holds the JSON fields the CLI reads on
    stdin (numpy arrays accepted), the answer the fields it prints (docs/cli/tool.md).

    Raises ValueError naming the field when the request is refused."""
    if not isinstance(name, str):
        raise ValueError(f"name: must be a string, not {type(name).__name__}")
    return json.loads(_visors.tool(name, _to_json(request, "request")))


def _scenario_arguments(scenario: str | os.PathLike | Mapping[str, Any]) -> tuple[str, str]:
    """(path, dict as JSON): exactly one is non-empty."""
    if isinstance(scenario, (str, os.PathLike)):
        return os.fspath(scenario), ""
    if isinstance(scenario, Mapping):
        return "", _to_json(scenario, "scenario")
    raise ValueError(f"scenario: must be a path or a dict, not {type(scenario).__name__}")


def _integer(value: Any, field: str, minimum: int) -> int:
    """An integer >= minimum (0 or 1), named `field` in the error."""
    if isinstance(value, bool) or not isinstance(value, (int, np.integer)) or value < minimum:
        kind = "non-negative" if minimum == 0 else "positive"
        raise ValueError(f"{field}: must be a {kind} integer, not {value!r}")
    return int(value)


def _seed(seed: int | None) -> int | None:
    return None if seed is None else _integer(seed, "seed", 0)


@contextlib.contextmanager
def _output_folder(out: str | os.PathLike | None, kind: str) -> Iterator[str]:
    """``out`` itself, or a temporary folder removed once the results are read."""
    if out is not None:
        yield os.fspath(out)
        return
    with tempfile.TemporaryDirectory(prefix=f"visors_{kind}_") as folder:
        yield folder


def run(scenario: str | os.PathLike | Mapping[str, Any] = DEFAULT_SCENARIO, out: str | os.PathLike | None = None,
        seed: int | None = None, *, parallel: bool = False, report: bool = False) -> dict:
    """The mission campaign in closed loop, as ``visors run``.

    scenario: a TOML file (a path, or relative to the data search path) or a dict of the same
        tables and keys (absent keys keep their defaults; unknown keys are refused).
    out: the run directory (docs/run-directory.md); None: a temporary one, removed once read.
    seed: replaces the scenario's seed.
    parallel: step the two flight components on two threads (same results).
    report: also write report.html into the run directory.

    Returns ``read_run`` of the run directory: its summary as a dict and its tables (time series,
    navigation, observations, events) as numpy structured arrays."""
    path, scenario_json = _scenario_arguments(scenario)
    with _output_folder(out, "run") as folder:
        _, directory = _visors.run_campaign(path, scenario_json, folder, _seed(seed), bool(parallel), bool(report))
        result = read_run(directory)
        if out is None:
            result["dir"] = None
    return result


def gnss_sim(scenario: str | os.PathLike | Mapping[str, Any] = "scenarios/gnss_sim.toml",
             out: str | os.PathLike = "out/gnss", seed: int | None = None) -> dict:
    """``visors gnss-sim``: the receivers' RINEX files, truth and attitude of a scenario, written to
    ``out`` (a folder ``nav_replay`` reads). Returns the summary with ``dir``."""
    path, scenario_json = _scenario_arguments(scenario)
    summary_json, directory = _visors.gnss_sim(path, scenario_json, os.fspath(out), _seed(seed))
    summary = json.loads(summary_json)
    summary["dir"] = directory
    return summary


def nav_replay(run_dir: str | os.PathLike, out: str | os.PathLike = "out/nav", *, duration_s: float = 0.0,
               elevation_weighting: bool = False, float_only: bool = False, no_laser: bool = False,
               settings_file: str | os.PathLike | None = None, crosslink_drop: float = 0.0,
               crosslink_delay_s: float = 0.0, outage: tuple[float, float] | None = None) -> dict:
    """``visors nav``: replays a ``gnss_sim`` folder through each spacecraft's CDGPS filter and scores
    it. ``outage`` = (start_s, duration_s). Returns summary.json as a dict and the per-epoch
    tables ``nav_dsc`` and ``nav_osc`` as structured arrays."""
    options = _visors.NavOptions()
    options.run_dir = os.fspath(run_dir)
    options.out = os.fspath(out)
    options.duration_s = _number(duration_s, "duration_s", minimum=0.0)
    options.elevation_weighting = bool(elevation_weighting)
    options.float_only = bool(float_only)
    options.no_laser = bool(no_laser)
    options.settings_file = "" if settings_file is None else os.fspath(settings_file)
    options.crosslink_drop = _number(crosslink_drop, "crosslink_drop", minimum=0.0, maximum=1.0)
    options.crosslink_delay_s = _number(crosslink_delay_s, "crosslink_delay_s", minimum=0.0)
    if outage is not None:
        if len(outage) != 2:
            raise ValueError("outage: must be (start_s, duration_s)")
        options.outage_start_s = _number(outage[0], "outage[0]", minimum=0.0)
        options.outage_s = _number(outage[1], "outage[1]", minimum=0.0)
    _visors.nav_replay(options)
    folder = pathlib.Path(options.out)
    result = {"summary": json.loads((folder / "summary.json").read_text()), "dir": str(folder)}
    for craft in ("dsc", "osc"):
        table = folder / f"nav_{craft}.csv"
        if table.exists():
            result[f"nav_{craft}"] = read_csv(table)
    return result


def mc(campaign: str | os.PathLike, out: str | os.PathLike | None = None, *, threads: int = 0,
       resume: bool = False, keep_runs: bool = False) -> dict:
    """``visors mc``: a Monte Carlo campaign or parameter sweep, each run in its own process, into
    ``out``/results.sqlite (default out/mc/<campaign name>). Returns ``read_store`` of it."""
    options = _visors.McOptions()
    options.campaign = os.fspath(campaign)
    options.out = "" if out is None else os.fspath(out)
    options.threads = _integer(threads, "threads", 0)
    options.resume = bool(resume)
    options.keep_runs = bool(keep_runs)
    _visors.mc(options)
    if out is None:
        name = _campaign_name(options.campaign)
        out = pathlib.Path("out") / "mc" / name
    return read_store(pathlib.Path(out) / "results.sqlite")


def _campaign_name(campaign: str) -> str:
    import tomllib
    path = find_data_file(campaign)
    if path is None:
        raise ValueError(f"campaign: '{campaign}' not found (nor in VISORS_DATA_PATH or data/)")
    with open(path, "rb") as file:
        return str(tomllib.load(file)["name"])


def find_data_file(relative: str | os.PathLike) -> str | None:
    """``relative`` (e.g. "scenarios/campaign.toml") on the data search path: VISORS_DATA_PATH, the
    repository's data/, the installed share/visors/data. None when found nowhere."""
    return _visors.find_data_file(os.fspath(relative))


def _number(value: Any, field: str, minimum: float | None = None, maximum: float | None = None) -> float:
    if isinstance(value, bool) or not isinstance(value, (int, float, np.integer, np.floating)):
        raise ValueError(f"{field}: must be a number, not {type(value).__name__}")
    x = float(value)
    if not math.isfinite(x):
        raise ValueError(f"{field}: must be finite")
    if minimum is not None and x < minimum:
        raise ValueError(f"{field}: must be >= {minimum}, not {x}")
    if maximum is not None and x > maximum:
        raise ValueError(f"{field}: must be <= {maximum}, not {x}")
    return x


def read_csv(path: str | os.PathLike) -> np.ndarray:
    """A CSV table of the run directory as a numpy structured array, one field per column: float64
    where every cell is a number or empty (empty: NaN; counts and flags too, so that a column's type
    never depends on its values), text otherwise (lines starting with '#' are comments)."""
    with open(path, newline="") as file:
        rows = list(csv.reader(line for line in file if not line.startswith("#")))
    if not rows:
        raise ValueError(f"{path}: empty (no header line)")
    header, body = rows[0], rows[1:]
    for k, row in enumerate(body):
        if len(row) != len(header):
            raise ValueError(f"{path}: line {k + 2}: {len(row)} cells, the header has {len(header)}")
    columns = list(zip(*body)) if body else [()] * len(header)
    return _structured(header, [_column(cells) for cells in columns], len(body))


def _structured(names: list[str], arrays: list[np.ndarray], rows: int) -> np.ndarray:
    """One structured array of equally long columns."""
    table = np.empty(rows, dtype=[(name, array.dtype) for name, array in zip(names, arrays)])
    for name, array in zip(names, arrays):
        table[name] = array
    return table


def _column(cells: tuple[str, ...]) -> np.ndarray:
    try:
        return np.array([float(c) if c else math.nan for c in cells], dtype=np.float64)
    except ValueError:
        return np.array(cells, dtype=str)


_RUN_TABLES = ("timeseries", "navigation", "observations", "events", "alignment_samples")


def read_run(directory: str | os.PathLike) -> dict:
    """A ``visors run`` directory: ``summary`` (dict), ``dir``, and each of its tables present
    (timeseries, navigation, observations, events, alignment_samples) as a structured array."""
    folder = pathlib.Path(directory)
    summary_file = folder / "summary.json"
    if not summary_file.exists():
        raise ValueError(f"directory: {folder} holds no summary.json (not a run directory)")
    result: dict[str, Any] = {"summary": json.loads(summary_file.read_text()), "dir": str(folder)}
    for name in _RUN_TABLES:
        table = folder / f"{name}.csv"
        if table.exists():
            result[name] = read_csv(table)
    return result


def read_store(database: str | os.PathLike) -> dict:
    """A Monte Carlo results store (results.sqlite, docs/monte-carlo.md): each of its tables as a
    structured array (``runs``, ``observations``, ...) and the campaign's metadata."""
    path = pathlib.Path(database)
    if not path.exists():
        raise ValueError(f"database: {path} not found")
    connection = sqlite3.connect(f"file:{path}?mode=ro", uri=True)
    try:
        names = [row[0] for row in connection.execute(
            "SELECT name FROM sqlite_master WHERE type = 'table' AND name NOT LIKE 'sqlite_%' ORDER BY name")]
        return {name: _sql_table(connection, name) for name in names}
    finally:
        connection.close()


def _sql_table(connection: sqlite3.Connection, name: str) -> np.ndarray:
    cursor = connection.execute(f'SELECT * FROM "{name}"')
    header = [d[0] for d in cursor.description]
    rows = cursor.fetchall()
    columns = list(zip(*rows)) if rows else [()] * len(header)
    arrays = []
    for cells in columns:
        if all(isinstance(c, int) for c in cells) and cells:
            arrays.append(np.array(cells, dtype=np.int64))
        elif all(c is None or isinstance(c, (int, float)) for c in cells):
            arrays.append(np.array([math.nan if c is None else float(c) for c in cells], dtype=np.float64))
        else:
            arrays.append(np.array(["" if c is None else str(c) for c in cells], dtype=str))
    return _structured(header, arrays, len(rows))


def integer_least_squares(a: Any, Q: Any, candidates: int = 2) -> dict:
    """The ``candidates`` best integer vectors of the float ambiguities ``a`` [cycles] with
    covariance ``Q`` [cycles^2] (LAMBDA reduction, MLAMBDA search): ``candidates`` (m x n),
    ``squared_norms``, ``ratio`` (second / best), ``success_rate`` (bootstrapped) and
    ``transformation`` (Z, z = Z' a)."""
    a = np.asarray(a, dtype=np.float64)
    Q = np.asarray(Q, dtype=np.float64)
    if a.ndim != 1:
        raise ValueError(f"a: must be a vector, not of shape {a.shape}")
    if Q.shape != (a.size, a.size):
        raise ValueError(f"Q: must be {a.size} x {a.size} (the size of a), not {Q.shape}")
    return _visors.integer_least_squares(a, Q, _integer(candidates, "candidates", 1))


def _array(value: Any, shape: tuple[int, ...], field: str) -> np.ndarray:
    try:
        array = np.asarray(value, dtype=np.float64)
    except (TypeError, ValueError):
        raise ValueError(f"{field}: must be an array of numbers") from None
    if array.shape != shape:
        raise ValueError(f"{field}: must have shape {shape}, not {array.shape}")
    if not np.all(np.isfinite(array)):
        raise ValueError(f"{field}: must be finite")
    return array


def _elements(value: Any, field: str) -> str:
    """Keplerian elements {a, e, i, raan, argp, M} [m, rad] as the JSON the C++ side reads."""
    if not isinstance(value, Mapping):
        raise ValueError(f"{field}: must be a dict {{a, e, i, raan, argp, M}} [m, rad]")
    return _to_json(value, field)


def control_input_matrix(chief: Mapping[str, float], mu: float = MU_EARTH) -> np.ndarray:
    """Gamma (6 x 3, [s/m]): d(roe) = Gamma dv_rtn for an impulse dv_rtn [m/s] in the chief's RTN frame
    at the burn, the chief's Keplerian elements {a, e, i, raan, argp, M} [m, rad] at that time
    (Gauss variational equations, eccentric form; docs/algorithms/relative-motion.md#control-input-matrix)."""
    return _visors.control_input_matrix(_elements(chief, "chief"), _number(mu, "mu", minimum=1.0))


class StochasticMpc:
    """The stochastic model predictive control of the science approach (control/stochastic_mpc.hpp,
    docs/algorithms/control.md): at each navigation update, the plan is kept while the Mahalanobis
    distance of its predicted terminal error stays below the threshold, else replanned with the
    reachable-set planner. Dimensionless mean ROE; times [s] on the caller's clock."""

    def __init__(self, *, mahalanobis_threshold: float = 4.100, execution_sigma_fraction: float = 0.01,
                 execution_sigma_floor_mps: float = 1e-4, freeze_time_s: float = 851.0,
                 burn_latency_s: float = 10.0):
        self._mpc = _visors.StochasticMpc(
            _number(mahalanobis_threshold, "mahalanobis_threshold"),
            _number(execution_sigma_fraction, "execution_sigma_fraction"),
            _number(execution_sigma_floor_mps, "execution_sigma_floor_mps"),
            _number(freeze_time_s, "freeze_time_s"), _number(burn_latency_s, "burn_latency_s"))

    def set_target(self, roe_target: Any, tf: float) -> None:
        """New goal: the mean ROE ``roe_target`` (6, dimensionless) at time ``tf`` [s]; clears the plan."""
        self._mpc.set_target(_array(roe_target, (6,), "roe_target"), _number(tf, "tf"))

    def step(self, t: float, chief_mean: Mapping[str, float], roe_estimate: Any, covariance: Any) -> dict:
        """One navigation update at ``t`` [s]: the chief's mean elements at t, the estimated mean ROE
        (6) and its covariance (6 x 6). Returns ``replanned``, ``mahalanobis``, ``remaining`` (the
        impulses still to execute, (t [s], dv_rtn [m/s]) pairs) and ``roe_final_predicted``."""
        return self._mpc.step(_number(t, "t"), _elements(chief_mean, "chief_mean"),
                              _array(roe_estimate, (6,), "roe_estimate"), _array(covariance, (6, 6), "covariance"))

    @property
    def replan_count(self) -> int:
        return self._mpc.replan_count
