"""A catkin package's own .action as genmsg and genpy make it: the seven messages add_action_files generates (its
Goal, Result and Feedback, and the ActionGoal, ActionResult, ActionFeedback and Action around them), with constants,
another package's type, arrays, times and strings. real_genaction_record.json is what Debian's genaction.py, genmsg
and genpy gave for explore_msgs (real_genaction.py); rosgrade's grader catalog and node classes must say the same, and
the record is taken again live where Debian's tools are installed."""
from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

from grader.interfaces import catalog_for, run_interfaces
from grader.nodelib import pythonpath
from grader.workspace import read_workspace

HERE = Path(__file__).resolve().parent
PACKAGE = HERE / "explore_msgs"
RECORD = json.loads((HERE / "real_genaction_record.json").read_text())
DEBIAN_PYTHON = "/usr/bin/python3"
_OURS = """import json, sys, importlib, rosgrade_interfaces
rosgrade_interfaces.install(json.load(open(sys.argv[1])))
module = importlib.import_module("explore_msgs.msg")
out = {}
for name in sys.argv[2:]:
    cls = getattr(module, name.split("/")[1])
    out[name] = {"md5sum": cls._md5sum, "class_md5sum": cls._md5sum, "slots": list(cls.__slots__),
                 "slot_types": list(cls._slot_types), "str": str(cls())}
print(json.dumps(out, sort_keys=True))
"""


@pytest.fixture(scope="module")
def interfaces():
    found = run_interfaces(read_workspace(PACKAGE), "ros1")
    assert found.findings == [] and list(found.actions) == ["explore_msgs/msg/Explore"]
    return found


def test_the_grader_catalog_has_genmsgs_md5sums(interfaces) -> None:
    catalog = catalog_for("ros1", interfaces)
    assert len(RECORD) == 7
    assert {name: catalog.md5sum(name) for name in RECORD} == {name: r["md5sum"] for name, r in RECORD.items()}


def test_the_nodes_classes_are_genpys(interfaces, tmp_path: Path) -> None:
    (tmp_path / "payload.json").write_text(json.dumps(interfaces.payload))
    out = subprocess.run([sys.executable, "-B", "-c", _OURS, str(tmp_path / "payload.json"), *RECORD],
                         capture_output=True, text=True, env={**os.environ, "PYTHONPATH": pythonpath("ros1")},
                         timeout=60, check=True)
    assert json.loads(out.stdout) == RECORD


def _debian_reason() -> str | None:
    if not Path(DEBIAN_PYTHON).exists() or not Path("/usr/lib/actionlib_msgs/genaction.py").exists():
        return "Debian's python3-actionlib-msgs (genaction.py) is not installed"
    probe = subprocess.run([DEBIAN_PYTHON, "-c", "import genpy, genmsg, actionlib_msgs.msg, geometry_msgs.msg"],
                           capture_output=True)
    return None if probe.returncode == 0 else "Debian's python3-genpy/genmsg or the message packages are not installed"


@pytest.mark.realros
@pytest.mark.skipif(_debian_reason() is not None, reason=str(_debian_reason()))
def test_the_record_is_what_debians_tools_give_now(tmp_path: Path) -> None:
    out = subprocess.run([DEBIAN_PYTHON, str(HERE / "real_genaction.py"), str(PACKAGE), str(tmp_path)],
                         capture_output=True, text=True, timeout=120, check=True, env={"PATH": "/usr/bin:/bin"})
    assert json.loads(out.stdout) == RECORD
