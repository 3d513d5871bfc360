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
        A ``crank_foundation`` or ``block_foundation`` scene (:func:`~foundation_calc.api.scene.load`),
        or a ``platform`` read as its block on its isolators (:meth:`~foundation_calc.scenes.platform.PlatformScene.as_block`).
    exact : bool
        ``--exact``: a crank scene's [mechanism] also by the exact periodic solution (harmonic
        balance), which then judges the limits; a block's machines with periodic inertia (cranks,
        exciters) judged by their exact periodic solution in place of their first approximation; no
        effect on loads, whose steady state is exact.

    Returns
    -------
    Result
        ``to_dict()`` is the document of ``fcalc amplitudes --json``.

    Raises
    ------
    SceneError
        An invalid scene, or a scene of another kind.
    """
    from foundation_calc.checks.amplitudes import scene_amplitudes
    from foundation_calc.checks.outcomes import exit_code
    from foundation_calc.output.amplitudes import amplitudes_document

    loaded = scene_of(scene, KINDS, platform_as_block=True)
    report = scene_amplitudes(loaded.model, exact=exact)
    document = amplitudes_document(report, loaded.model, loaded.source)
    return command_result("amplitudes", document, exit_code(report.amplitude_outcome), loaded, report)
