"""The physics benchmark runs and reports its figures (speed itself is measured with ``python -m sim.bench``, not here)."""
from __future__ import annotations

from sim.bench import physics_benchmark


def test_benchmark_reports_world_and_raw_rates() -> None:
    result = physics_benchmark("turtlebot3_waffle", sim_seconds=1.0)
    assert result["steps"] == 600
    # odometry, /tf, ground truth, the scripted command, /imu, /joint_states, /scan
    assert result["samples"] == 30 + 30 + 50 + 1 + 200 + 30 + 5
    for key in ("rtf", "cpu_rtf", "steps_per_s", "raw_rtf", "raw_steps_per_s", "raw_cpu_rtf"):
        assert isinstance(result[key], float) and result[key] > 0


def test_benchmark_times_world_set_up_first_and_from_the_cached_model() -> None:
    result = physics_benchmark("turtlebot3_burger", sim_seconds=0.5)
    assert isinstance(result["world_setup_cpu_s"], float) and result["world_setup_cpu_s"] >= 0
    assert isinstance(result["world_setup_cached_cpu_s"], float) and result["world_setup_cached_cpu_s"] >= 0
