"""How a turtlesim move ends: a zero command (full), turtlesim's 1 s timeout (partial), or still driven (none)."""
from __future__ import annotations

import pytest
from scoring_synth import commands, path

from grader.metrics import Commands, MetricError, RunData
from grader.metrics.turtle_stop import Params, measure


def turtle_run(driven: list[tuple[float, float, float]], sent: Commands) -> RunData:
    return RunData(odometry=path(driven), ground_truth=path(driven, source="ground_truth"), commands=sent)


def with_zero(sent: Commands, t: float) -> Commands:
    return Commands.of([*sent.t, t], [*sent.linear[:, 0], 0.0], [*sent.angular[:, 2], 0.0], "/turtle1/cmd_vel")


def test_a_zero_command_when_the_move_ends_earns_full_credit() -> None:
    m = measure(turtle_run([(2.0, 1.0, 0.0), (5.0, 0.0, 0.0)], with_zero(commands([(2.0, 1.0, 0.0)]), 2.0)), Params())
    assert (m["how"], m["stop_credit"], m["zero_command_sent"]) == ("zero_command", 1.0, True)
    assert m["stopped_at_s"] == pytest.approx(2.0, abs=0.05)


def test_stopping_by_the_one_second_timeout_earns_half() -> None:
    # Commands until 1.9 s; the turtle keeps the last one for 1 s more, then turtlesim zeroes it.
    m = measure(turtle_run([(2.9, 1.0, 0.0), (5.0, 0.0, 0.0)], commands([(2.0, 1.0, 0.0)])), Params())
    assert (m["how"], m["stop_credit"], m["zero_command_sent"]) == ("timeout", 0.5, False)


def test_a_zero_sent_after_the_timeout_stopped_the_turtle_still_ends_the_move() -> None:
    # One command, time.sleep(), then a zero: the node did end its move (the short move costs the distance instead).
    sent = with_zero(commands([(2.0, 1.0, 0.0)]), 6.0)
    m = measure(turtle_run([(2.9, 1.0, 0.0), (5.0, 0.0, 0.0)], sent), Params())
    assert (m["how"], m["stop_credit"]) == ("zero_command", 1.0)


def test_a_node_still_driving_at_the_end_earns_nothing() -> None:
    m = measure(turtle_run([(8.0, 1.0, 0.5)], commands([(8.0, 1.0, 0.5)])), Params())
    assert (m["how"], m["stop_credit"], m["moving_at_end"]) == ("commanding", 0.0, True)


def test_a_never_ending_loop_of_tiny_commands_is_still_driving() -> None:
    sent = commands([(2.0, 1.0, 0.0), (6.0, 0.001, 0.0)])
    m = measure(turtle_run([(2.0, 1.0, 0.0), (6.0, 0.001, 0.0)], sent), Params())
    assert m["how"] == "commanding" and m["moving_at_end"] is False


def test_a_turtle_that_never_moved_cannot_be_judged() -> None:
    with pytest.raises(MetricError):
        measure(turtle_run([(3.0, 0.0, 0.0)], Commands.empty()), Params())
