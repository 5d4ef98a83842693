"""visors.mc and read_store: a tiny sweep, each run in its own process, read back as arrays."""
import sqlite3

import numpy as np
import pytest

import visors

BASE = "[campaign]\nstandby_s = 0.0\nobservations = 0\ntail_s = 120.0\n[navigation]\nmode = \"ideal\"\n"
CAMPAIGN = """name = "tiny"
scenario = "base.toml"
seed = 7
runs_per_value = 2
time_limit_s = 120.0
[[sweep]]
key = "crosslink.delay_s"
values = [0.5, 1.0]
"""


@pytest.fixture(scope="module")
def store(tmp_path_factory) -> tuple[dict, object]:
    folder = tmp_path_factory.mktemp("mc")
    (folder / "base.toml").write_text(BASE)
    (folder / "campaign.toml").write_text(CAMPAIGN)
    return visors.mc(folder / "campaign.toml", out=folder / "out", threads=2), folder / "out" / "results.sqlite"


def test_every_run_is_stored_once(store):
    runs = store[0]["runs"]
    np.testing.assert_array_equal(np.sort(runs["run"]), [0, 1, 2, 3])


def test_swept_values_are_the_campaigns(store):
    runs = store[0]["runs"]
    assert sorted(runs["sweep_value_text"]) == ["0.5", "0.5", "1.0", "1.0"]


def test_tables_equal_sqlites_own_count(store):
    tables, path = store
    with sqlite3.connect(path) as connection:
        for name, table in tables.items():
            assert table.size == connection.execute(f'SELECT COUNT(*) FROM "{name}"').fetchone()[0], name


def test_missing_store_is_refused(tmp_path):
    with pytest.raises(ValueError, match=r"^database: .* not found"):
        visors.read_store(tmp_path / "none.sqlite")


def test_negative_threads_are_refused(tmp_path):
    with pytest.raises(ValueError, match=r"^threads: must be a non-negative integer"):
        visors.mc(tmp_path / "campaign.toml", threads=-1)


def test_bad_campaign_names_its_field(tmp_path):
    (tmp_path / "campaign.toml").write_text('name = "x"\nscenario = "base.toml"\nruns_per_value = 0\n')
    (tmp_path / "base.toml").write_text(BASE)
    with pytest.raises(ValueError, match=r"runs_per_value"):
        visors.mc(tmp_path / "campaign.toml", out=tmp_path / "out")


def test_store_example_reads_it(store, source_dir):
    # examples/monte_carlo_store.py on this store, without its figure: one line per swept value.
    import subprocess
    import sys
    printed = subprocess.run([sys.executable, str(source_dir / "examples" / "monte_carlo_store.py"), str(store[1]),
                              "--no-plot"], capture_output=True, text=True, check=True).stdout
    assert "swept key 'crosslink.delay_s'" in printed
    assert len([line for line in printed.splitlines() if line.strip().startswith(("0.5 ", "1 "))]) == 2
