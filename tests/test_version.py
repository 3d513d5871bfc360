"""The version names the build: the commit of a checkout, in ``fcalc --version`` and every JSON
document. ``head_commit`` reads .git by hand; git itself (``git rev-parse HEAD``) is the
independent reference, on real repositories: a branch, packed refs, a detached HEAD, a linked
worktree."""

from __future__ import annotations

import json
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from foundation_calc.version import head_commit, version
from tests.conftest import CONFIGS

ROOT = Path(__file__).resolve().parents[1]
FCALC = (sys.executable, "-m", "foundation_calc")

needs_git = pytest.mark.skipif(shutil.which("git") is None, reason="git is not installed")


def _git(cwd: Path, *args: str) -> str:
    env = {"GIT_AUTHOR_NAME": "t", "GIT_AUTHOR_EMAIL": "t@t", "GIT_COMMITTER_NAME": "t",
           "GIT_COMMITTER_EMAIL": "t@t", "PATH": "/usr/bin:/bin:/usr/local/bin", "HOME": str(cwd)}
    return subprocess.run(("git", *args), cwd=cwd, capture_output=True, text=True, check=True, env=env).stdout.strip()


@needs_git
def test_head_commit_agrees_with_git_on_branch_packed_detached_and_worktree(tmp_path):
    repo = tmp_path / "repo"
    repo.mkdir()
    _git(repo, "init", "-q", "-b", "main")
    for i in range(2):
        (repo / "f.txt").write_text(str(i))
        _git(repo, "add", "f.txt")
        _git(repo, "commit", "-q", "-m", f"c{i}")
    assert head_commit(repo) == _git(repo, "rev-parse", "HEAD")  # loose ref
    _git(repo, "pack-refs", "--all")
    assert head_commit(repo) == _git(repo, "rev-parse", "HEAD")  # packed-refs only
    _git(repo, "worktree", "add", "-q", "-b", "other", str(tmp_path / "wt"), "HEAD~1")
    assert head_commit(tmp_path / "wt") == _git(tmp_path / "wt", "rev-parse", "HEAD")  # .git is a file
    assert head_commit(tmp_path / "wt") != head_commit(repo)
    _git(repo, "checkout", "-q", "--detach", "HEAD~1")
    assert head_commit(repo) == _git(repo, "rev-parse", "HEAD")  # detached
    assert head_commit(tmp_path) is None  # not a work tree


@needs_git
def test_fcalc_version_names_the_checkouts_commit():
    if head_commit(ROOT) is None:
        pytest.skip("not run from a git checkout")
    head = _git(ROOT, "rev-parse", "HEAD")
    run = subprocess.run((*FCALC, "--version"), capture_output=True, text=True, check=True)
    assert run.stdout.strip() == f"fcalc {version()}"
    assert f"+g{head[:7]}" in version()


def test_json_documents_carry_the_version():
    from foundation_calc.output.check_report import check_document

    run = subprocess.run((*FCALC, "resonance", str(CONFIGS / "frame_saw.toml"), "--json"), capture_output=True,
                         text=True, check=False)
    for document in (json.loads(run.stdout), check_document([])):
        assert list(document)[:2] == ["schema_version", "fcalc_version"]
        assert document["fcalc_version"] == version()
