"""Measured totals, means and angles come out the same bits whatever kernels the CPU gives numpy."""
from __future__ import annotations

import math

import numpy as np

from grader import exact


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


def test_atan2_is_the_c_librarys_element_by_element_and_keeps_the_shape():
    y = np.random.default_rng(5).normal(size=(3, 400))
    x = np.random.default_rng(6).normal(size=(3, 400))
    got = exact.atan2(y, x)
    assert got.shape == (3, 400)
    assert [v.hex() for v in got.ravel().tolist()] == [math.atan2(a, b).hex() for a, b in zip(y.ravel(), x.ravel())]
