"""Contacts: the robot touching a wall or pillar is read from MuJoCo's contacts and published for the grader."""
from __future__ import annotations

from sim import Scenario, ScriptedCommand, World
from sim.model import mjcf
from sim.profile import load_robot
from sim.samples import ContactSample
from sim.world import CONTACT_TOPIC

WALL = {"kind": "box", "name": "north wall", "x": 1.0, "y": 0.0, "length": 0.1, "width": 2.0}
PILLAR = {"kind": "cylinder", "x": 0.5, "y": 0.6, "radius": 0.1}


def _contacts(obstacles: list[dict], duration: float = 6.0) -> tuple[World, list[ContactSample]]:
    world = World(Scenario(robot="turtlebot3_waffle", duration=duration, obstacles=obstacles,
                           script=[ScriptedCommand(t=0.0, linear=0.2)]))
    found = []
    t_ns = world.time_ns
    while t_ns < world.end_ns:
        t_ns += 100_000_000
        found += [s for s in world.advance_to(t_ns) if isinstance(s, ContactSample)]
    return world, found


def test_driving_into_a_wall_touches_it_at_its_face_and_stops_the_robot() -> None:
    world, found = _contacts([WALL, PILLAR])
    front = load_robot("turtlebot3_waffle").geometry.body.front
    assert found, "the robot drove 1.2 m towards a wall 0.95 m ahead of its front"
    assert {s.obstacle for s in found} == {"north wall"}  # the pillar beside the path is never touched
    first = found[0]
    assert abs(first.position[0] - 0.95) < 0.005 and first.depth < 0.01 and first.topic == CONTACT_TOPIC
    # its front 0.881 m from the wall at 0.2 m/s: 4.4 s after the 2 s start, and a little for the ramp up
    assert 6.4e9 < first.t_ns < 6.7e9
    assert abs(world.state()["x"] + front - 0.95) < 0.01  # held at the wall, not through it


def test_contacts_repeat_bit_for_bit() -> None:
    assert _contacts([WALL])[1] == _contacts([WALL])[1]


def test_an_open_floor_has_no_contact_topic_and_no_body_geom() -> None:
    world, found = _contacts([], duration=1.0)
    assert not found and CONTACT_TOPIC not in {p.topic for p in world.publications}
    profile = load_robot("turtlebot3_waffle")
    wall = Scenario(obstacles=[WALL]).obstacles
    assert 'name="body"' not in mjcf(profile, 0.033) and 'name="body"' in mjcf(profile, 0.033, wall)


def test_unnamed_obstacles_are_called_by_kind_and_number() -> None:
    _, found = _contacts([PILLAR, {**WALL, "name": ""}])
    assert {s.obstacle for s in found} == {"box 2"}
