"""``fc.amplitudes``: forced vibration amplitudes against their limits (``fcalc amplitudes``)."""

from __future__ import annotations

from foundation_calc.api.resonance import KINDS
from foundation_calc.api.result import Result, command_result
from foundation_calc.api.scene import scene_of


def amplitudes(scene, *, exact: bool = False) -> Result:
    """Steady-state amplitudes per harmonic, peaks and RMS values of the scene's points, limits
    and code zones; judges the amplitudes alone (``fc.check`` judges the rest).

    Parameters
    ----------
    scene : Scene, path or mapping
        A ``crank_foundation`` or ``block_foundation`` scene (:func:`~foundation_calc.api.scene.load`).
    exact : bool
        ``--exact``: a crank scene's [mechanism] also by the exact periodic solution (harmonic
        balance), which then judges the limits; no effect on loads, whose steady state is exact.

    Returns
    -------
    Result
        ``to_dict()`` is the document of ``fcalc amplitudes --json``.

    Raises
    ------
    SceneError
        An invalid scene, or a scene of another kind.
    """
    from foundation_calc.checks.outcomes import exit_code

    loaded = scene_of(scene, KINDS)
    model = loaded.model
    if loaded.kind == "block_foundation":
        from foundation_calc.checks.block import check_block
        from foundation_calc.output.block import amplitudes_document

        report = check_block(model, periodic=True)
        outcome = report.amplitude_outcome
    else:
        from foundation_calc.checks.crank_amplitudes import check_scene_amplitudes
        from foundation_calc.output.crank_amplitudes import amplitudes_document

        report = check_scene_amplitudes(model, exact=exact)
        outcome = report.outcome
    return command_result("amplitudes", amplitudes_document(report, model, loaded.source), exit_code(outcome), loaded, report)
