"""Collisions: touches of walls and pillars counted from the world's contact record."""
from __future__ import annotations

import math
from dataclasses import replace

from scoring_synth import run

from grader.metrics.collisions import Params, measure
from grader.metrics.run import Contact


def _with(contacts: list[Contact], start: float = 2.0):
    return replace(run([(10.0, 0.2, 0.0)], t0=start), contacts=tuple(contacts))


def test_a_lasting_touch_counts_once_and_a_return_counts_again() -> None:
    lasting = [Contact(6.5 + 0.02 * i, "north wall", 0.95, -0.13) for i in range(20)]
    again = [Contact(9.0, "north wall", 0.95, 0.1), Contact(9.0, "pillar 2", 0.4, 0.5)]
    m = measure(_with(lasting + again), Params())
    assert m["n_collisions"] == 3 and m["collided"] is True
    assert math.isclose(m["first_hit_s"], 4.5) and (m["first_hit_x"], m["first_hit_y"]) == (0.95, -0.13)
    assert m["first_obstacle"] == "north wall" and m["obstacles_touched"] == "north wall, pillar 2"


def test_no_contact_is_no_collision() -> None:
    m = measure(_with([]), Params())
    assert m["n_collisions"] == 0 and m["collided"] is False and math.isnan(m["first_hit_s"])


def test_contacts_after_ctrl_c_are_not_judged() -> None:
    data = replace(_with([Contact(20.0, "box 1", 1.0, 0.0)]), shutdown_at=10.0)
    assert data.until_ctrl_c().contacts == () and len(data.contacts) == 1
