"""`rosgrade bench`'s LiDAR cost figures: computed right from the runs' CPU times, and produced and sane for real runs
(their values are a benchmark's, not checked here)."""
from __future__ import annotations

import pytest

from grader.recording import Recording
from grader.runtime.bench_lidar import NODES, Sample, lidar_benchmark, summarize, time_run


def test_summary_has_best_and_median_cpu_per_sim_second_ratios_spread_and_where_the_extra_goes():
    sweeps = "physics and sensors"
    without = [Sample(1.0, 0.50, 0.10, {sweeps: 0.3}), Sample(1.0, 0.40, 0.10, {sweeps: 0.2}),
               Sample(1.0, 0.60, 0.20, {sweeps: 0.4, "# runs": 1})]
    with_scan = [Sample(1.0, 0.60, 0.12, {sweeps: 0.35}), Sample(1.0, 0.70, 0.10, {sweeps: 0.5}),
                 Sample(1.0, 0.45, 0.15, {sweeps: 0.4})]
    figures = summarize("ros1", without, with_scan, 10.0)
    assert figures["ros1_without_scan_cpu_ms_per_sim_s_best"] == 50.0  # 0.5 CPU-s over 10 sim-s
    assert figures["ros1_without_scan_cpu_ms_per_sim_s_median"] == 60.0
    assert figures["ros1_with_scan_cpu_ms_per_sim_s_best"] == 60.0
    assert figures["ros1_with_scan_cpu_ms_per_sim_s_median"] == 72.0
    assert figures["ros1_scan_ratio_median"] == 1.2 and figures["ros1_scan_ratio_best"] == 1.2
    assert figures["ros1_scan_ratio_spread"] == "0.750-1.600"  # 0.6/0.8, 0.72/0.6, 0.8/0.5
    assert figures["ros1_scan_grader_extra_ms_per_sim_s"] == 10.0  # medians 0.6 against 0.5
    assert figures["ros1_scan_node_extra_ms_per_sim_s"] == 2.0
    assert figures["ros1_scan_extra_ms_per_sim_s (physics and sensors)"] == 10.0  # medians 0.4 against 0.3
    assert figures["ros1_scan_extra_ms_per_sim_s (world messages (encode, record, queue))"] == 0.0  # not timed
    assert not any("#" in name for name in figures)


@pytest.mark.slow
@pytest.mark.parametrize("flavour", ["ros1", "ros2"])
def test_only_the_subscribed_node_gets_scans(flavour, tmp_path):
    for scan in (False, True):
        script = tmp_path / f"drive_{scan}.py"
        script.write_text(NODES[flavour].format(scan=scan))
        sample = time_run(script, flavour, 2.0, tmp_path)
        assert sample.node_cpu_s > 0 and sample.grader_cpu_s > 0
        scans = list(Recording.open(tmp_path / "b.mcap").world_messages("/scan"))
        assert bool(scans) == scan, f"with scan={scan}: {len(scans)} /scan messages"


@pytest.mark.slow
def test_benchmark_gives_every_figure_for_both_client_libraries():
    figures = lidar_benchmark(sim_seconds=3.0, repeats=1)
    assert figures["scan_run_sim_seconds"] == 3.0
    for flavour in ("ros1", "ros2"):
        for kind in ("without_scan", "with_scan"):
            assert figures[f"{flavour}_{kind}_cpu_ms_per_sim_s_best"] > 0
        assert 0.5 < figures[f"{flavour}_scan_ratio_median"] < 5.0  # sane: scans cost something, not everything
        low, high = (float(v) for v in str(figures[f"{flavour}_scan_ratio_spread"]).split("-"))
        assert low <= figures[f"{flavour}_scan_ratio_median"] <= high
