"""Writing files so that an interrupted run never leaves a half-written or lost file behind."""

from __future__ import annotations

import os
import tempfile
from collections.abc import Iterable
from pathlib import Path


def _umask() -> int:
    mask = os.umask(0o022)
    os.umask(mask)
    return mask


def write_atomically(path: str | Path, text: str, *, overwrite: bool = True) -> None:
    """Write ``text`` to ``path`` atomically (:func:`write_chunks_atomically` of one chunk)."""
    write_chunks_atomically(path, (text,), overwrite=overwrite)


def write_chunks_atomically(path: str | Path, chunks: Iterable[str], *, overwrite: bool = True) -> None:
    """Write the texts ``chunks`` (UTF-8), one after the other as they come, to ``path`` through a
    temporary file in the same folder: memory holds one chunk at a time.

    The temporary file is flushed and synced, then renamed over ``path`` with :func:`os.replace`,
    which is atomic on one file system: readers see the old file or the new one, never a mix.
    With ``overwrite=False`` the finished file is hard-linked to ``path`` instead, which fails
    atomically with :class:`FileExistsError` when ``path`` exists (that file is left alone).
    """
    path = Path(path)
    fd, tmp = tempfile.mkstemp(prefix=f".{path.name}.", suffix=".tmp", dir=path.parent)
    try:
        with os.fdopen(fd, "w", encoding="utf-8", newline="\n") as handle:
            for text in chunks:
                handle.write(text)
            handle.flush()
            os.fsync(handle.fileno())
        os.chmod(tmp, 0o666 & ~_umask())  # mkstemp makes it private; give it a normal file's mode
        if overwrite:
            os.replace(tmp, path)
        else:
            os.link(tmp, path)
    finally:
        Path(tmp).unlink(missing_ok=True)
