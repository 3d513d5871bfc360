"""Plausible ranges of scene inputs, with their sources, and the unit slips that leave them.

A value that validates but lies outside the range real designs use is probably typed in another
unit: soil density 1.8 (t/m³ for kg/m³), a block 6000 long (mm for m), an amplitude limit 0.15
(mm for m), a load phase -90 (degrees for radians). Such a value is a *warning* about the input,
never an error: it is printed on stderr, listed in the JSON ``warnings`` and on the calculation
sheet, and changes the exit code only with ``--strict``. Every range is one row of
:data:`RANGES`, with its source.

One table serves every scene kind: :data:`KEYS` says which range judges each key a scene file may
give (``soil.density``, ``machines[].loads[].phase``), :data:`INERTIA_KEYS` which moments of
inertia are judged against the mass beside them, and :func:`findings` walks any validated scene
and judges every value its file gives, naming the key as the user wrote it
(``machines[0].loads[1].phase``). Rules that relate several values (a position against the
block's size, a mass ratio) belong to the model that holds them: a model's ``related_findings``
method, which :func:`findings` calls after judging the model's own keys. A scene kind inherits
:class:`Plausible` and is judged by construction.

A :class:`Slip` is suggested only when the value is far outside (:attr:`PlausibleRange.slip_beyond`)
and the value in that unit lands inside the range, so a soft but real soil is not told it was
typed in kN/m³.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass, replace

from foundation_calc.errors import PhysicsError


def _number(value: float) -> str:
    return f"{value:.5g}"


@dataclass(frozen=True)
class Slip:
    """A unit typed in place of the SI one: the SI value is ``factor`` × the typed value."""

    unit: str  #: the unit the value was probably typed in, e.g. "t/m³"
    factor: float  #: typed value × factor = SI value
    advice: str = ""  #: what to write instead, formatted with ``value`` (the typed value)


@dataclass(frozen=True)
class PlausibleRange:
    """What real designs use for one quantity [``unit``], and where that is stated.

    ``magnitude``: the range bounds |value| (a phase). ``below`` and ``above`` say what a value
    outside probably means when no unit slip explains it.
    """

    quantity: str
    unit: str
    low: float
    high: float
    source: str
    slips: tuple[Slip, ...] = ()
    below: str = ""
    above: str = ""
    magnitude: bool = False
    slip_beyond: float = 10.0  #: suggest a slip only when the value is this factor outside
    basis: str = ""  #: what the source says, for the documentation
    zero_allowed: bool = False  #: 0 means something of its own (a machine of parts alone) and is not judged

    def span(self) -> str:
        """The range as text: ``1100 to 2500 kg/m³``, ``±6.2832 rad``."""
        unit = "" if self.unit == "-" else f" {self.unit}"
        if self.magnitude:
            return f"±{_number(self.high)}{unit}"
        return f"{_number(self.low)} to {_number(self.high)}{unit}"

    def outside(self, value):
        """True where ``value`` (a float or an array of candidates) lies outside the range."""
        size = abs(value) if self.magnitude else value
        return (size < self.low) | (size > self.high)

    def judge(self, key: str, value: float) -> "Implausible | None":
        """The finding for ``key = value`` (key as the user wrote it), or None inside the range."""
        return Implausible(key, value, self) if self.outside(value) and not (self.zero_allowed and value == 0) else None

    def in_unit(self, unit: str, per_unit: float, slips: tuple[Slip, ...]) -> "PlausibleRange":
        """The same range for a value given in ``unit``, one of which is ``per_unit`` of this
        range's unit (a speed as ``speed_rpm``: rpm, π/30 rad/s), with that unit's ``slips``."""
        return replace(self, unit=unit, low=self.low / per_unit, high=self.high / per_unit, slips=slips)


#: Standard gravity [m/s²], which defines the kilogram-force of kgf/cm³ and turns unit weights into densities.
STANDARD_GRAVITY = 9.80665

#: SI value of a unit weight [kN/m³] typed as a density [kg/m³]: ρ = γ/g.
_UNIT_WEIGHT = Slip("kN/m³ (a unit weight γ; ρ = γ/g)", 1e3 / STANDARD_GRAVITY)
_MM = Slip("mm", 1e-3)
_MICRON = Slip("µm", 1e-6)
_JUDGEMENT = "fcalc's bracket"
_HEAVY_BLOCK = "the machine is a small fraction of the block: was foundation.machine.mass typed in t (kg wanted)?"
_LIGHT_BLOCK = (
    "a block lighter than the rule of thumb moves more than its mass suggests; check"
    " foundation.machine.mass and the block's dimensions"
)
_RPM = Slip("rpm", math.pi / 30.0, "write speed_rpm = {value:g}")
_SPEED_BASIS = "large ball mills turn at about 12 rpm (1.2 rad/s)"

#: Every plausible range, by name (one name may serve several keys: block and base lengths).
RANGES: dict[str, PlausibleRange] = {
    "soil_density": PlausibleRange(
        "soil densities", "kg/m³", 1100.0, 2500.0, "Das, Principles of Geotechnical Engineering",
        (Slip("t/m³ (or g/cm³)", 1e3), _UNIT_WEIGHT),
        basis="total unit weights of soils, peat to dense gravel, about 11-24 kN/m³",
    ),
    "shear_modulus": PlausibleRange(
        "small-strain shear moduli of soils", "Pa", 5e6, 6e9, "G = ρ V_s² over the soil ranges",
        (Slip("MPa", 1e6), Slip("kPa", 1e3), Slip("GPa", 1e9)),
        basis="ρ V_s² with the soil densities and shear wave velocities of this table, rounded outward",
    ),
    "shear_wave_velocity": PlausibleRange(
        "shear wave velocities of soils under machine foundations", "m/s", 100.0, 1500.0,
        "ASCE 7-16, Table 20.3-1", (Slip("km/s", 1e3), Slip("ft/s", 0.3048)),
        below="if G was taken from a static deformation modulus as E/(2(1 + ν)), the springs come out"
        " several times too soft: give the small-strain G or V_s of the site investigation",
        basis="site classes E (soft clay, below 180 m/s) to B (rock, 760-1500 m/s); below 100 m/s G was"
        " probably taken from a static modulus (E = 20 MPa gives 65 m/s)",
    ),
    "poisson": PlausibleRange(
        "Poisson's ratios of soils", "-", 0.1, 0.5, "Bowles, Foundation Analysis and Design, Table 5-6",
        below="soils have ν from 0.1 (loess, unsaturated clay) to 0.5 (saturated clay, undrained)",
        basis="loess and unsaturated clay 0.1-0.3, sands 0.3-0.4, saturated clay 0.4-0.5",
    ),
    "deformation_modulus": PlausibleRange(
        "static deformation moduli of soils", "Pa", 2e6, 1e8, "Bowles, Foundation Analysis and Design, Table 5-5",
        (Slip("MPa", 1e6), Slip("kPa", 1e3)),
        above="if it is E = 2G(1 + ν) from a shear wave velocity, it is a dynamic modulus and SP 26's"
        " springs come out several times too stiff (4.7 × Lysmer's for V_s = 200 m/s): give the"
        ' static E, or use method "lysmer" with the V_s',
        basis="very soft clay 2-15 MPa, sands and clays of site reports about 5-60 MPa; above 100 MPa a"
        " dynamic modulus 2G(1 + ν) was probably given",
    ),
    "subgrade_coefficient": PlausibleRange(
        "Barkan's coefficients of soils", "N/m³", 3e6, 1e9, "Barkan, Dynamics of Bases and Foundations",
        (Slip("MN/m³", 1e6), Slip("kgf/cm³", STANDARD_GRAVITY * 1e6), Slip("kN/m³", 1e3)),
        basis="C_u up to 3 kgf/cm³ for weak soils, 3-10 for medium and strong soils, above 10 for rock"
        " (1 kgf/cm³ = 9.81e6 N/m³); one bracket for c_z, c_x (about 0.7 c_z) and c_phi (about 2 c_z),"
        " from 0.3 kgf/cm³",
    ),
    "block_length": PlausibleRange(
        "plan dimensions of block foundations", "m", 0.3, 60.0, _JUDGEMENT, (_MM,),
        basis="the blocks of ACI 351.3R-18, a pump's plinth to a large compressor or turbine mat",
    ),
    "block_height": PlausibleRange(
        "heights of block foundations", "m", 0.2, 15.0, _JUDGEMENT, (_MM,),
        basis="as the plan dimensions",
    ),
    "block_density": PlausibleRange(
        "densities of block materials", "kg/m³", 1500.0, 8000.0, "EN 1991-1-1, Annex A",
        (Slip("t/m³", 1e3), _UNIT_WEIGHT),
        basis="Tables A.1 and A.4: lightweight concrete to steel; reinforced concrete 25 kN/m³",
    ),
    "foundation_mass": PlausibleRange(
        "masses of block foundations with their machines", "kg", 1e3, 2e7, _JUDGEMENT, (Slip("t", 1e3),),
        basis="as the plan dimensions: 1 t to 20 000 t",
    ),
    "base_area": PlausibleRange(
        "base areas of block foundations", "m²", 0.09, 3600.0, _JUDGEMENT, (Slip("mm²", 1e-6),),
        basis="the squares of the plan dimensions",
    ),
    "pile_length": PlausibleRange(
        "lengths of foundation piles", "m", 2.0, 80.0, _JUDGEMENT, (_MM,),
        basis="short bored piles of a few metres to long driven or bored piles; EN 1998-5 Table C.1 needs flexible piles",
    ),
    "pile_diameter": PlausibleRange(
        "diameters of foundation piles", "m", 0.1, 3.0, _JUDGEMENT, (_MM,),
        basis="micropiles of 0.1-0.3 m to large bored piles of 2-3 m",
    ),
    "pile_modulus": PlausibleRange(
        "Young's moduli of pile materials", "Pa", 5e9, 2.2e11, "EN 1992-1-1, Table 3.1; EN 1993-1-1, 3.2.6",
        (Slip("MPa", 1e6), Slip("GPa", 1e9)),
        basis="timber about 10 GPa (from 5), concrete 27-44 GPa, steel 210 GPa",
    ),
    "isolator_stiffness": PlausibleRange(
        "spring rates of machine isolators", "N/m", 2e3, 2e8, _JUDGEMENT, (Slip("N/mm (or kN/m)", 1e3),), slip_beyond=1.0,
        basis="small spring and elastomer mounts of fans and pumps (a few kN/m) to the spring units under"
        " turbine tables and hammers (about 1e8 N/m)",
    ),
    "amplitude_limit": PlausibleRange(
        "peak displacement limits of block foundations", "m", 1e-6, 5e-3, _JUDGEMENT, (_MM, _MICRON),
        basis="limits of ACI 351.3R-18 and Barkan (0.1-0.2 mm for low-speed machines), with room either way",
    ),
    "transient_amplitude_limit": PlausibleRange(
        "displacement limits during start-up and run-down", "m", 1e-6, 5e-2, _JUDGEMENT, (_MM, _MICRON),
        slip_beyond=1.0, basis="ten times the steady limits: a passage through resonance may be allowed more",
    ),
    "velocity_limit": PlausibleRange(
        "velocity limits of machine foundations", "m/s", 1e-4, 5e-2, _JUDGEMENT, (Slip("mm/s", 1e-3),),
        basis="around ISO 10816-3's zone boundaries, 1.4-11 mm/s RMS",
    ),
    "acceleration_limit": PlausibleRange(
        "acceleration limits of machine foundations", "m/s²", 1e-3, 50.0, _JUDGEMENT, (Slip("mm/s²", 1e-3),),
        basis="from the velocity limits at 1-100 Hz",
    ),
    "settlement_limit": PlausibleRange(
        "allowable static settlements of machine foundations", "m", 5e-4, 0.15, _JUDGEMENT, (_MM,),
        basis="allowable total settlements of foundations are some 10-50 mm; a machine's block often less",
    ),
    "phase": PlausibleRange(
        "phases", "rad", 0.0, 2.0 * math.pi, "one turn is 2π rad", (Slip("degrees", math.pi / 180.0),),
        magnitude=True, slip_beyond=1.0, basis="a phase beyond one turn was probably typed in degrees",
    ),
    "mass_ratio_reciprocating": PlausibleRange(
        "block-to-machine mass ratios of reciprocating machines", "-", 3.0, 100.0,
        "ACI 351.3R-18; Arya, O'Neill & Pincus (1979)", below=_LIGHT_BLOCK, above=_HEAVY_BLOCK,
        basis="rules of thumb: the block at least 3-5 × a reciprocating machine (a crank mechanism);"
        " above 100 × is fcalc's bracket",
    ),
    "mass_ratio_rotating": PlausibleRange(
        "block-to-machine mass ratios", "-", 2.0, 100.0, "ACI 351.3R-18; Arya, O'Neill & Pincus (1979)",
        below=_LIGHT_BLOCK, above=_HEAVY_BLOCK,
        basis="rules of thumb: the block at least 2-3 × a rotating machine, 3-5 × a reciprocating one;"
        " a machine given by its loads may be either, so the lower rule; above 100 × is fcalc's bracket",
    ),
    "crank_speed": PlausibleRange(
        "crank speeds", "rad/s", 1.2, 200.0, _JUDGEMENT, (_RPM,), slip_beyond=1.0,
        basis=f"frame saws run at 250-350 rpm, compressors up to about 1000 rpm; 200 rad/s is 1900 rpm; {_SPEED_BASIS}",
    ),
    "machine_speed": PlausibleRange(
        "machine speeds", "rad/s", 1.2, 1000.0, _JUDGEMENT, (_RPM,), slip_beyond=1.0,
        basis=f"1000 rad/s is about 9500 rpm; {_SPEED_BASIS}",
    ),
    "machine_mass": PlausibleRange(
        "masses of machines on foundations", "kg", 100.0, 5e6, _JUDGEMENT, (Slip("t", 1e3),), slip_beyond=1.0,
        basis="a pump of 100 kg to a turbine-generator set of 5000 t; a machine lighter than 100 kg has no block"
        " of its own, so a lighter mass was probably typed in t; 0, a machine of parts alone (exciters' rotors, crank"
        " throws) with no frame of its own, is not judged", zero_allowed=True,
    ),
    "radius_of_gyration": PlausibleRange(
        "radii of gyration k = sqrt(J/m) about the centre of mass", "m", 0.1, 30.0, _JUDGEMENT,
        basis="a moment of inertia J is m k²: a body 0.3 m across has k of about 0.1 m, a 60 m mat about 17 m;"
        " J typed in t·m² makes k 32 times too small",
    ),
    "balance_grade": PlausibleRange(
        "balance quality grades", "mm/s", 0.4, 4000.0, "ISO 21940-11, Table 1", (Slip("m/s", 1e3),),
        basis="grades G 0.4 (gyroscopes, precision spindles) to G 4000 (crankshafts of slow marine diesel engines)",
    ),
    "crank_length": PlausibleRange(
        "lengths of crank mechanisms", "m", 1e-3, 5.0, _JUDGEMENT, (_MM,),
        basis="crank radii of compressors, presses and engines some 0.03-1 m, their rods up to about 4 m (slow"
        " marine engines); 0 (a rod's cog at its pin, no net unbalance) is not judged", zero_allowed=True,
    ),
    "exciter_eccentricity": PlausibleRange(
        "eccentricities of exciter rotors", "m", 1e-3, 1.0, _JUDGEMENT, (_MM,),
        basis="the eccentric weights of vibratory motors and exciters sit some 1 cm to 0.3 m from their shafts"
        " (paper 001's example 0.2 m); a rotor over 2 m across is not an exciter",
    ),
    "platform_amplitude": PlausibleRange(
        "amplitudes of vibro-tables", "m", 1e-4, 1e-2, _JUDGEMENT, (_MM,),
        above="vibro-tables vibrate 0.1-5 mm; was it typed in mm?", basis="vibro-tables vibrate 0.1-5 mm",
    ),
}


@dataclass(frozen=True)
class Implausible:
    """A value outside its plausible range: the key as the user wrote it, the value, the range.

    ``str()`` is the warning: the key and value, the range and its source, and the unit slip
    that explains the value (or what else it probably means).
    """

    key: str
    value: float
    range: PlausibleRange
    advice: str | None = None  #: what to write instead, replacing the slips' own (a value given as an option)

    def slips(self) -> list[tuple[Slip, float]]:
        """The unit slips that bring the value inside the range, each with the SI value it gives."""
        r = self.range
        size = abs(self.value) if r.magnitude else self.value
        beyond = size / r.high if size > r.high else (r.low / size if size > 0 else math.inf)
        if beyond < r.slip_beyond:
            return []
        found = []
        for slip in r.slips:
            fixed = self.value * slip.factor
            if r.low <= (abs(fixed) if r.magnitude else fixed) <= r.high:
                found.append((slip, fixed))
        return found

    @property
    def _side(self) -> str:
        r = self.range
        return "outside" if r.magnitude else "above" if self.value > r.high else "below"

    def _explanation(self) -> str:
        """The likely slip(s), or what else a value on this side probably means."""
        r = self.range
        unit = "" if r.unit == "-" else f" {r.unit}"
        slips = self.slips()
        if slips:
            return "likely typed in " + " or ".join(
                f"{slip.unit}: {_number(self.value)} {slip.unit.split(' ')[0]} = {_number(fixed)}{unit}"
                + (f" ({advice.format(value=self.value)})" if (advice := self._advice(slip)) else "")
                for slip, fixed in slips
            )
        hint = r.below if self._side == "below" else r.above
        return hint or f"check its unit ({r.unit})"

    def _advice(self, slip: Slip) -> str:
        return slip.advice if self.advice is None else self.advice

    def brief(self) -> str:
        """The key, the value, the range and the likely slip, without the source (for an error
        that names this value as its culprit)."""
        unit = "" if self.range.unit == "-" else f" {self.range.unit}"
        return f"{self.key} = {_number(self.value)}{unit} (plausible: {self.range.span()}), {self._explanation()}"

    def __str__(self) -> str:
        r = self.range
        unit = "" if r.unit == "-" else f" {r.unit}"
        return (
            f"{self.key} = {_number(self.value)}{unit} is {self._side} the plausible range of {r.quantity},"
            f" {r.span()} [{r.source}]; {self._explanation()}"
        )


@dataclass(frozen=True)
class Remark:
    """A value implausible relative to the rest of the scene (a length many times the
    foundation's size), with the key as the user wrote it."""

    key: str
    text: str

    def __str__(self) -> str:
        return self.text

    def brief(self) -> str:
        """The text itself (already short)."""
        return self.text


def judge(key: str, value: float | None, range_name: str) -> list[Implausible]:
    """``[finding]`` when ``key = value`` lies outside :data:`RANGES` ``[range_name]``, else ``[]``
    (also for a value the scene does not give)."""
    if value is None:
        return []
    found = RANGES[range_name].judge(key, value)
    return [] if found is None else [found]


def _speeds(prefix: str, range_name: str) -> dict[str, str]:
    """The three keys of a speed (``omega``, ``speed_rpm``, ``frequency_hz``) under ``prefix``."""
    return {f"{prefix}{name}": range_name for name in ("omega", *SPEED_UNITS)}


#: A speed given in another unit than rad/s is judged in its own unit: key's last name -> (unit,
#: rad/s per unit, the slips of that unit). ``omega`` is judged in rad/s with the range's slips.
SPEED_UNITS: dict[str, tuple[str, float, tuple[Slip, ...]]] = {
    "speed_rpm": ("rpm", math.pi / 30.0, (Slip("Hz", 60.0, "write frequency_hz = {value:g}"),)),
    "frequency_hz": ("Hz", 2.0 * math.pi, (Slip("rpm", 1.0 / 60.0, "write speed_rpm = {value:g}"),)),
}

#: The range that judges each key a scene file may give, for every scene kind: the key as written,
#: ``[]`` standing for any list index. A key that is not listed is not judged on its own (a
#: position is judged against the block by its scene's ``related_findings``).
KEYS: dict[str, str] = {
    # the soil (crank and block foundations; only the keys of the scene's method can be given)
    "soil.density": "soil_density",
    "soil.shear_modulus": "shear_modulus",
    "soil.shear_wave_velocity": "shear_wave_velocity",
    "soil.poisson": "poisson",
    "soil.deformation_modulus": "deformation_modulus",
    **{f"soil.{k}": "subgrade_coefficient" for k in ("c_z", "c_x", "c_phi", "c_psi")},
    # a crank foundation's [foundation] (a value computed from [foundation.block] is judged through it)
    "foundation.mass": "foundation_mass",
    "foundation.base_area": "base_area",
    "foundation.base_length": "block_length",
    "foundation.base_width": "block_length",
    "foundation.block.length": "block_length",
    "foundation.block.width": "block_length",
    "foundation.block.height": "block_height",
    "foundation.block.density": "block_density",
    # a block foundation's [block] and [[machines]]
    "block.length": "block_length",
    "block.width": "block_length",
    "block.height": "block_height",
    "block.density": "block_density",
    "block.mass": "foundation_mass",
    "machines[].mass": "machine_mass",
    # a block's [piles]
    "piles.length": "pile_length",
    "piles.diameter": "pile_diameter",
    "piles.modulus": "pile_modulus",
    "piles.density": "block_density",
    "machines[].unbalance.balance_grade_mm_s": "balance_grade",
    "machines[].exciters[].eccentricity": "exciter_eccentricity",
    # a crank mechanism's lengths (a crank scene's [mechanism], a block machine's [[machines.cranks]]): mm
    # typed as m keeps λ = r/l and the throw's place plausible
    **{f"{table}{k}": "crank_length" for table in ("mechanism.", "machines[].cranks[].")
       for k in ("crank_radius", "rod_length", "rod_cog_to_crank_pin", "rod_radius_of_gyration")},
    "machines[].cranks[].rotating_radius": "crank_length",
    # limits (crank and block foundations; a platform's transient_amplitude)
    **{f"limits.{k}": "amplitude_limit" for k in ("amplitude", "amplitude_rms")},
    **{f"limits.{k}": "velocity_limit" for k in ("velocity", "velocity_rms")},
    **{f"limits.{k}": "acceleration_limit" for k in ("acceleration", "acceleration_rms")},
    "limits.transient_amplitude": "transient_amplitude_limit",
    "limits.settlement": "settlement_limit",
    # phases of loads and rotors
    "loads[].phase": "phase",
    "machines[].loads[].phase": "phase",
    "machines[].cranks[].crank_angle": "phase",
    "machines[].cranks[].rotating_angle": "phase",
    "machines[].exciters[].phase": "phase",
    "extra_exciters[].phase": "phase",
    # speeds: a crank mechanism's, a machine's given by its loads (crank [operation], [[machines]]), a platform's exciter
    **_speeds("mechanism.", "crank_speed"),
    **_speeds("operation.", "machine_speed"),
    **_speeds("machines[].", "machine_speed"),
    "operation.amplitude": "platform_amplitude",
}

#: Moments of inertia about a body's own centre of mass, each judged as J = m k² against the
#: ``mass`` beside it and :data:`RANGES` ``["radius_of_gyration"]`` (J typed in t·m² lies 1000 × low).
INERTIA_KEYS: tuple[str, ...] = (
    "machines[].inertia", "block.inertia", "platform.inertia", "foundation.moment_of_inertia",
    "foundation.machine.moment_of_inertia",
)


def key_pattern(key: str) -> str:
    """``key`` with every list index as ``[]``: ``machines[0].loads[1].phase`` -> ``machines[].loads[].phase``."""
    return re.sub(r"\[\d+\]", "[]", key)


def _inertia(key: str, inertia, mass: float) -> list[Implausible]:
    """The first component of ``inertia`` [kg m²] (a number or [Jx, Jy, Jz]; 0 is a point mass and
    not judged) outside m k² with the radii of gyration of :data:`RANGES`, ``mass`` [kg] its body's."""
    k = RANGES["radius_of_gyration"]
    plausible = PlausibleRange(
        f"moments of inertia of a body of {_number(mass)} kg about its centre of mass (k = {k.span()})",
        "kg m²", mass * k.low**2, mass * k.high**2, k.source, (Slip("t·m²", 1e3),), slip_beyond=1.0,
    )
    parts = [(key, inertia)] if isinstance(inertia, (int, float)) else [(f"{key}[{i}]", j) for i, j in enumerate(inertia)]
    return next(([found] for part, j in parts if j > 0 and (found := plausible.judge(part, j))), [])


def _judge_key(key: str, value, model) -> list[Implausible]:
    """The finding of one value the user gave, ``key`` as written, ``model`` the table holding it."""
    pattern = key_pattern(key)
    if pattern in INERTIA_KEYS:
        return _inertia(key, value, model.mass)
    name = KEYS.get(pattern)
    if name is None or not isinstance(value, (int, float)):
        return []
    plausible = RANGES[name]
    unit = SPEED_UNITS.get(pattern.rsplit(".", 1)[-1])
    found = (plausible if unit is None else plausible.in_unit(*unit)).judge(key, value)
    return [] if found is None else [found]


def findings(model, prefix: str = "") -> list:
    """Every value the scene file gives in ``model`` (a validated scene, or a table of one under the
    key ``prefix``) outside its range of :data:`KEYS` or :data:`INERTIA_KEYS`, field by field and
    depth first, each named as written (``machines[0].loads[1].phase``); after a table's own keys,
    its ``related_findings(prefix, found)`` (``found``: the findings in the table so far), if it has
    one. A value the scene computes from others is not judged (it is not among the fields set).
    """
    found: list = []
    for name in (n for n in type(model).model_fields if n in model.model_fields_set):
        value, key = getattr(model, name), f"{prefix}{name}"
        if hasattr(value, "model_fields_set"):
            found += findings(value, f"{key}.")
        elif isinstance(value, list) and value and hasattr(value[0], "model_fields_set"):
            for i, item in enumerate(value):
                found += findings(item, f"{key}[{i}].")
        else:
            found += _judge_key(key, value, model)
    related = getattr(model, "related_findings", None)
    return found + (related(prefix, found) if related is not None else [])


class Plausible:
    """A scene kind whose inputs the table judges (every kind inherits it): :func:`findings` of the
    scene, and of its own ``related_findings`` rules."""

    def plausibility_findings(self) -> list:
        """Values that are valid but probably typed in the wrong unit (:func:`findings`), never an error."""
        return findings(self)

    def plausibility_warnings(self) -> list[str]:
        """The text of every :meth:`plausibility_findings`."""
        return [str(f) for f in self.plausibility_findings()]


def culprit_error(text: str, culprits: list, field: str, hint: str) -> PhysicsError:
    """The error of a foundation that tips over, ``text`` saying why: it names the likely culprits,
    implausible inputs the rocking spring or the overturning moment depends on (a modulus typed in
    MPa, a block in mm), else ``field``, the key to change, and ``hint``."""
    if culprits:
        return PhysicsError(f"{text}; likely culprit: " + "; ".join(x.brief() for x in culprits), field=culprits[0].key)
    return PhysicsError(text, field=field, hint=hint)


__all__ = [
    "INERTIA_KEYS", "KEYS", "Implausible", "Plausible", "PlausibleRange", "RANGES", "Remark", "SPEED_UNITS", "Slip",
    "culprit_error", "findings", "judge", "key_pattern",
]
