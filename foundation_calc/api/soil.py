"""``fc.soil``: springs, damping and frequencies of every soil method the scene allows (``fcalc soil``)."""

from __future__ import annotations

from foundation_calc.api.resonance import KINDS
from foundation_calc.api.result import Result, command_result
from foundation_calc.api.scene import scene_of


#: Allowed range of each option (its typer bounds on the command line).
RANGES = {"sample": (0, 10_000_000), "modulus_cov": (0.0, 2.0), "speed_cov": (0.0, 0.5), "seed": (0, None)}


def soil(scene, *, sample: int = 0, modulus_cov: float = 0.3, speed_cov: float = 0.0, seed: int = 0) -> Result:
    """The soil's springs, damping ratios and dashpots by every method the scene's [soil] data
    allow, and the frequencies they give; with ``sample`` > 0 the uncertain soil sampled. Judges
    nothing: the exit code is 0.

    Parameters
    ----------
    scene : Scene, path or mapping
        A ``crank_foundation`` or ``block_foundation`` scene (:func:`~foundation_calc.api.scene.load`),
        or a ``platform`` read as its block on its isolators (:meth:`~foundation_calc.scenes.platform.PlatformScene.as_block`).
    sample : int
        ``--sample``: draws of the soil's stiffness (lognormal factor, median 1) [-]; 0: none.
    modulus_cov : float
        ``--modulus-cov``: coefficient of variation of the soil's stiffness in the sample [-].
    speed_cov : float
        ``--speed-cov``: coefficient of variation of a crank scene's speed in the sample [-].
    seed : int
        ``--seed``: seed of the sample's random numbers.

    Returns
    -------
    Result
        ``to_dict()`` is the document of ``fcalc soil --json`` (its ``sample`` null without one);
        ``report`` is (the methods compared, or the support's springs and dashpots at the
        frequencies of a block or of a crank on a support that is no footing (a pile group),
        :class:`~foundation_calc.checks.soil_support.SupportSoil`; the sample or None).

    Raises
    ------
    SceneError
        An invalid scene, or a scene of another kind.
    UsageError
        A sample of a crank scene without a [mechanism], ``speed_cov`` for a block, or a sample of a
        scene on a support whose springs do not scale with the soil's modulus (piles).
    """
    from foundation_calc.api.options import within
    from foundation_calc.checks.soil_methods import compares_methods
    from foundation_calc.errors import UsageError
    from foundation_calc.output.soil import sample_document

    for keyword, value in (("sample", sample), ("modulus_cov", modulus_cov), ("speed_cov", speed_cov), ("seed", seed)):
        within(keyword, value, *RANGES[keyword])
    loaded = scene_of(scene, KINDS, platform_as_block=True)
    model, drawn = loaded.model, None
    block = loaded.kind == "block_foundation"
    sampled = block or compares_methods(model)  # a crank on a support that is no footing is not sampled
    if not sampled or block:  # a block, or a crank on a pile group
        from foundation_calc.checks.soil_sample import refuse_unscaled
        from foundation_calc.checks.soil_support import support_soil
        from foundation_calc.output.soil_support import soil_document

        if sample:
            if block and speed_cov:
                raise UsageError("a block's machines keep their speeds in the sample (a crank scene's speed is sampled)",
                                 "'--speed-cov'")
            refuse_unscaled(model)
        report = support_soil(model)
        document = soil_document(report, model, loaded.source)
    else:
        from foundation_calc.checks.soil_methods import compare_soil_methods
        from foundation_calc.output.soil import soil_document

        report = compare_soil_methods(model)
        if sample and model.mechanism is None:
            raise UsageError("samples the crank mechanism's closed forms; this scene gives the machine by its [[loads]] only",
                             "'--sample'")
        document = soil_document(report, model, loaded.source)
    if sample and sampled:
        from foundation_calc.checks.soil_sample import sample_scene

        drawn = sample_scene(model, sample, modulus_cov, speed_cov, seed)
    return command_result("soil", document | {"sample": sample_document(drawn)}, 0, loaded, (report, drawn))

