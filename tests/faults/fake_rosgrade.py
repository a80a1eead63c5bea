"""rosgrade's command line with the CLI tests' fake grading installed: for tests that kill a real batch process.

    python tests/faults/fake_rosgrade.py batch DIR --out OUT
"""
from __future__ import annotations

import sys
from pathlib import Path

HERE = Path(__file__).resolve()
sys.path[:0] = [str(HERE.parents[2]), str(HERE.parents[1])]  # this checkout's grader, and the tests' `cli` package

from cli import fakes  # noqa: E402

from grader.cli import main  # noqa: E402


def install_fakes() -> None:
    for name, module in (("grader.grading", fakes.grading_module()), ("grader.rubric", fakes.rubric_module()),
                         ("grader.scoring", fakes.scoring_module()), ("grader.recording", fakes.recording_module())):
        sys.modules[name] = module


if __name__ == "__main__":
    install_fakes()
    sys.exit(main(sys.argv[1:]))
