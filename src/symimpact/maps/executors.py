"""Where the runs of a map execute: in this process, on local worker processes, or on a Dask
cluster (a scheduler address, a client, or a loopback LocalCluster).  Each takes chunks of
points and yields the chunks' rows as they finish; ``chunk`` is the module-level function that
turns one chunk into rows (a map's runs by default, or the design map's frequency responses)."""

from __future__ import annotations

from collections.abc import Iterator
from typing import Any

from .._pool import FIRST, spread
from ..errors import ParameterError
from .runs import _run_chunk

EXECUTORS = ("serial", "processes", "dask")


def _serial(payloads: list, chunk=None) -> Iterator[list[dict[str, Any]]]:
    chunk = chunk or _run_chunk  # looked up at call time (tests replace it)
    for p in payloads:
        yield chunk(p)


def _processes(
    payloads: list, workers: int, chunk=None, counts: Any = None, on_wait: Any = None
) -> Iterator[list[dict[str, Any]]]:
    # the warm-up before the workers fork (symimpact._pool.spread): the payload the chunk's
    # function names for it (warm_payload: one point of a chunk), else the first chunk itself
    chunk = chunk or _run_chunk
    make = getattr(chunk, "warm_payload", None)
    warm = make(payloads[0]) if make is not None and payloads else FIRST
    yield from spread(chunk, payloads, workers, warm, counts, on_wait)


#: How long a Dask map waits with no worker before it gives up (all workers lost), and how
#: long it waits to connect to a scheduler.
DASK_NO_WORKER_TIMEOUT = 60.0
DASK_CONNECT_TIMEOUT = 10.0


def _scheduler_address(scheduler: str) -> tuple[str, str, int]:
    """(protocol, host, port) of ``tcp://HOST:PORT`` or ``tls://HOST:PORT`` (``HOST:PORT`` is
    taken as tcp); anything else is refused naming ``scheduler``."""
    import re

    m = re.fullmatch(r"(?:(tcp|tls)://)?(\[[0-9A-Fa-f:.]+\]|[A-Za-z0-9_.-]+):(\d{1,5})", scheduler)
    if m is None or not 0 < int(m[3]) < 65536:
        raise ParameterError(
            "scheduler", f"{scheduler!r} is not a scheduler address like tcp://10.0.0.5:8786"
        )
    return m[1] or "tcp", m[2].strip("[]"), int(m[3])


def _connect(scheduler: str) -> Any:
    """A ``distributed.Client`` of the scheduler at ``scheduler``, or one line saying why not."""
    import socket

    from distributed import Client

    protocol, host, port = _scheduler_address(scheduler)
    try:  # say "refused" at once rather than a time-out 20 s later
        socket.create_connection((host, port), timeout=DASK_CONNECT_TIMEOUT).close()
    except ConnectionRefusedError:
        raise ParameterError(
            "scheduler", f"nothing listens at {host}:{port} (connection refused)"
        ) from None
    except TimeoutError:
        raise ParameterError(
            "scheduler", f"{host}:{port} did not answer within {DASK_CONNECT_TIMEOUT:g} s"
        ) from None
    except OSError as exc:
        raise ParameterError(
            "scheduler", f"cannot reach {host}:{port}: {exc.strerror or exc}"
        ) from None
    try:
        return Client(f"{protocol}://{host}:{port}", timeout=f"{DASK_CONNECT_TIMEOUT:g}s")
    except Exception as exc:  # distributed raises assorted types (OSError, TimeoutError, ...)
        raise ParameterError(
            "scheduler",
            f"{scheduler!r} is not a Dask scheduler that answers ({type(exc).__name__})",
        ) from None


class DaskLost(OSError):
    """The Dask scheduler or every worker was lost during a map (a fault, not bad input)."""


def _dask(
    payloads: list, client: Any, scheduler: str | None, chunk=None
) -> Iterator[list[dict[str, Any]]]:
    chunk = chunk or _run_chunk
    import time

    try:
        from distributed import Client, LocalCluster, as_completed
    except ImportError:  # pragma: no cover - distributed is a dependency
        raise ParameterError("executor", "dask needs the 'distributed' package") from None
    cluster = None
    own = client is None
    if own and scheduler is None:
        # a local cluster: on the loopback interface only, no dashboard
        cluster = LocalCluster(
            host="127.0.0.1", dashboard_address=None, threads_per_worker=1, processes=True
        )
        client = Client(cluster)
    elif own:
        client = _connect(scheduler)
    try:
        futures = client.map(chunk, payloads, pure=False)
        pending = as_completed(futures)
        alone_since = None
        try:
            while not pending.is_empty():
                batch = pending.next_batch(block=False)
                for f in batch:
                    try:
                        yield f.result()
                    except ParameterError:
                        raise
                    except Exception as exc:
                        raise DaskLost(
                            f"the Dask map failed: {type(exc).__name__}: {exc}"
                        ) from None
                if batch:
                    continue
                if client.status != "running":
                    raise DaskLost("the Dask scheduler was lost during the map")
                try:
                    workers = len(client.scheduler_info()["workers"])
                except Exception:
                    raise DaskLost("the Dask scheduler was lost during the map") from None
                now = time.monotonic()
                alone_since = None if workers else (alone_since or now)
                if alone_since is not None and now - alone_since > DASK_NO_WORKER_TIMEOUT:
                    raise DaskLost(
                        f"no Dask worker for {DASK_NO_WORKER_TIMEOUT:g} s: every worker was lost"
                    )
                time.sleep(0.05)
        finally:
            try:
                client.cancel(futures)
            except Exception:  # a lost scheduler: nothing left to cancel
                pass
    finally:
        if own:
            try:
                client.close()
            finally:
                if cluster is not None:
                    cluster.close()
