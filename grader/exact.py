"""Sums, means and atan2 that are the same bits on every CPU. numpy picks its kernels for the CPU it runs on (AVX-512
lanes on one grader, AVX2 on another): its sums add in another order and its arctan2 rounds otherwise, so a yaw or
a measured total would differ in its last bits between machines."""
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


def atan2(y: np.ndarray, x: np.ndarray) -> np.ndarray:
    """Element-wise atan2 from the C library, for arrays of any shape (numpy's arctan2 has per-CPU kernels)."""
    pairs = zip(np.asarray(y, dtype=float).ravel().tolist(), np.asarray(x, dtype=float).ravel().tolist())
    return np.array([math.atan2(a, b) for a, b in pairs], dtype=float).reshape(np.shape(y))
