"""Sums and means that are the same bits on every CPU: numpy's kernels add in an order chosen for the CPU (AVX-512
lanes on one grader, AVX2 on another), so a measured total would differ in its last bits between machines."""
from __future__ import annotations

import math
from collections.abc import Iterable

import numpy as np


def total(values: np.ndarray | Iterable[float]) -> float:
    """The correctly rounded sum (math.fsum): independent of order, hence of the CPU."""
    return math.fsum(np.asarray(values, dtype=float).ravel().tolist())


def mean(values: np.ndarray | Iterable[float]) -> float:
    """The correctly rounded sum over the count (nan when empty, as numpy's mean with a warning)."""
    flat = np.asarray(values, dtype=float).ravel()
    return math.fsum(flat.tolist()) / flat.size if flat.size else math.nan
