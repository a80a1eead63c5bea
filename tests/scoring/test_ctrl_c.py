"""Issue 33: a run that ends with Ctrl+C after the task is done earns what the same run without Ctrl+C earns, for every
built-in criterion; what the node does after Ctrl+C (here the worst: it drives on, too fast, prints nonsense and hits
a wall) is judged by the shutdown criteria alone."""
from __future__ import annotations

import math
from dataclasses import replace
from functools import cache
from types import SimpleNamespace

import pytest
from number_game_synth import play, scenario_requests
from scoring_synth import Segment, commands, path, run, square_segments

from grader.metrics import OutputLine, RunData, RunInfo
from grader.metrics.action_record import ActionGoal
from grader.metrics.run import ServiceCall, Trajectory
from grader.metrics.motion import wrap
from grader.metrics.lidar_distance import beams_ahead, nearest
from grader.metrics.stop_distance import scan_ahead
from grader.metrics.wall_hits import WARNING
from grader.report import CriterionResult
from grader.rubric import Scenario, load_rubrics
from sim.profile import load_robot
from grader.scoring import score_task

RUBRICS = load_rubrics()
CENTRE = 5.544445  # turtlesim spawns turtle1 here
AFTER_S = 2.0  # recorded after the Ctrl+C, as a scenario's duration does
# What the node does after Ctrl+C: drives on faster than the robot may, turning, or stops dead without a zero command;
# either way it prints wrong poses and the turtle hits a wall.
AFTER: dict[str, tuple[list[Segment], list[Segment]]] = {  # (motion, commands)
    "drives": ([(AFTER_S, 2.0, 1.0)], [(AFTER_S, 2.0, 3.0)]),
    "stops": ([(AFTER_S, 0.0, 0.0)], []),
}


def _rest_until(segments: list[Segment], end: float) -> list[Segment]:
    """``segments`` cut at ``end`` seconds, or padded with rest up to it."""
    out, elapsed = [], 0.0
    for d, v, w in segments:
        if elapsed + d >= end:
            return [*out, (end - elapsed, v, w)]
        out.append((d, v, w))
        elapsed += d
    return [*out, (end - elapsed, 0.0, 0.0)]


def _to(x: float, y: float, yaw: float, points: list[tuple[float, float]], v: float, w: float) -> list[Segment]:
    """Turn on the spot towards each point in turn, then drive straight to it."""
    segs: list[Segment] = []
    for px, py in points:
        turn = float(wrap(math.atan2(py - y, px - x) - yaw))
        if abs(turn) > 1e-9:
            segs.append((abs(turn) / w, 0.0, math.copysign(w, turn)))
        segs.append((math.hypot(px - x, py - y) / v, v, 0.0))
        x, y, yaw = px, py, math.atan2(py - y, px - x)
    return segs


def _start(rubric_robot: str, s: Scenario) -> tuple[float, float, float]:
    p = s.initial_pose
    if rubric_robot == "turtlesim" and (p.x, p.y, p.yaw) == (0.0, 0.0, 0.0):
        return CENTRE, CENTRE, 0.0
    return p.x, p.y, p.yaw


def _param(s: Scenario, name: str, default: float | bool) -> float | bool:
    return s.params.get(name, default)


def _motion(task: str, s: Scenario, x: float, y: float, yaw: float) -> list[Segment]:
    """A correct node's motion in scenario ``s`` of ``task``, from its start pose."""
    if task in ("move_square", "square_odom_launch"):
        return square_segments(loops=2)
    if task == "mover_odom_square":
        return square_segments(loops=1)
    if task == "mover_timed_square":
        return square_segments(loops=6, v=0.25)  # driving a side (not turning) when Ctrl+C comes at 80 s
    if task == "move_circle":
        return [(s.duration, 0.1, 0.2)]
    if task in ("move_distance", "move_distance_launch"):
        return [(((3.02 if task == "move_distance" else 2.02) - x) / 0.2, 0.2, 0.0)]
    if task == "husky_distance":
        return [(10.2 / 0.8, 0.8, 0.0)]
    if task == "obstacle_stop":  # straight ahead until /scan reads the wall 0.5 m ahead
        free = scan_ahead(_in_world(RUBRICS[task].robot, s, run([])), x, y, yaw)
        return [((free - 0.5) / 0.2, 0.2, 0.0)]
    if task == "obstacle_avoidance":  # through the four corner zones, then turning on the spot until 90 s
        tour = _to(x, y, yaw, [(2.0, 2.0), (-2.0, 2.0), (-2.0, -2.0), (2.0, -2.0)], 0.22, 0.8)
        return [*tour, (90.0 - sum(d for d, _, _ in tour), 0.0, 0.5)]
    if task == "wall_follower":  # the run's distance from its side's wall to the end zone, round the course's corner
        asked = {"side": "left", "desired_distance": 0.4, **RUBRICS[task].nodes[0].params, **s.node_params}
        d, left = float(asked["desired_distance"]), asked["side"] == "left"
        lane = (0.6 - d) * (1 if left else -1)  # the corridors' wall faces are 0.6 m either side of the entrance
        # after the corner: the inner wall's face is at x = 2.0, the outer one's at x = 3.2
        inner, outer = 2.0 + d, 3.2 - d
        turn = {"l_corridor": [((inner if left else outer), lane), ((inner if left else outer), 2.5)],
                "l_corridor_mirrored": [((outer if left else inner), lane), ((outer if left else inner), -2.5)]}
        return _to(x, y, yaw, [(0.5, lane), *turn.get(s.world or "", [(3.5, lane)])], 0.2, 1.0)
    if task == "lidar_distance":  # the grader turns the robot (the scenario's script); the node only prints
        return [(1.0, 0.0, 0.0), (4.0, 0.0, 0.3), (7.0, 0.0, -0.3)]
    if task == "figure_of_eight":  # two 1 m loops of 30 s each, anticlockwise then clockwise
        v, w = math.pi / 30.0, 2.0 * math.pi / 30.0
        return [(30.0, v, w), (30.0, v, -w)]
    if task == "odom_subscriber":
        return [(1.0, 0.0, 0.0), (6.0, 0.1, 0.5), (8.0, 0.1, -0.5)]
    if task == "turtle_circle":
        return [(s.duration, 2.0, 1.0)]
    if task == "turtle_clean":  # to the lower left corner, then rows 1 m apart (the turtle's width)
        rows = [p for k in range(11) for p in ((0.5, 0.5 + k), (10.5, 0.5 + k))[:: 1 if k % 2 == 0 else -1]]
        return _to(x, y, yaw, rows, 2.0, 2.0)
    if task == "turtle_goal":
        return _to(x, y, yaw, [(float(_param(s, "goal_x", 0.0)), float(_param(s, "goal_y", 0.0)))], 1.0, 1.0)
    if task in ("turtle_move", "turtle_launch", "turtle_rotate"):
        if "angle_deg" in s.params:
            turn = math.radians(float(s.params["angle_deg"]))
            return [(turn, 0.0, -1.0 if s.params.get("clockwise") else 1.0)]
        distance = float(_param(s, "distance", 2.0))
        return [(distance, 1.0 if _param(s, "forward", True) else -1.0, 0.0)]
    if task == "turtle_triangle":
        return [(2.0, 1.0, 0.0), (math.radians(120.0), 0.0, 1.0)] * 2 + [(2.0, 1.0, 0.0)]
    raise AssertionError(f"no correct motion for {task}")


def _lines(task: str, odom, t_end: float) -> list[OutputLine]:
    """What a correct node prints before ``t_end``."""
    keep = [i for i in range(len(odom)) if odom.t[i] + 0.002 < t_end]
    if task in ("odom_subscriber", "square_odom_launch"):  # every third /odom message, 2 ms after it
        return [OutputLine(float(odom.t[i]) + 0.002, "stdout",
                           f"x = {odom.x[i]:.3f}, y = {odom.y[i]:.3f}, yaw = {odom.yaw[i]:.3f}") for i in keep[::3]]
    if task == "figure_of_eight":  # once a second, relative to the start pose, in the start frame
        c, s = math.cos(odom.yaw[0]), math.sin(odom.yaw[0])
        out = []
        for i in keep[::30]:
            dx, dy = odom.x[i] - odom.x[0], odom.y[i] - odom.y[0]
            yaw = math.degrees(float(wrap(odom.yaw[i] - odom.yaw[0])))
            text = f"x={c * dx + s * dy:.2f} [m], y={-s * dx + c * dy:.2f} [m], yaw={yaw:.1f} [degrees]."
            out.append(OutputLine(float(odom.t[i]) + 0.002, "rosout", text, "INFO"))
        return out
    return []


def _scan_readings(task: str, robot: str, s: Scenario, odom, t_end: float) -> list[OutputLine]:
    """lidar_distance: the nearest object within 20° ahead, printed 2 ms after each 5 Hz sweep before ``t_end``."""
    if task != "lidar_distance":
        return []
    scan = load_robot(robot).modes["gazebo"].sensors.scan
    world = _in_world(robot, s, run([]))
    out = []
    for i in range(len(odom)):
        t = float(odom.t[i])
        if t + 0.002 < t_end and abs(t * 5 - round(t * 5)) < 1e-6:
            d, a = nearest(beams_ahead(world, scan, (float(odom.x[i]), float(odom.y[i]), float(odom.yaw[i])),
                                       math.radians(20)))
            if math.isfinite(d):
                out.append(OutputLine(t + 0.002, "stdout", f"Nearest object ahead: {d:.3f} m at {a:.1f} degrees"))
    return out


def _in_world(robot: str, s: Scenario, data: RunData) -> RunData:
    """``data`` as recorded in scenario ``s``'s world: its robot, walls and pillars."""
    return replace(data, robot=robot, obstacles=s.all_obstacles)


@cache
def _scores(task: str, after: str | None, announced: bool = True) -> dict[str, CriterionResult]:
    """Every criterion of ``task`` scored on a correct node's runs up to ``T`` (the scenario's Ctrl+C, else its end).
    ``after`` None: the recording ends at ``T`` without Ctrl+C; else a Ctrl+C at ``T`` and 2 s of ``AFTER[after]``,
    recorded (``announced``) as the run's Ctrl+C or not, so that all of it is judged."""
    rubric = RUBRICS[task]
    runs = {}
    for s in rubric.scenarios:
        end = s.shutdown_at if s.shutdown_at is not None else s.duration
        x, y, yaw = _start(rubric.robot, s)
        segs = _rest_until(_motion(task, s, x, y, yaw), end)
        t0 = s.start_time
        odom = path(segs, x, y, yaw, t0)
        lines = _lines(task, odom, t0 + end) + _scan_readings(task, rubric.robot, s, odom, t0 + end)
        if after is None:
            runs[s.name] = _in_world(rubric.robot, s, run(segs, x0=x, y0=y, yaw0=yaw, t0=t0, lines=lines,
                                                          info=RunInfo(exit_code=0, status="exited", ended_s=t0 + end)))
            continue
        shutdown = t0 + end
        later = [OutputLine(shutdown + 0.5, "rosout", f"{WARNING} Clamping from [x=11.2, y=3.0]", "WARN")]
        for k in range(20):  # wrong poses at 10 Hz, printed and logged
            later += [OutputLine(shutdown + 0.1 * k, "stdout", "x = 99.000, y = -99.000, yaw = 9.000"),
                      OutputLine(shutdown + 0.1 * k, "rosout", "x=99 [m], y=-99 [m], yaw=999 [degrees].", "ERROR")]
        motion, sent = AFTER[after]
        info = RunInfo(shutdown_requested_s=shutdown if announced else None, exit_code=0, status="exited",
                       ended_s=shutdown + AFTER_S)
        data = run(segs + motion, x0=x, y0=y, yaw0=yaw, t0=t0, lines=lines + later, info=info,
                   shutdown_at=end if announced else None)
        runs[s.name] = _in_world(rubric.robot, s, replace(data, commands=commands(segs + sent, t0)))
    return {c.id: c for c in score_task(rubric, runs).criteria}


# The tasks that drive a robot, each with a correct motion in ``_motion`` (a task added later needs one there).
DRIVING_TASKS = (
    "figure_of_eight", "husky_distance", "lidar_distance", "move_circle", "move_distance", "move_distance_launch",
    "move_square", "mover_odom_square", "mover_timed_square", "obstacle_avoidance", "obstacle_stop", "odom_subscriber",
    "square_odom_launch",
    "turtle_circle", "turtle_clean", "turtle_goal", "turtle_launch", "turtle_move", "turtle_rotate", "turtle_triangle",
    "wall_follower",
)
CRITERIA = [(task, c.id, after) for task in DRIVING_TASKS for c in RUBRICS[task].criteria
            if not c.metric_def.needs_shutdown for after in AFTER]


@pytest.mark.parametrize("task, criterion, after", CRITERIA, ids=["-".join(case) for case in CRITERIA])
def test_ctrl_c_after_the_task_changes_no_credit(task: str, criterion: str, after: str) -> None:
    plain, interrupted = _scores(task, None)[criterion], _scores(task, after)[criterion]
    assert plain.score == plain.max_score, plain.feedback  # a correct run: the comparison could fail
    assert interrupted.score == plain.score, interrupted.feedback


def test_every_criterion_of_the_driving_tasks_but_the_shutdown_ones_is_compared() -> None:
    every = {(t, c.id) for t in DRIVING_TASKS for c in RUBRICS[t].criteria}
    shutdown = {(t, c.id) for t in DRIVING_TASKS for c in RUBRICS[t].criteria if c.metric_def.needs_shutdown}
    assert every == {(t, c) for t, c, _ in CRITERIA} | shutdown
    assert {c for _, c in shutdown} == {"shutdown_stop"}
    assert set(RUBRICS) - set(DRIVING_TASKS) == {  # compared on their own below
        "add_two_ints", "param_circle", "number_game", "number_game_client", "fibonacci", "fibonacci_client",
        "explore_forward", "turtle_spawn_draw", "add_two_ints_client", "turtle_rotate_absolute", "turtle_mimic"}


def _served(ctrl_c: bool) -> dict[str, RunData]:
    """add_two_ints' server answering the scenario's three calls; with Ctrl+C at the end, a call made after it
    goes unanswered (the node is shutting down)."""
    rubric = RUBRICS["add_two_ints"]
    runs = {}
    for s in rubric.scenarios:
        t0, end = s.start_time, s.duration
        calls = [ServiceCall(t0 + 0.5 * (k + 1), "/add_two_ints", {"a": a, "b": b}, {"sum": a + b})
                 for k, (a, b) in enumerate([(2, 3), (-7, 4), (4000000000, 1)])]
        data = run([(end + (AFTER_S if ctrl_c else 0.0), 0.0, 0.0)], t0=t0,
                   info=RunInfo(shutdown_requested_s=t0 + end if ctrl_c else None), shutdown_at=end if ctrl_c else None)
        late = [ServiceCall(t0 + end + 0.5, "/add_two_ints", {"a": 1, "b": 1}, None)] if ctrl_c else []
        runs[s.name] = replace(data, service_calls=tuple(calls + late))
    return runs


@pytest.mark.parametrize("criterion", ["serves", "sums"])
def test_ctrl_c_after_the_calls_changes_no_service_credit(criterion: str) -> None:
    rubric = RUBRICS["add_two_ints"]
    plain, interrupted = (next(c for c in score_task(rubric, _served(ctrl_c)).criteria if c.id == criterion)
                          for ctrl_c in (False, True))
    assert plain.score == plain.max_score, plain.feedback
    assert interrupted.score == plain.score and interrupted.measured["n_calls"] == 3


def _number_game(ctrl_c: bool) -> dict[str, RunData]:
    """A correct number game server answering the scenario's calls (secret 42, then 7 after the win); with Ctrl+C
    at the end, a guess made after it goes unanswered."""
    runs = {}
    for s in RUBRICS["number_game"].scenarios:
        t0, end = s.start_time, s.duration
        calls = play(scenario_requests(s), [42, 7], t0=t0)
        data = run([(end + (AFTER_S if ctrl_c else 0.0), 0.0, 0.0)], t0=t0,
                   info=RunInfo(shutdown_requested_s=t0 + end if ctrl_c else None), shutdown_at=end if ctrl_c else None)
        late = [ServiceCall(t0 + end + 0.5, "/guess_the_number", {"guess": 3, "cheat": False}, None)] if ctrl_c else []
        runs[s.name] = replace(data, service_calls=tuple(calls + late))
    return runs


@pytest.mark.parametrize("criterion", [c.id for c in RUBRICS["number_game"].criteria])
def test_ctrl_c_after_the_game_changes_no_number_game_credit(criterion: str) -> None:
    plain, interrupted = (next(c for c in score_task(RUBRICS["number_game"], _number_game(ctrl_c)).criteria
                               if c.id == criterion) for ctrl_c in (False, True))
    assert plain.score == plain.max_score, plain.feedback
    assert interrupted.score == plain.score and interrupted.measured["n_calls"] == plain.measured["n_calls"] == 103


def _number_game_client(ctrl_c: bool) -> dict[str, RunData]:
    """A correct client: its parameters' request, answered by the grader's server, and the response logged; with
    Ctrl+C at the end, it logs nonsense after it."""
    runs = {}
    for s in RUBRICS["number_game_client"].scenarios:
        t0, end = s.start_time, s.duration
        call = ServiceCall(t0 + 0.5, "/guess_the_number", {"guess": 99, "cheat": True},
                           {"num_guesses": 7, "hint": "The answer is 37!", "correct": False})
        lines = [OutputLine(t0 + 0.51, "rosout", "Number of attempts so far: 7, hint: 'The answer is 37!'", "INFO")]
        late = [OutputLine(t0 + end + 0.5, "rosout", "nonsense", "INFO")] if ctrl_c else []
        data = run([(end + (AFTER_S if ctrl_c else 0.0), 0.0, 0.0)], t0=t0,
                   info=RunInfo(shutdown_requested_s=t0 + end if ctrl_c else None), shutdown_at=end if ctrl_c else None)
        runs[s.name] = replace(data, service_calls=(call,), lines=tuple(lines + late))
    return runs


@pytest.mark.parametrize("criterion", [c.id for c in RUBRICS["number_game_client"].criteria])
def test_ctrl_c_after_the_response_changes_no_client_credit(criterion: str) -> None:
    plain, interrupted = (next(c for c in score_task(RUBRICS["number_game_client"], _number_game_client(ctrl_c))
                               .criteria if c.id == criterion) for ctrl_c in (False, True))
    assert plain.score == plain.max_score, plain.feedback
    assert interrupted.score == plain.score, interrupted.feedback


@pytest.mark.parametrize("task, criterion, after", [
    ("turtle_circle", "keeps_moving", "stops"), ("move_distance", "stays_stopped", "drives"),
    ("move_square", "two_loop_stop", "drives"), ("turtle_clean", "no_wall_hit", "drives"),
    ("turtle_move", "stops", "drives"), ("move_circle", "velocity_limits", "drives"),
    ("figure_of_eight", "stop_position", "drives"), ("turtle_goal", "reaches_goal", "drives"),
    ("odom_subscriber", "pose_output", "stops"), ("figure_of_eight", "log_values", "stops"),
    ("turtle_rotate", "angle", "drives"), ("turtle_triangle", "stops", "drives"),
])
def test_what_came_after_ctrl_c_would_cost_credit_if_it_were_judged(task: str, criterion: str, after: str) -> None:
    unannounced = _scores(task, after, announced=False)[criterion]
    assert unannounced.score < unannounced.max_score


def _turtle_circle(ctrl_c_at: float | None, stops_after: float) -> RunData:
    """turtle_circle's node driving a 2 m circle; it stops ``stops_after`` s after the Ctrl+C (turtlesim's timeout)."""
    t_end = 15.0
    driven = t_end if ctrl_c_at is None else ctrl_c_at + stops_after
    segs = [(driven, 2.0, 1.0), (t_end + 2.0 - driven, 0.0, 0.0)]
    info = RunInfo() if ctrl_c_at is None else RunInfo(shutdown_requested_s=ctrl_c_at, ended_s=ctrl_c_at)
    return run(segs, x0=CENTRE, y0=CENTRE, command_segments=[(ctrl_c_at or t_end, 2.0, 1.0)], info=info)


def test_a_circle_stopped_by_ctrl_c_kept_moving_until_then() -> None:
    metric = RUBRICS["turtle_circle"].criteria[1].metric_def
    m = metric.judge(_turtle_circle(ctrl_c_at=13.0, stops_after=1.0), metric.params())
    assert m["moving_at_end"] is True and m["how"] == "commanding"
    assert m["judged_until_s"] == 13.0 and m["judged_until_ctrl_c"] is True


def test_a_move_cut_by_ctrl_c_is_judged_as_it_was_at_ctrl_c() -> None:
    # turtle_goal's node is still driving to its goal when Ctrl+C comes; what turtlesim's timeout does after it
    # (the turtle stops a second later) is no stop of the node's.
    metric = RUBRICS["turtle_goal"].criteria[1].metric_def
    m = metric.judge(_turtle_circle(ctrl_c_at=6.0, stops_after=1.0), metric.params())
    assert m["how"] == "commanding" and m["stop_credit"] == 0.0


def test_a_run_without_ctrl_c_is_judged_to_its_end() -> None:
    metric = RUBRICS["turtle_circle"].criteria[1].metric_def
    m = metric.judge(_turtle_circle(ctrl_c_at=None, stops_after=0.0), metric.params())
    assert m["judged_until_ctrl_c"] is False and m["judged_until_s"] == pytest.approx(17.0, abs=0.04)


def test_shutdown_criteria_still_see_what_came_after_ctrl_c() -> None:
    metric = RUBRICS["move_circle"].criteria[-1].metric_def
    assert metric.needs_shutdown
    data = run([(20.0, 0.1, 0.2), (5.0, 0.1, 0.2)], command_segments=[(20.0, 0.1, 0.2)], shutdown_at=20.0)
    m = metric.judge(data, metric.params())
    assert m["moving_at_end"] is True and m["observed_s"] == pytest.approx(5.0, abs=0.05)
    assert "judged_until_s" not in m


def _param_circle(ctrl_c: bool) -> dict[str, RunData]:
    """A correct param_circle at 0.1 m/s: each stretch's circle has the radius the grader set at its start (the
    recorded SetParameters calls, accepted); with Ctrl+C at the end the robot then drives on, too fast."""
    rubric = RUBRICS["param_circle"]
    runs = {}
    for s in rubric.scenarios:
        t0, end = s.start_time, s.shutdown_at
        times = [0.0] + [p.t for p in s.param_sets] + [end]
        radii = [0.5] + [p.value for p in s.param_sets]
        segs = [(later - earlier, 0.1, 0.1 / r) for earlier, later, r in zip(times, times[1:], radii)]
        calls = tuple(ServiceCall(
            t0 + p.t, "/param_circle/set_parameters",
            {"parameters": [SimpleNamespace(name="radius", value=SimpleNamespace(type=3, double_value=p.value))]},
            {"results": [SimpleNamespace(successful=True, reason="")]}) for p in s.param_sets)
        motion = segs + (AFTER["drives"][0] if ctrl_c else [])
        data = run(motion, x0=s.initial_pose.x, y0=s.initial_pose.y, yaw0=s.initial_pose.yaw, t0=t0,
                   info=RunInfo(shutdown_requested_s=t0 + end if ctrl_c else None), shutdown_at=end if ctrl_c else None)
        runs[s.name] = replace(data, service_calls=calls)
    return runs


def test_ctrl_c_after_the_stretches_changes_no_radius_follows_credit() -> None:
    rubric = RUBRICS["param_circle"]
    plain, interrupted = (next(c for c in score_task(rubric, _param_circle(ctrl_c)).criteria
                               if c.id == "radius_follows") for ctrl_c in (False, True))
    assert plain.score == plain.max_score, plain.feedback
    assert interrupted.score == plain.score, interrupted.feedback


def _fibonacci(ctrl_c: bool) -> dict[str, RunData]:
    """A cancel-aware Fibonacci server: order 5 succeeds after four feedbacks, order 10 ends CANCELED after the
    grader's cancel; with Ctrl+C at the end, a goal sent after it is never accepted."""
    runs = {}
    for s in RUBRICS["fibonacci"].scenarios:
        t0, end = s.start_time, s.duration
        goals = [ActionGoal(t0 + 0.5, "/fibonacci", {"order": 5}, True, tuple(t0 + 0.5 + k for k in range(4)), (2, 4),
                            4, {"sequence": [0, 1, 1, 2, 3, 5]}),
                 ActionGoal(t0 + 5.5, "/fibonacci", {"order": 10}, True, (t0 + 5.5, t0 + 6.5), (2, 3, 5), 5,
                            {"sequence": []}, t0 + 7.0, 0)]
        late = [ActionGoal(t0 + end + 0.5, "/fibonacci", {"order": 3})] if ctrl_c else []
        data = run([(end + (AFTER_S if ctrl_c else 0.0), 0.0, 0.0)], t0=t0,
                   info=RunInfo(shutdown_requested_s=t0 + end if ctrl_c else None), shutdown_at=end if ctrl_c else None)
        runs[s.name] = replace(data, action_goals=tuple(goals + late))
    return runs


@pytest.mark.parametrize("criterion", [c.id for c in RUBRICS["fibonacci"].criteria])
def test_ctrl_c_after_the_goals_changes_no_fibonacci_credit(criterion: str) -> None:
    plain, interrupted = (next(c for c in score_task(RUBRICS["fibonacci"], _fibonacci(ctrl_c)).criteria
                               if c.id == criterion) for ctrl_c in (False, True))
    assert plain.score == plain.max_score, plain.feedback
    assert interrupted.score == plain.score and interrupted.measured["judged_until_ctrl_c"]
    assert {k: v for k, v in interrupted.measured.items() if k != "judged_until_ctrl_c"} == {
        k: v for k, v in plain.measured.items() if k != "judged_until_ctrl_c"}


def _fibonacci_client(ctrl_c: bool) -> dict[str, RunData]:
    """A correct client: order 10 sent, the grader's server's feedback and result logged; with Ctrl+C at the end, it
    logs nonsense after it."""
    runs = {}
    sequence = [0, 1, 1, 2, 3, 5, 8, 13, 21, 34, 55]
    for s in RUBRICS["fibonacci_client"].scenarios:
        t0, end = s.start_time, s.duration
        calls = (ServiceCall(t0 + 0.5, "/fibonacci/_action/send_goal", {"goal": {"order": 10}}, {"accepted": True}),
                 ServiceCall(t0 + 0.6, "/fibonacci/_action/get_result", {}, {"status": 4,
                                                                             "result": {"sequence": sequence}}))
        lines = [OutputLine(t0 + 0.6 + 0.2 * k, "rosout", f"Received feedback: {sequence[:k + 3]}", "INFO")
                 for k in range(9)] + [OutputLine(t0 + 2.5, "rosout", f"Result: {sequence}", "INFO")]
        late = [OutputLine(t0 + end + 0.5, "rosout", "nonsense", "INFO")] if ctrl_c else []
        data = run([(end + (AFTER_S if ctrl_c else 0.0), 0.0, 0.0)], t0=t0,
                   info=RunInfo(shutdown_requested_s=t0 + end if ctrl_c else None), shutdown_at=end if ctrl_c else None)
        runs[s.name] = replace(data, service_calls=calls, lines=tuple(lines + late))
    return runs


@pytest.mark.parametrize("criterion", [c.id for c in RUBRICS["fibonacci_client"].criteria])
def test_ctrl_c_after_the_result_changes_no_action_client_credit(criterion: str) -> None:
    plain, interrupted = (next(c for c in score_task(RUBRICS["fibonacci_client"], _fibonacci_client(ctrl_c))
                               .criteria if c.id == criterion) for ctrl_c in (False, True))
    assert plain.score == plain.max_score, plain.feedback
    assert interrupted.score == plain.score, interrupted.feedback


def _explore_forward(ctrl_c: bool) -> dict[str, RunData]:
    """A correct ExploreForward server: to the wall at 0.2 m/s until /scan reads 0.5 m, SUCCEEDED with the distances;
    the cancelled goal driven at 0.1 m/s for 3 s, then at rest and CANCELED. With Ctrl+C at the end, the robot drives
    on after it and a goal sent then is never accepted."""
    rubric = RUBRICS["explore_forward"]
    runs = {}
    for s in rubric.scenarios:
        t0, end = s.start_time, s.duration
        x, y, yaw = _start(rubric.robot, s)
        goal = dict(s.action_goals[0].goal)
        if s.name == "to_the_wall":
            free = scan_ahead(_in_world(rubric.robot, s, run([])), x, y, yaw)
            segs = [(1.0, 0.0, 0.0), ((free - 0.5) / 0.2, 0.2, 0.0)]
            goals = [ActionGoal(t0 + 1.0, "/explore_forward", goal, True, tuple(t0 + 1.0 + 0.1 * k for k in range(90)),
                                (2, 4), 4, {"total_distance_travelled": free - 0.5, "closest_obstacle": 0.5})]
        else:
            segs = [(1.0, 0.0, 0.0), (3.0, 0.1, 0.0)]
            goals = [ActionGoal(t0 + 1.0, "/explore_forward", goal, True, tuple(t0 + 1.0 + 0.1 * k for k in range(30)),
                                (2, 3, 5), 5, {"total_distance_travelled": 0.3, "closest_obstacle": 3.5}, t0 + 4.0, 0)]
        segs = _rest_until(segs, end)
        late = [ActionGoal(t0 + end + 0.5, "/explore_forward", goal)] if ctrl_c else []
        motion = AFTER["drives"][0] if ctrl_c else []
        data = run(segs + motion, x0=x, y0=y, yaw0=yaw, t0=t0,
                   info=RunInfo(shutdown_requested_s=t0 + end if ctrl_c else None), shutdown_at=end if ctrl_c else None)
        runs[s.name] = _in_world(rubric.robot, s, replace(data, action_goals=tuple(goals + late)))
    return runs


@pytest.mark.parametrize("criterion", [c.id for c in RUBRICS["explore_forward"].criteria])
def test_ctrl_c_after_the_goals_changes_no_explore_forward_credit(criterion: str) -> None:
    plain, interrupted = (next(c for c in score_task(RUBRICS["explore_forward"], _explore_forward(ctrl_c)).criteria
                               if c.id == criterion) for ctrl_c in (False, True))
    assert plain.score == plain.max_score, plain.feedback
    assert interrupted.score == plain.score, interrupted.feedback


def _add_two_ints_client(ctrl_c: bool) -> dict[str, RunData]:
    """A correct client: 2 and 3 from its arguments, the grader's server's sum logged; with Ctrl+C at the end, it logs
    nonsense after it."""
    runs = {}
    for s in RUBRICS["add_two_ints_client"].scenarios:
        t0, end = s.start_time, s.duration
        call = ServiceCall(t0 + 0.5, "/add_two_ints", {"a": 2, "b": 3}, {"sum": 5})
        lines = [OutputLine(t0 + 0.51, "rosout", "Result of add_two_ints: for 2 + 3 = 5", "INFO")]
        late = [OutputLine(t0 + end + 0.5, "rosout", "nonsense", "INFO")] if ctrl_c else []
        data = run([(end + (AFTER_S if ctrl_c else 0.0), 0.0, 0.0)], t0=t0,
                   info=RunInfo(shutdown_requested_s=t0 + end if ctrl_c else None), shutdown_at=end if ctrl_c else None)
        runs[s.name] = replace(data, service_calls=(call,), lines=tuple(lines + late))
    return runs


@pytest.mark.parametrize("criterion", [c.id for c in RUBRICS["add_two_ints_client"].criteria])
def test_ctrl_c_after_the_response_changes_no_add_client_credit(criterion: str) -> None:
    plain, interrupted = (next(c for c in score_task(RUBRICS["add_two_ints_client"], _add_two_ints_client(ctrl_c))
                               .criteria if c.id == criterion) for ctrl_c in (False, True))
    assert plain.score == plain.max_score, plain.feedback
    assert interrupted.score == plain.score, interrupted.feedback


def _mimicked(ctrl_c_at: float | None) -> dict[str, RunData]:
    """turtle_mimic's windows: the first turtle drives a circle for 8 s and the second follows 32 ms behind, until a
    Ctrl+C stops mimic (the second turtle then stands while the first drives on)."""
    t = [k * 0.016 for k in range(501)]
    leader = Trajectory.of(t, [CENTRE + math.sin(s) for s in t], [CENTRE - 1 + math.cos(s) for s in t], t)
    lag = [max(0.0, s - 0.032) if ctrl_c_at is None or s < ctrl_c_at else ctrl_c_at for s in t]
    follower = Trajectory.of(t, [CENTRE + math.sin(s) for s in lag], [CENTRE - 1 + math.cos(s) for s in lag], lag)
    info = RunInfo() if ctrl_c_at is None else RunInfo(shutdown_requested_s=ctrl_c_at, ended_s=ctrl_c_at)
    data = RunData(odometry=leader, ground_truth=leader, run=info, poses={"/turtle1/pose": leader},
                   windows=("/turtlesim2/sim",), window_poses={"/turtlesim2/turtle1/pose": follower})
    return {s.name: data for s in RUBRICS["turtle_mimic"].scenarios}


@pytest.mark.parametrize("criterion", [c.id for c in RUBRICS["turtle_mimic"].criteria])
def test_ctrl_c_after_mimicking_changes_no_mimic_credit(criterion: str) -> None:
    plain = {c.id: c for c in score_task(RUBRICS["turtle_mimic"], _mimicked(None)).criteria}[criterion]
    cut = {c.id: c for c in score_task(RUBRICS["turtle_mimic"], _mimicked(7.0)).criteria}[criterion]
    assert plain.score == plain.max_score, plain.feedback
    assert cut.score == plain.score, cut.feedback
