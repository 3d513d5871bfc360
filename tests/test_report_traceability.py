"""Traceability of a sheet: the office file and its SHA-256, the purpose of issue, the revision in
its history, and whether fcalc is a release or a development build."""

from __future__ import annotations

import hashlib

import pytest

import foundation_calc
from foundation_calc.cli.app import app
from tests.conftest import CONFIGS

pytest.importorskip("matplotlib")

SAW = (CONFIGS / "frame_saw.toml").read_text(encoding="utf-8")  # [project] revision "A", history A


def _scene(tmp_path, text: str = SAW, office: str | None = None):
    if office is not None:
        (tmp_path / "fcalc.toml").write_text(office, encoding="utf-8")
    scene = tmp_path / "job" / "saw.toml"
    scene.parent.mkdir(exist_ok=True)
    scene.write_text(text, encoding="utf-8")
    return scene


def _sheet(runner, scene, tmp_path) -> str:
    out = tmp_path / "sheet.md"
    result = runner.invoke(app, ["report", str(scene), "-o", str(out)])
    assert result.exit_code == 0, result.output
    return out.read_text(encoding="utf-8").replace("\\", "")


def test_sheet_names_and_hashes_the_office_file_and_the_purpose(runner, tmp_path):
    office = '[project]\npurpose = "for approval"\n'
    text = _sheet(runner, _scene(tmp_path, office=office), tmp_path)
    digest = hashlib.sha256(office.encode()).hexdigest()  # the file's bytes as written
    assert f"| office file | {tmp_path / 'fcalc.toml'} |" in text
    assert f"| SHA-256 of the office file | {digest} |" in text
    assert "| purpose of issue | for approval |" in text
    assert text.startswith("job J-2041 · calc. CALC-017 · rev. A · for approval")


def test_sheet_without_office_file_says_so(runner, tmp_path):
    assert "| office file | none (no fcalc.toml" in _sheet(runner, _scene(tmp_path), tmp_path)


@pytest.mark.parametrize("version, kind", [("1.2.0", "release"), ("0.1.dev5+g1234567", "development build")])
def test_sheet_says_release_or_development_build(runner, tmp_path, monkeypatch, version, kind):
    monkeypatch.setattr(foundation_calc, "__version__", version)
    assert f"| fcalc version | {version} ({kind}) |" in _sheet(runner, _scene(tmp_path), tmp_path)


@pytest.mark.parametrize(
    "edit, message",
    [
        (('revision = "A"', 'revision = "B"'), "revision = 'B' is not in the revision history (revisions: A)"),
        (('revision = "A"', 'revision = "A"\npurpose = "for tender"'), "project.purpose: must be 'for information'"),
    ],
)
def test_bad_revision_or_purpose_is_an_invalid_scene(runner, tmp_path, edit, message):
    scene = _scene(tmp_path, SAW.replace(*edit, 1))
    for command in (["check", str(scene)], ["report", str(scene), "-o", str(tmp_path / "s.md")]):
        result = runner.invoke(app, command)
        assert result.exit_code == 3, (command, result.output)
        assert message in " ".join(result.output.split()), (command, result.output)
