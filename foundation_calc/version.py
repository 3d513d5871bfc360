"""The version of fcalc, with the commit it was built from, read only when asked for.

Built from a git checkout (``pip install .`` or ``pip install -e .``), setuptools-scm writes the
version into ``foundation_calc/_version.py``: ``X.Y.Z`` at a tag ``vX.Y.Z``, else
``X.Y.devN+g<commit>`` (``.dYYYYMMDD`` added when the tree had uncommitted changes). An
installed distribution without that file falls back to its metadata; a copy of the sources built
without git metadata is ``0.0`` (pyproject's ``fallback_version``), run uninstalled ``0+unknown``.

An editable install runs the checkout's code as it is now, not as it was installed: when the
package lives in a git work tree whose HEAD is another commit than the one built, the local part
names HEAD instead (read from ``.git`` directly, no subprocess: a few file reads).
"""

from __future__ import annotations

import re
from functools import cache
from pathlib import Path

#: What a copy with neither build metadata nor git reports.
UNKNOWN = "0+unknown"


def built_version() -> str:
    """The version recorded when the package was built or installed."""
    try:
        from foundation_calc._version import version

        return version
    except ImportError:
        pass
    from importlib.metadata import PackageNotFoundError, version

    try:
        return version("foundation_calc")
    except PackageNotFoundError:
        return UNKNOWN


def _git_dir(root: Path) -> Path | None:
    """The git directory of the work tree ``root`` (a worktree's ``.git`` is a file naming it)."""
    dot_git = root / ".git"
    if dot_git.is_dir():
        return dot_git
    if dot_git.is_file():
        text = dot_git.read_text(encoding="utf-8").strip()
        if text.startswith("gitdir:"):
            return (root / text.removeprefix("gitdir:").strip()).resolve()
    return None


def head_commit(root: Path) -> str | None:
    """The commit checked out in the git work tree ``root`` (40 hex digits), None outside git.

    Follows HEAD to its branch in the loose refs or ``packed-refs`` of the repository (the
    common directory of a linked worktree).
    """
    git = _git_dir(root)
    if git is None or not (git / "HEAD").is_file():
        return None
    head = (git / "HEAD").read_text(encoding="utf-8").strip()
    if not head.startswith("ref:"):
        return head or None  # detached HEAD
    ref = head.removeprefix("ref:").strip()
    common = git
    if (git / "commondir").is_file():
        common = (git / (git / "commondir").read_text(encoding="utf-8").strip()).resolve()
    for base in (git, common):
        if (base / ref).is_file():
            return (base / ref).read_text(encoding="utf-8").strip()
    packed = common / "packed-refs"
    if packed.is_file():
        for line in packed.read_text(encoding="utf-8").splitlines():
            commit, _, name = line.partition(" ")
            if name == ref:
                return commit
    return None


def with_commit(built: str, commit: str | None) -> str:
    """``built`` with its local part naming ``commit`` when it names another one (or none).

    >>> with_commit("0.1.dev5+g1234567", "1234567abcdef"), with_commit("0.1.dev5+g1234567", "89abcde0123")
    ('0.1.dev5+g1234567', '0.1.dev5+g89abcde01')
    >>> with_commit("0.2.0", None), with_commit("0+unknown", "89abcde0123")
    ('0.2.0', '0+g89abcde01')
    >>> with_commit("0.1.dev9+g1234567.d20261126", "1234567abcdef")
    '0.1.dev9+g1234567.d20261126'

    """
    if commit is None:
        return built
    public, _, local = built.partition("+")
    built_commit = local.split(".")[0].removeprefix("g") if local.startswith("g") else ""
    if built_commit and commit.startswith(built_commit):
        return built
    return f"{public}+g{commit[:9]}"


@cache
def version() -> str:
    """fcalc's version: the built one, its commit replaced by HEAD in an editable checkout."""
    return with_commit(built_version(), head_commit(Path(__file__).resolve().parents[1]))


#: A release as setuptools-scm writes it at a tag vX.Y.Z: X.Y.Z and nothing after it.
RELEASE = re.compile(r"\d+\.\d+\.\d+")


def build_kind(text: str) -> str:
    """Whether the version ``text`` is a release (built at a tag vX.Y.Z), a development build
    (``.devN``, a commit or uncommitted changes after it) or of unknown origin.

    >>> build_kind("1.2.0"), build_kind("0.1.dev5+g1234567"), build_kind("1.2.0+g1234567.d20261126"), build_kind(UNKNOWN)
    ('release', 'development build', 'development build', 'unknown build (no version metadata)')
    """
    if RELEASE.fullmatch(text):
        return "release"
    if text in (UNKNOWN, "0.0"):
        return "unknown build (no version metadata)"
    return "development build"


__all__ = ["RELEASE", "UNKNOWN", "build_kind", "built_version", "head_commit", "version", "with_commit"]
