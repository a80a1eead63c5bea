"""Run a batch's jobs on Dask distributed: a running scheduler (`--scheduler`) or a LocalCluster (`--dask-workers`).

Each job is `grader.gradejob.run_job` on a worker: the submission and the rubric files travel with it and the
report and recordings come back as data, so workers need no shared file system. Dask re-runs the job of a
worker that dies. Dask is imported only here, and only when a batch asks for it.
"""
from __future__ import annotations

import contextlib
import uuid
from collections.abc import Callable, Sequence
from typing import Any

import grader
from grader.gradejob import Job, Outcome, run_job
from grader.roster import Student

CONNECT_TIMEOUT_S = 30


class DaskPoolError(Exception):
    """Dask is missing, the scheduler cannot be reached, or its workers run another rosgrade."""


def rosgrade_version() -> str:
    """The rosgrade version a worker runs (compared with ours before any job is sent)."""
    return grader.__version__


def dask_pool(scheduler: str | None = None, workers: int | None = None) -> Callable[..., None]:
    """An executor for `run_batch` that sends each student's job to Dask (scheduler address, else a LocalCluster)."""

    def execute(students: Sequence[Student], make_job: Callable[[Student], Job],
                on_done: Callable[[Outcome], None]) -> None:
        try:
            import dask
            from distributed import Client, LocalCluster, as_completed
        except ImportError:
            raise DaskPoolError("Dask is not installed; install it with pip install 'rosgrade[dask]'") from None
        with contextlib.ExitStack() as stack:
            if scheduler:
                try:
                    client = stack.enter_context(Client(scheduler, timeout=CONNECT_TIMEOUT_S))
                except (OSError, TimeoutError) as exc:
                    raise DaskPoolError(f"cannot reach the Dask scheduler at {scheduler}: {exc}") from None
            else:
                # Workers fork a grading process per job, which daemonic processes may not do.
                stack.enter_context(dask.config.set({"distributed.worker.daemon": False}))
                cluster = stack.enter_context(LocalCluster(n_workers=workers or 1, threads_per_worker=1,
                                                           processes=True, dashboard_address=None))
                client = stack.enter_context(Client(cluster))
            _check_workers(client)
            _run(client, as_completed, students, make_job, on_done)

    return execute


def _check_workers(client: Any) -> None:
    versions = client.run(rosgrade_version)
    if not versions:
        raise DaskPoolError("the Dask scheduler has no workers; start some with `dask worker <scheduler address>`")
    other = {address: v for address, v in versions.items() if v != grader.__version__}
    if other:
        raise DaskPoolError(f"Dask workers run another rosgrade ({', '.join(f'{a}: {v}' for a, v in other.items())}); "
                            f"install rosgrade {grader.__version__} on every worker")


def _run(client: Any, as_completed: Any, students: Sequence[Student], make_job: Callable[[Student], Job],
         on_done: Callable[[Outcome], None]) -> None:
    run_id = uuid.uuid4().hex[:8]
    futures: dict[Any, Student] = {}
    try:
        for student in students:
            try:
                job = make_job(student)
            except OSError as exc:
                on_done(Outcome(student.key, "error", message=f"cannot read the submission: {exc.strerror or exc}"))
                continue
            futures[client.submit(run_job, job, key=f"rosgrade-{run_id}-{student.key}", pure=False)] = student
        for future in as_completed(futures):
            student = futures[future]
            try:
                outcome = future.result()
            except Exception as exc:  # e.g. KilledWorker: the job took down every worker that tried it
                outcome = Outcome(student.key, "error", message=f"Dask could not grade it: {type(exc).__name__}: {exc}")
            on_done(outcome)
    finally:
        client.cancel(list(futures), force=True)
