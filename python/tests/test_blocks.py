"""The building blocks bound directly: the control input matrix and the stochastic MPC."""
import math

import numpy as np
import pytest

import visors

MU = visors.MU_EARTH
A = 6878136.3
CHIEF = {"a": A, "e": 0.0, "i": math.radians(97.8), "raan": math.radians(157.5), "argp": 0.0, "M": 0.7}


def test_control_input_matrix_of_a_circular_chief_is_the_near_circular_gve():
    # Near-circular Gauss variational equations of the quasi-nonsingular ROE (D'Amico, PhD thesis,
    # TU Delft 2010, eq. 2.38), u = argp + M, times n a:
    #   da: (0, 2, 0); dlambda: (-2, 0, 0); dex: (sin u, 2 cos u, 0); dey: (-cos u, 2 sin u, 0);
    #   dix: (0, 0, cos u); diy: (0, 0, sin u).
    u = CHIEF["argp"] + CHIEF["M"]
    expected = np.array([[0, 2, 0], [-2, 0, 0], [math.sin(u), 2 * math.cos(u), 0],
                         [-math.cos(u), 2 * math.sin(u), 0], [0, 0, math.cos(u)], [0, 0, math.sin(u)]])
    n = math.sqrt(MU / A ** 3)
    np.testing.assert_allclose(visors.control_input_matrix(CHIEF) * n * A, expected, atol=1e-12)


def test_control_input_matrix_names_a_bad_element():
    with pytest.raises(ValueError, match=r"^chief\.e: "):
        visors.control_input_matrix({**CHIEF, "e": 1.5})


def test_control_input_matrix_refuses_an_unknown_key():
    with pytest.raises(ValueError, match=r"^chief\.ecc: is not a recognised field"):
        visors.control_input_matrix({**CHIEF, "ecc": 0.0})


def test_mpc_plans_towards_its_target_and_keeps_a_good_plan():
    # From standby to the science orbit in 2 orbits with an exact estimate: the first step plans
    # (no plan yet: infinite distance), the plan's predicted end is the target, and a second step
    # on the same (still exact) estimate keeps it.
    chief = {**CHIEF, "e": 0.004, "argp": math.radians(90.0), "M": 0.0}
    standby = np.array([0, 0, 0, 200, 0, 200.0]) / A
    science = np.array([-2.62, 45.21, -34.51, 4.78, -18.72, 2.72]) / A
    period = 2 * math.pi * math.sqrt(A ** 3 / MU)
    mpc = visors.StochasticMpc()
    mpc.set_target(science, 2 * period)
    covariance = np.eye(6) * (0.01 / A) ** 2
    first = mpc.step(0.0, chief, standby, covariance)
    assert first["replanned"]
    assert math.isinf(first["mahalanobis"])
    assert A * np.linalg.norm(first["roe_final_predicted"] - science) < 1e-3  # [m]
    second = mpc.step(0.0, chief, standby, covariance)
    assert not second["replanned"]
    assert mpc.replan_count == 1


def test_mpc_refuses_a_covariance_of_the_wrong_shape():
    mpc = visors.StochasticMpc()
    with pytest.raises(ValueError, match=r"^covariance: must have shape \(6, 6\)"):
        mpc.step(0.0, CHIEF, np.zeros(6), np.eye(5))


def test_mpc_refuses_a_step_without_a_target():
    mpc = visors.StochasticMpc()
    with pytest.raises(ValueError, match=r"target"):
        mpc.step(0.0, CHIEF, np.zeros(6), np.eye(6) * 1e-12)
