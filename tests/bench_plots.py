"""Benchmark (run by hand, not a test): CPU seconds the report's plots cost, from the recordings of saved reports.

Make the reports once, e.g. `python3 -m grader.cli check reference_solutions --out /tmp/plots-ref`, then

    python3 tests/bench_plots.py /tmp/plots-ref [MORE_REPORT_FOLDERS...] [--plots OTHER_PLOTS.py]

`--plots` measures another version of grader/reports/plots.py instead (e.g. the last commit's, saved with
`git show HEAD:grader/reports/plots.py > /tmp/plots_before.py`), for before/after figures in one sitting.

Recordings are read before the clock starts (`rosgrade bench` times reading as its own stage), so the figures are
what is measured: the whole report's plots, then each task's alone (a `check --task` report), best of 3 in
process CPU time. Per-plot figures are the report's CPU divided by the plots it made.
"""
from __future__ import annotations

import argparse
import importlib.util
import sys
import time
from collections import Counter
from collections.abc import Callable
from pathlib import Path
from typing import Any
from unittest import mock

from grader.recording import Recording
from grader.report import SubmissionReport
from grader.reports import plots as current_plots
from grader.reports.plots import Plot

REPEATS = 3


def best_cpu(work: Callable[[], Any]) -> float:
    """The smallest process CPU time of REPEATS runs of `work`."""
    times = []
    for _ in range(REPEATS):
        started = time.process_time()
        work()
        times.append(time.process_time() - started)
    return min(times)


def load_plots(path: Path | None) -> Any:
    """grader.reports.plots, or the module in the file `path` standing in for it."""
    if path is None:
        return current_plots
    spec = importlib.util.spec_from_file_location("bench_plots_under_test", path)
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    sys.modules[spec.name] = module  # its dataclasses look their module up
    spec.loader.exec_module(module)
    return module


def main(folders: list[Path], plots_file: Path | None) -> None:
    report_plots = load_plots(plots_file).report_plots
    reports = [SubmissionReport.model_validate_json((folder / "report.json").read_text()) for folder in folders]
    opened = {path: Recording.open(Path(path))
              for report in reports for task in report.tasks for path in task.recordings}
    with mock.patch.object(Recording, "open", staticmethod(lambda path, **_: opened[str(path)])):
        plots: list[Plot] = [plot for report in reports for plot in report_plots(report)[0]]  # also warms imports
        kinds = Counter(plot.name for plot in plots)
        total = best_cpu(lambda: [report_plots(report) for report in reports])
        print(f"{len(opened)} recordings, {len(plots)} plots ({', '.join(f'{n} {k}' for k, n in kinds.items())}), "
              f"{sum(len(p.png) for p in plots) / 1000:.0f} kB of PNG")
        print(f"all reports:  {total:6.2f} CPU-s  {total / len(plots) * 1000:5.1f} ms/plot")
        for report in reports:
            for task in report.tasks:
                alone = report.model_copy(update={"tasks": [task]})
                count = len(report_plots(alone)[0])
                if count:
                    cpu = best_cpu(lambda: report_plots(alone))
                    print(f"  {task.id:<22} {count:3d} plots {cpu:6.2f} CPU-s  {cpu / count * 1000:5.1f} ms/plot")


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("folders", nargs="*", type=Path, default=[Path("/tmp/plots-ref")])
    parser.add_argument("--plots", type=Path, help="another plots.py to measure instead of the current one")
    args = parser.parse_args()
    main(args.folders, args.plots)
