"""Every file fcalc is asked to write (``--junit``, ``--csv``, ``--plot``, ``--write``, ``-o``,
``check --report-dir``, ``init``), written by one rule (:func:`output_target`):

* nothing there yet, or a regular file: the data go to a temporary file in the same folder,
  flushed and synced, then renamed over the path (:func:`os.replace`, atomic on one file system):
  readers see the old file or the new one, never a mix, and an interrupted run leaves the old file;
* a FIFO or a character device (``/dev/null``, a terminal, a pipe reached as ``/dev/stdout``): opened
  and written in place, never replaced (a FIFO waits for its reader, as a shell's ``>`` does);
* the file this process's stdout or stderr already writes to (``--junit /dev/stdout > log``):
  written through that stream, after what it holds, not replaced under it;
* a symbolic link is followed: the rule applies to the file it names; a regular file is replaced
  in its own folder, and the link stays, naming the new file;
* anything else (a folder, a block device, a socket) or a missing folder: :class:`OutputPathError`,
  nothing written. An entry that is not a regular file is never replaced.
"""

from __future__ import annotations

import errno
import os
import stat
import sys
import tempfile
from collections.abc import Iterable
from pathlib import Path

#: :func:`output_target`: the path is (or will be) a regular file, replaced whole.
REPLACE = "replace"
#: :func:`output_target`: the path is a FIFO or a character device, written in place.
STREAM = "stream"


class OutputPathError(OSError):
    """A path that cannot take an output file: a folder, a block device, a socket, or a path whose
    folder does not exist; the message says which."""


def output_target(path: str | Path) -> str:
    """How ``path`` is written: :data:`REPLACE` or :data:`STREAM` (module docstring); raises
    :class:`OutputPathError` for a path that takes no output file. Only the path's status is read
    (a FIFO is not opened)."""
    try:
        mode = os.stat(path).st_mode  # through symbolic links
    except (FileNotFoundError, NotADirectoryError):
        folder = Path(os.path.realpath(path)).parent
        if not folder.is_dir():
            why = "is not a folder" if folder.exists() else "does not exist"
            raise OutputPathError(f"folder {str(folder)!r} of {str(path)!r} {why}") from None
        return REPLACE
    if stat.S_ISREG(mode):
        return REPLACE
    if stat.S_ISFIFO(mode) or stat.S_ISCHR(mode):
        return STREAM
    if stat.S_ISDIR(mode):
        raise OutputPathError(f"{str(path)!r} is a folder; give a file name")
    what = "a block device" if stat.S_ISBLK(mode) else "a socket" if stat.S_ISSOCK(mode) else "not a regular file"
    raise OutputPathError(f"{str(path)!r} is {what}: fcalc writes a regular file (replaced whole), a FIFO or a"
                          " character device (written in place)")


def write_atomically(path: str | Path, data: str | bytes, *, overwrite: bool = True, wait: bool = True) -> None:
    """Write ``data`` to ``path`` (:func:`write_chunks_atomically` of one chunk)."""
    write_chunks_atomically(path, (data,), overwrite=overwrite, wait=wait)


def write_chunks_atomically(
    path: str | Path, chunks: Iterable[str | bytes], *, overwrite: bool = True, wait: bool = True
) -> None:
    """Write ``chunks`` (text as UTF-8, or bytes), one after the other as they come, to ``path`` by
    the rule of the module docstring: memory holds one chunk at a time.

    A regular file is replaced atomically through a temporary file in its folder. With
    ``overwrite=False`` the finished file is hard-linked to ``path`` instead, which fails
    atomically with :class:`FileExistsError` when ``path`` exists (that file is left alone; a FIFO
    or a device there raises it too). With ``wait=False`` a FIFO without a reader raises
    :class:`OSError` (ENXIO) instead of waiting for one.

    Raises :class:`OutputPathError` for a path that takes no output file, :class:`OSError` when
    the write fails.
    """
    kind = output_target(path)
    if not overwrite and os.path.lexists(path):
        raise FileExistsError(errno.EEXIST, "File exists", str(path))
    own = _own_stream(path)
    if own is not None:
        _flush_standard_streams()
        _write_descriptor(os.dup(own), chunks)
    elif kind == STREAM:
        flags = os.O_WRONLY | os.O_NOCTTY | (0 if wait else os.O_NONBLOCK)
        descriptor = os.open(path, flags)  # a FIFO: waits for its reader unless wait=False
        os.set_blocking(descriptor, True)
        mode = os.fstat(descriptor).st_mode
        if not (stat.S_ISFIFO(mode) or stat.S_ISCHR(mode)):  # replaced between the look and the open
            os.close(descriptor)
            raise OutputPathError(f"{str(path)!r} changed while it was opened; not written")
        _write_descriptor(descriptor, chunks)
    else:
        _replace(Path(os.path.realpath(path)), chunks, overwrite)


def _own_stream(path: str | Path) -> int | None:
    """1 or 2 when ``path`` is the file this process's stdout or stderr writes to, else None."""
    try:
        target = os.stat(path)
    except OSError:
        return None
    for descriptor in (1, 2):
        try:
            own = os.fstat(descriptor)
        except OSError:  # closed
            continue
        if (own.st_dev, own.st_ino) == (target.st_dev, target.st_ino):
            return descriptor
    return None


def _flush_standard_streams() -> None:
    """What Python holds for stdout and stderr goes out first, so the file follows it in order."""
    for stream in (sys.stdout, sys.stderr):
        try:
            stream.flush()
        except (AttributeError, OSError, ValueError):
            pass


def _encoded(chunk: str | bytes) -> bytes:
    return chunk.encode("utf-8") if isinstance(chunk, str) else chunk


def _write_descriptor(descriptor: int, chunks: Iterable[str | bytes]) -> None:
    """Write ``chunks`` to the open ``descriptor`` and close it."""
    with os.fdopen(descriptor, "wb") as handle:
        for chunk in chunks:
            handle.write(_encoded(chunk))


def _umask() -> int:
    mask = os.umask(0o022)
    os.umask(mask)
    return mask


def _replace(path: Path, chunks: Iterable[str | bytes], overwrite: bool) -> None:
    """Replace the regular file ``path`` (or create it) through a temporary file beside it."""
    fd, tmp = tempfile.mkstemp(prefix=f".{path.name}.", suffix=".tmp", dir=path.parent)
    try:
        with os.fdopen(fd, "wb") as handle:
            for chunk in chunks:
                handle.write(_encoded(chunk))
            handle.flush()
            os.fsync(handle.fileno())
        os.chmod(tmp, 0o666 & ~_umask())  # mkstemp makes it private; give it a normal file's mode
        if not overwrite:
            os.link(tmp, path)
            return
        try:
            mode = os.lstat(path).st_mode
        except FileNotFoundError:
            mode = stat.S_IFREG
        if not stat.S_ISREG(mode):  # appeared while the data were written: never replace it
            raise OutputPathError(f"{str(path)!r} is no longer a regular file; not replaced")
        os.replace(tmp, path)
    finally:
        Path(tmp).unlink(missing_ok=True)


__all__ = ["REPLACE", "STREAM", "OutputPathError", "output_target", "write_atomically", "write_chunks_atomically"]
