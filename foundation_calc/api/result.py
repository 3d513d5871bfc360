"""What a command of the Python API returns: its JSON document, verdict and exit code."""

from __future__ import annotations

import copy
from dataclasses import dataclass, field
from typing import Any

#: Verdicts from best to worst: a check's (pass, warn, fail), then a scene that cannot be used
#: (invalid) and a bug (internal), as ``fcalc check --json`` writes them.
VERDICTS = ("pass", "warn", "fail", "invalid", "internal")


def worst(verdicts) -> str:
    """The worst of ``verdicts`` (:data:`VERDICTS`), ``"pass"`` for none.

    >>> worst(["pass", "warn"]), worst([])
    ('warn', 'pass')
    """
    return max(verdicts, key=VERDICTS.index, default="pass")


@dataclass(frozen=True, eq=False)
class Result:
    """The result of one command on one scene.

    Attributes
    ----------
    command : str
        The command (``"resonance"``, ``"check"`` ...).
    document : dict
        The JSON document the command prints with ``--json`` (SI units); :meth:`to_dict` gives a
        copy to keep.
    exit_code : int
        The command's exit code: 0 pass (or nothing judged), 1 a check fails (a warning too with
        ``strict=True``), 4 a check met a bug (``check``, ``design``).
    verdict : str
        ``"pass"``, ``"warn"`` or ``"fail"`` (``"invalid"`` or ``"internal"`` for a ``check``
        whose check could not judge the scene); a command that judges nothing (``soil``) passes.
    scene : Scene or None
        The scene, as :func:`~foundation_calc.api.scene.load` gave it.
    report : object
        The checks' own result object, from which the command prints its tables.
    """

    command: str
    document: dict = field(repr=False)
    exit_code: int
    verdict: str
    scene: Any = field(default=None, repr=False)
    report: Any = field(default=None, repr=False)

    def to_dict(self) -> dict:
        """The command's JSON document (``fcalc COMMAND --json``) as a new dict."""
        return copy.deepcopy(self.document)


def document_verdict(document: dict, exit_code: int) -> str:
    """The verdict of a single-scene command: its document's ``verdict``, else ``"pass"`` for
    exit code 0 (a command that judges nothing) and ``"fail"`` for 1."""
    return document.get("verdict") or ("pass" if exit_code == 0 else "fail")


def command_result(command: str, document: dict, exit_code: int, scene, report=None) -> Result:
    """The :class:`Result` of a single-scene command whose ``document`` is printed as it is
    (:func:`~foundation_calc.output.console.print_json`: fcalc's version after the schema's), its
    numbers, lists and texts as JSON gives them back (a tuple is a list).

    Raises
    ------
    NonFiniteError
        when a number of the document is NaN or infinite (JSON has none), naming its path, as the
        command exits 3 for it.
    """
    import json

    from foundation_calc.output.console import json_text, with_version

    document = json.loads(json_text(with_version(document)))
    code = int(exit_code)
    return Result(command, document, code, document_verdict(document, code), scene, report)
