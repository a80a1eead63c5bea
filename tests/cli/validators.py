"""Validators written from grading-platforms.md: each raises AssertionError when a document breaks its format."""
from __future__ import annotations

import base64
import json
import math
import xml.etree.ElementTree as ET
from typing import Any

GS_TOP = {"score", "execution_time", "output", "output_format", "test_output_format", "test_name_format",
          "visibility", "stdout_visibility", "extra_data", "tests", "leaderboard"}
GS_TEST = {"score", "max_score", "status", "name", "name_format", "number", "output", "output_format", "tags",
           "visibility", "extra_data"}
GS_VISIBILITY = {"hidden", "after_due_date", "after_published", "visible"}
GS_FORMATS = {"text", "html", "simple_format", "md", "ansi"}
PL_TOP = {"gradable", "score", "format_errors", "message", "output", "images", "tests"}
PL_TEST = {"name", "description", "points", "max_points", "message", "output", "images"}


def _number(value: Any) -> bool:
    return isinstance(value, (int, float)) and not isinstance(value, bool) and math.isfinite(value)


def validate_gradescope(text: str) -> dict[str, Any]:
    """results.json: valid JSON, known keys and types; a score at the top or on every test."""
    data = json.loads(text)
    assert isinstance(data, dict) and set(data) <= GS_TOP, set(data) - GS_TOP
    for key in ("score", "execution_time"):
        assert key not in data or _number(data[key])
    for key in ("output_format", "test_output_format", "test_name_format"):
        assert key not in data or data[key] in GS_FORMATS
    for key in ("visibility", "stdout_visibility"):
        assert key not in data or data[key] in GS_VISIBILITY
    tests = data.get("tests", [])
    assert isinstance(tests, list)
    assert "score" in data or all("score" in t for t in tests)
    for test in tests:
        assert set(test) <= GS_TEST, set(test) - GS_TEST
        for key in ("score", "max_score"):
            assert key not in test or _number(test[key])
        assert "status" not in test or test["status"] in {"passed", "failed"}
        assert "visibility" not in test or test["visibility"] in GS_VISIBILITY
        assert "output_format" not in test or test["output_format"] in GS_FORMATS
        assert all(isinstance(test.get(k, ""), str) for k in ("name", "number", "output"))
        assert isinstance(test.get("tags", []), list) and all(isinstance(t, str) for t in test.get("tags", []))
        assert "\r\n" not in test.get("output", "")
    return data


def validate_github_result(result: dict[str, Any]) -> dict[str, Any]:
    """Runner result version 1 with consistent statuses."""
    assert result["version"] == 1
    assert result["status"] in {"pass", "fail", "error"}
    assert _number(result["max_score"])
    for test in result["tests"]:
        assert {"name", "status", "score", "message", "test_code", "filename", "line_no", "duration"} <= set(test)
        assert test["status"] in {"pass", "fail", "error"} and _number(test["score"])
        assert isinstance(test["line_no"], int) and isinstance(test["duration"], (int, float))
    statuses = {t["status"] for t in result["tests"]}
    expected = "error" if "error" in statuses else "fail" if "fail" in statuses else "pass"
    assert result["status"] == expected
    return result


def decode_github_output(text: str) -> dict[str, Any]:
    """The runner result from a $GITHUB_OUTPUT file's `result=<base64>` line."""
    lines = [line for line in text.splitlines() if line.startswith("result=")]
    assert len(lines) == 1
    encoded = lines[0][len("result="):]
    decoded = base64.b64decode(encoded, validate=True)
    assert base64.b64encode(decoded).decode() == encoded  # exact round trip
    return validate_github_result(json.loads(decoded))


def validate_prairielearn(text: str) -> dict[str, Any]:
    """results.json under 1 MB, score in [0, 1], tests with points, images as data URIs or URLs."""
    assert len(text.encode("utf-8")) < 1_000_000
    data = json.loads(text)
    assert set(data) <= PL_TOP, set(data) - PL_TOP
    assert _number(data["score"]) and 0.0 <= data["score"] <= 1.0
    assert isinstance(data.get("gradable", True), bool)
    for image in data.get("images", []):
        assert isinstance(image, str) or (set(image) == {"label", "url"} and image["url"].startswith("data:image/png;base64,"))
    for test in data.get("tests", []):
        assert set(test) <= PL_TEST and isinstance(test["name"], str)
        assert _number(test["points"]) and _number(test["max_points"]) and 0 <= test["points"] <= test["max_points"]
    return data


def validate_junit(text: str) -> ET.Element:
    """JUnit XML that parses, with testsuite counts matching their testcases."""
    root = ET.fromstring(text.encode("utf-8"))
    assert root.tag == "testsuites"
    total = 0
    for suite in root.iter("testsuite"):
        cases = suite.findall("testcase")
        assert int(suite.get("tests")) == len(cases)
        assert int(suite.get("failures")) == sum(c.find("failure") is not None for c in cases)
        assert int(suite.get("errors")) == sum(c.find("error") is not None for c in cases)
        total += len(cases)
    assert int(root.get("tests")) == total
    return root
