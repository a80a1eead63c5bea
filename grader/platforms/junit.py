"""JUnit XML for any other CI: one testsuite per task, one testcase per criterion."""
from __future__ import annotations

import xml.etree.ElementTree as ET
from pathlib import Path

from grader.report import SubmissionReport
from grader.reports.cause import criterion_feedback, criterion_measured, lead_lines, noticed
from grader.reports.escape import one_line, xml
from grader.reports.files import write_atomic
from grader.reports.text import NOTICED_HEADING, fmt_points


def junit_xml(report: SubmissionReport, duration_s: float = 0.0) -> str:
    """The report as a JUnit XML document (failures for lost points, errors for tasks that could not run).

    Student text goes through `xml`/`one_line`: XML 1.0 cannot hold most control characters at all.
    """
    root = ET.Element("testsuites", name="rosgrade", time=f"{duration_s:.3f}")
    totals = {"tests": 0, "failures": 0, "errors": 0}
    for task in report.tasks:
        suite = ET.SubElement(root, "testsuite", name=task.id)
        counts = {"tests": 0, "failures": 0, "errors": 0}
        ET.SubElement(ET.SubElement(suite, "properties"), "property", name="score", value=fmt_points(task.score, task.max_score))
        lead = " ".join(lead_lines(task))
        if task.status != "graded":
            case = ET.SubElement(suite, "testcase", classname=f"rosgrade.{task.id}", name=f"{task.id}: {task.status}", time="0")
            ET.SubElement(case, "error", message=one_line(lead),
                          type=task.status).text = xml("\n".join(noticed(task)))
            counts["tests"] += 1
            counts["errors"] += 1
        for c in task.criteria:
            case = ET.SubElement(suite, "testcase", classname=f"rosgrade.{task.id}",
                                 name=one_line(f"{c.id}: {c.title}"), time="0")
            counts["tests"] += 1
            details = xml(f"{fmt_points(c.score, c.max_score)} points. {criterion_measured(task, c)}".strip())
            if c.score < c.max_score:
                message = " ".join(filter(None, (lead, criterion_feedback(task, c)))) or "lost points"
                ET.SubElement(case, "failure", message=one_line(message), type="points").text = details
                counts["failures"] += 1
            else:
                ET.SubElement(case, "system-out").text = details
        notes = noticed(task)
        if notes:
            ET.SubElement(suite, "system-out").text = xml("\n".join([f"{NOTICED_HEADING}:"] + [f"- {n}" for n in notes]))
        for key, value in counts.items():
            suite.set(key, str(value))
            totals[key] += value
    for key, value in totals.items():
        root.set(key, str(value))
    ET.indent(root)
    return ET.tostring(root, encoding="unicode", xml_declaration=True) + "\n"


def junit_failure(message: str) -> str:
    """A JUnit XML document with one error, for a submission that could not be graded at all."""
    root = ET.Element("testsuites", name="rosgrade", tests="1", failures="0", errors="1")
    suite = ET.SubElement(root, "testsuite", name="rosgrade", tests="1", failures="0", errors="1")
    case = ET.SubElement(suite, "testcase", classname="rosgrade", name="grade submission", time="0")
    ET.SubElement(case, "error", message=one_line(message), type="error")
    ET.indent(root)
    return ET.tostring(root, encoding="unicode", xml_declaration=True) + "\n"


def write_junit(path: Path, document: str) -> Path:
    """Write a JUnit XML document atomically."""
    return write_atomic(path, document)
