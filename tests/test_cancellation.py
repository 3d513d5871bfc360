"""A cancelled batch (SIGTERM from a CI runner, SIGINT from Ctrl-C) ends at once with 143 / 130,
takes its worker processes with it, and leaves a JUnit report that says it was interrupted, never
half a file. Real processes and real signals; every wait is bounded."""

from __future__ import annotations

import os
import signal
import subprocess
import sys
import time
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest

from tests.conftest import CONFIGS

#: Bound on every wait of these tests [s]: far above what a cancellation takes (well under a
#: second), far below a hang.
PATIENCE = 60.0


def _children(pid: int) -> set[int]:
    """Process ids of the children of ``pid`` (Linux /proc)."""
    found = set()
    for task in Path(f"/proc/{pid}/task").glob("*"):
        try:
            found |= {int(x) for x in (task / "children").read_text().split()}
        except OSError:
            pass
    return found


def _alive(pid: int) -> bool:
    """True while ``pid`` exists and is not a zombie waiting to be reaped."""
    try:
        fields = Path(f"/proc/{pid}/stat").read_text().rsplit(")", 1)[1].split()
    except OSError:
        return False
    return fields[0] != "Z"


@pytest.mark.skipif(not Path("/proc/self/task").exists(), reason="reads children from Linux /proc")
@pytest.mark.parametrize(("signum", "code"), [(signal.SIGTERM, 143), (signal.SIGINT, 130)], ids=["SIGTERM", "SIGINT"])
def test_a_signal_ends_the_batch_and_its_workers_and_marks_the_report(tmp_path, signum, code):
    folder = tmp_path / "scenes"
    folder.mkdir()
    slow = (CONFIGS / "frame_saw_soft_soil_runup.toml").read_bytes()  # a start-up: seconds per scene
    (folder / "a_quick.toml").write_bytes((CONFIGS / "frame_saw.toml").read_bytes())  # checked first, before the fork
    for k in range(12):
        (folder / f"saw_{k:02d}.toml").write_bytes(slow)
    report = tmp_path / "fcalc.xml"
    code_text = "import sys; from foundation_calc.cli.app import main; sys.argv[0] = 'fcalc'; main()"
    messages = tmp_path.parent / f"{tmp_path.name}.stderr"  # a file: a pipe held by orphans never ends
    with open(messages, "wb") as stderr:
        process = subprocess.Popen(
            [sys.executable, "-c", code_text, "check", str(folder), "--junit", str(report), "--jobs", "2"],
            stdout=subprocess.DEVNULL, stderr=stderr,
        )
    workers: set[int] = set()
    try:
        deadline = time.monotonic() + PATIENCE
        while len(_children(process.pid)) < 2 and time.monotonic() < deadline and process.poll() is None:
            time.sleep(0.05)
        workers = _children(process.pid)
        assert len(workers) >= 2, "the workers never started"
        process.send_signal(signum)
        assert process.wait(timeout=PATIENCE) == code, messages.read_text()
        deadline = time.monotonic() + PATIENCE
        while any(_alive(pid) for pid in workers) and time.monotonic() < deadline:
            time.sleep(0.05)
        assert not [pid for pid in workers if _alive(pid)], "workers outlived the batch"
    finally:  # whatever failed, leave no process behind
        for pid in [process.pid, *workers]:
            try:
                os.kill(pid, signal.SIGKILL)
            except ProcessLookupError:
                pass
        process.wait()
    assert sorted(p.name for p in tmp_path.iterdir()) in (["scenes"], ["fcalc.xml", "scenes"])  # no temp file
    if report.exists():
        root = ET.parse(report).getroot()  # a whole document
        assert "interrupted" in root.get("name")
        assert any(case.get("name") == "interrupted" for case in root.iter("testcase"))
    assert signal.Signals(signum).name in messages.read_text()
