"""fcalc report: the sheet's numbers are the --json numbers, user text stays text, lazy imports."""

from __future__ import annotations

import json
import math
import re
import subprocess
import sys
from pathlib import Path

import pytest
import tomli_w

from foundation_calc.cli.app import app
from tests.conftest import CONFIGS, ROOT
from tests.sheet_numbers import numbers

pytest.importorskip("matplotlib")
typst = pytest.importorskip("typst")
pypdf = pytest.importorskip("pypdf")

#: The sheet prints at least 3 significant figures (amplitudes 3, speeds and derived numbers 4): a
#: printed number is within 5e-3 (relative) of the JSON one.
TOLERANCE = 5e-3
HOSTILE = "{x} [b] %s #set <script> $ * _"





#: Margins print in percent to one decimal: a printed margin is within 0.05 (percentage points).
MARGIN_TOLERANCE = 0.05


def assert_all_shown(expected: dict[str, float], shown: list[float]) -> None:
    """Every expected value (name -> SI value) is among the numbers shown, to 6 significant figures
    (margins, named ``margin ...``, to the 0.1 % they print at)."""
    missing = {
        name: value
        for name, value in expected.items()
        if not any(
            abs(x - value) <= (MARGIN_TOLERANCE if "margin" in name else TOLERANCE * abs(value)) for x in shown
        )
    }
    assert not missing, f"numbers of the --json document missing from the sheet: {missing}"


def crank_expected(res: dict, amp: dict) -> dict[str, float]:
    """The numbers of the resonance and amplitudes JSON documents that the sheet must show."""
    out = {f"natural {k}": v for k, v in res["natural_frequencies"].items()}
    out |= {f"critical {r['condition']}": r["critical_speed"]["omega"] for r in res["resonances"]}
    out |= {f"margin {r['condition']}": 100 * r["margin"] for r in res["resonances"]}
    out |= {f"mu": res["derived"]["mu"], "rho1": res["derived"]["rho1"]}
    checked = amp["approximations"][amp["checked_with"]]
    for point, dirs in checked["points"].items():
        for direction, peaks in dirs.items():
            out |= {f"{point} {direction} {q}": v for q, v in peaks.items() if v > 0}
    out |= {f"limit {r['point']} {r['direction']}": r["value"] for r in amp["limits"]}
    return out


def json_of(runner, command: str, scene) -> dict:
    result = runner.invoke(app, [command, str(scene), "--json"])
    assert result.exit_code in (0, 1), result.output
    return json.loads(result.stdout)


def pdf_text(path) -> str:
    return "\n".join(page.extract_text() for page in pypdf.PdfReader(path).pages)


def html_text(path) -> str:
    text = path.read_text(encoding="utf-8")
    text = re.sub(r"<svg.*?</svg>", " ", text, flags=re.S)
    return re.sub(r"<[^>]+>", " ", text)


@pytest.mark.parametrize("suffix", [".pdf", ".html"])
def test_crank_sheet_shows_the_json_numbers(runner, tmp_path, suffix):
    scene = CONFIGS / "frame_saw.toml"
    out = tmp_path / f"sheet{suffix}"
    result = runner.invoke(app, ["report", str(scene), "-o", str(out), "--units", "m,m/s"])  # SI, as --json
    assert result.exit_code in (0, 1), result.output
    text = pdf_text(out) if suffix == ".pdf" else html_text(out)
    expected = crank_expected(json_of(runner, "resonance", scene), json_of(runner, "amplitudes", scene))
    assert_all_shown(expected, numbers(text))


def test_platform_sheet_shows_the_json_numbers(runner, tmp_path):
    scene = CONFIGS / "platform_paper_example.toml"
    out = tmp_path / "sheet.pdf"
    assert runner.invoke(app, ["report", str(scene), "-o", str(out), "--units", "m"]).exit_code == 0  # SI, as --json
    doc = json_of(runner, "platform", scene)
    d, v = doc["design"], doc["verification"]
    expected = {k: d[k] for k in ("c0", "c3", "a", "b", "c", "static_deflection", "translation_frequency")}
    expected |= {f"c{i + 1}{j + 1}": x for i, row in enumerate(d["stiffness_table"]) for j, x in enumerate(row) if x}
    u = doc["inputs"]["u"]
    expected |= {f"amplitude {k}": a for k, a in v["amplitudes"].items() if a > 1e-9 * u}  # below: round-off, printed 0
    expected |= {f"mode {n}": f["omega"] for n, f in enumerate(doc["natural_frequencies"])}
    expected |= {f"margin {n}": 100 * f["margin"] for n, f in enumerate(doc["natural_frequencies"])}
    expected |= {"regime margin": 100 * d["regime_margin"]}
    text = pdf_text(out)
    assert_all_shown(expected, numbers(text))
    # the paper's design moves translationally: z and the rocking are round-off, printed as 0
    assert v["amplitudes"]["z"] < 1e-12 * u and v["rocking_percent"] < 1e-9
    assert re.search(r"amplitude of z 0 m\b", text) and re.search(r"rocking of the corners 0 % of u", text), text


def test_units_convert_the_tables(runner, tmp_path):
    scene = CONFIGS / "frame_saw.toml"
    out = tmp_path / "sheet.html"
    runner.invoke(app, ["report", str(scene), "-o", str(out), "--units", "mm,rpm"])
    res = json_of(runner, "resonance", scene)
    expected = {f"{k} [rpm]": res["natural_frequencies"][k] * 30 / 3.141592653589793 for k in ("k0", "p1", "p2")}
    assert_all_shown(expected, numbers(html_text(out)))


def hostile_scene(tmp_path, kind_file: str):
    import tomllib

    scene = tomllib.loads((CONFIGS / kind_file).read_text(encoding="utf-8"))
    scene["name"] = HOSTILE
    if scene["kind"] == "crank_foundation":
        scene["points"] = [{"name": HOSTILE + " pt", "horizontal": 1.0, "height": 1.0}]
    path = tmp_path / "hostile.toml"
    path.write_text(tomli_w.dumps(scene), encoding="utf-8")
    return path


@pytest.mark.parametrize(
    ("kind_file", "suffix"),
    [("frame_saw.toml", ".pdf"), ("frame_saw.toml", ".html"), ("frame_saw.toml", ".md"), ("platform_paper_example.toml", ".pdf")],
)
def test_user_text_is_never_markup(runner, tmp_path, kind_file, suffix):
    scene = hostile_scene(tmp_path, kind_file)
    out = tmp_path / f"sheet{suffix}"
    result = runner.invoke(app, ["report", str(scene), "-o", str(out)])
    assert result.exit_code in (0, 1), result.output
    if suffix == ".pdf":
        assert HOSTILE in pdf_text(out).replace("\n", " ")
    elif suffix == ".html":
        text = out.read_text(encoding="utf-8")
        assert "<script>" not in text
        assert "{x} [b] %s #set &lt;script&gt; $ * _" in text
    else:
        from foundation_calc.output.report.markdown import escape

        text = out.read_text(encoding="utf-8")
        assert escape(HOSTILE) in text
        assert "<script>" not in text


def test_check_writes_one_sheet_per_scene(runner, tmp_path):
    for name in ("frame_saw.toml", "platform_paper_example.toml", "other/frame_saw.toml"):
        (tmp_path / name).parent.mkdir(exist_ok=True)
        (tmp_path / name).write_bytes((CONFIGS / Path(name).name).read_bytes())
    (tmp_path / "broken.toml").write_text("kind = 'crank_foundation'\n", encoding="utf-8")
    sheets = tmp_path / "sheets"
    result = runner.invoke(app, ["check", str(tmp_path), "--report-dir", str(sheets), "--json"])
    assert result.exit_code == 3, result.output
    assert sorted(p.name for p in sheets.iterdir()) == ["frame_saw-2.pdf", "frame_saw.pdf", "platform_paper_example.pdf"]


def test_unknown_format_is_a_usage_error(runner, tmp_path):
    result = runner.invoke(app, ["report", str(CONFIGS / "frame_saw.toml"), "-o", str(tmp_path / "x.docx")])
    assert result.exit_code == 2
    assert not (tmp_path / "x.docx").exists()


def test_core_commands_do_not_import_the_report_extra():
    code = (
        "import sys\n"
        "from foundation_calc.cli.app import app\n"
        "try:\n"
        "    app(['resonance', sys.argv[1]])\n"
        "except SystemExit:\n"
        "    pass\n"
        "print(sorted(m for m in ('typst', 'matplotlib') if m in sys.modules))\n"
    )
    out = subprocess.run(
        [sys.executable, "-c", code, str(CONFIGS / "frame_saw.toml")], capture_output=True, text=True, cwd=ROOT, check=True
    )
    assert out.stdout.strip().splitlines()[-1] == "[]"


def test_exact_states_the_errors_of_the_closed_forms(runner, tmp_path):
    scene = CONFIGS / "frame_saw.toml"
    out = tmp_path / "sheet.html"
    runner.invoke(app, ["report", str(scene), "-o", str(out), "--exact"])
    amp = json.loads(runner.invoke(app, ["amplitudes", str(scene), "--exact", "--json"]).stdout)
    points = amp["errors"]["first_approximation"]["points"].values()
    largest = {q: max(max(p[q].values()) for p in points) for q in ("displacement", "velocity", "acceleration")}
    shown = numbers(html_text(out).split("Accuracy")[-1])
    assert all(any(abs(x - v) <= 5e-3 * v for x in shown) for v in largest.values()), (largest, shown)


def test_missing_report_extra_is_a_usage_error(runner, tmp_path, monkeypatch):
    import importlib.util

    real = importlib.util.find_spec
    monkeypatch.setattr(importlib.util, "find_spec", lambda name, *a: None if name == "typst" else real(name, *a))
    result = runner.invoke(app, ["report", str(CONFIGS / "frame_saw.toml"), "-o", str(tmp_path / "x.pdf")])
    assert result.exit_code == 2
    assert "foundation_calc[report]" in result.output


def test_damped_sheet_shows_the_phases_and_the_damping(runner, tmp_path):
    scene = CONFIGS / "compressor_damped_near_resonance.toml"
    out = tmp_path / "sheet.md"
    assert runner.invoke(app, ["report", str(scene), "-o", str(out)]).exit_code == 1
    text = out.read_text(encoding="utf-8")
    amp = json_of(runner, "amplitudes", scene)
    assert "Phase lag φ per harmonic" in text
    checked = amp["approximations"][amp["checked_with"]]
    for name in ("x1", "y1", "theta1"):
        assert f"{math.degrees(checked['harmonics'][name]['phase']):.1f}" in text, name
    expected = {f"ratio {i}": z for i, z in enumerate(amp["damping"]["modal_damping_ratios"])}
    shown = numbers(text)
    assert all(any(abs(x - z) <= 5e-3 * z for x in shown) for z in expected.values())
