"""Which world a script is written for, from the velocity topic it names: turtlesim's turtleN/cmd_vel or a robot's.

A file name can belong to a TurtleBot task and a turtlesim task at once (``move_circle.py`` is the TurtleBot circle
task's script and an alias of the turtlesim circle task). When task detection finds one file for both, the topics it
names decide: a script that names a turtle's cmd_vel is graded as the turtlesim task, any other as the robot's.
Detection runs on a submission's folder (grading) and on its zip (a batch choosing the class's tasks).
"""
from __future__ import annotations

import io
import re
import zipfile
from collections.abc import Callable, Mapping, Sequence
from pathlib import Path, PurePosixPath
from typing import TYPE_CHECKING

from grader.runtime.scripts import MAX_SCRIPT_BYTES, candidates, read_script
from sim.scenario import TURTLESIM

if TYPE_CHECKING:  # only for annotations: the CLI's tests stand in for grader.rubric with a module of their own
    from grader.rubric import Rubric

TURTLE_TOPIC = re.compile(rb"""["'/]turtle\d+/cmd_vel\b""")

# The script a single-node task would run, as (where it is, its text), or None.
ScriptOf = Callable[["Rubric"], "tuple[str, bytes] | None"]


def _names(rubric: Rubric) -> list[str]:
    """The file names a single-node task's script may have, in the order they are tried; none for other tasks."""
    if len(rubric.nodes) != 1:
        return []
    return [rubric.nodes[0].script, *rubric.nodes[0].aliases]


def in_folder(folder: Path) -> ScriptOf:
    """Scripts as grading finds them in an unpacked submission (a folder or one .py file)."""
    def script_of(rubric: Rubric) -> tuple[str, bytes] | None:
        found = next((paths[0] for name in _names(rubric) if (paths := candidates(folder, name))), None)
        raw = None if found is None else read_script(found)
        return (str(found), raw) if isinstance(raw, bytes) else None
    return script_of


def in_zip(pack: Callable[[], bytes]) -> ScriptOf:
    """Scripts in a zipped submission (``pack`` makes its bytes, once, when a script is first asked for), found by
    file name anywhere in it, the shortest path first."""
    members: dict[str, str] = {}
    archive: list[zipfile.ZipFile] = []

    def script_of(rubric: Rubric) -> tuple[str, bytes] | None:
        if not archive:
            archive.append(zipfile.ZipFile(io.BytesIO(pack())))
            for member in sorted(archive[0].namelist(), key=lambda m: (m.count("/"), m)):
                members.setdefault(PurePosixPath(member).name, member)
        member = next((members[name] for name in _names(rubric) if name in members), None)
        if member is None:
            return None
        with archive[0].open(member) as handle:
            return member, handle.read(MAX_SCRIPT_BYTES)
    return script_of


def names_turtle_topic(text: bytes) -> bool:
    """The script names a turtle's velocity topic (``"turtle1/cmd_vel"``, ``'/turtle2/cmd_vel'``)."""
    return TURTLE_TOPIC.search(text) is not None


def fitting_tasks(tasks: Sequence[str], rubrics: Mapping[str, Rubric], script_of: ScriptOf) -> list[str]:
    """``tasks`` without those that share their script with a task of the other world the script is written for.

    Scripts are read only for tasks whose file names a task of the other world also accepts."""
    def world(task: str) -> bool:
        return rubrics[task].robot == TURTLESIM

    rivals = {task: [o for o in tasks if world(o) != world(task) and set(_names(rubrics[o])) & set(_names(rubrics[task]))]
              for task in tasks}
    scripts = {task: script_of(rubrics[task]) for task in tasks if rivals[task]}
    kept = []
    for task in tasks:
        mine = scripts.get(task)
        shared = mine is not None and any(scripts[o] is not None and scripts[o][0] == mine[0] for o in rivals[task])
        if not shared or names_turtle_topic(mine[1]) == world(task):
            kept.append(task)
    return kept
