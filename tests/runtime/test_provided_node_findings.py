"""The grader's own nodes (a server the student's client calls) run beside the student's, but the findings about
publishers, subscribers and exceptions, and the topic summary, are the student's only: a student cannot act on the
grader's node; only its failure is said."""
from __future__ import annotations

from pathlib import Path

from grader.runtime import NodeSpec, RunSpec
from grader.runtime.session import run
from sim import Scenario

TALKER = '''
import rospy
from std_msgs.msg import String
rospy.init_node("{name}")
pub = rospy.Publisher("/chatter_{name}", String, queue_size=1)
rospy.sleep(0.5)
pub.publish(String(data="hi"))
rospy.sleep(0.5)
raise RuntimeError("{name} fails on purpose")
'''


def test_only_the_students_node_gets_findings_and_a_summary(tmp_path: Path) -> None:
    scripts = {}
    for name in ("student", "server"):
        scripts[name] = tmp_path / f"{name}.py"
        scripts[name].write_text(TALKER.format(name=name))
    spec = RunSpec(Scenario(robot="turtlebot3_burger", duration=2.0),
                   (NodeSpec(script=scripts["student"]), NodeSpec(script=scripts["server"], provided=True)))
    result = run(spec, tmp_path / "run.mcap", tmp_path / "run.log")
    findings = "\n".join(result.diagnostics)
    assert "student.py stopped with an uncaught RuntimeError" in findings
    assert "server.py" not in findings.replace("the grader's server.py", "")
    assert "the grader's server.py stopped with an uncaught RuntimeError: server fails" in findings  # still said
    summary = "\n".join(result.topics)
    assert "student.py published 1 message on /chatter_student" in summary
    assert "server.py" not in summary
