"""Writing files safely, and stopping a command cleanly.

Writing. Every file the package's tools write (a command's ``--write`` output, the runner's
notebooks, sidecars, index and times) goes through :func:`write_output`: the text is written to
a temporary file in the target's own folder, flushed to disk, and renamed over the target, so a
stop, a full disk or a concurrent writer at any moment leaves either the old file or the new one,
never a truncated one. A file that already holds the same text is left untouched (compared only
when its size equals the new text's, so a huge file is never read into memory). A symbolic link
is written through: the file it points to is replaced and the link kept. Anything but a regular
file (a FIFO, a device, a terminal, ``/dev/stdout``) is refused, before any work when the command
checks its path with :func:`as_output_path` while it parses its arguments; to print, a command
leaves out ``--write``. A command reports a write that fails at the end in one line
(:func:`write_or_report`). Read-modify-write updates of a shared file (the runner's index of
reruns) hold :func:`locked`, an exclusive lock on a file beside it, so concurrent commands never
lose each other's entries.

Stopping. :func:`command` wraps a command line's ``main(argv)``: SIGINT (Ctrl-C), SIGTERM (a CI
cancel, ``timeout``, ``kill``) and SIGHUP (a closed terminal) raise :class:`Stopped` in the main
thread instead of killing the process, so every ``finally`` runs and every temporary file is
removed; the command prints one line, ``<prog>: stopped by SIGTERM ...``, and exits with the
conventional status ``128 + signal number`` (130, 143, 129). A block that must not be cut in two
(writing a record made of two files) runs under :func:`uninterrupted`: a signal that arrives
inside it takes effect at its end. While a stop is under way, further signals are ignored.
"""

from __future__ import annotations

import contextlib
import functools
import os
import signal
import stat
import sys
import tempfile
import threading
from pathlib import Path

__all__ = ["OutputPathError", "as_output_path", "as_input_file", "write_output", "write_or_report",
           "locked",
           "Stopped", "STOP_SIGNALS", "command", "uninterrupted"]


class OutputPathError(ValueError):
    """An output path that cannot be written (missing directory, not a directory, no permission,
    not a regular file)."""


#: What :func:`stat.S_IFMT` says a path is, in words, for the refusals.
_KINDS = {stat.S_IFIFO: "a FIFO (named pipe)", stat.S_IFCHR: "a character device",
          stat.S_IFBLK: "a block device", stat.S_IFSOCK: "a socket", stat.S_IFDIR: "a directory"}


def _stat(p: Path):
    """``os.stat`` of ``p`` (links followed), ``None`` if nothing is there, or the reason as an
    :class:`OutputPathError`."""
    try:
        return p.stat()
    except FileNotFoundError:  # nothing there, or a dangling link (written through)
        return None
    except NotADirectoryError:
        raise OutputPathError(f"{p}: a part of the path is not a directory") from None
    except OSError as exc:
        raise OutputPathError(f"{p}: {exc.strerror}") from None


def _target(p: Path) -> Path:
    """The file a write to ``p`` replaces: the file a symbolic link points to (through every
    link of a chain), else ``p``."""
    return Path(os.path.realpath(p)) if p.is_symlink() else p


def as_output_path(path) -> Path:
    """``path`` as a :class:`~pathlib.Path` if a regular file can be written there, else
    :class:`OutputPathError` saying why. Nothing is created or written.

    A symbolic link is accepted when the file it points to could be written (it is written
    through); a FIFO, a device, a terminal or a socket is refused.

    Examples
    --------
    >>> as_output_path("/no-dir/x.json")
    Traceback (most recent call last):
    ...
    obslib._io.OutputPathError: /no-dir/x.json: directory /no-dir does not exist
    >>> as_output_path("/dev/null")
    Traceback (most recent call last):
    ...
    obslib._io.OutputPathError: /dev/null: is a character device, ...
    """
    if path is None or str(path) == "":
        raise OutputPathError("the output path is empty; give a file name")
    if not isinstance(path, (str, os.PathLike)):
        raise OutputPathError(f"the output path must be a file name, got {path!r}")
    p = Path(path)
    st = _stat(p)
    if st is not None:
        if stat.S_ISDIR(st.st_mode):
            raise OutputPathError(f"{p}: is a directory, give a file name")
        if not stat.S_ISREG(st.st_mode):
            kind = _KINDS.get(stat.S_IFMT(st.st_mode), "not a regular file")
            raise OutputPathError(f"{p}: is {kind}, not a regular file; the output is written "
                                  "to a file (leave out --write to print it)")
        if not os.access(p, os.W_OK):
            raise OutputPathError(f"{p}: permission denied")
    target = _target(p)
    parent = target.parent
    if not parent.exists():
        if any(q.exists() and not q.is_dir() for q in parent.parents):
            raise OutputPathError(f"{p}: a part of the path is not a directory")
        raise OutputPathError(f"{p}: directory {parent} does not exist")
    if not parent.is_dir():
        raise OutputPathError(f"{p}: {parent} is not a directory")
    if not os.access(parent, os.W_OK | os.X_OK):
        raise OutputPathError(f"{p}: cannot write in directory {parent} (permission denied)")
    return p


def as_input_file(path) -> Path:
    """``path`` as a :class:`~pathlib.Path` if it is a regular file (links followed) that can be
    read, else a :class:`~obslib._validate.MissingFileError` (a ``FileNotFoundError`` and a
    ``ValueError``) saying why: nothing there, or a FIFO or device, which a reader could wait on
    forever.

    Examples
    --------
    >>> as_input_file("/no-dir/data.json")
    Traceback (most recent call last):
    ...
    obslib._validate.MissingFileError: /no-dir/data.json: no such file
    """
    from ._validate import MissingFileError

    if not isinstance(path, (str, os.PathLike)) or str(path) == "":
        raise MissingFileError(f"the input path must be a file name, got {path!r}")
    p = Path(path)
    try:
        st = _stat(p)
    except OutputPathError as exc:
        raise MissingFileError(str(exc)) from None
    if st is None:
        raise MissingFileError(f"{p}: no such file")
    if not stat.S_ISREG(st.st_mode):
        kind = _KINDS.get(stat.S_IFMT(st.st_mode), "not a regular file")
        raise MissingFileError(f"{p}: is {kind}, not a regular file")
    if not os.access(p, os.R_OK):
        raise MissingFileError(f"{p}: permission denied")
    return p


def write_output(path, text: str | bytes) -> bool:
    """Write ``text`` (or bytes, such as a PNG) to ``path`` atomically (see the module
    docstring); returns whether anything was written.

    Raises :class:`OSError` if the write itself fails (a full device, say), and
    :class:`OutputPathError` for a path that is not a regular file; the file is then left as it
    was, and no temporary file remains.

    Examples
    --------
    >>> import tempfile
    >>> p = Path(tempfile.mkdtemp()) / "out.txt"
    >>> write_output(p, "x\\n"), write_output(p, "x\\n"), p.read_text()
    (True, False, 'x\\n')
    """
    p = Path(path)
    data = text if isinstance(text, bytes) else text.encode("utf-8")
    st = _stat(p)
    if st is not None and not stat.S_ISREG(st.st_mode):
        kind = _KINDS.get(stat.S_IFMT(st.st_mode), "not a regular file")
        raise OutputPathError(f"{p}: is {kind}, not a regular file")
    if st is not None and st.st_size == len(data) and p.read_bytes() == data:
        return False
    target = _target(p)
    fd, tmp = tempfile.mkstemp(prefix=f".{target.name}.", suffix=".tmp", dir=target.parent)
    try:
        with os.fdopen(fd, "wb") as fh:
            fh.write(data)
            fh.flush()
            os.fsync(fh.fileno())  # on disk before the rename makes it the file
        os.chmod(tmp, stat.S_IMODE(st.st_mode) if st is not None else 0o666 & ~_umask())
        os.replace(tmp, target)
    except BaseException:
        with contextlib.suppress(FileNotFoundError):
            os.unlink(tmp)
        raise
    return True


def write_or_report(prog: str, path, text: str | bytes) -> bool:
    """:func:`write_output` for a command line: a failed write is one line on standard error,
    ``<prog>: error: cannot write <path>: <reason>``, and ``False`` (the command then exits 1).

    Examples
    --------
    >>> write_or_report("prog", "/dev/full", "x")  # doctest: +SKIP
    False
    """
    try:
        write_output(path, text)
    except OSError as exc:  # OutputPathError is a ValueError: the path changed since parsing
        print(f"{prog}: error: cannot write {path}: {exc.strerror or exc}", file=sys.stderr)
        return False
    except OutputPathError as exc:
        print(f"{prog}: error: cannot write {exc}", file=sys.stderr)
        return False
    return True


@contextlib.contextmanager
def locked(path):
    """Hold an exclusive lock on the file ``path`` (created if missing, never removed) while the
    block runs; other processes and threads taking the same lock wait for it.

    Examples
    --------
    >>> import tempfile
    >>> with locked(Path(tempfile.mkdtemp()) / ".lock"):
    ...     pass
    """
    import fcntl

    with open(path, "a") as fh:
        fcntl.flock(fh, fcntl.LOCK_EX)
        try:
            yield
        finally:
            fcntl.flock(fh, fcntl.LOCK_UN)


def _umask() -> int:
    mask = os.umask(0)
    os.umask(mask)
    return mask


# --------------------------------------------------------------------------------------------
# Stopping a command cleanly
# --------------------------------------------------------------------------------------------

#: The signals that stop a command cleanly: Ctrl-C, a termination request, a closed terminal.
STOP_SIGNALS = (signal.SIGINT, signal.SIGTERM, signal.SIGHUP)


class Stopped(BaseException):
    """A command stopped by a signal of :data:`STOP_SIGNALS`. Like :class:`KeyboardInterrupt` it
    is no :class:`Exception`, so ``except Exception`` lets it through.

    ``name`` is the signal's name, ``status`` the conventional exit status ``128 + signum``, and
    ``detail`` (set by the code that stops) says what was stopped.
    """

    def __init__(self, signum: int, detail: str = ""):
        self.signum = int(signum)
        self.name = signal.Signals(signum).name
        self.status = 128 + self.signum
        self.detail = detail
        super().__init__(f"stopped by {self.name}")


class _StopState:
    """The signal handlers of :func:`command` and the blocks of :func:`uninterrupted`."""

    def __init__(self):
        self.signum = None  # the first stop signal received
        self.raised = False  # Stopped raised already: later signals are ignored
        self.depth = 0  # nesting of uninterrupted() blocks

    def handler(self, signum, frame):
        if self.signum is not None:
            return  # the stop is under way
        self.signum = signum
        if self.depth == 0:
            self.raised = True
            raise Stopped(signum)


_STOP = _StopState()


@contextlib.contextmanager
def uninterrupted():
    """A block that a stop signal does not cut in two: a signal received inside it raises
    :class:`Stopped` at its end (only under :func:`command`; elsewhere the block is plain)."""
    _STOP.depth += 1
    try:
        yield
    finally:
        _STOP.depth -= 1
    if _STOP.depth == 0 and _STOP.signum is not None and not _STOP.raised:
        _STOP.raised = True
        raise Stopped(_STOP.signum)


@contextlib.contextmanager
def _stop_signals():
    """Within the block, :data:`STOP_SIGNALS` raise :class:`Stopped` (main thread only)."""
    if threading.current_thread() is not threading.main_thread():
        yield
        return
    global _STOP
    saved, _STOP = _STOP, _StopState()
    old = {s: signal.signal(s, _STOP.handler) for s in STOP_SIGNALS}
    try:
        yield
    finally:
        for s, h in old.items():
            signal.signal(s, h)
        _STOP = saved


def command(prog: str):
    """Decorate a command line's ``main(argv=None) -> int`` so that a stop signal ends it
    cleanly: one line on standard error, ``<prog>: stopped by <SIGNAL>[: detail]``, and the
    exit status ``128 + signum`` (see the module docstring).

    Examples
    --------
    >>> @command("python -m demo")
    ... def main(argv=None):
    ...     raise Stopped(signal.SIGTERM, "nothing finished")
    >>> main([])
    143
    """
    def decorate(main):
        @functools.wraps(main)
        def wrapper(argv=None):
            with _stop_signals():
                try:
                    return main(argv)
                except Stopped as exc:
                    detail = f": {exc.detail}" if exc.detail else ""
                    print(f"{prog}: stopped by {exc.name}{detail}", file=sys.stderr, flush=True)
                    return exc.status
        return wrapper
    return decorate
