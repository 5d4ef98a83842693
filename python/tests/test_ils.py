"""Integer least squares from Python, against published closed forms."""
import math

import numpy as np
import pytest

import visors


def test_uncorrelated_case_is_the_rounding():
    # With a diagonal covariance the ILS solution is the componentwise rounding (Teunissen,
    # J. Geodesy 70, 1995): (1.2, -0.9) with 0.1-cycle sigmas -> (1, -1); runner-up (2, -1):
    # ratio (0.64 + 0.01) / (0.04 + 0.01) = 13.
    result = visors.integer_least_squares([1.2, -0.9], 0.01 * np.eye(2))
    np.testing.assert_array_equal(result["candidates"][0], [1.0, -1.0])
    assert result["ratio"] == pytest.approx(13.0, rel=1e-12)


def test_bootstrapped_success_rate_of_a_diagonal_covariance():
    # P = prod(2 Phi(1 / (2 sigma_i)) - 1) = prod erf(1 / (2 sqrt(2) sigma_i)) (Teunissen, 1998,
    # the bootstrapped success rate), sigmas 0.1 and 0.2 cycles.
    result = visors.integer_least_squares([0.1, 0.2], np.diag([0.01, 0.04]))
    expected = math.erf(1 / (2 * math.sqrt(2) * 0.1)) * math.erf(1 / (2 * math.sqrt(2) * 0.2))
    assert result["success_rate"] == pytest.approx(expected, rel=1e-12)


def test_covariance_of_the_wrong_size_is_refused():
    with pytest.raises(ValueError, match=r"^Q: must be 2 x 2"):
        visors.integer_least_squares([0.1, 0.2], np.eye(3))


def test_indefinite_covariance_is_refused():
    with pytest.raises(ValueError, match=r"^Q: is not positive definite"):
        visors.integer_least_squares([0.1, 0.2], np.array([[1.0, 2.0], [2.0, 1.0]]))
