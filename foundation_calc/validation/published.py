"""Cases against values printed in publications: worked examples, a code's tables, exact solutions.

Tolerance of a printed value: half a unit of its last printed digit (the value the source
computed could be anywhere in that interval). Scenes are given here in full, not read from
``configs/``, so the record does not move when a shipped example is edited.
"""

from __future__ import annotations

import math
from functools import cache

from foundation_calc.validation.record import Case, half_digit, printed_case

#: Das & Ramana's block (4 m in the plane of motion, 2 m wide, 1.5 m high, concrete 2400 kg/m³,
#: 28.8 t) with a 6 t machine on Lysmer's half-space; the machine is given by a nominal load so
#: that the scene has no crank (the springs and frequencies do not depend on it).
DAS_RAMANA_SCENE = {
    "kind": "crank_foundation",
    "foundation": {
        "block": {"length": 4.0, "width": 2.0, "height": 1.5, "density": 2400.0},
        "machine": {"mass": 6000.0, "cog_height": 2.0},
    },
    "soil": {"method": "lysmer", "shear_wave_velocity": 200.0, "density": 1800.0, "poisson": 0.33},
    "operation": {"speed_rpm": 500.0},
    "loads": [{"order": 1, "vertical": 1.0}],
}

#: A square surface footing 3 m x 3 m, G = 50 MPa, ν = 0.3, springs by Gazetas (1991).
GAZETAS_SQUARE = {"side": 3.0, "G": 50.0e6, "nu": 0.3}

#: Bolotnik et al., section 3: M = 2·10⁴ kg, m = 25 kg, l = 0.2 m, u = 10⁻³ m, ξ = A/2, η = B/2,
#: a = b = 0, K = 10⁸ N/m, ζ = 0.65 m (section 4), ω = 50π rad/s (the printed "50 s⁻¹" does not
#: reproduce the printed stiffnesses; 50π does, every one of them). A, B do not enter the design.
PLATFORM_SCENE = {
    "kind": "platform",
    "platform": {"mass": 2.0e4, "length": 3.0, "width": 2.0, "cog": [1.5, 1.0, 0.65],
                 "inertia": [9.5e3, 1.8e4, 2.2e4]},
    "exciter": {"rotor_mass": 25.0, "eccentricity": 0.2, "position": [0.0, 0.0]},
    "operation": {"omega": 50.0 * math.pi, "amplitude": 1.0e-3, "regime": "above"},
    "isolators": {"vertical_reference": 1.0e8},
}

def _scene(data: dict):
    from foundation_calc.scenes import parse_scene

    return parse_scene(data, source="validation record")


@cache
def _lysmer():
    """(scene, fcalc soil's Lysmer row) of Das & Ramana's example."""
    from foundation_calc.checks.soil_methods import compare_soil_methods

    scene = _scene(DAS_RAMANA_SCENE)
    rows = {r.method: r for r in compare_soil_methods(scene).results}
    return scene, rows["lysmer"]


def _das_r0() -> float:
    from foundation_calc.solvers.soil.lysmer import equivalent_radii

    scene, _ = _lysmer()
    return equivalent_radii(*scene.foundation.dimensions)[0]


def _gazetas_square_K_z() -> float:
    from foundation_calc.solvers.soil.gazetas import gazetas_springs

    g = GAZETAS_SQUARE
    return float(gazetas_springs(g["G"], 1800.0, g["nu"], g["side"], g["side"], 0.0, 1.0e5, 1.0e5, 0.0).K_z) / 1e6


def _rigid_circle_K_z() -> float:
    """Exact vertical stiffness 4 G r0/(1 - ν) of the rigid circle of the square's area [MN/m]."""
    g = GAZETAS_SQUARE
    r0 = g["side"] / math.sqrt(math.pi)
    return 4.0 * g["G"] * r0 / (1.0 - g["nu"]) / 1e6


def _lewis() -> float:
    from foundation_calc.solvers.numerics.passage import LEWIS_COEFFICIENT

    return LEWIS_COEFFICIENT


def _iso_boundaries(group: int, foundation: str, quantity: str) -> tuple[float, ...]:
    """The values at which the code's classification of ``quantity`` changes zone, found by
    bisection on the classification itself (not read from the stored table): velocities [mm/s]
    by :func:`~foundation_calc.checks.codes.zone`, displacements [µm] by
    :func:`~foundation_calc.checks.codes.displacement_zone`."""
    from foundation_calc.checks.codes import TABLES, ZONES, displacement_zone, zone

    table = TABLES["ISO 10816-3", group, foundation]
    classify, shown = (zone, 1e3) if quantity == "velocity" else (displacement_zone, 1e6)
    found = []
    for above in ZONES[1:]:
        lo, hi = 0.0, 0.1  # m/s or m, above every boundary
        for _ in range(80):
            mid = 0.5 * (lo + hi)
            lo, hi = (lo, mid) if ZONES.index(classify(mid, table)) >= ZONES.index(above) else (mid, hi)
        found.append(hi * shown)
    return tuple(found)


@cache
def _platform():
    return _scene(PLATFORM_SCENE).design()


def _stiffness_ratio() -> float:
    s = _platform().stiffness
    return float((s[2, 2] + s[1, 2]) / _platform().c3)


def _sum(name: str) -> float:
    return float(_platform().horizontal_sums[name]) / 1e8


def _iso_case(group: int, foundation: str, printed: str, quantity: str = "velocity") -> Case:
    unit, suffix = ("mm/s", "") if quantity == "velocity" else ("µm", "-displacement")
    classify = "zone" if quantity == "velocity" else "displacement_zone"
    return printed_case(
        f"iso-10816-3-group{group}-{foundation}{suffix}", f"group {group}, {foundation} [{unit} RMS]",
        f"ISO 10816-3 zone boundaries A/B, B/C, C/D of the r.m.s. {quantity}", "ISO",
        f"Table {'A.1' if group == 1 else 'A.2'}", printed,
        lambda: _iso_boundaries(group, foundation, quantity), f"checks.codes.{classify} (bisection on the zone it returns)",
    )


DR = "Das & Ramana: block 4 × 2 × 1.5 m on Lysmer's half-space"
BGN = "Vibrating platform, section 3 example (ω = 50π rad/s)"
DESIGN = "fcalc platform (solvers.platform.design.design_from_position)"
SOIL = "fcalc soil (checks.soil_methods, method lysmer)"



def _rederived(key: str, quantity: str, digits: str, fcalc, method: str) -> Case:
    """A case against Das & Ramana's example worked again by hand from its printed inputs and
    formulas to six significant digits, more than the book prints (the book's own digits are the
    printed cases beside it): tolerance half a unit of the last digit of that re-derivation."""
    return Case(key=key, quantity=quantity, example=DR, source="DR",
                where="ch. 5 example's inputs, re-derived by hand (not printed)", reference=float(digits),
                printed=None, fcalc=fcalc, method=method, tolerance=half_digit(digits),
                basis="half a unit of the last digit of the re-derivation")


def _table_c1(profile: str, ratio: float) -> tuple[float, float, float]:
    """K_HH/(d E_s), K_MM/(d³ E_s), K_HM/(d² E_s) of fcalc's single pile at E_p/E_s = ``ratio``
    (d = 1 m, E_s = 1 Pa: the table's normalised quantities)."""
    from foundation_calc.solvers.piles.single import lateral_static

    return tuple(float(k) for k in lateral_static(1.0, ratio, 1.0, profile))


def _table_c1_exponents(profile: str) -> tuple[float, float, float]:
    """The exponents of E_p/E_s in fcalc's K_HH, K_MM, K_HM: log(K(10⁴)/K(1))/log(10⁴)."""
    return tuple(math.log(a / b) / math.log(1.0e4) for a, b in zip(_table_c1(profile, 1.0e4), _table_c1(profile, 1.0)))


def _pile_cases(profile: str, model: str, coefficients: str, exponents: str) -> tuple[Case, ...]:
    example = f"Flexible pile, soil modulus {model} (EN 1998-5 Table C.1, row {profile})"
    method = "solvers.piles.single.lateral_static"
    return (
        printed_case(f"ec8-c1-{profile}-coefficients", "K_HH/(d E_s), K_MM/(d³ E_s), K_HM/(d² E_s) at E_p/E_s = 1 [-]",
                     example, "EC8", "Table C.1, coefficients", coefficients, lambda: _table_c1(profile, 1.0), method),
        printed_case(f"ec8-c1-{profile}-exponents", "exponents of E_p/E_s in K_HH, K_MM, K_HM [-]", example, "EC8",
                     "Table C.1, exponents", exponents, lambda: _table_c1_exponents(profile),
                     f"{method} (log of K at E_p/E_s = 10⁴ over K at 1)"),
    )


def _das_K_z() -> float:
    return _lysmer()[1].K_z / 1e6


def _das_f_z() -> float:
    return _lysmer()[1].omega_z / (2.0 * math.pi)


CASES: tuple[Case, ...] = (
    printed_case("das-ramana-r0", "equivalent radius r0 [m]", DR, "DR", "ch. 5 example", "1.5958", _das_r0,
                 "solvers.soil.lysmer.equivalent_radii"),
    printed_case("das-ramana-K_z", "vertical spring K_z [MN/m]", DR, "DR", "ch. 5 example", "685.9", _das_K_z, SOIL),
    printed_case("das-ramana-f_z", "vertical frequency f_z [Hz]", DR, "DR", "ch. 5 example", "22.345", _das_f_z, SOIL),
    _rederived("das-ramana-r0-rederived", "equivalent radius r0 [m]", "1.59577", _das_r0,
               "solvers.soil.lysmer.equivalent_radii"),
    _rederived("das-ramana-K_z-rederived", "vertical spring K_z [MN/m]", "685.94", _das_K_z, SOIL),
    _rederived("das-ramana-f_z-rederived", "vertical frequency f_z [Hz]", "22.3447", _das_f_z, SOIL),
    Case(
        key="gazetas-square-vs-rigid-circle",
        quantity="K_z by Gazetas (1991) [MN/m]",
        example="Square footing 3 × 3 m (G = 50 MPa, ν = 0.3) against the rigid circle of its area",
        source="RHW",
        where="exact 4 G r0/(1 − ν)",
        reference=_rigid_circle_K_z(),
        printed=None,
        fcalc=_gazetas_square_K_z,
        method="solvers.soil.gazetas.gazetas_springs (Gazetas 1991, Table 1)",
        tolerance=0.02,
        relative=True,
        basis="2 %: a square and the circle of its area differ by about 1 % in the rigorous solutions",
    ),
    *_pile_cases("uniform", "E_s constant", "1.08 / 0.16 / -0.22", "0.21 / 0.75 / 0.50"),
    *_pile_cases("linear", "E_s z/d", "0.60 / 0.14 / -0.17", "0.35 / 0.80 / 0.60"),
    *_pile_cases("parabolic", "E_s sqrt(z/d)", "0.79 / 0.15 / -0.24", "0.28 / 0.77 / 0.53"),
    printed_case("lewis-passage", "peak × sqrt(η) / (F/k) [-]", "Undamped passage through resonance, η = Ω̇/ω_n² → 0",
                 "Le", "1.467 / sqrt(η)", "1.467", _lewis,
                 "solvers.numerics.passage.passage_peak (envelope, Faddeeva function; ζ = 0)"),
    _iso_case(1, "rigid", "2.3 / 4.5 / 7.1"),
    _iso_case(1, "flexible", "3.5 / 7.1 / 11.0"),
    _iso_case(2, "rigid", "1.4 / 2.8 / 4.5"),
    _iso_case(2, "flexible", "2.3 / 4.5 / 7.1"),
    _iso_case(1, "rigid", "29 / 57 / 90", "displacement"),
    _iso_case(1, "flexible", "45 / 90 / 140", "displacement"),
    _iso_case(2, "rigid", "22 / 45 / 71", "displacement"),
    _iso_case(2, "flexible", "37 / 71 / 113", "displacement"),
    printed_case("platform-3.18", "(c33 + c23)/c3 [-]", BGN, "BC", "Eq. (3.18)", "0.499", _stiffness_ratio, DESIGN),
    printed_case("platform-3.19", "c22 + c32 [1e8 N/m]", BGN, "BC", "Eq. (3.19)", "2.467", lambda: _sum("c22+c32"),
                 DESIGN),
    printed_case("platform-3.20", "c11 + c21 [1e8 N/m]", BGN, "BC", "Eq. (3.20)", "1.240", lambda: _sum("c11+c21"),
                 DESIGN),
    printed_case("platform-3.21-c3", "c3 = Σ c_i3 [1e8 N/m]", BGN, "BC", "(3.21), printed as c13", "4.005",
                 lambda: float(_platform().c3) / 1e8, DESIGN),
    printed_case("platform-static-deflection", "static deflection |z| [mm]", BGN, "BC", "after (3.21)", "0.49",
                 lambda: -float(_platform().static_deflection) * 1e3, DESIGN),
    printed_case("platform-exciter-height", "exciter height c [m], ζ = 0.65 m", BGN, "BC", "section 4, (3.15)", "2.6",
                 lambda: float(_platform().c), DESIGN),
)

__all__ = ["CASES", "DAS_RAMANA_SCENE", "GAZETAS_SQUARE", "PLATFORM_SCENE"]
