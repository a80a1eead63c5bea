"""Measured totals and means come out the same bits whatever order the CPU's kernels add in."""
from __future__ import annotations

import math

import numpy as np

from grader.metrics import exact


def test_a_total_does_not_depend_on_the_order_of_its_terms():
    values = np.random.default_rng(3).normal(size=10_000) * np.logspace(-8, 8, 10_000)
    orders = [values, values[::-1], np.random.default_rng(4).permutation(values)]
    assert len({exact.total(v).hex() for v in orders}) == 1
    # numpy's own sum, for contrast, is not order-free: the reason the metrics do not use it for measured totals.
    assert len({float(np.sum(v)).hex() for v in orders}) > 1


def test_total_and_mean_are_the_correctly_rounded_values():
    values = [0.1] * 10 + [1e16, 1.0, -1e16]
    assert exact.total(values) == math.fsum(values) == 2.0
    assert exact.mean(np.array(values)) == 2.0 / 13


def test_the_mean_of_nothing_is_nan():
    assert math.isnan(exact.mean([]))
