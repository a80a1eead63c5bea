"""Runs made up for the replay tests: a TurtleBot driving a known arc and a turtle drawing with its pen, as RunData
with the recording metadata the replay reads, and the reports that go with them."""
from __future__ import annotations

import json

import numpy as np

from grader.metrics.run import Commands, OutputLine, ParamChange, RunData, RunInfo, ServiceCall, Trajectory
from grader.report import CriterionResult, SubmissionReport, TaskReport
from grader.reports.html import render_html
from grader.reports.replay import Replay, replay_of

START = 2.0  # the node starts 2 s into the world's time, as scenarios do by default
SPEED, TURN = 0.2, 0.1  # the TurtleBot's arc: m/s and rad/s
PILLAR = {"kind": "cylinder", "x": -0.5, "y": -0.8, "radius": 0.2}
WALL = {"kind": "box", "x": 2.5, "y": 1.0, "yaw": 0.3, "length": 0.2, "width": 2.0}


class Recording:
    """What the replay reads of a recording besides its series: the metadata records."""

    def __init__(self, robot: str, **scenario: object) -> None:
        self.metadata = {"rosgrade": {"robot": robot, "scenario": json.dumps({"start_time": START, **scenario})}}


def arc_pose(t: float) -> tuple[float, float, float]:
    """Where the TurtleBot is ``t`` seconds after the start (x, y, yaw): an arc from the origin, heading +x."""
    radius = SPEED / TURN
    return radius * np.sin(TURN * t), radius * (1 - np.cos(TURN * t)), TURN * t


def robot_run(seconds: float = 20.0, rate_hz: float = 62.5, lines: int = 20) -> RunData:
    """The TurtleBot's arc with Ctrl+C at 15 s, a 10 Hz command loop and a log line every second."""
    t = np.arange(0.0, seconds, 1 / rate_hz)
    x, y, yaw = arc_pose(t)
    truth = Trajectory.of(t + START, x, y, yaw, source="ground_truth")
    cmd_t = np.arange(0.0, 15.0, 0.1) + START
    commands = Commands.of(cmd_t, np.full(len(cmd_t), SPEED), np.full(len(cmd_t), TURN))
    log = tuple(OutputLine(START + i + 0.5, "rosout", f"step {i}: all is well", "INFO") for i in range(lines))
    info = RunInfo(shutdown_requested_s=START + 15.0, exit_code=0, status="exited", ended_s=START + 15.4)
    return RunData(odometry=truth, ground_truth=truth, commands=commands, lines=log, run=info, start_time=START)


def turtle_run() -> RunData:
    """turtle1 drives right along y = 5.5 for 4 s; at 1 s its pen turns red, at 3 s the canvas is cleared."""
    t = np.arange(0.0, 4.0, 0.016)
    truth = Trajectory.of(t + START, 3.0 + 1.0 * t, np.full(len(t), 5.5), np.zeros(len(t)), source="ground_truth")
    pen = ServiceCall(START + 1.0, "/turtle1/set_pen", {"r": 255, "g": 0, "b": 0, "width": 3, "off": 0}, {})
    clear = ServiceCall(START + 3.0, "/clear", {}, {})
    params = (ParamChange(START, "/", {"turtlesim": {"background_r": 69, "background_g": 86, "background_b": 255}}, 0),)
    return RunData(odometry=truth, ground_truth=truth, poses={"/turtle1/pose": truth}, service_calls=(pen, clear),
                   param_changes=params, start_time=START,
                   lines=(OutputLine(START + 2.0, "stdout", "</script><script>alert(1)</script>"),))


def criterion(cid: str, passed: bool, scenario: str, **measured: float) -> CriterionResult:
    return CriterionResult(id=cid, title=cid.replace("_", " "), score=1.0 if passed else 0.0, max_score=1.0,
                           passed=passed, scenario=scenario, measured=measured)


def robot_task() -> TaskReport:
    return TaskReport(id="move_arc", title="Drive an arc", status="graded", score=1.0, max_score=2.0,
                      recordings=["out/move_arc/nominal.mcap"],
                      criteria=[criterion("stops_in_time", True, "nominal", stopped_at_s=12.0),
                                criterion("at_rest_after_ctrl_c", False, "nominal", rest_time=0.8)])


def turtle_task() -> TaskReport:
    return TaskReport(id="turtle_line", title="Draw a line", status="graded", score=1.0, max_score=1.0,
                      recordings=["out/turtle_line/nominal.mcap"],
                      criteria=[criterion("draws", True, "nominal", judged_until_s=4.0)])


def replays() -> list[Replay]:
    robot = Recording("turtlebot3_waffle", shutdown_at=15.0, obstacles=[PILLAR, WALL])
    return [replay_of(robot_task(), "nominal", robot, robot_run()),
            replay_of(turtle_task(), "nominal", Recording("turtlesim"), turtle_run())]


def page() -> str:
    report = SubmissionReport(submission="alice", tasks=[robot_task(), turtle_task()], score=2.0, max_score=3.0)
    return render_html(report, replays=replays())
