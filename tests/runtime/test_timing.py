"""Stage timing for `rosgrade bench`: exclusive stages that add up, absorbing stages, nothing kept when off."""
from __future__ import annotations

import time

from grader import timing


def test_nothing_is_kept_when_not_collecting() -> None:
    with timing.stage("plots"):
        timing.add("physics and sensors", 1.0)
        timing.count("runs")
    assert not timing.enabled() and timing.snapshot() == {}


def test_a_nested_stage_is_taken_out_of_the_one_around_it() -> None:
    with timing.collect() as stages:
        with timing.stage("plots"):
            time.sleep(0.02)
            with timing.stage("reading recordings"):
                time.sleep(0.03)
    assert 0.015 < stages["plots"] < 0.028 and stages["reading recordings"] >= 0.03


def test_an_absorbing_stage_keeps_what_is_timed_inside_it() -> None:
    with timing.collect() as stages:
        with timing.stage("node start-up", absorb=True):
            timing.add("waiting for nodes", 5.0)
            time.sleep(0.01)
    assert "waiting for nodes" not in stages and stages["node start-up"] >= 0.01


def test_counters_and_merging_another_process_snapshot() -> None:
    with timing.collect() as stages:
        timing.count("runs", 2)
        timing.merge({"# runs": 3.0, "plots": 1.5})
        timing.merge({"plots": 0.5})
    assert stages == {"# runs": 5.0, "plots": 2.0}


def test_restart_forgets_but_keeps_collecting() -> None:
    with timing.collect() as stages:
        timing.add("plots", 1.0)
        timing.restart()
        timing.add("scoring", 2.0)
    assert stages == {"scoring": 2.0}


def test_an_absorbing_stage_keeps_what_stages_inside_it_time() -> None:
    with timing.collect() as stages:
        with timing.stage("node start-up", absorb=True):
            with timing.stage("node steps"):
                timing.add("waiting for nodes", 5.0)
                time.sleep(0.01)
    assert set(stages) == {"node start-up"} and stages["node start-up"] >= 0.01
