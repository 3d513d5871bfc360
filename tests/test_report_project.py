"""Sign-off: the scene's [project] table, the office defaults file fcalc.toml, the page header."""

from __future__ import annotations

import pytest

from foundation_calc.cli.app import app
from tests.conftest import CONFIGS


def _saw_without_project() -> str:
    """configs/frame_saw.toml without its own [project] table, as TOML text."""
    import tomllib

    import tomli_w

    scene = tomllib.loads((CONFIGS / "frame_saw.toml").read_text(encoding="utf-8"))
    scene.pop("project", None)
    return tomli_w.dumps(scene)

pytest.importorskip("matplotlib")

PROJECT = """
[project]
calculation = "CALC-017"
revision = "B"
prepared_by = "P. Preparer"
prepared_date = 2026-11-26
revisions = [
  { revision = "A", date = 2026-10-01, description = "first issue" },
  { revision = "B", date = 2026-11-26, description = "start-up limit added", by = "P. Preparer" },
]
"""

OFFICE = """
[project]
job = "J-2041"
client = "Sawmill Ltd"
checked_by = "A. Checker"
calculation = "CALC-000"
"""


@pytest.fixture
def office(tmp_path):
    """An office folder: fcalc.toml at the top, a scene with its own [project] two folders down."""
    (tmp_path / "fcalc.toml").write_text(OFFICE, encoding="utf-8")
    scene = tmp_path / "jobs" / "saw" / "saw.toml"
    scene.parent.mkdir(parents=True)
    scene.write_text(_saw_without_project() + PROJECT, encoding="utf-8")
    return scene


def test_scene_with_project_is_accepted_by_every_command(runner, office):
    for command in (["check"], ["resonance"], ["amplitudes"], ["sweep", "--speed", "20:30:5"], ["soil"]):
        result = runner.invoke(app, [*command, str(office)])
        assert result.exit_code == 0, (command, result.output)


def test_sheet_carries_project_office_defaults_and_page_header(runner, office, tmp_path):
    out = tmp_path / "sheet.md"
    assert runner.invoke(app, ["report", str(office), "-o", str(out)]).exit_code == 0
    text = out.read_text(encoding="utf-8").replace("\\", "")
    assert text.startswith("job J-2041 · calc. CALC-017 · rev. B")  # the scene's calculation no. wins
    for row in ("| client | Sawmill Ltd |", "| prepared | P. Preparer | 2026-11-26 |  |",
                "| checked | A. Checker |  |  |", "| approved |  |  |  |", "| B | 2026-11-26 | start-up limit added | P. Preparer |"):
        assert row in text, row


def test_pdf_pages_are_headed_with_page_n_of_n(runner, office, tmp_path):
    pypdf = pytest.importorskip("pypdf")
    pytest.importorskip("typst")
    out = tmp_path / "sheet.pdf"
    assert runner.invoke(app, ["report", str(office), "-o", str(out)]).exit_code == 0
    pages = pypdf.PdfReader(out).pages
    for n, page in enumerate(pages, 1):
        assert f"job J-2041 · calc. CALC-017 · rev. B · page {n} of {len(pages)}" in page.extract_text(), n


@pytest.mark.parametrize(
    ("where", "text", "message"),
    [
        ("scene", '\n[project]\nprepard_by = "x"\n', "project.prepard_by: unknown key (misspelt, or not part of this scene kind); did you mean prepared_by?"),
        ("office", '[project]\nclent = "x"\n', "project.clent: unknown key (misspelt, or not part of this scene kind); did you mean client?"),
        ("office", '[limits]\namplitude = 1e-3\n', "limits: fcalc.toml holds only a [project] table"),
    ],
)
def test_unknown_project_keys_are_errors(runner, tmp_path, where, text, message):
    scene = tmp_path / "saw.toml"
    body = _saw_without_project()
    scene.write_text(body + (text if where == "scene" else ""), encoding="utf-8")
    if where == "office":
        (tmp_path / "fcalc.toml").write_text(text, encoding="utf-8")
    for command in ("check", "resonance", "report"):
        result = runner.invoke(app, [command, str(scene), *(["-o", str(tmp_path / "s.md")] if command == "report" else [])])
        assert result.exit_code == 3, (command, result.output)
        assert message in result.output.replace("\n", " ").replace("  ", " "), (command, result.output)


def test_office_file_is_no_scene_of_a_folder(runner, office):
    result = runner.invoke(app, ["check", str(office.parents[2])])
    assert result.exit_code == 0, result.output
    assert "fcalc.toml" not in result.output
