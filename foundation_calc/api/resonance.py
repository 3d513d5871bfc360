"""``fc.resonance``: natural frequencies and resonance margins (``fcalc resonance``)."""

from __future__ import annotations

from foundation_calc.api.result import Result, command_result
from foundation_calc.api.scene import scene_of

#: The kinds ``resonance`` and ``amplitudes`` take.
KINDS = ("crank_foundation", "block_foundation")


def resonance(scene, *, strict: bool = False) -> Result:
    """Natural frequencies of the foundation and the margin of every forcing order from them.

    Parameters
    ----------
    scene : Scene, path or mapping
        A ``crank_foundation`` or ``block_foundation`` scene (:func:`~foundation_calc.api.scene.load`),
        or a ``platform`` read as its block on its isolators (:meth:`~foundation_calc.scenes.platform.PlatformScene.as_block`).
    strict : bool
        ``--strict``: a warning (an extra resonance, a plausibility warning) fails (exit code 1).

    Returns
    -------
    Result
        ``to_dict()`` is the document of ``fcalc resonance --json``; ``report`` the checks'
        resonance report (:class:`~foundation_calc.checks.resonance.report.ResonanceReport`).

    Raises
    ------
    SceneError
        An invalid scene, or a scene of another kind.
    """
    from foundation_calc.checks.outcomes import exit_code
    from foundation_calc.checks.resonance import scene_resonances
    from foundation_calc.output.resonance import resonance_document

    loaded = scene_of(scene, KINDS, platform_as_block=True)
    model = loaded.model
    report = scene_resonances(model)
    code = exit_code(report.outcome, strict, bool(model.plausibility_warnings()))
    return command_result("resonance", resonance_document(report, model, loaded.source), code, loaded, report)
