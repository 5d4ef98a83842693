"""visors.gnss_sim and visors.nav_replay: a 5-minute GPS simulation of the default gnss-sim
scenario replayed through both filters, equal to `visors nav` on the same files."""
import filecmp
import pathlib
import subprocess
import tomllib

import numpy as np
import pytest

import visors


@pytest.fixture(scope="module")
def gnss_run(tmp_path_factory, source_dir) -> dict:
    with open(source_dir / "data" / "scenarios" / "gnss_sim.toml", "rb") as file:
        scenario = tomllib.load(file)
    scenario["gnss"]["duration_s"] = 300.0
    return visors.gnss_sim(scenario, out=tmp_path_factory.mktemp("gnss") / "run")


@pytest.fixture(scope="module")
def replay(gnss_run, tmp_path_factory) -> dict:
    return visors.nav_replay(gnss_run["dir"], out=tmp_path_factory.mktemp("nav") / "nav")


def test_gnss_sim_writes_the_receivers_files(gnss_run):
    folder = pathlib.Path(gnss_run["dir"])
    assert (folder / "truth.csv").exists()
    assert list(folder.glob("*.rnx"))


def test_replay_scores_both_filters(replay):
    assert replay["nav_dsc"].size > 0 and replay["nav_osc"].size > 0


@pytest.fixture(scope="module")
def cli_replay(gnss_run, visors_binary, tmp_path_factory) -> pathlib.Path:
    out = tmp_path_factory.mktemp("cli") / "nav"
    subprocess.run([visors_binary, "nav", gnss_run["dir"], "--out", str(out)], check=True, capture_output=True)
    return out


@pytest.mark.parametrize("table", ["fixes_dsc.csv", "fixes_osc.csv"])
def test_fixes_equal_the_clis(cli_replay, replay, table):
    assert filecmp.cmp(cli_replay / table, pathlib.Path(replay["dir"]) / table, shallow=False)


@pytest.mark.parametrize("craft", ["dsc", "osc"])
def test_epochs_equal_the_clis_but_the_step_time(cli_replay, replay, craft):
    # step_us is the host's wall time of each filter step: the only column that may differ.
    cli = visors.read_csv(cli_replay / f"nav_{craft}.csv")
    ours = replay[f"nav_{craft}"]
    assert cli.dtype.names == ours.dtype.names
    for name in cli.dtype.names:
        if name != "step_us":
            np.testing.assert_array_equal(cli[name], ours[name], err_msg=name)


def test_replay_of_a_folder_without_a_run_names_what_is_missing(tmp_path):
    with pytest.raises(ValueError, match=r"scenario\.toml: cannot be read \(is this a gnss-sim run directory\?\)"):
        visors.nav_replay(tmp_path, out=tmp_path / "nav")


def test_crosslink_drop_out_of_range_is_refused(tmp_path):
    with pytest.raises(ValueError, match=r"^crosslink_drop: must be <= 1"):
        visors.nav_replay(tmp_path, crosslink_drop=1.5)
