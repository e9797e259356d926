"""Sweeps on a Dask cluster: the connection to a scheduler, a local cluster tuned for sweeps
and the chunks submitted to it."""

from __future__ import annotations

CONNECT_TIMEOUT = 10.0
"""Seconds to reach a Dask scheduler before the sweep is refused (a scheduler on the network
answers within a second)."""


class SchedulerError(Exception):
    """The Dask scheduler given cannot be reached (one line for the user)."""


def connect(address: str, timeout: float | None = None):
    """A Dask client of the scheduler at ``address``; :class:`SchedulerError` when dask is
    not installed, the address is malformed or nothing answers within ``timeout`` s
    (default :data:`CONNECT_TIMEOUT`)."""
    try:
        from dask.distributed import Client
    except ImportError:
        raise SchedulerError("dask.distributed is not installed; install it with "
                             "`pip install \"dask[distributed]\"`") from None
    timeout = CONNECT_TIMEOUT if timeout is None else timeout
    try:
        return Client(address, timeout=timeout)
    except (OSError, ValueError, TypeError) as exc:
        why = str(exc).splitlines()[0] if str(exc) else type(exc).__name__
        raise SchedulerError(f"cannot reach the Dask scheduler within {timeout:g} s "
                             f"({why[:200]})") from None


def local_cluster(workers: int = 2):
    """A Dask ``LocalCluster`` of ``workers`` single-threaded worker processes for sweeps
    (the benchmark and the tests; ``--scheduler`` takes its address).

    Dask's nanny starts workers with ``MALLOC_TRIM_THRESHOLD_=65536``, which fixes glibc's
    mmap threshold: every array of a chunk above 128 kB is then mapped and unmapped anew
    (page faults, system time about six times the local run's), and two such workers were
    slower than one local process.  Unset here, glibc keeps its dynamic threshold as a local
    process does.  A cluster started otherwise (``dask worker``) is set the same way with
    ``distributed.nanny.pre-spawn-environ.MALLOC_TRIM_THRESHOLD_: null`` in its Dask
    configuration (docs/sweep.md)."""
    import dask
    from distributed import LocalCluster

    with dask.config.set({"distributed.nanny.pre-spawn-environ.MALLOC_TRIM_THRESHOLD_": None}):
        return LocalCluster(n_workers=workers, threads_per_worker=1, processes=True,
                            dashboard_address=None)




def on_cluster(address: str, spec_data: dict, sw, rows: bool, chunk: int, tasks):
    """The summaries of the tasks ``tasks(workers)`` (their ``(start, stop)``, for the number
    of workers of the cluster) evaluated on the Dask cluster of the scheduler at
    ``address``, yielded in the order of the tasks (the merge is the local loop's)."""
    from dask.distributed import as_completed

    from geardesign.spur.sweep_chunk import run_task, samplers

    with connect(address) as client:
        bounds = tasks(max(1, len(client.nthreads())))
        futures = [client.submit(run_task, spec_data, sw, ab, rows, chunk, e, pure=False)
                   for ab, e in zip(bounds, samplers(sw, bounds, copies=True))]
        order = {fut.key: i for i, fut in enumerate(futures)}
        done: dict = {}
        following = 0
        for fut in as_completed(futures):     # each as soon as those before it are in
            i = order[fut.key]
            done[i] = fut.result()
            futures[i] = None                 # the worker may drop its copy
            while following in done:
                yield done.pop(following)
                following += 1
