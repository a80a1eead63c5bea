"""The replay's data and page: what a run's recording becomes in report.html, without a browser."""
from __future__ import annotations

import json
import re
from dataclasses import replace

import numpy as np
import pytest

from grader.cli import main
from grader.metrics.run import Commands, Contact, OutputLine, RunData, Trajectory
from grader.report import SubmissionReport, TaskReport
from grader.reports.replay import MAX_BYTES, replay_of
from grader.reports.text import watch_first

from . import replay_runs as runs


def data(replay):
    return json.loads(replay.data)


def summed(deltas, scale):
    return np.cumsum(deltas) / scale


def test_kept_poses_are_recorded_ones_and_the_path_between_them_is_within_a_pixel():
    robot = data(runs.replays()[0])
    body = robot["bodies"]["robot"]
    t, x, y = summed(body["t"], 100), summed(body["x"], 1000), summed(body["y"], 1000)
    expected_x, expected_y, _ = runs.arc_pose(t)
    assert np.allclose(x, expected_x, atol=2e-3) and np.allclose(y, expected_y, atol=2e-3)  # mm, 1/100 s
    assert t[0] == 0 and t[-1] == pytest.approx(19.98)
    fine = np.arange(0, 19.98, 0.016)
    between_x, between_y = np.interp(fine, t, x), np.interp(fine, t, y)
    pixel = max(b - a for a, b in zip(robot["world"]["bounds"][:2], robot["world"]["bounds"][2:])) / 480
    assert np.hypot(between_x - runs.arc_pose(fine)[0], between_y - runs.arc_pose(fine)[1]).max() < pixel
    assert len(t) < len(fine) / 3  # and most poses were left out


def test_the_view_holds_the_path_and_a_straight_drive_is_not_a_thin_strip():
    straight = RunData(odometry=Trajectory.of([2, 12], [0, 10], [0, 0], [0, 0]), start_time=2.0)
    bounds = data(replay_of(runs.robot_task(), "nominal", runs.Recording("husky_a200"), straight))["world"]["bounds"]
    assert bounds[0] < 0 and bounds[2] > 10
    assert (bounds[3] - bounds[1]) >= 0.6 * (bounds[2] - bounds[0]) - 1e-6


def test_the_same_run_gives_the_same_page_byte_for_byte():
    assert runs.page() == runs.page()


def test_the_page_loads_nothing_from_elsewhere_and_its_controls_are_real_and_labelled():
    page = runs.page()
    assert not re.search(r"""(src|href)=["']?(https?:)?//|@import|url\(""", page)
    assert page.count('<section class="replay" id=') == 2
    for anchor in ("replay-move_arc-nominal", "replay-turtle_line-nominal"):
        assert f'<label for="{anchor}-time">' in page and f'<input type="range" class="rp-time" id="{anchor}-time"' in page
    assert page.count('<button type="button" class="rp-play"') == 2 and page.count('class="rp-speed"') == 6
    assert 'name="viewport"' in page


def test_printed_text_cannot_end_the_script_that_holds_the_data():
    page = runs.page()
    assert "<script>alert(1)" not in page
    blocks = re.findall(r'<script type="application/json" class="rp-data">(.*?)</script>', page, re.S)
    assert [line[3] for line in json.loads(blocks[1])["lines"]] == ["</script><script>alert(1)</script>"]


def test_the_pen_changes_colour_at_set_pen_and_the_canvas_clears():
    pen = data(runs.replays()[1])["pen"]
    assert [s["c"] for s in pen["strokes"]] == ["#b3b8ff", "#ff0000", "#ff0000"]  # the clear ends a stroke
    assert [s["w"] for s in pen["strokes"]] == [3, 3, 3]
    assert pen["clears"] == [[None, "#4556ff"], [3.0, "#4556ff"]]
    starts = [summed(s["t"], 100)[0] for s in pen["strokes"]]
    assert starts[1] == pytest.approx(1.0, abs=0.02) and starts[2] > 3.0
    assert all(len(s["t"]) <= 3 for s in pen["strokes"])  # a straight line needs little more than its ends


def test_events_say_what_happened_and_when_criteria_were_decided():
    replay = runs.replays()[0]
    events = [(t, kind, cid) for t, kind, _, cid in data(replay)["events"]]
    assert events == [(12.0, "pass", "stops_in_time"), (15.0, "ctrl_c", ""), (15.4, "exit", ""),
                      (15.8, "fail", "at_rest_after_ctrl_c")]  # rest_time counts from the Ctrl+C
    assert dict(replay.moments) == {"stops_in_time": 12.0, "at_rest_after_ctrl_c": 15.8}


def test_each_criterion_row_links_to_its_moment():
    page = runs.page()
    assert ('<a class="rp-jump" href="#replay-move_arc-nominal" data-replay="replay-move_arc-nominal" '
            'data-t="15.80">▶ watch at 15.80 s (nominal)</a>') in page


def test_a_long_busy_run_still_fits_the_size_limit():
    seconds, rate = 600.0, 62.5
    t = np.arange(0, seconds, 1 / rate)
    wiggle = Trajectory.of(t, np.cos(t) * 3, np.sin(1.3 * t) * 3, 2.1 * t, source="ground_truth")
    commands = Commands.of(np.arange(0, seconds, 0.01), np.sin(np.arange(0, seconds, 0.01)), np.zeros(60000))
    lines = tuple(OutputLine(i * 0.01, "stdout", "x" * 300) for i in range(5000))
    run = RunData(odometry=wiggle, ground_truth=wiggle, commands=commands, lines=lines)
    replay = replay_of(runs.robot_task(), "nominal", runs.Recording("turtlebot3_waffle", start_time=0.0), run)
    assert len(replay.data.encode()) <= MAX_BYTES
    body = data(replay)
    assert summed(body["bodies"]["robot"]["t"], 100)[-1] == pytest.approx(t[-1], abs=0.01)
    assert body["more_lines"] == 5000 - len(body["lines"]) and len(body["lines"][0][3]) <= 160


def test_the_run_to_watch_first_is_the_one_that_lost_most_points():
    task = runs.robot_task().model_copy(update={"recordings": ["a/nominal.mcap", "a/slow.mcap"]})
    task.criteria[0] = task.criteria[0].model_copy(update={"scenario": "slow", "score": 0.0, "passed": False})
    task.criteria[1] = task.criteria[1].model_copy(update={"scenario": "slow"})
    other = TaskReport(id="t2", status="graded", recordings=["b/nominal.mcap"])
    first = watch_first(SubmissionReport(submission="s", tasks=[other, task]))
    assert (first[0].id, first[1]) == ("move_arc", "slow")
    assert watch_first(SubmissionReport(submission="s", tasks=[TaskReport(id="x", status="not_found")])) is None


def test_bare_rosgrade_shows_what_it_grades_and_an_example_per_command(capsys):
    with pytest.raises(SystemExit) as ended:
        main([])
    assert ended.value.code == 2
    text = capsys.readouterr().out
    for words in ("rospy (ROS 1)", "rclpy (ROS 2)", "TurtleBot3", "Husky", "turtlesim", "report.html replays"):
        assert words in text
    for command in ("check", "batch", "score", "tasks", "bench", "gradescope-package", "launch", "rubric check"):
        assert f"  rosgrade {command} " in text
    assert max(len(line) for line in text.splitlines()) <= 80


def test_a_criterion_is_placed_where_its_own_quantity_says():
    never_at_rest = runs.criterion("stops_at_ctrl_c", False, "nominal", rest_time=None, exit_delay=0.4)
    travel = runs.criterion("travel", True, "nominal", travelled=2.0, exit_delay=0.4, judged_until_s=15.0)
    task = runs.robot_task().model_copy(update={"criteria": [never_at_rest, travel]})
    replay = replay_of(task, "nominal", runs.Recording("turtlebot3_waffle"), runs.robot_run())
    assert dict(replay.moments) == {"stops_at_ctrl_c": 19.98, "travel": 15.0}  # never at rest: the end of the run


def test_walls_and_pillars_are_in_the_view():
    world = data(runs.replays()[0])["world"]
    assert world["obstacles"] == [{"kind": "cylinder", "x": -0.5, "y": -0.8, "r": 0.2},
                                  {"kind": "box", "x": 2.5, "y": 1.0, "a": 0.3, "l": 0.2, "w": 2.0}]
    x0, y0, x1, y1 = world["bounds"]
    assert x0 < -0.5 < x1 and y0 < -0.8 and x1 > 2.5


def test_the_robot_touching_a_wall_is_an_event_once_per_touch():
    robot = runs.Recording("turtlebot3_waffle", shutdown_at=15.0, obstacles=[runs.PILLAR, runs.WALL])
    # 20 ms apart is one touch that lasts; a second later it is another.
    contacts = tuple(Contact(t=runs.START + t, obstacle="end wall", x=2.4, y=1.0) for t in (9.0, 9.02, 9.04, 10.5))
    replay = replay_of(runs.robot_task(), "nominal", robot, replace(runs.robot_run(), contacts=contacts))
    hits = [(t, text) for t, kind, text, _ in data(replay)["events"] if kind == "hit"]
    assert hits == [(9.0, "the robot touched the end wall"), (10.5, "the robot touched the end wall")]


def test_an_infinite_command_is_shown_as_text_and_the_data_stays_json():
    robot = runs.Recording("turtlebot3_waffle", shutdown_at=15.0, obstacles=[runs.PILLAR, runs.WALL])
    run = runs.robot_run()
    linear = np.where(run.commands.t > runs.START + 5.0, np.inf, runs.SPEED)
    commands = Commands.of(run.commands.t, linear, np.full(len(linear), runs.TURN))
    replay = replay_of(runs.robot_task(), "nominal", robot, replace(run, commands=commands))

    def refuse(constant: str) -> float:
        raise ValueError(f"{constant} is not JSON: the browser's JSON.parse stops at it")
    rows = json.loads(replay.data, parse_constant=refuse)["commands"]
    assert rows[-1][1] == "inf" and isinstance(rows[0][1], float)
