"""Every option that writes a file follows one rule (foundation_calc/output/files.py): a regular
file is replaced whole, a FIFO or a character device is written in place and stays what it was,
anything else (a socket, a block device, a folder) is a usage error (exit 2) before any work.

A CI job as root with ``--junit /dev/null`` once replaced the system's /dev/null with a regular
file. These tests never touch /dev/null when they can make a device of their own: a node of the
same device numbers (1, 3) in tmp_path; the real /dev/null is written only where this process
cannot replace it (/dev not writable), and is shown to be a character device afterwards.
"""

from __future__ import annotations

import errno
import os
import socket
import stat
import subprocess
import sys
import threading
import tomllib
from pathlib import Path

import pytest

from foundation_calc.cli.app import app
from foundation_calc.output import files
from tests.conftest import CONFIGS

SAW = str(CONFIGS / "frame_saw.toml")
TWO = str(CONFIGS / "block_two_machines.toml")
NO_BENCH = [arg for section in ("accuracy", "harmonic_balance", "runup", "throughput", "startup", "points", "batch",
                                "block", "soil_sample", "design") for arg in ("--skip", section)]

#: option -> (file name, the command writing it to FILE, the first bytes of what it writes).
OPTIONS = {
    "check --junit": ("junit.xml", lambda f: ["check", SAW, "--jobs", "1", "--junit", f], b"<?xml"),
    "sweep --csv": ("sweep.csv", lambda f: ["sweep", SAW, "--speed", "100:600:5", "--csv", f], b"omega_rad_s,"),
    "sweep --csv (block)": ("block.csv", lambda f: ["sweep", TWO, "--machine", "compressor", "--speed", "500:1500:3",
                                                    "--csv", f], b"omega_rad_s,"),
    "sweep --plot": ("sweep.png", lambda f: ["sweep", SAW, "--speed", "100:600:5", "--plot", f], b"\x89PNG"),
    "design --write": ("best.toml", lambda f: ["design", TWO, "--vary", "block.height=1.2:1.6", "--points", "2",
                                               "--write", f], b"# A reciprocating compressor and its drive motor"),
    "design --plot": ("design.svg", lambda f: ["design", TWO, "--vary", "block.height=1.2:1.6", "--points", "2",
                                               "--plot", f], b"<?xml"),
    "runup --plot": ("runup.png", lambda f: ["runup", SAW, "--time", "0.3", "--plot", f], b"\x89PNG"),
    "bench --plot": ("bench.png", lambda f: ["bench", SAW, "--quick", *NO_BENCH, "--plot", f], b"\x89PNG"),
    "report -o": ("sheet.html", lambda f: ["report", SAW, "-o", f], b"<!DOCTYPE html>"),
    "init PATH --force": ("scene.toml", lambda f: ["init", "platform", f, "--force"], b"# Scene of kind 'platform'"),
}
#: The options whose command needs matplotlib.
PLOTS = {"sweep --plot", "design --plot", "runup --plot", "bench --plot"}


class FifoReader:
    """A FIFO made at ``path`` and read on a thread, as ``cat FIFO`` would. A spare hard link to
    the FIFO ends the reader's wait when nobody ever writes it (a writer that replaced the FIFO
    with a regular file)."""

    def __init__(self, path: Path):
        os.mkfifo(path)
        self.path, self.spare, self.data = path, path.with_name(f".{path.name}.spare"), b""
        os.link(path, self.spare)
        self.thread = threading.Thread(target=self._read, daemon=True)
        self.thread.start()

    def _read(self) -> None:
        with open(self.path, "rb") as fifo:
            self.data = fifo.read()

    def finish(self) -> bytes:
        """What the reader got, once the writer has closed (or never came)."""
        if self.thread.is_alive():
            try:
                os.close(os.open(self.spare, os.O_WRONLY | os.O_NONBLOCK))  # a writer that closes: end of file
            except OSError as exc:  # the reader has finished meanwhile
                assert exc.errno == errno.ENXIO
        self.thread.join()
        self.spare.unlink()
        return self.data


def null_device(tmp_path: Path) -> Path:
    """A character device that discards what is written: a node of /dev/null's numbers in
    ``tmp_path``, or /dev/null itself where this process could not replace it."""
    node = tmp_path / "null"
    try:
        os.mknod(node, stat.S_IFCHR | 0o666, os.makedev(1, 3))
        with open(node, "wb") as device:  # a file system mounted nodev refuses to open it
            device.write(b"x")
        return node
    except OSError:
        node.unlink(missing_ok=True)
    if os.access("/dev", os.W_OK):
        pytest.skip("cannot make a device node here, and /dev/null could be replaced by a regression")
    return Path("/dev/null")


def _needs(option: str) -> None:
    if option in PLOTS:
        pytest.importorskip("matplotlib")


@pytest.mark.parametrize("option", list(OPTIONS))
@pytest.mark.filterwarnings("ignore:No artists with labels")  # bench --plot with every section skipped
def test_a_fifo_is_written_in_place_and_stays_a_fifo(runner, tmp_path, option):
    _needs(option)
    name, command, start = OPTIONS[option]
    target = tmp_path / name
    reader = FifoReader(target)
    try:
        result = runner.invoke(app, command(str(target)))
    finally:
        data = reader.finish()
    assert result.exit_code in (0, 1), result.output  # as the command judges the scene
    assert stat.S_ISFIFO(os.lstat(target).st_mode), f"{option} replaced the FIFO"
    assert data.startswith(start), data[:80]
    leftovers = sorted(p.name for p in tmp_path.iterdir() if p.name not in (name, "sheet-figure1.svg"))
    assert leftovers == []  # no temporary file left behind


@pytest.mark.parametrize("option", ["check --junit", "init PATH --force"])
def test_a_character_device_is_written_and_stays_a_device(runner, tmp_path, option):
    device = null_device(tmp_path)
    before = os.stat(device)
    result = runner.invoke(app, OPTIONS[option][1](str(device)))
    assert result.exit_code == 0, result.output
    after = os.lstat(device)
    assert stat.S_ISCHR(after.st_mode) and after.st_rdev == before.st_rdev and after.st_ino == before.st_ino


@pytest.mark.parametrize("option", list(OPTIONS))
@pytest.mark.parametrize("make", ["socket", "block device", "folder"])
def test_what_takes_no_file_is_a_usage_error_before_any_work(runner, tmp_path, monkeypatch, option, make):
    _needs(option)
    name, command, _ = OPTIONS[option]
    target = tmp_path / name
    if make == "socket":
        monkeypatch.chdir(tmp_path)  # a short relative name: AF_UNIX paths hold ~100 bytes
        server = socket.socket(socket.AF_UNIX)
        server.bind(name)
    elif make == "block device":
        try:
            os.mknod(target, stat.S_IFBLK | 0o600, os.makedev(7, 0))  # a loop device's numbers; never opened
        except PermissionError:
            pytest.skip("making a block device node needs CAP_MKNOD")
    elif option.startswith("init"):
        pytest.skip("init PATH takes a folder: it writes KIND.toml into it")
    else:
        target.mkdir()
    mode = os.lstat(target).st_mode
    read = []  # every scene file read: none before the path is judged (init reads only its template)
    if not option.startswith("init"):
        monkeypatch.setattr(tomllib, "loads", lambda *args, **kwargs: read.append(args) or {})
    result = runner.invoke(app, command(str(target)))
    if make == "socket":
        server.close()
    assert result.exit_code == 2, result.output
    assert read == []
    text = " ".join(result.output.split())
    word = {"socket": "is a socket", "block device": "is a block device", "folder": "is a folder"}[make]
    assert word in text and option.split()[1] in text, text
    assert os.lstat(target).st_mode == mode
    assert sorted(p.name for p in tmp_path.iterdir()) == [name]


def test_a_link_to_a_file_replaces_the_file_and_keeps_the_link(runner, tmp_path):
    """A symbolic link is followed: its file is replaced in its own folder, the link still names it."""
    (tmp_path / "reports").mkdir()
    real = tmp_path / "reports" / "junit.xml"
    real.write_text("old\n", encoding="utf-8")
    link = tmp_path / "junit.xml"
    link.symlink_to(real)
    result = runner.invoke(app, ["check", SAW, "--jobs", "1", "--junit", str(link)])
    assert result.exit_code == 0, result.output
    assert link.is_symlink() and link.resolve() == real.resolve()
    assert real.read_text(encoding="utf-8").startswith("<?xml")


def test_a_link_to_a_fifo_streams_into_the_fifo(runner, tmp_path):
    reader = FifoReader(tmp_path / "pipe")
    link = tmp_path / "junit.xml"
    link.symlink_to(tmp_path / "pipe")
    try:
        result = runner.invoke(app, ["check", SAW, "--jobs", "1", "--junit", str(link)])
    finally:
        data = reader.finish()
    assert result.exit_code == 0, result.output
    assert link.is_symlink() and stat.S_ISFIFO(os.stat(link).st_mode) and data.startswith(b"<?xml")


def test_stdout_redirected_to_a_file_gets_the_report_in_order(tmp_path):
    """``--junit /dev/stdout > log``: the report goes through the stream that writes ``log``, after
    what it already holds and before the table; replacing ``log`` would lose the earlier output and
    send the table to a file nobody sees. The link is made in tmp_path, as /dev/stdout is made
    (to /proc/self/fd/1): a writer that replaces what it is given must not replace the system's."""
    log, stdout = tmp_path / "log.txt", tmp_path / "stdout"
    stdout.symlink_to("/proc/self/fd/1")
    code = "import sys; from foundation_calc.cli.app import main; sys.argv[0] = 'fcalc'; main()"
    with open(log, "wb") as out:
        out.write(b"earlier output\n")
        out.flush()
        done = subprocess.run([sys.executable, "-c", code, "check", SAW, "--jobs", "1", "--junit", str(stdout)],
                              stdout=out, timeout=60)
    assert done.returncode == 0
    assert stdout.is_symlink() and os.readlink(stdout) == "/proc/self/fd/1"
    text = log.read_text(encoding="utf-8")
    assert text.startswith("earlier output\n<?xml") and "</testsuites>" in text, text[:200]
    assert text.index("</testsuites>") < text.index("1 scene: 1 pass") and text.rstrip().endswith("exit code 0")


def test_a_fifo_without_a_reader_is_not_waited_for_when_asked(tmp_path):
    """The JUnit report of an interrupted run (its signals ignored by then) must not wait forever
    for a FIFO's reader: ``wait=False`` fails at once (ENXIO) and leaves the FIFO."""
    fifo = tmp_path / "junit.xml"
    os.mkfifo(fifo)
    with pytest.raises(OSError) as raised:
        files.write_atomically(fifo, "<testsuites/>\n", wait=False)
    assert raised.value.errno == errno.ENXIO and stat.S_ISFIFO(os.lstat(fifo).st_mode)
    from foundation_calc.output.check_report import write_junit

    with pytest.raises(OSError):
        write_junit(fifo, [], interrupted="interrupted by SIGTERM")


def test_a_regular_file_is_still_replaced_whole(tmp_path):
    target = tmp_path / "out.csv"
    target.write_text("old, and longer than the new text\n", encoding="utf-8")
    old = os.stat(target).st_ino
    files.write_chunks_atomically(target, ["a,b\n", b"1,2\n"])
    assert target.read_bytes() == b"a,b\n1,2\n" and os.stat(target).st_ino != old  # a new file, renamed over
    assert sorted(p.name for p in tmp_path.iterdir()) == ["out.csv"]
