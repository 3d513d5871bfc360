"""The block sheet derives its six soil springs and dashpots and prints those each order used.

Every spring is recomputed here from the sheet's printed inputs (the ``[block]`` and ``[soil]``
tables) by an independent transcription of the source's formulas: Lysmer's, Hall's and
Reissner-Sagoci's analogs (Richart, Hall & Woods 1970, ch. 10; Das & Ramana, ch. 5) and Gazetas
(1991) Table 1 with Pais & Kausel's torsion modifier ([NIST] Table 2-3a). The sheet prints 4
significant figures: a printed value x.xxx carries at most 5e-4 of relative rounding, so each
comparison allows 6e-4 (1e-3 where a formula multiplies rounded values). One order's response is
solved here from the printed M, K, the printed k(nω), c(nω) and Q_n; the printed inputs' 4-figure
rounding moves Z by less than 1 %, and Z is printed to 3 figures, so 1e-2 relative.
The chains' end values are also compared with the solver's springs (``soil_impedance``) to 1e-9
for every method, embedded or not.
"""

from __future__ import annotations

import math
import re

import numpy as np
import pytest

from foundation_calc.scenes import load_scene
from tests.conftest import CONFIGS

ROUNDED = 6e-4
SUPERSCRIPT = str.maketrans("⁰¹²³⁴⁵⁶⁷⁸⁹⁻", "0123456789-")


def _value(cell: str) -> float:
    """A printed number ("4.473·10⁸", "-9.5", "5.48·10⁻⁶ ∠43.4°") as a float (its magnitude part)."""
    text = cell.split("∠")[0].strip().replace("−", "-")
    if "·10" in text:
        mantissa, power = text.split("·10")
        return float(mantissa) * 10.0 ** int(power.translate(SUPERSCRIPT))
    return float(text)


def _phasor(cell: str) -> complex:
    """|Q| ∠ φ (each entry |Q| cos(Ωt − φ)) as the complex amplitude |Q| e^{−iφ}."""
    if "∠" not in cell:
        return complex(_value(cell))
    return _value(cell) * np.exp(-1j * math.radians(float(cell.split("∠")[1].rstrip("°"))))


def _tables(markdown: str) -> dict[str, list[list[str]]]:
    """Each bold-titled table of the sheet: title -> rows of unescaped cells (header dropped)."""
    out, title = {}, None
    for line in markdown.splitlines():
        if line.startswith("**") and line.endswith("**"):
            title = re.sub(r"\\(.)", r"\1", line.strip("*"))
            out[title] = []
        elif line.startswith("|") and title is not None and not line.startswith("| ---"):
            out[title].append([re.sub(r"\\(.)", r"\1", c.strip()) for c in line.strip("|").split(" | ")])
    return {t: rows[1:] for t, rows in out.items()}


def _table(tables, start: str) -> list[list[str]]:
    found = [rows for title, rows in tables.items() if title.startswith(start)]
    assert found, f"no table {start!r} on the sheet"
    return found[0]


def _inputs(tables, section: str) -> dict[str, float]:
    return {row[0]: _value(row[2]) for row in _table(tables, f"[{section}]") if re.match(r"^[-0-9.]", row[2])}


def _sheet(path) -> dict:
    from foundation_calc.api.report import SHEET_UNITS
    from foundation_calc.output.display_units import parse_units
    from foundation_calc.output.report import markdown
    from foundation_calc.output.report.documents import scene_sheet

    sheet, _ = scene_sheet(path, "fcalc report", parse_units([], SHEET_UNITS), figures=False)
    return _tables(markdown.render(sheet, []))


def _results(rows) -> dict[str, float]:
    """A chain's rows: symbol -> printed result."""
    return {row[0]: _value(row[3]) for row in rows}


def _close(printed: float, ours: float, tolerance: float = ROUNDED) -> bool:
    return abs(printed - ours) <= tolerance * abs(ours)


def test_lysmer_block_springs_are_richart_hall_woods_of_the_printed_inputs():
    tables = _sheet(CONFIGS / "block_fan_torsion_near_speed.toml")
    block, soil = _inputs(tables, "block"), _inputs(tables, "soil")
    printed = _results(_table(tables, "Block soil springs and dashpots at O: Lysmer"))
    L, B = block["length"], block["width"]
    G, nu = soil["density"] * soil["shear_wave_velocity"] ** 2, soil["poisson"]
    r0 = math.sqrt(L * B / math.pi)                               # equal area
    r_rx, r_ry = (L * B**3 / (3 * math.pi)) ** 0.25, (B * L**3 / (3 * math.pi)) ** 0.25   # equal second moment
    r_t = (L * B * (L**2 + B**2) / (6 * math.pi)) ** 0.25         # equal polar moment
    expected = {"K_x": 32 * (1 - nu) * G * r0 / (7 - 8 * nu), "K_z": 4 * G * r0 / (1 - nu),
                "K_rx": 8 * G * r_rx**3 / (3 * (1 - nu)), "K_ry": 8 * G * r_ry**3 / (3 * (1 - nu)),
                "K_rz": 16 * G * r_t**3 / 3}
    for name, value in expected.items():
        assert _close(printed[name], value), (name, printed[name], value)
    # the dashpots from the printed ratios and springs, and the printed M's diagonal
    M = _matrix(tables, "M")
    for C, xi, K, m in (("C_z", "ξ_z", "K_z", M[2, 2]), ("C_rz", "ξ_rz", "K_rz", M[5, 5])):
        assert _close(printed[C], 2 * printed[xi] * math.sqrt(printed[K] * m), 1e-3), C


def _matrix(tables, key: str) -> np.ndarray:
    rows = [r for r in _table(tables, "Matrices of Eq. (1)") if r[0].startswith(f"{key}, row")]
    return np.array([[_value(c) for c in r[1:7]] for r in rows])


def _gazetas_scene(tmp_path, method="gazetas"):
    text = (CONFIGS / "block_two_machines.toml").read_text()
    text = re.sub(r"\[soil\].*?(?=\n\[\[points)", f'[soil]\nmethod = "{method}"\nshear_wave_velocity = 250.0\ndensity = 1900.0\n'
                  "poisson = 0.3\nmaterial_damping = 0.03\n", text, flags=re.S)
    path = tmp_path / "gazetas.toml"
    path.write_text(text)
    return path


def _springs_table(tables) -> dict[tuple[str, str], list[float]]:
    return {(r[0], r[1]): [_value(c) for c in r[2:]] for r in _table(tables, "Springs at O each order (and mode) is solved with")}


def test_gazetas_block_springs_are_table_1_of_the_printed_inputs(tmp_path):
    tables = _sheet(_gazetas_scene(tmp_path))
    block, soil = _inputs(tables, "block"), _inputs(tables, "soil")
    L, B = block["length"], block["width"]          # L >= B: L' = L/2 along x
    G, nu = soil["density"] * soil["shear_wave_velocity"] ** 2, soil["poisson"]
    Lh, Bh = L / 2, B / 2
    chi = Bh / Lh
    K_z = 2 * G * Lh / (1 - nu) * (0.73 + 1.54 * chi**0.75)
    K_y = 2 * G * Lh / (2 - nu) * (2 + 2.5 * chi**0.85)
    K_x = K_y - 0.2 / (0.75 - nu) * G * Lh * (1 - chi)
    I_x, I_y = L * B**3 / 12, B * L**3 / 12
    K_rx = G / (1 - nu) * I_x**0.75 * (Lh / Bh) ** 0.25 * (2.4 + 0.5 * chi)
    K_ry = 3 * G / (1 - nu) * I_y**0.75 * (Lh / Bh) ** 0.15
    J_t = I_x + I_y
    K_t = G * J_t**0.75 * (4 + 11 * (1 - chi) ** 10)
    springs = _springs_table(tables)
    static = springs[("static", "-")][1:]
    for name, printed, ours in zip(("K_x", "K_y", "K_z", "K_rx", "K_ry", "K_rz"), static, (K_x, K_y, K_z, K_rx, K_ry, K_t)):
        assert _close(printed, ours), (name, printed, ours)
    # torsion at the motor's order 1: Pais & Kausel's modifier k_t(a0), a0 = Ω B'/V_s
    omega, *at = springs[("motor", "1")]
    a0, r = omega * Bh / soil["shear_wave_velocity"], Lh / Bh
    k_t = 1 - (0.33 - 0.03 * math.sqrt(r - 1)) * a0**2 / (0.8 / (1 + 0.33 * (r - 1)) + a0**2)
    assert _close(at[5], k_t * K_t, 1e-3)


def test_one_orders_response_solves_from_the_printed_k_c_m_and_q(tmp_path):
    tables = _sheet(_gazetas_scene(tmp_path))
    M, K = _matrix(tables, "M"), _matrix(tables, "K")
    springs = _springs_table(tables)
    dashpots = {(r[0], r[1]): [_value(c) for c in r[2:]] for r in _table(tables, "Dashpots at O each order (and mode) is solved with")}
    loads = {(r[0], r[1]): r for r in _table(tables, "Generalised loads about O")}
    response = {(r[0], r[1]): r for r in _table(tables, "Z = (K − Ω² M")}
    order = ("compressor", "1")
    omega, *k = springs[order]
    K_n = K + np.diag(np.array(k) - np.array(springs[("static", "-")][1:]))
    C_n = np.diag(dashpots[order][1:])
    Q = np.array([_phasor(c) for c in loads[order][3:9]])
    Z = np.linalg.solve(K_n - omega**2 * M + 1j * omega * C_n, Q)
    printed = np.array([_value(c) for c in response[order][3:9]])
    largest = np.argmax(printed)
    assert abs(abs(Z[largest]) - printed[largest]) <= 1e-2 * printed[largest]
    assert np.abs(np.abs(Z) - printed).max() <= 1e-2 * printed.max()


SOILS = {
    "lysmer": "shear_wave_velocity = 150.0\ndensity = 1850.0\npoisson = 0.33\nmaterial_damping = 0.03\n",
    "gazetas": "shear_modulus = 9.0e7\ndensity = 1900.0\npoisson = 0.3\nmaterial_damping = 0.03\n",
    "pais_kausel": "shear_wave_velocity = 250.0\ndensity = 1900.0\npoisson = 0.45\nmaterial_damping = 0.02\n",
    "coefficients": "c_z = 6.0e7\nc_x = 4.2e7\ndamping = [0.15, 0.1, 0.08, 0.05]\n",
    "sp26": "deformation_modulus = 3.0e7\nsoil_class = \"sand\"\n",
}


@pytest.mark.parametrize("method, embedment", [(m, 0.0) for m in SOILS] + [("gazetas", 1.2), ("pais_kausel", 0.8)])
def test_block_soil_chains_end_in_the_solvers_springs(tmp_path, method, embedment):
    """Each chain's six springs and dashpots at O (and, on a frequency-dependent soil, those at
    every order's n ω) are the solver's ``soil_impedance`` to 1e-9."""
    from foundation_calc.output.report.block_soil import DASHPOTS, SPRINGS, block_soil_blocks, orders_of
    from foundation_calc.output.report.handcalc import Chain, Columns

    text = (CONFIGS / "block_fan_torsion_near_speed.toml").read_text()
    text = re.sub(r"\[soil\].*?(?=\n\[\[points)", f'[soil]\nmethod = "{method}"\n{SOILS[method]}', text, flags=re.S)
    if embedment:
        text = text.replace("density = 2400.0", f"embedment = {embedment}\ndensity = 2400.0", 1)
    path = tmp_path / "soil.toml"
    path.write_text(text)
    scene = load_scene(path)
    model = scene.model()
    blocks = block_soil_blocks(scene, model)
    *chains, tilt = [b for b in blocks if isinstance(b, Chain)]
    np.testing.assert_allclose([tilt.values["K_44"], tilt.values["K_55"]], np.diagonal(model.K)[3:5], rtol=1e-9)
    if method in ("gazetas", "pais_kausel"):
        orders = orders_of(scene)
        springs, dashpots = scene.soil_impedance(np.array([w for *_, w in orders]))
        columns = [b for b in blocks if isinstance(b, Columns)]
        for i in range(len(orders)):
            # the plane of x's and of y's columns share their names: each from its own table
            x, y, t = (c.values[i] for c in columns)
            ours = [x["K_xw"], y["K_xw"], x["K_zw"], y["K_phiw"], x["K_phiw"], t["K_rzw"]]
            theirs = [x["C_xw"], y["C_yw"], x["C_zw"], y["C_rxw"], x["C_ryw"], t["C_rzw"]]
            np.testing.assert_allclose(ours, springs[i], rtol=1e-9)
            np.testing.assert_allclose(theirs, dashpots[i], rtol=1e-9)
        static = [chains[1].values["K_x"], chains[2].values["K_x"], chains[1].values["K_z"], chains[2].values["K_phi"],
                  chains[1].values["K_phi"], chains[0].values["K_rz"]]
        np.testing.assert_allclose(static, scene.soil_impedance(0.0)[0], rtol=1e-9)
        return
    (chain,) = chains
    springs, dashpots = scene.soil_impedance(0.0)
    np.testing.assert_allclose([chain.values[n] for n in SPRINGS], springs, rtol=1e-9)
    np.testing.assert_allclose([chain.values[n] for n in DASHPOTS], dashpots, rtol=1e-9)


def test_a_power_with_decimals_prints_whole():
    """r**2.45 prints r^{2.45} (fcalc's plain exponent, typeset in the PDF), not r²·.45 (Pais & Kausel's
    K_ry and K_t have such powers)."""
    from foundation_calc.output.report.handcalc import Chain

    chain = Chain("")
    chain.given("r", 2.0, "-", "ratio")
    chain.step("K", "4.25*r**2.45 + r**2", "-", "[PK]", "a spring")
    assert chain.rows[-1][1] == "4.25·r^{2.45} + r²"


def test_each_mode_returns_its_own_frequency_from_the_printed_springs(tmp_path):
    """Mode j at its printed ω*: the j-th p of the printed M and K(ω*) = K + diag(k(ω*) − k(0)) is
    ω* (4-figure inputs move p = √(k/m) by at most about 5e-4; 2e-3 allowed)."""
    tables = _sheet(_gazetas_scene(tmp_path))
    M, K = _matrix(tables, "M"), _matrix(tables, "K")
    springs = _springs_table(tables)
    static = np.array(springs[("static", "-")][1:])
    for j in range(6):
        omega, *k = springs[(f"mode {j + 1}", "ω*")]
        p = np.sort(np.sqrt(np.linalg.eigvals(np.linalg.solve(M, K + np.diag(np.array(k) - static))).real))
        assert abs(p[j] - omega) <= 2e-3 * omega, (j, p[j], omega)


def test_given_springs_are_the_printed_k_less_the_printed_tilt():
    """block_two_machines gives its springs at O: K's diagonal is them, rocking less W z_G, with
    z_G = M_{u_x θ_y}/M from the printed M (an independent reading of block_model's −P h)."""
    tables = _sheet(CONFIGS / "block_two_machines.toml")
    given = [_value(v) for v in next(r for r in _table(tables, "[soil]") if r[0] == "stiffness")[2].split(", ")]
    M, K = _matrix(tables, "M"), _matrix(tables, "K")
    tilt = M[0, 0] * 9.81 * M[0, 4] / M[0, 0]
    expected = np.array(given) - np.array([0, 0, 0, tilt, tilt, 0])
    np.testing.assert_allclose(np.diagonal(K), expected, rtol=ROUNDED)
    printed = _results(_table(tables, "Rocking entries of K"))
    assert _close(printed["z_G"], M[0, 4] / M[0, 0]) and _close(printed["K_44"], expected[3])
