"""``fc.check``: every check of a scene's kind (``fcalc check``, one scene)."""

from __future__ import annotations

from foundation_calc.api.result import Result, worst
from foundation_calc.api.scene import scene_of


def check(scene, *, strict: bool = False) -> Result:
    """Run every check that the scene's kind supports, as ``fcalc check`` does for each scene.

    Parameters
    ----------
    scene : Scene, path or mapping
        A scene of any kind (:func:`~foundation_calc.api.scene.load`).
    strict : bool
        ``--strict``: a warning fails (verdict ``"fail"``, exit code 1).

    Returns
    -------
    Result
        ``to_dict()`` is this scene's entry of the ``scenes`` list of ``fcalc check --json``;
        ``verdict`` its worst check's (``"invalid"`` when a check finds the scene cannot be
        computed, ``"internal"`` for a bug); ``report`` the
        :class:`~foundation_calc.checks.batch.SceneRun` with every check's own report.

    Raises
    ------
    SceneError
        An invalid scene (the entry of such a file in ``fcalc check --json`` has one check,
        ``load``, whose ``problems`` are the error's).
    """
    import json

    from foundation_calc.checks.batch import check_scene
    from foundation_calc.output.check_report import json_entry

    loaded = scene_of(scene)
    run = check_scene(loaded.model, loaded.source)
    light, text = json_entry(run, strict)
    entry = json.loads(text)
    return Result("check", entry, int(light.exit_code(strict)), worst(c["verdict"] for c in entry["checks"]), loaded, run)
