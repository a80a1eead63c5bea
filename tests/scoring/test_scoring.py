"""score_task on synthetic runs: full marks when ideal, the expected partial credit and feedback when flawed."""
from __future__ import annotations

from collections.abc import Sequence
from types import SimpleNamespace

import numpy as np
import pytest
from scoring_synth import Segment, commands, path, run, square_segments

from grader.metrics import OutputLine, RunData, RunInfo
from grader.rubric import Rubric, Scenario, load_rubrics
from grader.scoring import score_task

RUBRICS = load_rubrics()


def _scenario_run(s: Scenario, segments: Sequence[Segment], command_segments: Sequence[Segment] | None = None,
                  lines: Sequence[OutputLine] = (), ground_truth: bool = True) -> RunData:
    """A run of ``segments`` from the scenario's pose and clock, with Ctrl+C (if any) recorded as requested."""
    shutdown = None if s.shutdown_at is None else s.start_time + s.shutdown_at
    info = RunInfo(shutdown_requested_s=shutdown, exit_code=0, status="exited",
                   ended_s=None if shutdown is None else shutdown + 0.6)
    p = s.initial_pose
    return run(segments, x0=p.x, y0=p.y, yaw0=p.yaw, t0=s.start_time, command_segments=command_segments,
               lines=lines, info=info, shutdown_at=s.shutdown_at, ground_truth=ground_truth)


def _circle_runs(rubric: Rubric, v: float, w: float, hook_publishes_zero: bool, **kw: object) -> dict[str, RunData]:
    runs = {}
    for s in rubric.scenarios:
        assert s.shutdown_at is not None
        drive = [(s.shutdown_at, v, w)]
        after = [(0.2, v / 2, w / 2), (4.8, 0.0, 0.0)] if hook_publishes_zero else [(5.0, v, w)]
        cmds = drive + [(0.1, 0.0, 0.0)] if hook_publishes_zero else drive
        runs[s.name] = _scenario_run(s, drive + after, cmds, **kw)  # type: ignore[arg-type]
    return runs


def _by_id(report: object) -> dict:
    return {c.id: c for c in report.criteria}  # type: ignore[attr-defined]


def test_ideal_circle_gets_full_marks_in_every_scenario() -> None:
    report = score_task(RUBRICS["move_circle"], _circle_runs(RUBRICS["move_circle"], 0.1, 0.2, True))
    assert (report.status, report.score, report.max_score) == ("graded", 10.0, 10.0)
    assert all(c.passed for c in report.criteria) and report.diagnostics == []
    assert "radius 0.50 m" in _by_id(report)["radius"].feedback


def test_equal_speeds_and_a_flag_only_hook() -> None:
    report = score_task(RUBRICS["move_circle"], _circle_runs(RUBRICS["move_circle"], 0.2, 0.2, False))
    c = _by_id(report)
    assert c["radius"].score == 0.0 and c["radius"].measured["radius"] == pytest.approx(1.0, abs=1e-3)
    assert "v/ω = 0.20/0.20 = 1.00 m" in c["radius"].feedback and "ω = 0.40 rad/s" in c["radius"].feedback
    assert c["shutdown_stop"].score == 0.0 and "must publish a zero Twist" in c["shutdown_stop"].feedback
    assert "still moving 5 s after Ctrl+C" in c["shutdown_stop"].feedback
    assert c["velocity_limits"].passed
    assert report.score == 2.0


def test_swapped_speeds_are_named() -> None:
    report = score_task(RUBRICS["move_circle"], _circle_runs(RUBRICS["move_circle"], 0.2, 0.1, True))
    assert "did you swap linear and angular" in _by_id(report)["radius"].feedback


def test_hook_called_at_registration_crashes_the_node() -> None:
    crash = [OutputLine(0.1, "stderr", "Traceback (most recent call last):"),
             OutputLine(0.1, "stderr", '  File "move_circle.py", line 14, in __init__'),
             OutputLine(0.1, "stderr", "TypeError: shutdown hook [None] must be a function or callable object: "
                                       "<class 'NoneType'>")]
    rubric = RUBRICS["move_circle"]
    runs = {s.name: _scenario_run(s, [(s.duration, 0.0, 0.0)], [(0.01, 0.0, 0.0)], lines=crash)
            for s in rubric.scenarios}
    c = _by_id(score_task(rubric, runs))
    assert c["radius"].score == 0 and "Could not measure this" in c["radius"].feedback
    assert "calls the hook immediately" in c["shutdown_stop"].feedback
    assert c["shutdown_stop"].score == 0


def test_partial_credit_for_a_small_overshoot() -> None:
    rubric = RUBRICS["move_distance"]
    runs = {}
    for s in rubric.scenarios:
        dist = 3.10 - s.initial_pose.x
        runs[s.name] = _scenario_run(s, [(dist / 0.2, 0.2, 0.0), (s.duration - dist / 0.2, 0.0, 0.0)])
    c = _by_id(score_task(rubric, runs))
    assert c["stop_position"].score == pytest.approx(3.2)  # 0.05 m past the bounds of a 0.25 m margin: 80 %
    assert not c["stop_position"].passed and c["stays_stopped"].passed
    assert "x = 3.100 m" in c["stop_position"].feedback


def test_one_failing_hidden_variant_sets_the_credit_and_is_named() -> None:
    rubric = RUBRICS["move_distance"]
    runs = {}
    for s in rubric.scenarios:
        # Drives 3 m from wherever it starts: right from (0, 0), wrong from (-2.0, -0.5).
        runs[s.name] = _scenario_run(s, [(15.1, 0.2, 0.0), (s.duration - 15.1, 0.0, 0.0)])
    c = _by_id(score_task(rubric, runs))["stop_position"]
    assert c.score == 0 and c.scenario == "world_start"
    assert c.feedback.startswith("In scenario 'world_start' (starts at (-2.0, -0.5)")
    assert "The robot started at x = -2.00 m" in c.feedback


def test_missing_scenario_scores_zero_and_says_why() -> None:
    rubric = RUBRICS["move_circle"]
    runs = _circle_runs(rubric, 0.1, 0.2, True)
    del runs["wheel_error"]
    report = score_task(rubric, runs)
    assert report.score == 0.0
    assert all("'wheel_error' has no recording" in c.feedback for c in report.criteria)
    assert any("'wheel_error' was not recorded" in d for d in report.diagnostics)


def test_without_ground_truth_it_scores_from_odometry_and_says_so() -> None:
    rubric = RUBRICS["move_circle"]
    report = score_task(rubric, _circle_runs(rubric, 0.1, 0.2, True, ground_truth=False))
    assert report.score == report.max_score
    assert len(report.diagnostics) == 3 and "scored from odometry" in report.diagnostics[0]


def test_scores_are_deterministic_and_json_safe() -> None:
    rubric = RUBRICS["move_circle"]
    a = score_task(rubric, _circle_runs(rubric, 0.2, 0.2, False)).model_dump_json()
    b = score_task(rubric, _circle_runs(rubric, 0.2, 0.2, False)).model_dump_json()
    assert a == b and "NaN" not in a and "Infinity" not in a


def test_two_loop_square_full_marks_and_one_loop_loses_only_two_loop_stop() -> None:
    rubric = RUBRICS["move_square"]

    def runs(loops: int) -> dict[str, RunData]:
        out = {}
        for s in rubric.scenarios:
            segs = square_segments(loops=loops, v=0.2, w=0.5)
            if s.shutdown_at is not None:  # interrupted mid-side: the hook stops the robot at once
                segs = [(s.shutdown_at, 0.2, 0.0), (s.duration - s.shutdown_at, 0.0, 0.0)]
            total = sum(d for d, _, _ in segs)
            out[s.name] = _scenario_run(s, segs + [(s.duration - total, 0.0, 0.0)] if total < s.duration else segs)
        return out

    full = score_task(rubric, runs(2))
    assert full.score == full.max_score, [(c.id, c.feedback) for c in full.criteria if not c.passed]
    one = _by_id(score_task(rubric, runs(1)))
    assert [k for k, c in one.items() if not c.passed] == ["two_loop_stop"]
    assert one["two_loop_stop"].score == 0.0 and "stopped after one loop" in one["two_loop_stop"].feedback


def test_odom_subscriber_prints_scored_against_odometry() -> None:
    rubric = RUBRICS["odom_subscriber"]
    runs = {}
    for s in rubric.scenarios:
        script = [(1.0, 0.0, 0.0)] + [(b.t - a.t, a.linear[0], a.angular[2]) for a, b in zip(s.script, s.script[1:])]
        script.append((s.duration - s.script[-1].t, 0.0, 0.0))
        odom = path(script, s.initial_pose.x, s.initial_pose.y, s.initial_pose.yaw, s.start_time)
        lines = [OutputLine(float(t) + 0.002, "stdout", f"x={x:.2f} y={y:.2f} yaw={np.degrees(a):.1f}")
                 for t, x, y, a in zip(odom.t, odom.x, odom.y, odom.yaw)]
        runs[s.name] = RunData(odometry=odom, lines=tuple(lines), start_time=s.start_time, shutdown_at=s.shutdown_at)
    report = score_task(rubric, runs)
    assert report.score == report.max_score
    assert _by_id(report)["pose_output"].measured["yaw_unit"] == "degrees"


def test_recording_objects_are_adapted() -> None:
    """The documented Recording API (DEVELOPERS.md) is read into arrays, driver commands left out."""
    rubric = RUBRICS["husky_distance"]
    recs = {}
    for s in rubric.scenarios:
        segs = [(10.2, 1.0, 0.0), (s.duration - 10.2, 0.0, 0.0)]
        p = s.initial_pose
        traj = path(segs, p.x, p.y, p.yaw, s.start_time)
        series = SimpleNamespace(t=traj.t, x=traj.x, y=traj.y, yaw=traj.yaw, vx=traj.t * 0, wz=traj.t * 0)
        cmd = commands(segs, s.start_time)
        cmd_series = SimpleNamespace(
            t=np.append(cmd.t, s.start_time), linear=np.vstack([cmd.linear, [[5.0, 0, 0]]]),
            angular=np.vstack([cmd.angular, [[0, 0, 0]]]), topic=["/husky_velocity_controller/cmd_vel"] * (len(cmd) + 1),
            callerid=["/ctrl_husky"] * len(cmd) + ["/rosgrade_driver"],
        )
        recs[s.name] = SimpleNamespace(
            odometry=lambda series=series: series, ground_truth=lambda: None, commands=lambda c=cmd_series: c,
            output_lines=lambda: [(s.start_time + 11.0, "stdout", "[INFO] [1.0, 2.0]: Finished Planning")],
            metadata={"rosgrade.run": {"exit_code": "0", "status": '"exited"'}}, path=f"/tmp/{s.name}.mcap",
        )
    report = score_task(rubric, recs)
    assert report.score == report.max_score
    assert report.recordings == ["/tmp/nominal.mcap", "/tmp/offset_start.mcap"]
    assert _by_id(report)["stop_distance"].measured["final_distance"] == pytest.approx(10.2)


def test_a_criterion_with_parts_averages_their_credit_and_instead_hints_replace_the_verdict(tmp_path) -> None:
    from test_rubric import MINIMAL

    from grader.rubric import load_rubric

    parts = 'parts = [{ quantity = "revolutions", tolerance = { bounds = [10, 20] } }]\ntolerance = {'
    instead = ('[[criteria.hints]]\nwhen = [{ quantity = "revolutions", max = 5 }]\ninstead = true\n'
               'text = "only {revolutions:.1f} turns"\n')
    path = tmp_path / "figure_eight.toml"  # MINIMAL's task id
    path.write_text(MINIMAL.replace("tolerance = {", parts) + instead, encoding="utf-8")
    rubric = load_rubric(path)
    s = rubric.scenarios[0]
    result = score_task(rubric, {"nominal": _scenario_run(s, [(25.0, 0.1, 0.2), (5.0, 0.0, 0.0)])}).criteria[0]
    assert result.score == 1.0 and not result.passed  # radius right (full), 0.8 of 10 revolutions (none)
    assert result.feedback == "only 0.8 turns"


def test_rosout_levels_reach_the_metrics() -> None:
    from grader.metrics.run import RunData

    recording = SimpleNamespace(
        odometry=lambda: SimpleNamespace(t=[0.0, 1.0], x=[0, 0], y=[0, 0], yaw=[0, 0]), ground_truth=lambda: None,
        commands=lambda: SimpleNamespace(t=[], linear=np.zeros((0, 3)), angular=np.zeros((0, 3))),
        output_lines=lambda: [(0.5, "stdout", "[WARN] [1.0, 0.5]: careful"), (0.5, "rosout", "careful"),
                              (0.6, "rosout", "fine")],
        rosout=lambda: [SimpleNamespace(level=4), SimpleNamespace(level=2)], metadata={})
    lines = RunData.from_recording(recording).lines
    assert [line.level for line in lines] == [None, "WARN", "INFO"]
    assert [line.message() for line in lines] == [("WARN", "careful"), ("WARN", "careful"), ("INFO", "fine")]
