"""visors.run against `visors run`: the same scenario gives the same run directory, bit for bit."""
import filecmp
import json
import pathlib
import subprocess

import numpy as np
import pytest

import visors

# 300 s of standby in closed loop with the default carrier-phase GPS navigation, from t0: the
# flight software, the truth and the recorder all run, in a fraction of a second.
SHORT = {"campaign": {"standby_s": 0.0, "observations": 0, "tail_s": 300.0}}
SHORT_TOML = "[campaign]\nstandby_s = 0.0\nobservations = 0\ntail_s = 300.0\n"

# Summary fields that measure the host, not the run.
HOST_FIELDS = ("wall_s", "flight_step_us")


def host_independent(summary: dict) -> dict:
    return {k: v for k, v in summary.items() if not any(k.startswith(h) for h in HOST_FIELDS)}


@pytest.fixture(scope="module")
def cli_run(tmp_path_factory, visors_binary) -> pathlib.Path:
    folder = tmp_path_factory.mktemp("cli")
    (folder / "short.toml").write_text(SHORT_TOML)
    subprocess.run([visors_binary, "run", str(folder / "short.toml"), "--out", str(folder / "run"), "--threads", "1"],
                   check=True, capture_output=True)
    return folder / "run"


@pytest.fixture(scope="module")
def python_run(tmp_path_factory) -> dict:
    return visors.run(SHORT, out=tmp_path_factory.mktemp("py") / "run")


@pytest.mark.parametrize("table", ["timeseries.csv", "navigation.csv", "observations.csv", "events.csv",
                                   "scenario.toml"])
def test_tables_equal_the_clis(cli_run, python_run, table):
    assert filecmp.cmp(cli_run / table, pathlib.Path(python_run["dir"]) / table, shallow=False)


def test_summary_equals_the_clis(cli_run, python_run):
    cli = json.loads((cli_run / "summary.json").read_text())
    assert host_independent(python_run["summary"]) == host_independent(cli)


def test_time_series_as_a_structured_array(python_run):
    series = python_run["timeseries"]
    assert series.dtype["t_s"] == np.float64
    assert series["mode"].dtype.kind == "U"
    # output_step_s 10 over [0, 300] s.
    np.testing.assert_array_equal(series["t_s"][:3], [0.0, 10.0, 20.0])


def test_navigation_rows_are_both_spacecraft(python_run):
    assert set(python_run["navigation"]["spacecraft"]) == {"dsc", "osc"}


def test_temporary_run_is_removed_and_its_data_kept():
    result = visors.run(SHORT, seed=3)
    assert result["dir"] is None
    assert result["summary"]["seed"] == 3
    assert result["timeseries"].size > 0


def test_seed_is_applied(python_run):
    assert python_run["summary"]["seed"] == 1


def test_unknown_key_is_refused_naming_it():
    with pytest.raises(ValueError, match=r"campaign\.standby"):
        visors.run({"campaign": {"standby": 1.0}})


def test_bad_value_is_refused_naming_it():
    with pytest.raises(ValueError, match=r"campaign\.observations"):
        visors.run({"campaign": {"observations": -1}})


def test_missing_scenario_file_is_refused():
    with pytest.raises(ValueError, match=r"^scenario: 'no_such.toml' not found"):
        visors.run("no_such.toml")


def test_negative_seed_is_refused():
    with pytest.raises(ValueError, match=r"^seed: must be a non-negative integer"):
        visors.run(SHORT, seed=-1)


def test_scenario_of_the_wrong_type_is_refused():
    with pytest.raises(ValueError, match=r"^scenario: must be a path or a dict"):
        visors.run(42)

