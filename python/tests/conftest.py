"""Shared fixtures: the `visors` program of the same build (for CLI-against-Python comparisons)
and the source tree (examples/)."""
import os
import pathlib

import pytest


@pytest.fixture(scope="session")
def visors_binary() -> str:
    binary = os.environ.get("VISORS_BINARY")
    if not binary or not pathlib.Path(binary).exists():
        pytest.fail("VISORS_BINARY must name the visors program of this build (CTest sets it)")
    return binary


@pytest.fixture(scope="session")
def source_dir() -> pathlib.Path:
    return pathlib.Path(os.environ.get("VISORS_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))
