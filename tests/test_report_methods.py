"""The sheet's hand calculations end in the solvers' numbers; what a sheet cites, it references.

The chains evaluate their own printed formulas; the solvers compute the same numbers by other
code (the soil methods, the zero-order operator with its cancellation-free smaller root, the
dashpots, the platform design). Agreement to 1e-9 relative: the same formulas in double
precision, rearranged (p1 by the product of the roots here, by a cancellation-free form there).
"""

from __future__ import annotations

import pytest

from foundation_calc.output.report.methods import crank_chains, methods_section, platform_chain
from foundation_calc.scenes import load_scene
from tests.conftest import CONFIGS, sheet_configs

TOLERANCE = 1e-9

CRANK = sorted(p for p in sheet_configs() if load_scene(p).kind == "crank_foundation")
PLATFORM = sorted(p for p in CONFIGS.glob("*.toml") if load_scene(p).kind == "platform")


def _close(a: float, b: float) -> bool:
    return abs(a - b) <= TOLERANCE * max(abs(a), abs(b), 1e-300)


@pytest.mark.parametrize("path", CRANK, ids=lambda p: p.stem)
def test_crank_chains_end_in_the_solvers_numbers(path):
    from foundation_calc.checks.resonance import check_scene_resonances

    scene = load_scene(path)
    chains = {c.title.split(" ")[0]: c.values for c in crank_chains(scene)}
    springs = scene.soil_springs()
    if "Soil" in chains:
        for key in ("K_z", "K_x", "K_phi") + (("xi_z", "xi_x", "xi_phi") if scene.soil.method_used != "coefficients" else ()):
            assert _close(chains["Soil"][key], float(getattr(springs, key))), key
    from foundation_calc.output.resonance import resonance_document

    natural = resonance_document(check_scene_resonances(scene), scene, "")["natural_frequencies"]
    for key in ("k0", "p1", "p2"):
        assert _close(chains["Natural"][key], natural[key]), key
    if "Base" in chains:  # the dashpots the solvers get (solvers.soil.dashpots)
        dashpots = scene.base_dashpots(springs, scene.total_mass)
        for key in ("C_z", "C_x", "C_phi"):
            assert _close(chains["Base"][key], float(dashpots[key])), key


def _gazetas_scene(length: float, width: float, embedment: float, method: str = "gazetas"):
    """The shipped Lysmer compressor on Gazetas' (or Pais & Kausel's) soil, base L × B embedded D [m]."""
    from foundation_calc.scenes import parse_scene, read_toml

    data = read_toml(CONFIGS / "compressor_medium_sand_lysmer.toml")
    data["soil"]["method"] = method
    data["foundation"].update(base_length=length, base_width=width, embedment=embedment)
    data["foundation"]["block"].update(length=length, width=width)
    return parse_scene(data)


@pytest.mark.parametrize("method", ["gazetas", "pais_kausel"])
@pytest.mark.parametrize("base", [(6.0, 4.0, 0.0), (6.0, 4.0, 1.5), (4.0, 6.0, 0.0), (4.0, 6.0, 1.5)],
                         ids=["long-surface", "long-embedded", "short-surface", "short-embedded"])
def test_gazetas_chain_ends_in_the_solvers_springs(base, method):
    """Both orientations of the base (K_x, K_ry or K_y, K_rx) with and without embedment factors:
    the chain re-types Gazetas' (Pais & Kausel's) tables as printed, the solver evaluates them
    vectorised with the general d/D and the sidewall terms of the impedance module."""
    from foundation_calc.output.report.soil_methods import gazetas_chains

    scene = _gazetas_scene(*base, method)
    static, dynamic = (chain.values for chain in gazetas_chains(scene))
    springs = scene.soil_springs()
    for key in ("K_z", "K_x", "K_phi", "xi_z", "xi_x", "xi_phi"):
        assert _close(static[key], float(getattr(springs, key))), key
    at_speed = scene.soil_springs(omega=scene.speed.omega_rad_s)  # the first harmonic's springs
    for key in ("K_z", "K_x", "K_phi", "xi_z", "xi_x", "xi_phi"):
        assert _close(dynamic[key + "w"], float(getattr(at_speed, key))), key
    assert dynamic["K_phiw"] < static["K_phi"]  # the rocking spring softens with frequency
    if base[2] > 0:  # the embedded base's rocking radiates through its walls even at rest
        assert static["xi_phi"] > scene.soil.material_damping


@pytest.mark.parametrize("path", PLATFORM, ids=lambda p: p.stem)
def test_platform_chain_ends_in_the_design(path):
    from foundation_calc.checks.platform import check_platform
    from foundation_calc.output.platform import platform_document

    scene = load_scene(path)
    report = check_platform(scene.design(), scene.model(), scene.limits, scene.inertia_given)
    doc = platform_document(report, scene, "", scene.operation.speed_given_as)
    values = platform_chain(doc).values
    d = doc["design"]
    for key, judged in (("c0", "c0"), ("c3", "c3"), ("z", "static_deflection"), ("omega_t", "translation_frequency"),
                        ("c31_41", "c31+c41"), ("c11_21", "c11+c21"), ("c22_32", "c22+c32"), ("c12_42", "c12+c42")):
        assert _close(values[key], d[judged]), key
    size = max(doc["inputs"]["A"], doc["inputs"]["B"])  # a, b, c are often 0: judged against the platform's size
    for key in ("a", "b", "c"):
        assert abs(values[key] - d[key]) <= TOLERANCE * max(size, abs(d[key])), key


@pytest.mark.parametrize("path", [*CRANK, *PLATFORM], ids=lambda p: p.stem)
def test_every_symbol_of_a_chain_is_in_the_nomenclature(path):
    from foundation_calc.output.report.handcalc import SYMBOLS

    scene = load_scene(path)
    doc = None
    if scene.kind == "platform":
        from foundation_calc.checks.platform import check_platform
        from foundation_calc.output.platform import platform_document

        report = check_platform(scene.design(), scene.model(), scene.limits, scene.inertia_given)
        doc = {"design": platform_document(report, scene, "", scene.operation.speed_given_as)}
    assert_every_symbol_defined(methods_section(scene, doc or {}))
    assert SYMBOLS  # symbols used by the chains


def assert_every_symbol_defined(section) -> None:
    """Every symbol of the section's chains, and every name in their formulas, is in its
    nomenclature (the last table); tables without formulas (summaries) are skipped."""
    *chains, nomenclature = [b for b in section.blocks if hasattr(b, "rows")]
    defined = {row[0] for row in nomenclature.rows}
    for chain in chains:
        if chain.header[1:2] != ("formula",):
            continue
        for symbol, formula, *_ in chain.rows:
            assert symbol in defined
            if formula.startswith(("ω* =", "n ω", "given")):  # how a column's input was found
                continue
            for compound in sorted((d for d in defined if any(c in d for c in "()+,")), key=len, reverse=True):
                formula = formula.replace(compound, " ")  # symbols such as (c31+c41), K_z,s
            names = set(formula.replace("·", " ").replace("√", " ").replace(", ", " ").translate(str.maketrans("()/+-²³⁴⁵^¼½{}", "              ")).split())
            functions = {"π", "max", "min", "abs"}
            assert {n for n in names if not n.replace(".", "").isdigit() and n not in functions} <= defined, (chain.title, formula)


def test_loads_only_sheet_lists_no_crank_equations(runner, tmp_path):
    pytest.importorskip("matplotlib")
    from foundation_calc.cli.app import app

    out = tmp_path / "sheet.md"
    runner.invoke(app, ["report", str(CONFIGS / "compressor_vendor_loads.toml"), "-o", str(out), "--exact"])
    text = out.read_text(encoding="utf-8").replace("\\", "")
    assert "(4.11)" not in text and "(4.14)" not in text and "x_c = μ" not in text
    assert "not computed" not in text and "exact solution of the linear rigid-block model" in text


def test_every_cited_source_has_a_full_reference(tmp_path):
    pytest.importorskip("matplotlib")
    import re

    from foundation_calc.output.display_units import DisplayUnits
    from foundation_calc.output.report import markdown
    from foundation_calc.output.report.documents import scene_sheet
    from foundation_calc.references import REFERENCES

    for path in (CONFIGS / "compressor_medium_sand_lysmer.toml", CONFIGS / "compressor_vendor_loads.toml", CONFIGS / "platform_damped.toml"):
        sheet, _ = scene_sheet(path, "fcalc report", DisplayUnits(), figures=False)
        text = markdown.render(sheet, []).replace("\\", "")
        body, _, references = text.partition("## ")[2].rpartition("References")
        for key in set(re.findall(r"\[([A-Za-z0-9]+)\]", body)) & set(REFERENCES):
            assert f"| [{key}] | {REFERENCES[key]}" in references, (path.name, key)


def test_the_manual_lists_every_reference_in_full():
    from foundation_calc.references import REFERENCES
    from tests.conftest import ROOT

    page = (ROOT / "docs" / "theory.md").read_text(encoding="utf-8")
    for key, entry in REFERENCES.items():
        assert f"- **[{key}]** {entry}" in page, key


def test_one_key_per_source():
    """The sheet and the validation record cite from one list, and no source has two keys there
    (two entries of one source begin with the same authors)."""
    from foundation_calc.references import REFERENCES
    from foundation_calc.validation import independent, published

    authors = [entry.split(",")[0] for entry in REFERENCES.values()]
    assert len(set(authors)) == len(authors), authors
    assert {case.source for case in (*published.CASES, *independent.CASES)} <= set(REFERENCES)


@pytest.mark.parametrize("name", ["frame_saw.toml", "platform_paper_example.toml"])
def test_no_column_mixes_notations(name):
    """A numeric column is in plain decimals or in a·10ⁿ throughout (0 and - aside)."""
    from foundation_calc.output.display_units import DisplayUnits
    from foundation_calc.output.report.documents import scene_sheet
    from foundation_calc.output.report.model import Table

    sheet, _ = scene_sheet(CONFIGS / name, "fcalc report", DisplayUnits(amplitude="mm"), figures=False)
    tables = [b for s in sheet.sections for b in s.blocks if isinstance(b, Table) and "Amplitude per harmonic" in b.title
              or isinstance(b, Table) and "Sensitivity" in b.title or isinstance(b, Table) and b.title.startswith("Peaks")]
    assert tables
    for t in tables:
        for j, numeric in enumerate(t.numeric):
            cells = [row[j] for row in t.rows if numeric and row[j] not in ("0", "-")]
            assert len({"·10" in c for c in cells}) <= 1, (t.title, cells)


def test_platform_markdown_sheet_writes_the_figure_the_manual_promises(runner, tmp_path):
    """docs/report.md: `fcalc report configs/platform_paper_example.toml -o platform.md` (+ platform-figure1.svg)."""
    pytest.importorskip("matplotlib")
    from foundation_calc.cli.app import app

    out = tmp_path / "platform.md"
    assert runner.invoke(app, ["report", str(CONFIGS / "platform_paper_example.toml"), "-o", str(out)]).exit_code == 0
    svg = (tmp_path / "platform-figure1.svg").read_text(encoding="utf-8")
    assert svg.startswith("<svg") and "platform-figure1.svg" in out.read_text(encoding="utf-8")


@pytest.mark.parametrize("path", [p for p in CRANK if load_scene(p).mechanism is not None], ids=lambda p: p.stem)
def test_first_approximation_chain_ends_in_the_solvers_amplitudes(path):
    """The sheet's hand calculation of |y1|, |y2| (slider lumped, base dashpot kept) against the
    solver's complex first approximation (Smith's division of the damped (4.11)); on a
    frequency-dependent soil harmonic n takes the design at n ω, as the amplitudes check does."""
    from foundation_calc.output.report.first_approximation_methods import first_approximation_chain
    from foundation_calc.solvers.crank.closed_form import design_first_approximation

    scene = load_scene(path)
    values = first_approximation_chain(scene).values
    omega = scene.speed.omega_rad_s
    dependent = scene.soil.frequency_dependent
    for n, name in ((1, "y1"), (2, "y2")):
        fa = design_first_approximation(scene.design(n * omega if dependent else 0.0))
        if bool(fa.resonant):
            continue
        assert _close(values[name], abs(complex(getattr(fa, name)))), name
