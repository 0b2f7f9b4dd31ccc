"""curtainCase -steadyFrom: the first iteration the steady window may end a run at
(setUp.check_from), its default (one window, for runs from still gas and warm
starts alike) and its refusals."""

import os

import pytest

from flightedDryer import PROJECT
from flightedDryer.curtain.inputs import check_inputs
from flightedDryer.curtain.setUp import check_from
from flightedDryer.errors import InputError

BASE = {"-dir": "unused", "-gasVelocity": "1", "-spillRate": "3", "-fallHeight": "2",
        "-flightLength": "1.133", "-density": "1590", "-diameters": "8.5e-4", "-fractions": "1",
        "-template": os.path.join(PROJECT, "etc", "templates", "curtain", "windTunnelMULES")}


def inputs(**extra):
    opts = dict(BASE)
    opts.update({"-" + k: v for k, v in extra.items()})
    return check_inputs(opts)


def test_the_default_is_one_window_from_still_gas_and_from_a_neighbour():
    s = inputs(iterations="300")
    assert (s["window"], check_from(s)) == (50, 50)
    s["startFrom"] = "neighbour"
    assert check_from(s) == 50
    s = inputs(iterations="60")
    assert (s["window"], check_from(s)) == (20, 20)


def test_a_given_iteration_is_the_first_the_window_may_end_at():
    assert check_from(inputs(iterations="300", steadyFrom="150")) == 150
    assert check_from(inputs(iterations="300", steadyFrom="0")) == 0


@pytest.mark.parametrize("value,match", [
    ("301", r"-steadyFrom = 301 iterations outside the allowed range \[0, 300\]"),
    ("-1", r"-steadyFrom = -1 iterations outside the allowed range \[0, 300\]"),
    ("nan", r"-steadyFrom = nan iterations outside the allowed range"),
    ("12.5", r"-steadyFrom = 12.5 is not a whole number of iterations"),
    ("ten", r"-steadyFrom = 'ten' is not a number"),
])
def test_bad_values_are_refused_with_the_range(value, match):
    with pytest.raises(InputError, match=match):
        inputs(iterations="300", steadyFrom=value)
