"""Writing a command's output file safely; refusing, before any work, a path that cannot be written.

Every command line of the package that takes an output path (``--write``) calls
:func:`as_output_path` while it parses its arguments, so an impossible path is a command-line
error (exit status 2) before anything is computed, and :func:`write_output` at the end:

- a regular file is replaced atomically (a temporary file in the same directory, then a rename),
  and left untouched when it already holds the same text (compared only when its size equals the
  new text's, so a huge file is never read into memory);
- anything else that can be opened for writing (``/dev/stdout``, a FIFO, a terminal, a device) is
  written once and never read.
"""

from __future__ import annotations

import os
import stat
import tempfile
from pathlib import Path

__all__ = ["OutputPathError", "as_output_path", "write_output"]


class OutputPathError(ValueError):
    """An output path that cannot be written (missing directory, not a directory, no permission)."""


def as_output_path(path) -> Path:
    """``path`` as a :class:`~pathlib.Path` if a file can be written there, else
    :class:`OutputPathError` saying why. Nothing is created or written.

    Examples
    --------
    >>> as_output_path("/no-dir/x.json")
    Traceback (most recent call last):
    ...
    obslib._io.OutputPathError: /no-dir/x.json: directory /no-dir does not exist
    """
    if path is None or str(path) == "":
        raise OutputPathError("the output path is empty; give a file name")
    p = Path(path)
    try:
        st = p.stat()
    except FileNotFoundError:
        st = None
    except NotADirectoryError:
        raise OutputPathError(f"{p}: a part of the path is not a directory") from None
    except OSError as exc:
        raise OutputPathError(f"{p}: {exc.strerror}") from None
    if st is not None:
        if stat.S_ISDIR(st.st_mode):
            raise OutputPathError(f"{p}: is a directory, give a file name")
        if not os.access(p, os.W_OK):
            raise OutputPathError(f"{p}: permission denied")
        if not stat.S_ISREG(st.st_mode):
            return p  # a device, FIFO or terminal: written in place, once
    parent = p.parent
    if not parent.exists():
        if any(q.exists() and not q.is_dir() for q in parent.parents):
            raise OutputPathError(f"{p}: a part of the path is not a directory")
        raise OutputPathError(f"{p}: directory {parent} does not exist")
    if not parent.is_dir():
        raise OutputPathError(f"{p}: {parent} is not a directory")
    if not os.access(parent, os.W_OK | os.X_OK):
        raise OutputPathError(f"{p}: cannot write in directory {parent} (permission denied)")
    return p


def write_output(path, text: str) -> bool:
    """Write ``text`` to ``path`` (see the module docstring); returns whether anything was written.

    Raises :class:`OSError` if the write itself fails (a full device, say); a regular file is then
    left as it was.
    """
    p = Path(path)
    data = text.encode("utf-8")
    try:
        st = p.stat()
    except FileNotFoundError:
        st = None
    if st is not None and not stat.S_ISREG(st.st_mode):
        with open(p, "wb") as fh:  # never read: /dev/stdout, a FIFO, a device
            fh.write(data)
        return True
    if st is not None and st.st_size == len(data) and p.read_bytes() == data:
        return False
    fd, tmp = tempfile.mkstemp(prefix=f".{p.name}.", suffix=".tmp", dir=p.parent)
    try:
        with os.fdopen(fd, "wb") as fh:
            fh.write(data)
        os.chmod(tmp, stat.S_IMODE(st.st_mode) if st is not None else 0o666 & ~_umask())
        os.replace(tmp, p)
    except BaseException:
        try:
            os.unlink(tmp)
        except FileNotFoundError:
            pass
        raise
    return True


def _umask() -> int:
    mask = os.umask(0)
    os.umask(mask)
    return mask
