"""Executing one notebook with papermill so that nothing is lost: the worker behind
:func:`obslib.tools.run.execute`.

Papermill writes the executed notebook to a temporary file beside its destination (it truncates,
then writes); :func:`cleaned` strips what changes from run to run, and the result replaces the
destination in one rename (:func:`obslib._io.write_output`). Kernels talk over Unix sockets in a
private folder (:func:`kernel_config`), and every kernel is registered in :data:`KERNELS` as it
starts, so that a stop can kill the running ones (:meth:`Kernels.kill`).
"""

from __future__ import annotations

import contextlib
import functools
import os
import signal
import sys
import tempfile
import threading
import time
from pathlib import Path

from .._io import write_output

__all__ = ["KERNEL", "KERNEL_STARTS", "KERNEL_START_FAILURES", "merge_streams", "cleaned",
           "Kernels", "KERNELS", "kill_kernel", "kernel_manager_class", "kernel_config",
           "execute_into"]

#: The Jupyter kernel every notebook runs in.
KERNEL = "python3"
#: Kernels started for one notebook before its failure to start is an error (a kernel that dies
#: before its first reply has run nothing of the notebook).
KERNEL_STARTS = 2
#: How jupyter_client reports a kernel that did not start (nothing of the notebook has run).
KERNEL_START_FAILURES = ("Kernel died before replying to kernel_info", "Kernel didn't respond")


def merge_streams(outputs: list) -> list:
    """Join consecutive stream outputs of the same name (stdout/stderr).

    How the kernel chunks printed text into messages depends on timing, so two runs with the
    same text can store it as different lists of outputs; merged, they are identical.
    """
    merged: list = []
    for out in outputs:
        prev = merged[-1] if merged else None
        if (out.get("output_type") == "stream" and prev is not None
                and prev.get("output_type") == "stream" and prev.get("name") == out.get("name")):
            prev["text"] = prev["text"] + out["text"]
        else:
            merged.append(out)
    return merged


def cleaned(path: Path) -> str:
    """The notebook at ``path`` without run-specific metadata and chunking, as the text
    ``nbformat.write`` would store: identical results give identical files."""
    import nbformat

    nb = nbformat.read(path, as_version=4)
    nb.metadata.pop("papermill", None)
    nb.metadata.get("language_info", {}).pop("version", None)
    for cell in nb.cells:
        if cell.cell_type == "code":
            cell.outputs = merge_streams(cell.outputs)
        cell.metadata.pop("papermill", None)
        cell.metadata.pop("execution", None)
        tags = [t for t in cell.metadata.pop("tags", []) if t != "papermill-error-cell-tag"]
        if tags:
            cell.metadata["tags"] = tags
    text = nbformat.writes(nb)
    return text if text.endswith("\n") else text + "\n"


class Kernels:
    """The kernels this process's notebooks run in, so that a stop can kill them.

    Kernels start in sessions of their own (jupyter_client), so a Ctrl-C on the terminal never
    reaches them, and a runner that exits leaves them running until they notice (a second).
    Each is registered, with the thread that runs its notebook, as soon as it has started;
    :meth:`kill` kills the process groups of those still running (the kernel and whatever it
    started). A kernel that finishes starting after a :meth:`kill` of every kernel is killed at
    once.
    """

    def __init__(self):
        self._lock = threading.Lock()
        self._kernels: list = []  # (jupyter_client provisioner, thread)
        self.stopping = False

    def started(self, provisioner) -> None:
        with self._lock:
            self._kernels.append((provisioner, threading.get_ident()))
            if self.stopping:
                kill_kernel(provisioner)

    def forget(self, thread: int) -> None:
        """Forget the kernels of ``thread`` (its notebook is done: they are shut down)."""
        with self._lock:
            self._kernels = [(p, t) for p, t in self._kernels if t != thread]

    def kill(self, thread: int | None = None) -> None:
        """Kill the kernels of ``thread``, or every kernel (and any that starts until
        :meth:`reset`)."""
        with self._lock:
            if thread is None:
                self.stopping = True
            for p, t in self._kernels:
                if thread is None or t == thread:
                    kill_kernel(p)

    def reset(self) -> None:
        """The stop is over: kernels started from now on live."""
        with self._lock:
            self.stopping = False


def kill_kernel(provisioner) -> None:
    """SIGKILL to a running kernel's process group (its own session: the kernel and what it
    started), or to the kernel alone if it shares this process's group. A kernel already ended
    (and reaped, so its number may belong to another process by now) is left alone."""
    process = getattr(provisioner, "process", None)
    if process is None or process.poll() is not None:
        return
    group = getattr(provisioner, "pgid", None)
    try:
        if group is not None and group != os.getpgid(0):
            os.killpg(group, signal.SIGKILL)
        else:
            process.kill()
    except (ProcessLookupError, PermissionError):
        pass  # ended meanwhile


KERNELS = Kernels()


@functools.cache
def kernel_manager_class():
    """jupyter_client's asynchronous kernel manager (nbclient's default), registering each
    kernel it starts in :data:`KERNELS`."""
    from jupyter_client import AsyncKernelManager

    class TrackedKernelManager(AsyncKernelManager):
        async def start_kernel(self, **kw):
            await super().start_kernel(**kw)
            KERNELS.started(self.provisioner)

    return TrackedKernelManager


def kernel_config(folder: str):
    """Kernels talk over Unix sockets in ``folder`` (a private temporary folder), not TCP.

    Over TCP, ipykernel warns on every start that its traffic is not encrypted, and a kernel can
    lose the ports chosen for it to another process starting at the same moment; sockets in a
    folder of their own have neither problem.
    """
    from traitlets.config import Config

    return Config({"KernelManager": {"transport": "ipc", "ip": os.path.join(folder, "kernel")}})


def execute_into(src: Path, dst: Path, parameters: dict, progress) -> float:
    """Execute the notebook ``src`` into ``dst`` with papermill (arguments validated by
    :func:`obslib.tools.run.execute`); the wall time in seconds."""
    import papermill as pm
    from papermill.exceptions import PapermillExecutionError


    dst.parent.mkdir(parents=True, exist_ok=True)
    os.environ.setdefault("PYTHONHASHSEED", "0")
    options = dict(
        parameters=parameters,
        kernel_name=KERNEL,
        progress_bar=progress,
        # the kernel starts in the notebook's folder; papermill's cwd= would chdir this whole
        # process, which notebooks running side by side in threads cannot share
        resources={"metadata": {"path": str(src.parent)}},
        # write the result once, at the end (on an error papermill still writes what ran), rather
        # than the whole notebook again after every cell
        request_save_on_cell_execute=False,
        # every output has arrived when the last cell is done; a graceful shutdown only runs the
        # kernel's exit hooks, and ipykernel sometimes takes seconds to honour it
        shutdown_kernel="immediate",
        kernel_manager_class=kernel_manager_class(),
    )
    # papermill writes here (it truncates, then writes); dst is replaced only by a whole notebook
    fd, scratch = tempfile.mkstemp(prefix=f".{dst.stem}.running-", suffix=".ipynb",
                                   dir=dst.parent)
    os.close(fd)
    t0 = time.perf_counter()
    try:
        for attempt in range(1, KERNEL_STARTS + 1):
            if KERNELS.stopping:
                raise RuntimeError(f"{src.name}: not started, the run is stopping")
            try:
                with tempfile.TemporaryDirectory(prefix="obslib-kernel-") as sockets:
                    pm.execute_notebook(str(src), scratch, config=kernel_config(sockets),
                                        **options)
                break
            except PapermillExecutionError:  # a cell raised: saved with its error, as papermill
                write_output(dst, cleaned(Path(scratch)))
                raise
            except RuntimeError as exc:
                if (attempt == KERNEL_STARTS or KERNELS.stopping
                        or not str(exc).startswith(KERNEL_START_FAILURES)):
                    raise
                print(f"{src.name}: the kernel did not start ({exc}); starting another",
                      file=sys.stderr, flush=True)
        elapsed = time.perf_counter() - t0
        write_output(dst, cleaned(Path(scratch)))
    except BaseException:
        KERNELS.kill(threading.get_ident())  # a stop in this thread: its kernel must not linger
        raise
    finally:
        KERNELS.forget(threading.get_ident())
        with contextlib.suppress(FileNotFoundError):
            os.unlink(scratch)
    return elapsed
