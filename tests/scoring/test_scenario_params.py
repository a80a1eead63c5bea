"""A scenario's own stdin and the metric parameters it asks for (the distance its stdin types, a goal)."""
from __future__ import annotations

from pathlib import Path

import pytest

from grader.rubric import RubricError, load_rubric, load_rubrics

RUBRIC = '''
id = "walk"
title = "Walk"
robot = "turtlesim"

[[nodes]]
script = "move.py"
stdin = "2.0\\n3.0\\n1\\n"

[[scenarios]]
name = "nominal"
params = {{ distance = 3.0 }}

[[scenarios]]
name = "backwards"
stdin = "1.0\\n2.0\\n0\\n"
params = {{ {backwards} }}

[[criteria]]
id = "distance"
title = "Distance"
points = 1
metric = "turtle_travel"
quantity = "distance_error_rel"
params = {{ min_travel = 0.02 }}
tolerance = {{ bounds = [0.0, 0.02] }}

[[criteria]]
id = "no_wall_hit"
title = "Walls"
points = 1
metric = "wall_hits"
quantity = "n_wall_hits"
tolerance = {{ bounds = [0.0, 0.0] }}
'''


def write(tmp_path: Path, backwards: str) -> Path:
    path = tmp_path / "walk.toml"
    path.write_text(RUBRIC.format(backwards=backwards))
    return path


def test_each_scenario_overrides_the_parameters_its_metrics_take(tmp_path: Path) -> None:
    rubric = load_rubric(write(tmp_path, "distance = 2.0, forward = false"))
    distance = rubric.criteria[0]
    nominal, backwards = rubric.scenarios
    assert (distance.params_for(nominal).distance, distance.params_for(nominal).forward) == (3.0, True)
    assert (distance.params_for(backwards).distance, distance.params_for(backwards).forward) == (2.0, False)
    assert distance.params_for(backwards).min_travel == 0.02  # the criterion's own parameters stay
    assert rubric.criteria[1].params_for(backwards) == rubric.criteria[1].metric_params  # wall_hits takes none
    assert (nominal.stdin, backwards.stdin) == (None, "1.0\n2.0\n0\n")


def test_a_scenario_parameter_no_metric_takes_is_an_error(tmp_path: Path) -> None:
    with pytest.raises(RubricError, match="distanse are taken by no metric"):
        load_rubric(write(tmp_path, "distanse = 2.0"))


def test_a_scenario_parameter_of_the_wrong_type_names_scenario_and_criterion(tmp_path: Path) -> None:
    with pytest.raises(RubricError, match="scenario 'backwards': params for criterion 'distance'"):
        load_rubric(write(tmp_path, "distance = -1.0"))


def test_the_turtlesim_tasks_ask_in_each_scenario_what_its_stdin_types() -> None:
    rubrics = load_rubrics()
    for scenario in rubrics["turtle_move"].scenarios:
        stdin = scenario.stdin or rubrics["turtle_move"].nodes[0].stdin
        speed, distance, forward = stdin.split()
        assert (float(distance), forward == "1") == (scenario.params["distance"], scenario.params["forward"])
    for scenario in rubrics["turtle_goal"].scenarios:
        stdin = scenario.stdin or rubrics["turtle_goal"].nodes[0].stdin
        assert [float(v) for v in stdin.split()] == [scenario.params["goal_x"], scenario.params["goal_y"]]


WALL_RUBRIC = '''
id = "follow"
title = "Follow"
robot = "turtlebot3_waffle"

[[nodes]]
script = "follow.py"

[[scenarios]]
name = "left"

[[scenarios]]
name = "right"
node_params = {{ side = "right", desired_distance = 0.5, velocity = 0.3 }}
{extra}

[[criteria]]
id = "distance"
title = "Distance"
points = 1
metric = "wall_following"
quantity = "mit_score"
params = {{ side = "left", desired_distance = 0.4 }}
tolerance = {{ bounds = [0.9, 1.0] }}
'''


def test_node_params_are_the_metric_parameters_of_the_same_name(tmp_path: Path) -> None:
    path = tmp_path / "follow.toml"
    path.write_text(WALL_RUBRIC.format(extra=""))
    rubric = load_rubric(path)
    left, right = (rubric.criteria[0].params_for(s) for s in rubric.scenarios)
    assert (left.side, left.desired_distance) == ("left", 0.4)
    # velocity is the node's alone: no metric takes it, and that is not a spelling error as in `params`
    assert (right.side, right.desired_distance) == ("right", 0.5)


def test_a_scenario_params_overrides_its_node_params_for_the_metric(tmp_path: Path) -> None:
    path = tmp_path / "follow.toml"
    path.write_text(WALL_RUBRIC.format(extra="params = { desired_distance = 0.45 }"))
    right = load_rubric(path).criteria[0].params_for(load_rubric(path).scenarios[1])
    assert (right.side, right.desired_distance) == ("right", 0.45)


def test_the_wall_follower_runs_vary_side_distance_and_speed_as_mits_tests_do() -> None:
    runs = load_rubrics()["wall_follower"].scenarios
    asked = {(s.node_params.get("side", "left"), s.node_params.get("desired_distance", 0.4),
              s.node_params.get("velocity", 0.2)) for s in runs}
    assert len(runs) == 6 and len(asked) == 4
    assert {side for side, _, _ in asked} == {"left", "right"}
    assert len({world for world in (s.world for s in runs)}) == 3
