"""Run independent tasks on joblib (process workers, embedded) or on a Dask distributed cluster.

One code path: joblib's ``Parallel``; with a scheduler address its Dask backend sends the same calls
to the cluster's workers through a ``distributed.Client``. Results come back as they finish (with a
progress bar on a terminal); the caller orders them by the index each task returns.
"""

from __future__ import annotations

import contextlib
import os
import sys
from collections.abc import Callable, Iterator, Sequence
from typing import Any

from joblib import Parallel, delayed, parallel_config

from ..errors import MechplanError


def default_workers() -> int:
    """One worker per core this process may use."""
    try:
        return max(1, len(os.sched_getaffinity(0)))
    except AttributeError:          # not on Linux
        return max(1, os.cpu_count() or 1)


def progress_wanted(flag: bool | None) -> bool:
    """Show a progress bar when asked, or by default when stderr is a terminal."""
    return sys.stderr.isatty() if flag is None else flag


@contextlib.contextmanager
def _backend(workers: int | None, scheduler: str | None) -> Iterator[int]:
    if not scheduler:
        n = workers or default_workers()
        with parallel_config(backend="loky" if n > 1 else "sequential", n_jobs=n):
            yield n
        return
    try:
        from distributed import Client
    except ImportError:
        raise MechplanError("a scheduler address needs dask.distributed; install it with "
                            "pip install 'mechplan[cluster]'") from None
    try:
        client = Client(scheduler, timeout="10s", set_as_default=False)
    except OSError as exc:
        raise MechplanError(f"the Dask scheduler must be reachable (got {scheduler!r}: {exc}); "
                            "start one with 'dask scheduler' and 'dask worker ADDRESS'") from None
    try:
        n = workers or max(1, sum(client.nthreads().values()))
        with parallel_config(backend="dask", n_jobs=n, wait_for_workers_timeout=30,
                             client=client):
            yield n
    finally:
        client.close()


def run_tasks(fn: Callable[..., Any], calls: Sequence[tuple[Any, ...]], *,
              workers: int | None = None, scheduler: str | None = None,
              progress: bool | None = None, desc: str = "", unit: str = "task") -> Iterator[Any]:
    """Yield ``fn(*args)`` for every args tuple, in completion order, with a progress bar."""
    from tqdm import tqdm

    if not calls:
        return
    with tqdm(total=len(calls), desc=desc, unit=unit, disable=not progress_wanted(progress),
              file=sys.stderr, dynamic_ncols=True) as bar, _backend(workers, scheduler):
        results = Parallel(return_as="generator_unordered")(delayed(fn)(*a) for a in calls)
        for result in results:
            bar.update(1)
            yield result
