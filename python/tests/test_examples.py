"""examples/formation_design.py runs (without its figure) and its table holds what the building
blocks promise."""
import subprocess
import sys


def test_formation_design_example(source_dir):
    printed = subprocess.run([sys.executable, str(source_dir / "examples" / "formation_design.py"), "--no-plot"],
                             capture_output=True, text=True, check=True).stdout
    rows = [line.split() for line in printed.splitlines() if line.strip() and line.split()[0].replace(".", "").isdigit()]
    assert len(rows) == 6
    # A parallel e/i vector formation of size d keeps a minimum RN separation close to d (D'Amico &
    # Montenbruck, JGCD 29(3), 2006): every row at least half of it.
    for d, min_rn, *_ in rows:
        assert float(min_rn) > 0.5 * float(d)
