"""Run independent tasks on joblib (process workers, embedded) or on a Dask distributed cluster.

One code path: joblib's ``Parallel``; with a scheduler address its Dask backend sends the same calls
to the cluster's workers through a ``distributed.Client``. Results come back as they finish (with a
progress bar on a terminal); the caller orders them by the index each task returns.
"""

from __future__ import annotations

import contextlib
import os
import re
import signal
import sys
import threading
import time
import warnings
from collections.abc import Callable, Iterator, Sequence
from typing import Any

from joblib import Parallel, delayed, parallel_config

from ..errors import MechplanError
from .texts import say

_ADDRESS = re.compile(r"^(?:(?:tcp|tls|ws|wss|ucx)://)?(\[[0-9A-Fa-f:.]+\]|[A-Za-z0-9_.-]+):(\d{1,5})$")
#: how often a local worker checks that the main process is still there (seconds)
WATCH_SECONDS = 0.2


def _worker_init(owner: int) -> None:
    """Start a local worker: Ctrl-C is the main process's to handle (no worker tracebacks),
    and the worker ends as soon as the main process is gone instead of going on writing."""
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    # a watchdog, not the parent-death signal: that one follows the thread that started the
    # worker, and a reused worker may outlive it
    threading.Thread(target=_watch, args=(owner,), name="mechplan-watch", daemon=True).start()


def _watch(owner: int) -> None:
    while os.getppid() == owner:
        time.sleep(WATCH_SECONDS)
    os._exit(1)


def check_scheduler(address: str) -> str:
    """Refuse a scheduler address that is not ``[tcp://]HOST:PORT`` before connecting."""
    m = _ADDRESS.match(address.strip())
    if not m or not 0 < int(m.group(2)) < 65536:
        raise MechplanError(say("scheduler_address", address=repr(address)))
    return address.strip()


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
        if n == 1:
            with parallel_config(backend="sequential", n_jobs=1):
                yield n
            return
        with parallel_config(backend="loky", n_jobs=n, initializer=_worker_init,
                             initargs=(os.getpid(),)):
            yield n
        return
    scheduler = check_scheduler(scheduler)
    try:
        from distributed import Client
    except ImportError:
        from ..i18n import Text

        raise MechplanError(Text("batchvars.scheduler")) from None
    try:
        client = Client(scheduler, timeout="10s", set_as_default=False)
    except (OSError, ValueError, TypeError) as exc:
        raise MechplanError(say("scheduler_unreachable", address=repr(scheduler), reason=str(exc)),
                            key="--scheduler") from None
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
        try:
            for result in results:
                bar.update(1)
                yield result
        finally:
            # an interrupted run: joblib's note about the cancelled tasks is not for the user
            with warnings.catch_warnings():
                warnings.simplefilter("ignore", UserWarning)
                results.close()
