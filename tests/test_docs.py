"""The manual's examples do what it says, and its links lead somewhere.

The manual is README.md (the front page) and every page of docs/. In each page:

- every fenced ```sh block: each line that starts with ``fcalc`` is run (in a scratch folder that
  sees the shipped ``configs/``) and its exit code compared with the documented one: the ``N`` of a
  trailing ``echo $?   # N: ...``, else 0. A command written on several pages runs once.
- every fenced ```toml block that is a whole scene (it has a ``kind`` line) is written to a file and
  checked with ``fcalc check``; the sentence after the block states its exit code as "`fcalc check`
  on this block exits N". Any other ```toml block (a part of a scene) must be valid TOML.
- the fenced ```python blocks of a page run in order in one namespace, as a notebook runs its
  cells, in a scratch folder that sees ``configs/``.
- a fenced block that is not run says so by its language: ```text (diagrams, trees, output), or any
  language but sh, toml and python. A fence without a language is an error, so that no example
  escapes the tests unnoticed. Indented blocks (synopses, printed output) are not run.

Every relative link (to a page, a file or folder of the repository, an anchor of a page) must lead
somewhere; links to web addresses are not fetched.
"""

from __future__ import annotations

import re
import shlex
import tomllib
from pathlib import Path

import pytest

from tests.conftest import CONFIGS, ROOT

PAGES = [ROOT / "README.md", *sorted((ROOT / "docs").rglob("*.md"))]
FENCE = re.compile(r"^```([^\n]*)\n(.*?)^```\n(.*?)(?=\n\n|\Z)", re.S | re.M)
RUN = {"sh", "toml", "python"}

#: Lines left out, for their cost: the calculation sheets (`fcalc report`, and `fcalc check
#: --report-dir` that typesets one PDF per shipped scene) are typeset by tests/test_report.py.
COSTLY = ("fcalc report", "--report-dir")

def _name(page: Path) -> str:
    return page.relative_to(ROOT).as_posix()


BLOCKS = [(page, lang.strip(), body, after) for page in PAGES for lang, body, after in FENCE.findall(page.read_text())]


def _commands() -> dict[tuple[str, int], list[str]]:
    """(command, documented exit code) -> the pages that show it."""
    found: dict[tuple[str, int], list[str]] = {}
    for page, lang, body, _ in BLOCKS:
        if lang != "sh":
            continue
        for line in body.splitlines():
            if not line.startswith("fcalc ") and line.strip() != "fcalc" and not line.startswith("fcalc\t"):
                continue
            command, _, comment = line.partition("#")
            documented = 0
            if "echo $?" in command:
                command = command.split(";")[0]
                documented = int(re.match(r"\s*(\d+)", comment).group(1))
            if not any(part in command for part in COSTLY):
                found.setdefault((command.strip(), documented), []).append(_name(page))
    return found


COMMANDS = list(_commands())
SCENES = [(page, body, after) for page, lang, body, after in BLOCKS if lang == "toml" and re.search(r"^kind = ", body, re.M)]
FRAGMENTS = [(page, body) for page, lang, body, _ in BLOCKS if lang == "toml" and not re.search(r"^kind = ", body, re.M)]
NOTEBOOKS = sorted({page for page, lang, _, _ in BLOCKS if lang == "python"})


def test_the_manual_has_examples_to_run():
    assert len(COMMANDS) >= 6 and len(SCENES) >= 2


@pytest.mark.parametrize("page, lang", [(_name(p), lang) for p, lang, _, _ in BLOCKS if lang.split()[:1] != ["text"]])
def test_a_block_that_is_not_run_says_so(page, lang):
    assert lang, f"{page}: a fenced block without a language: write ```text for one that is not run"
    assert lang in RUN or lang.split()[0] not in RUN, f"{page}: ```{lang}: a run block takes no options"


@pytest.mark.parametrize("command, documented", COMMANDS, ids=[c for c, _ in COMMANDS])
def test_shell_example_exits_as_documented(command, documented, runner, tmp_path, monkeypatch):
    from foundation_calc.cli.app import app

    (tmp_path / "configs").symlink_to(CONFIGS)
    monkeypatch.chdir(tmp_path)
    result = runner.invoke(app, shlex.split(command)[1:])
    assert result.exit_code == documented, result.output


@pytest.mark.parametrize(
    "page, body, after", SCENES, ids=[_name(p) + ":" + re.search(r'kind = "(\w+)"', b).group(1) for p, b, _ in SCENES]
)
def test_scene_block_checks_as_documented(page, body, after, runner, tmp_path):
    from foundation_calc.cli.app import app

    stated = re.search(r"`fcalc check` on this block exits (\d)", after)
    assert stated, f"{_name(page)}: the sentence after a scene block states what `fcalc check` does with it"
    scene = tmp_path / "scene.toml"
    scene.write_text(body)
    result = runner.invoke(app, ["check", str(scene)])
    assert result.exit_code == int(stated.group(1)), result.output


def test_every_part_of_a_scene_is_valid_toml():
    for page, body in FRAGMENTS:
        try:
            tomllib.loads(body)
        except tomllib.TOMLDecodeError as error:
            pytest.fail(f"{_name(page)}: {error}\n{body}")


@pytest.mark.parametrize("page", NOTEBOOKS, ids=_name)
def test_python_examples_run_as_a_notebook(page, tmp_path, monkeypatch):
    (tmp_path / "configs").symlink_to(CONFIGS)
    monkeypatch.chdir(tmp_path)
    namespace: dict = {"__name__": "__docs__"}
    for number, (_, lang, body, _) in enumerate(b for b in BLOCKS if b[0] == page and b[1] == "python"):
        exec(compile(body, f"{_name(page)}, python block {number + 1}", "exec"), namespace)


def slug(heading: str) -> str:
    """The anchor GitHub gives a heading: link text kept, lower case, punctuation dropped, spaces to -."""
    text = re.sub(r"\[([^\]]*)\]\([^)]*\)", r"\1", heading).strip().lower()
    return re.sub(r"[^\w\- ]", "", text).replace(" ", "-")


def anchors(text: str) -> set[str]:
    """Every heading's anchor; a repeated heading gets -1, -2 ... as on GitHub."""
    found: set[str] = set()
    seen: dict[str, int] = {}
    for heading in re.findall(r"^#{1,6} (.+)$", _unfenced(text), re.M):
        base = slug(heading)
        count = seen.get(base, 0)
        seen[base] = count + 1
        found.add(base if count == 0 else f"{base}-{count}")
    return found


def _unfenced(text: str) -> str:
    """The page without its fenced blocks (a ``#`` there starts a comment, not a heading)."""
    return re.sub(r"^```.*?^```$", "", text, flags=re.S | re.M)


def _prose(text: str) -> str:
    """The page without its fenced blocks and code spans, where a link is only text."""
    return re.sub(r"`[^`\n]*`", "", _unfenced(text))


LINKS = [
    (page, target)
    for page in PAGES
    for target in re.findall(r"\]\(([^)\s]+)\)", _prose(page.read_text()))
    if not re.match(r"[a-z]+:", target)  # http:, https:, mailto: are not fetched
]


@pytest.mark.parametrize("page, target", LINKS, ids=[f"{_name(p)}->{t}" for p, t in LINKS])
def test_link_leads_somewhere(page, target):
    path, _, anchor = target.partition("#")
    file = (page.parent / path).resolve() if path else page
    assert file.is_relative_to(ROOT), f"{_name(page)}: {target} leaves the repository"
    assert file.exists(), f"{_name(page)}: {target}: no such file"
    if anchor and file.suffix == ".md":
        assert anchor in anchors(file.read_text()), f"{_name(page)}: {target}: no such heading in {_name(file)}"


def test_every_docs_page_is_in_the_index():
    index = (ROOT / "docs" / "README.md").read_text()
    listed = {(ROOT / "docs" / t).resolve() for t in re.findall(r"\]\(([\w/-]+\.md)\)", index)}
    pages = set((ROOT / "docs").rglob("*.md")) - {ROOT / "docs" / "README.md"}
    assert pages <= listed, sorted(_name(p) for p in pages - listed)


def test_the_front_page_stays_a_front_page():
    assert len((ROOT / "README.md").read_text().splitlines()) <= 300


def test_ci_runs_the_test_command_of_the_quick_start():
    """.ci/run's last line is the README's install-and-test command, word for word."""
    readme = (ROOT / "README.md").read_text()
    (command,) = [line for _, lang, body, _ in BLOCKS if lang == "sh" for line in body.splitlines() if "pytest" in line]
    assert "## Quick start" in readme.split(command)[0]
    assert (ROOT / ".ci" / "run").read_text().strip().splitlines()[-1] == command
