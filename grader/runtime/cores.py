"""How many cores this process may use: what `-j` defaults to, so a container's CPU quota is respected."""
from __future__ import annotations

import os
from pathlib import Path

CGROUP_ROOT = Path("/sys/fs/cgroup")
OWN_CGROUP = Path("/proc/self/cgroup")


def _v2_quota(folder: Path) -> float | None:
    """Cores a cgroup v2 folder's cpu.max ("<quota> <period>" µs, or "max <period>") allows; None: no limit."""
    try:
        quota, period = (folder / "cpu.max").read_text().split()
        return None if quota == "max" else int(quota) / int(period)
    except (OSError, ValueError):
        return None


def _v1_quota(folder: Path) -> float | None:
    """Cores a cgroup v1 cpu folder allows (cpu.cfs_quota_us, -1 for none, over cpu.cfs_period_us)."""
    try:
        quota = int((folder / "cpu.cfs_quota_us").read_text())
        period = int((folder / "cpu.cfs_period_us").read_text())
        return None if quota <= 0 or period <= 0 else quota / period
    except (OSError, ValueError):
        return None


def _with_parents(root: Path, path: str) -> list[Path]:
    folder = root / path.strip().lstrip("/")
    return [folder, *folder.parents[: len(folder.relative_to(root).parts)]]


def _quotas() -> list[float]:
    """Every CPU quota that applies to this process: its cgroup and those above it, v2 and v1 (Docker's)."""
    folders: list[tuple[Path, bool]] = [(CGROUP_ROOT, True), (CGROUP_ROOT / "cpu", False)]  # a container's own
    try:
        lines = OWN_CGROUP.read_text().splitlines()
    except OSError:
        lines = []
    for line in lines:
        _, controllers, path = (line.split(":", 2) + ["", ""])[:3]
        if line.startswith("0::"):
            folders += [(f, True) for f in _with_parents(CGROUP_ROOT, path)]
        elif "cpu" in controllers.split(","):
            folders += [(f, False) for f in _with_parents(CGROUP_ROOT / "cpu", path)]
    found = (_v2_quota(folder) if v2 else _v1_quota(folder) for folder, v2 in folders)
    return [q for q in found if q is not None]


def available_cores() -> int:
    """Cores this process may use: its CPU affinity, capped by the tightest CPU quota of its cgroups."""
    try:
        cores = len(os.sched_getaffinity(0))
    except (AttributeError, OSError):
        cores = os.cpu_count() or 1
    quotas = _quotas()
    if quotas:
        cores = min(cores, max(1, round(min(quotas))))
    return max(1, cores)
