"""sph_soil.verification: the observed order, Richardson's extrapolate and Roache's GCI of a
sequence of answers at halving spacings."""
import math

import pytest

from sph_soil import verification as v


def test_second_order_sequence_gives_order_two_and_the_exact_answer():
    # f(d) = 1 + 0.5 d^2 at d = 4, 2, 1: differences 6, 1.5
    f = [1 + 0.5 * d * d for d in (4.0, 2.0, 1.0)]
    p = v.observed_order(*f)
    assert p == pytest.approx(2.0, abs=1e-12)
    assert v.richardson(f[1], f[2], p) == pytest.approx(1.0, abs=1e-12)
    # GCI = 1.25 |(1.5 - 3) / 1.5| / 3
    assert v.grid_convergence_index(f[1], f[2], p) == pytest.approx(1.25 * 1.0 / 3.0, rel=1e-12)


def test_first_order_at_ratio_three():
    f = [2.0 + 0.1 * d for d in (9.0, 3.0, 1.0)]
    p = v.observed_order(*f, ratio=3.0)
    assert p == pytest.approx(1.0, abs=1e-12)
    assert v.richardson(f[1], f[2], p, ratio=3.0) == pytest.approx(2.0, abs=1e-12)


def test_oscillating_or_flat_sequences_have_no_order():
    assert v.observed_order(1.0, 1.2, 1.1) is None      # up, then down
    assert v.observed_order(1.0, 1.0, 1.1) is None      # a zero difference
    assert v.richardson(1.2, 1.1, None) is None
    assert v.grid_convergence_index(1.2, 1.1, None) is None


def test_diverging_sequence_has_a_negative_order_and_no_extrapolate():
    # differences growing as the spacing halves: finer is farther
    p = v.observed_order(1.0, 1.01, 1.03)
    assert p == pytest.approx(-1.0, abs=1e-12)
    assert v.richardson(1.01, 1.03, p) is None


def test_differences_alone():
    assert v.order_of_differences(1.42, 1.28) == pytest.approx(math.log2(1.42 / 1.28))
    assert v.order_of_differences(1.0, -0.5) is None


def test_sequence_of_four_answers():
    spacings = [0.04, 0.02, 0.01, 0.005]
    answers = [1 + 3.0 * d for d in spacings]
    rows = v.sequence(spacings, answers)
    assert len(rows) == 2
    for row in rows:
        assert row["observed_order"] == pytest.approx(1.0, abs=1e-9)
        assert row["extrapolated"] == pytest.approx(1.0, abs=1e-9)
    with pytest.raises(ValueError):
        v.sequence([0.04, 0.02, 0.005], [1.0, 1.0, 1.0])
    with pytest.raises(ValueError):
        v.sequence([0.04, 0.02], [1.0])
