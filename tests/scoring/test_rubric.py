"""Rubrics: every shipped TOML loads with the contracted criterion ids; malformed ones say file, field, expectation."""
from __future__ import annotations

import math
from pathlib import Path

import pytest

from grader.rubric import DEFAULT_DIR, RUBRICS_ENV, Condition, RubricError, load_rubric, load_rubrics, render

CONTRACT = {
    "odom_subscriber": ["pose_output", "output_rate"],
    "move_circle": ["radius", "velocity_limits", "shutdown_stop"],
    "move_square": ["side_length", "corner_angle", "closure", "two_loop_stop", "velocity_limits", "shutdown_stop"],
    "mover_timed_square": ["square_shape", "velocity_limits", "shutdown_stop"],
    "mover_odom_square": ["side_length", "corner_angle", "closure", "velocity_limits", "shutdown_stop"],
    "move_distance": ["stop_position", "stays_stopped", "velocity_limits"],
    "husky_distance": ["stop_distance", "velocity_limits"],
    "obstacle_stop": ["stop_distance", "no_collision", "velocity_limits"],
    "figure_of_eight": ["loop_shape", "loop_directions", "stop_position", "duration", "log_rate", "log_format",
                        "log_values", "velocity_limits", "shutdown_stop"],
    "move_distance_launch": ["stop_position", "stays_stopped", "velocity_limits"],
    "square_odom_launch": ["side_length", "corner_angle", "two_loop_stop", "pose_output", "output_rate"],
    "turtle_move": ["distance", "direction", "stops"],
    "turtle_rotate": ["angle", "direction", "stops"],
    "turtle_circle": ["circle", "keeps_moving", "no_wall_hit"],
    "turtle_triangle": ["sides_equal", "turn_angle", "closure", "stops"],
    "turtle_goal": ["reaches_goal", "stops", "no_wall_hit", "short_way"],
    "turtle_clean": ["coverage", "no_wall_hit", "finishes"],
    "turtle_launch": ["drives", "direction", "turns"],
    "turtle_mimic": ["two_windows", "first_turtle_drives", "mimics"],
    "add_two_ints": ["serves", "sums"],
    "param_circle": ["radius_follows", "shutdown_stop"],
    "number_game": ["serves", "hints", "counts_guesses", "cheat", "correct_guess"],
    "number_game_client": ["sends_request", "reports_response"],
    "fibonacci": ["accepts_goal", "feedback", "result", "cancel_stops"],
    "fibonacci_client": ["sends_goal", "reports_feedback", "reports_result"],
    "add_two_ints_client": ["sends_request", "reports_response"],
    "explore_forward": ["accepts_goal", "feedback", "stops_at_distance", "result", "cancel_stops", "cancel_halts"],
    "turtle_spawn_draw": ["spawned", "pens", "figure"],
    "turtle_rotate_absolute": ["reaches_angle", "uses_action", "reads_result"],
    "lidar_distance": ["distances", "rate"],
    "obstacle_avoidance": ["zones", "no_collision", "stops_at_end"],
    "wall_follower": ["distance", "reaches_end", "no_collision"],
}

MINIMAL = '''
id = "figure_eight"
title = "Figure of eight"
robot = "turtlebot3_waffle"

[[nodes]]
script = "figure_eight.py"

[[scenarios]]
name = "nominal"
duration = 30.0
shutdown_at = 25.0

[[criteria]]
id = "radius"
title = "Loop radius"
points = 2
metric = "circle_fit"
quantity = "radius"
tolerance = { bounds = [0.45, 0.55], margin = 0.1 }
feedback.failed = "radius {radius:.2f} m"
'''


def _write(tmp_path: Path, text: str, name: str = "figure_eight.toml") -> Path:
    path = tmp_path / name
    path.write_text(text, encoding="utf-8")
    return path


def test_every_shipped_rubric_loads_with_the_contracted_ids() -> None:
    rubrics = load_rubrics()
    assert {k: [c.id for c in r.criteria] for k, r in rubrics.items()} == CONTRACT
    for r in rubrics.values():
        assert r.max_score == sum(c.points for c in r.criteria) > 0
        assert r.nodes or r.launch is not None
        assert all(node.script.endswith(".py") for node in r.nodes)
        assert r.launch is None or r.launch.file.endswith((".launch", ".launch.py", ".launch.xml", ".launch.yaml"))


def test_robot_profiles_and_seed_specifics() -> None:
    rubrics = load_rubrics()
    assert rubrics["husky_distance"].robot == "husky_a200"
    assert rubrics["move_distance"].nodes[0].args == ["0.2", "0", "3"]
    assert "mover.py" in rubrics["mover_timed_square"].nodes[0].aliases
    limits = {k: c.metric_params for k, r in rubrics.items() for c in r.criteria if c.id == "velocity_limits"}
    assert {(p.max_linear, p.max_angular) for p in limits.values()} == {(0.26, 1.82), (1.0, 2.0)}  # type: ignore[attr-defined]


@pytest.mark.parametrize("task", ["move_square", "mover_odom_square", "move_circle", "figure_of_eight"])
def test_hidden_variants_cover_world_start_yaw_near_pi_and_wheel_error(task: str) -> None:
    scenarios = load_rubrics()[task].scenarios
    assert any((s.initial_pose.x, s.initial_pose.y) == (-2.0, -0.5) for s in scenarios)
    assert any(abs(s.initial_pose.yaw) > math.radians(165) for s in scenarios)
    assert any(s.imperfections.wheel_radius_error for s in scenarios)
    assert any(s.start_time > 0 for s in scenarios)


def test_odom_subscriber_script_crosses_pi() -> None:
    for s in load_rubrics()["odom_subscriber"].scenarios:
        yaw, t_prev, w = s.initial_pose.yaw, 0.0, 0.0
        headings = [yaw]
        for cmd in s.script:
            yaw += w * (cmd.t - t_prev)
            headings.append(yaw)
            t_prev, w = cmd.t, cmd.angular[2]
        assert max(abs(h) for h in headings) > math.pi, s.name


def test_scenario_defaults_fill_each_scenario() -> None:
    r = load_rubrics()["move_square"]
    by_name = {s.name: s for s in r.scenarios}
    assert by_name["nominal"].duration == 150.0 and by_name["interrupted"].duration == 8.0
    assert all(s.robot == "turtlebot3_waffle" for s in r.scenarios)


def test_minimal_instructor_rubric_loads(tmp_path: Path) -> None:
    r = load_rubric(_write(tmp_path, MINIMAL))
    assert (r.id, r.max_score, r.criteria[0].expected_text) == ("figure_eight", 2.0, "between 0.45 and 0.55")


@pytest.mark.parametrize(
    "old, new, field, expectation",
    [
        ('title = "Figure of eight"\n', 'title = \n', "line 3", "TOML syntax error"),
        ('metric = "circle_fit"', 'metric = "circle"', "criteria[0] ('radius').metric", "unknown metric 'circle'"),
        ("bounds = [0.45, 0.55]", "bounds = [0.55, 0.45]", "criteria[0] ('radius').tolerance", "lower <= upper"),
        ("radius {radius:.2f} m", "radius {radus:.2f} m", "criteria[0] ('radius')", "{radus} is unknown"),
        ('quantity = "radius"', 'quantity = "radious"', "criteria[0] ('radius')", "expected one of"),
        ("points = 2", "ponts = 2", "criteria[0] ('radius').points", "('radius').ponts: unknown field"),
        ('title = "Loop radius"\n', "", "criteria[0] ('radius').title", "required field is missing"),
        ("shutdown_at = 25.0", "shutdown_at = 35.0", "scenarios[0] ('nominal')", "after the end of the run"),
        ("tolerance = {", 'params = { settle = 2 }\ntolerance = {', "criteria[0] ('radius')", "settle"),
        ("tolerance = {", 'parts = [{ quantity = "radios", tolerance = { bounds = [0, 1] } }]\ntolerance = {',
         "criteria[0] ('radius')", "quantity 'radios' is not measured by 'circle_fit'"),
        ("tolerance = {", 'parts = [{ quantity = "rms_residual" }]\ntolerance = {',
         "criteria[0] ('radius').parts[0].tolerance", "required field is missing"),
        ('feedback.failed = "radius {radius:.2f} m"', 'feedback.failed = "r"\n[[criteria.hints]]\nwhen = '
         '[{ quantity = "radius", min = 1 }]\ntext = "t"\ninstead = "maybe"', "criteria[0] ('radius').hints[0].instead",
         "valid boolean"),
    ],
)
def test_malformed_rubric_names_file_field_and_expectation(
    tmp_path: Path, old: str, new: str, field: str, expectation: str
) -> None:
    assert old in MINIMAL
    path = _write(tmp_path, MINIMAL.replace(old, new, 1))
    with pytest.raises(RubricError) as info:
        load_rubric(path)
    err = info.value
    assert err.file == str(path) and str(path) in str(err)
    assert err.field.startswith(field), err.field
    assert expectation in str(err)


def test_criterion_on_an_unknown_scenario(tmp_path: Path) -> None:
    path = _write(tmp_path, MINIMAL.replace('quantity = "radius"', 'quantity = "radius"\nscenarios = ["hidden"]'))
    with pytest.raises(RubricError, match="names scenario 'hidden'; expected one of nominal"):
        load_rubric(path)


def test_shutdown_criterion_needs_a_scenario_with_ctrl_c(tmp_path: Path) -> None:
    text = MINIMAL.replace("shutdown_at = 25.0\n", "") + '''
[[criteria]]
id = "shutdown_stop"
title = "Stops"
points = 1
metric = "shutdown"
quantity = "rest_time"
tolerance = { bounds = [0.0, 1.0] }
'''
    with pytest.raises(RubricError, match="has no shutdown_at"):
        load_rubric(_write(tmp_path, text))


def test_task_id_must_match_the_file_name(tmp_path: Path) -> None:
    with pytest.raises(RubricError) as info:
        load_rubric(_write(tmp_path, MINIMAL, name="eight.toml"))
    assert info.value.field == "id"


def test_directory_from_the_environment(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    _write(tmp_path, MINIMAL)
    monkeypatch.setenv(RUBRICS_ENV, str(tmp_path))
    assert list(load_rubrics()) == ["figure_eight"]
    assert DEFAULT_DIR.name == "rubrics" and (DEFAULT_DIR / "__init__.py").is_file()


def test_conditions_and_safe_rendering() -> None:
    values = {"radius": 1.0, "exception": "TypeError: shutdown hook [None] must be callable", "gone": None}
    assert Condition(quantity="radius", min=0.9, max=1.1).holds(values)
    assert not Condition(quantity="radius", max=0.9).holds(values)
    assert Condition(quantity="exception", contains="hook [none]").holds(values)
    assert not Condition(quantity="gone", min=0.0).holds(values)
    assert render("{radius:.2f} m, {gone:.3f}, {missing}", values) == "1.00 m, None, n/a"
    assert render("{x:.1f}", {"x": math.nan}) == "n/a"


def test_limits_table_sets_the_node_limits(tmp_path) -> None:
    source = (DEFAULT_DIR / "move_circle.toml").read_text()
    path = tmp_path / "move_circle.toml"
    path.write_text(source + "\n[limits]\nwall_s = 30.0\nmemory_mb = 256\n")
    limits = load_rubric(path).limits
    assert (limits.wall_s, limits.memory_mb, limits.cpu_s) == (30.0, 256, 120.0)


@pytest.mark.parametrize(("table", "message"), [("wal_s = 30.0", "limits.wal_s"),
                                                ("memory_mb = -1", "must be positive")])
def test_bad_limits_name_the_field(tmp_path, table: str, message: str) -> None:
    path = tmp_path / "move_circle.toml"
    path.write_text((DEFAULT_DIR / "move_circle.toml").read_text() + f"\n[limits]\n{table}\n")
    with pytest.raises(RubricError, match=message):
        load_rubric(path)
