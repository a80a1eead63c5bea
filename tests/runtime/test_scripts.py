"""Script discovery and the rosrun checks reported as findings."""
from __future__ import annotations

import os
from pathlib import Path

import pytest

from grader.runtime.scripts import ScriptNotFound, check_script, find_script

GOOD = b"#!/usr/bin/env python3\nimport rospy\nprint('hi')\n"


def write(path: Path, data: bytes, executable: bool = True) -> Path:
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_bytes(data)
    os.chmod(path, 0o755 if executable else 0o644)
    return path


def test_clean_script_has_no_findings(tmp_path):
    assert check_script(write(tmp_path / "move_circle.py", GOOD)) == []


def test_missing_shebang_is_reported_with_the_fix(tmp_path):
    notes = check_script(write(tmp_path / "a.py", b"import rospy\n"))
    assert len(notes) == 1 and "no shebang" in notes[0] and "#!/usr/bin/env python3" in notes[0]


def test_crlf_line_endings_quote_the_env_error(tmp_path):
    notes = check_script(write(tmp_path / "a.py", GOOD.replace(b"\n", b"\r\n")))
    assert any("python3\\r" in n and "LF" in n for n in notes)


def test_plain_python_shebang_is_reported(tmp_path):
    notes = check_script(write(tmp_path / "a.py", b"#!/usr/bin/env python\nimport rospy\n"))
    assert any("python3" in n for n in notes)


def test_missing_executable_bit_suggests_chmod(tmp_path):
    notes = check_script(write(tmp_path / "a.py", GOOD, executable=False))
    assert notes == [n for n in notes if "chmod +x a.py" in n] and notes


def test_python2_print_is_a_syntax_error_with_a_hint(tmp_path):
    notes = check_script(write(tmp_path / "a.py", b"#!/usr/bin/env python3\nprint 'hello'\n"))
    assert len(notes) == 1
    assert "line 2: SyntaxError" in notes[0] and "Python 2" in notes[0]


def test_non_utf8_source_is_reported(tmp_path):
    notes = check_script(write(tmp_path / "a.py", b"#!/usr/bin/env python3\n# caf\xe9\nx = 1\n"))
    assert any("not valid UTF-8" in n for n in notes)


def test_find_script_prefers_package_src_over_stray_copies(tmp_path):
    write(tmp_path / "old" / "backup" / "deep" / "move_square.py", GOOD)
    best = write(tmp_path / "catkin_ws" / "src" / "part2" / "src" / "move_square.py", GOOD)
    path, notes = find_script(tmp_path, "move_square.py")
    assert path == best
    assert len(notes) == 1 and "Several files" in notes[0]


def test_find_script_skips_build_and_hidden_folders(tmp_path):
    write(tmp_path / "build" / "move_square.py", GOOD)
    write(tmp_path / ".git" / "move_square.py", GOOD)
    with pytest.raises(ScriptNotFound, match="no file named move_square.py"):
        find_script(tmp_path, "move_square.py")


def test_find_script_accepts_a_single_file(tmp_path):
    script = write(tmp_path / "move_circle.py", GOOD)
    assert find_script(script, "move_circle.py") == (script, [])

