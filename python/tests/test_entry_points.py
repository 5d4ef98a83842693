"""The three fixed entry points: __version__, tool(), and the errors they raise."""
import json
import subprocess

import numpy as np
import pytest

import visors

CHIEF = {"a": 6878136.3, "e": 0.004, "i": 1.7069, "raan": 2.7489, "argp": 1.5708, "M": 0.0}


def test_version_is_the_programs(visors_binary):
    # One version source (CMake's project(VERSION)): the program prints "visors <version>".
    printed = subprocess.run([visors_binary, "--version"], capture_output=True, text=True, check=True).stdout
    assert printed.split()[-1] == visors.__version__


def test_every_tool_of_the_program_is_reachable(visors_binary):
    listing = subprocess.run([visors_binary, "tool", "--help"], capture_output=True, text=True).stdout
    for name in visors.tool_names():
        assert name in listing


def test_tool_answers_as_the_cli_does_bit_for_bit(visors_binary):
    # `visors tool plan` on stdin/stdout and visors.tool("plan") in-process: the same JSON text.
    request = {"chief": CHIEF, "roe_start": [0, 0, 0, 200, 0, 200],
               "roe_target": [-2.62, 45.21, -34.51, 4.78, -18.72, 2.72], "tf": 9000.0, "algorithm": "closed-form"}
    cli = subprocess.run([visors_binary, "tool", "plan"], input=json.dumps(request), capture_output=True,
                         text=True, check=True).stdout
    assert visors.tool("plan", request) == json.loads(cli)


def test_tool_takes_numpy_arrays():
    request = {"chief": CHIEF, "roe_start": np.array([0, 0, 0, 200, 0, 200.0]),
               "roe_target": np.array([-2.62, 45.21, -34.51, 4.78, -18.72, 2.72]), "tf": np.float64(9000.0),
               "algorithm": "closed-form"}
    assert visors.tool("plan", request)["dv_total"] > 0.0


def test_refused_request_names_the_field():
    with pytest.raises(ValueError, match=r"^tf: must be after t0"):
        visors.tool("plan", {"chief": CHIEF, "roe_start": [0] * 6, "roe_target": [0] * 6, "tf": -1.0,
                             "algorithm": "closed-form"})


def test_unknown_field_is_refused():
    with pytest.raises(ValueError, match=r"^horizn: is not a recognised field"):
        visors.tool("safety", {"chief": CHIEF, "roe": [0] * 6, "horizn": 1.0, "plane": "rn", "q": 3})


def test_unknown_tool_is_refused():
    with pytest.raises(ValueError, match=r"^name: no tool 'plann'"):
        visors.tool("plann", {})


def test_request_must_be_a_dict():
    with pytest.raises(ValueError, match=r"^request: must be a dict"):
        visors.tool("plan", [1, 2])


def test_nan_in_a_request_is_refused():
    with pytest.raises(ValueError, match=r"^request: "):
        visors.tool("plan", {"tf": float("nan")})
