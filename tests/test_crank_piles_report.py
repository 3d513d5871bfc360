"""The calculation sheet of a crank on a pile group (configs/crank_on_piles.toml): its verdict and
exit code are ``fcalc check``'s, and its frequencies come from the plane's one model, reproducible
by hand from what it prints.

Independent references, written here:

- ``fcalc check --json`` on the same file as ``tests/test_json_record.py`` records it and holds it
  equal to the live command's (exit code, verdicts, reasons, frequencies);
- a brute-force eigen-solve assembled here from the sheet's printed numbers only (the plane's
  springs at O at each mode's ω*, six figures; the masses M_tot, M̄_xθ, M̄_θθ, four; h from the
  inputs): the springs at O carried to C by the congruence Tᵀ K T of u_x = x − h θ, the weights'
  tilt on θ (P h of the block and machine at C, g M̄_xθ of the moving masses at their mean height
  above C), then ``scipy.linalg.eigvals`` of (K̄, M̄). Tolerance: half a unit of the printed p's last
  figure plus the change of the solve over half a unit of each printed input's last figure (a
  linear bound of the rounding the sheet prints), so "to the printed digits".

The figures of the piled crank's sheet need the speed sweep on a coupled support, which lands with
the sweep's own change: until then these tests make the sheet without figures (``figures=False``).
"""

from __future__ import annotations

import gzip
import json
import math
import re

import numpy as np
import pytest
from scipy.linalg import eigvals

from foundation_calc.api.report import SHEET_UNITS
from foundation_calc.api.options import display_units
from foundation_calc.output.report import write_sheet
from foundation_calc.output.report.documents import scene_sheet

from tests.conftest import CONFIGS
from tests.sheet_numbers import numbers
from tests.sheet_reader import read_html, read_markdown

CONFIG = CONFIGS / "crank_on_piles.toml"
MODES = ("k0", "p1", "p2")
GRAVITY = 9.81  # m/s², the value the sheet prints as g


@pytest.fixture(scope="module")
def written(tmp_path_factory):
    """The sheet as Markdown and HTML text, and its SceneRun."""
    sheet, run = scene_sheet(CONFIG, "fcalc report", display_units(None, SHEET_UNITS), figures=False, fit_units=True)
    out = tmp_path_factory.mktemp("sheet")
    write_sheet(sheet, out / "s.md")
    write_sheet(sheet, out / "s.html")
    return (out / "s.md").read_text(encoding="utf-8"), (out / "s.html").read_text(encoding="utf-8"), run


@pytest.fixture(scope="module")
def printed(written):
    return read_markdown(written[0])


@pytest.fixture(scope="module")
def checked():
    """(exit code, the scene's entry) of ``fcalc check --json`` on the scene, as
    tests/test_json_record.py records it and holds it equal to the live command's."""
    from tests.test_json_record import RECORD

    with gzip.open(RECORD, "rt", encoding="utf-8") as f:
        entry = json.load(f)[f"{CONFIG.name} check"]
    return entry["exit_code"], entry


def _table(printed, start: str, exact: bool = False):
    found = [t for t in printed.tables() if (t.title == start if exact else t.title.startswith(start))]
    assert len(found) == 1, [t.title for t in printed.tables()]
    return found[0]


def _value(text: str) -> float:
    (value,) = numbers(text)
    return value


def _half_unit(text: str) -> float:
    """Half a unit of the last printed figure of ``text`` (``5.36301·10⁸``, ``358959``, ``63.59``)."""
    mantissa = text.replace("−", "-").split("·10")[0]
    decimals = len(mantissa.split(".")[1]) if "." in mantissa else 0
    return 0.5 * 10.0 ** -decimals * abs(_value(text)) / abs(float(mantissa))


def test_the_sheet_exits_and_judges_as_check_does(written, checked):
    """The sheet's exit code, its overall verdict line and each check's verdict are fcalc check's."""
    code, scene = checked
    assert written[2].exit_code(strict=False) == code == 0
    (verdicts,) = next(s for s in read_markdown(written[0]).sections if s.title == "Verdict").tables
    assert [row[:2] for row in verdicts.rows] == [[c["check"], c["verdict"].upper()] for c in scene["checks"]]
    assert verdicts.rows[0][2] == scene["checks"][0]["reason"]  # the resonance reason has no displacement unit to convert
    overall = "FAIL" if code == 1 else "PASS"
    assert f"Overall verdict: {overall}; 2 checks as fcalc check runs them, exit code {code}." in written[0]


def _plane_model(printed, mode: str) -> dict[str, str]:
    """The printed inputs of the sway-rocking solve at ω* of ``mode``: springs at O (their table) and
    masses (the frequency chain's given rows), as text."""
    springs = _table(printed, "Springs in the plane at O")
    row = next(r for r in springs.rows if r[0] == f"ω* of {mode}")
    K = dict(zip(("K_x", "K_z", "K_phi", "K_xphi"), row[2:]))
    chain = _table(printed, "Natural frequencies of the plane model")
    column = chain.header.index(f"at ω* of {mode}")
    given = {r[0]: r[column] for r in chain.rows}
    foundation = _table(printed, "[foundation]")
    h = next(r[2] for r in foundation.rows if r[0] == "cog_height")
    return {**K, "M_tot": given["M_tot"], "M_xt": given["M̄_xθ"], "M_tt": given["M̄_θθ"], "h": h}


def _brute_force(values: dict[str, float]) -> dict[str, float]:
    """k0, p1, p2 [rad/s] of the plane model about C from the springs at O and the masses (module
    docstring): eigenvalues of (K̄, M̄) in x, y, θ, named by the mode's dominant motion."""
    v = values
    K_O = np.array([[v["K_x"], 0.0, v["K_xphi"]], [0.0, v["K_z"], 0.0], [v["K_xphi"], 0.0, v["K_phi"]]])  # u_x, u_z, θ_y at O
    T = np.array([[1.0, 0.0, -v["h"]], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]])  # (u_x, u_z, θ_y) = T (x, y, θ)
    K = T.T @ K_O @ T
    K[2, 2] -= v["M_tot"] * GRAVITY * v["h"] + GRAVITY * v["M_xt"]
    M = np.array([[v["M_tot"], 0.0, v["M_xt"]], [0.0, v["M_tot"], 0.0], [v["M_xt"], 0.0, v["M_tt"]]])
    k0 = math.sqrt(K[1, 1] / M[1, 1])
    sway_rocking = np.sort(np.sqrt(eigvals(K[np.ix_([0, 2], [0, 2])], M[np.ix_([0, 2], [0, 2])]).real))
    whole = np.sort(np.sqrt(eigvals(K, M).real))
    assert np.allclose(whole, np.sort([k0, *sway_rocking]), rtol=1e-12)  # y decouples: the 3 × 3 has the same roots
    return {"k0": k0, "p1": float(sway_rocking[0]), "p2": float(sway_rocking[1])}


@pytest.mark.parametrize("mode", MODES)
def test_each_printed_frequency_is_the_eigen_solve_of_the_printed_numbers(printed, mode):
    """Every k0, p1, p2 the frequency chain prints at ω* of ``mode`` is the brute-force eigen-solve
    of the springs and masses it prints, to its printed figures (module docstring); the mode's own
    row is its ω*."""
    texts = _plane_model(printed, mode)
    values = {key: _value(text) for key, text in texts.items()}
    solved = _brute_force(values)
    chain = _table(printed, "Natural frequencies of the plane model")
    column = chain.header.index(f"at ω* of {mode}")
    shown = {r[0]: r[column] for r in chain.rows}
    for name in MODES:
        spread = sum(abs(_brute_force({**values, key: values[key] + _half_unit(text)})[name] - solved[name])
                     for key, text in texts.items())
        assert abs(solved[name] - _value(shown[name])) <= _half_unit(shown[name]) + spread, (name, solved[name], shown[name])
    assert shown[mode] == shown["ω_s"]


def test_the_printed_quadratic_is_the_determinant(printed):
    """A2 p⁴ − A1 p² + A0 = det(K̄ − p² M̄) of the sway-rocking plane: A1/A2 the trace and A0/A2 the
    determinant of M̄⁻¹ K̄ from the printed numbers (four figures each: 2e-3)."""
    chain = _table(printed, "Natural frequencies of the plane model")
    for mode in MODES:
        column = chain.header.index(f"at ω* of {mode}")
        shown = {r[0]: _value(r[column]) for r in chain.rows}
        v = {key: _value(text) for key, text in _plane_model(printed, mode).items()}
        x_theta = v["K_xphi"] - v["h"] * v["K_x"]
        theta = v["K_phi"] - 2 * v["h"] * v["K_xphi"] + v["h"] ** 2 * v["K_x"] - GRAVITY * (v["M_tot"] * v["h"] + v["M_xt"])
        A = np.linalg.solve([[v["M_tot"], v["M_xt"]], [v["M_xt"], v["M_tt"]]], [[v["K_x"], x_theta], [x_theta, theta]])
        assert shown["A1"] / shown["A2"] == pytest.approx(np.trace(A), rel=2e-3)
        assert shown["A0"] / shown["A2"] == pytest.approx(np.linalg.det(A), rel=2e-3)


def test_the_resonance_table_prints_the_chains_frequencies(printed, checked):
    """The frequencies the resonance section prints are each mode's own row of the chain and
    fcalc check's (its resonance result, four figures)."""
    resonance = next(c for c in checked[1]["checks"] if c["check"] == "resonance")["result"]
    freqs = _table(printed, "Natural frequencies", exact=True)
    chain = _table(printed, "Natural frequencies of the plane model")
    for row in freqs.rows:
        mode = row[0]
        own = next(r for r in chain.rows if r[0] == mode)[chain.header.index(f"at ω* of {mode}")]
        assert row[1] == row[3] == own
        assert _value(own) == pytest.approx(resonance["natural_frequencies"][mode], rel=5e-4)


#: Text of a soil method's chain in the plane (springs and damping ratios by the paper's soil
#: methods, the closed forms (4.5)-(4.14)), which a pile group's sheet must not state.
SOIL_METHOD_TEXT = ("Barkan", "Lysmer", "SP 26", "soil.method =", "Gazetas' springs", "Gazetas' stiffnesses", "ξ_z", "ξ_x", "ξ_φ", "k0² = c S",
                    "b1 = (c1", "(4.11), (4.14) corrected", "zero-order operator", "damped (4.11)")


@pytest.mark.parametrize("index", [0, 1])
def test_no_soil_method_on_the_piled_sheet(written, index):
    """Neither the Markdown nor the HTML sheet states a soil method's chain; the input table's row
    of the scene's own ``[soil] method`` key (its options listed) is the scene as written."""
    text = "\n".join(line for line in written[index].splitlines() if "how the six springs are found" not in line)
    text = text.replace("\\", "").replace("&#x27;", "'").replace("&#39;", "'")
    assert [t for t in SOIL_METHOD_TEXT if t in text] == []


def test_the_sheet_says_what_the_piles_change(written, printed):
    """The damped line names C_xφ; the first approximation is not applicable, with its reason; the
    methods state the group's springs at O and the plane's, at rest and at each mode's ω*."""
    from foundation_calc.checks.amplitudes.approximations import FIRST_NOT_APPLICABLE

    md = re.sub(r"\\(.)", r"\1", written[0])
    assert "C_xφ = " in next(line for line in md.splitlines() if line.startswith("Damped: base dashpots"))
    assert f"First approximation: {FIRST_NOT_APPLICABLE}." in md
    assert _table(printed, "The group's springs at O at rest").header[1:] == ["x", "y", "z", "rx", "ry", "rz"]
    rows = [r[0] for r in _table(printed, "Dashpots in the plane at O").rows]
    assert rows[0] == "rest" and rows[-3:] == [f"ω* of {m}" for m in MODES]
    html = read_html(written[1])
    assert [t.title for t in html.tables()] == [t.title for t in printed.tables()]
