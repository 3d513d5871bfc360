"""The ``[project]`` table of a scene: who a calculation is for and who signs it, and the office
defaults file ``fcalc.toml`` that a folder of scenes shares.

The calculation sheet prints it in its title block and in every page's header ("job · calc no. ·
rev · page n of N"); no check reads it. The office file may also hold a ``[require]`` table
(:class:`Requirements`): rules the office imposes on every scene under it, which the check
``requirements`` judges; a scene may impose them on itself, never lift the office's. ``fcalc.toml`` is looked for in the scene's folder and
then in each parent folder (as pyproject.toml is), the nearest one counting; its ``[project]``
gives the values a scene's own ``[project]`` does not (a scene's value wins). A CI batch of many
scenes thus shares the job, client and signatories. Unknown keys are errors in both files.
"""

from __future__ import annotations

import datetime
from pathlib import Path
from typing import Any, Literal

from pydantic import Field, model_validator

from foundation_calc.errors import SceneError
from foundation_calc.scenes.common import SCENE_SCHEMA_VERSION, SceneModel, quantity

#: Name of the office defaults file.
OFFICE_FILE = "fcalc.toml"

#: A date as TOML writes it (``2026-11-26``, unquoted) or free text (``"26 Nov 2026"``).
DateText = datetime.date | str


def _text(text: str, example: str, length: int = 120) -> Any:
    return Field(None, description=f"- [-]: {text}", max_length=length, examples=[example])


def _date(text: str) -> Any:
    return Field(None, description=f"- [-]: {text}, a TOML date (2026-11-26) or text", examples=[datetime.date(2026, 11, 26)])


class Revision(SceneModel):
    """One line of the revision history."""

    revision: str = Field(description="- [-]: revision mark, e.g. \"A\" or \"P01\"", max_length=20, examples=["A"])
    date: DateText | None = _date("date of the revision")
    description: str = Field("", description="- [-]: what changed", max_length=300, examples=["first issue"])
    by: str | None = _text("who made the revision", "P. Preparer", 80)


class Project(SceneModel):
    """Title-block fields of a calculation sheet (all optional; a sign box without a name stays blank)."""

    job: str | None = _text("job or project number", "J-2041", 60)
    calculation: str | None = _text("calculation number", "CALC-017", 60)
    revision: str | None = _text("current revision mark", "B", 20)
    purpose: Literal["for information", "for comment", "for approval", "for construction", "as built"] | None = Field(
        None, description="- [-]: purpose of issue: for information, for comment, for approval, for construction or as built",
        examples=["for approval"],
    )
    title: str | None = _text("title of the calculation (default: the scene's name)", "Sawmill frame foundation, dynamic check", 200)
    client: str | None = _text("client", "Sawmill Ltd", 200)
    office: str | None = _text("office or company that issues the calculation", "Foundations Office", 200)
    prepared_by: str | None = _text("name of the engineer who prepared the calculation", "P. Preparer", 80)
    prepared_date: DateText | None = _date("date prepared")
    checked_by: str | None = _text("name of the checking engineer", "A. Checker", 80)
    checked_date: DateText | None = _date("date checked")
    approved_by: str | None = _text("name of the approving engineer", "B. Approver", 80)
    approved_date: DateText | None = _date("date approved")
    revisions: list[Revision] = Field(
        default_factory=list, description="- [-]: revision history, oldest first", max_length=100
    )

    @model_validator(mode="after")
    def _revision_in_history(self) -> "Project":
        """A current ``revision`` must be a line of the revision history, when there is one."""
        marks = [r.revision for r in self.revisions]
        if self.revision is not None and marks and self.revision not in marks:
            raise ValueError(f"revision = {self.revision!r} is not in the revision history (revisions: {', '.join(marks)});"
                             " add its line to revisions or correct the mark")
        return self


class Requirements(SceneModel):
    """Rules an office imposes on every calculation under its fcalc.toml, judged by the check requirements.

    Set in ``fcalc.toml`` ``[require]`` (or a scene's own ``[require]``)."""

    soil_bracketing: bool = Field(
        False, description="- [-]: a scene on soil must bracket the soil's stiffness with [soil] modulus_range"
        " (ACI 351.3R-18 asks for the response over a range of soil properties); without it the scene fails",
        examples=[True],
    )


class SheetOptions(SceneModel):
    """The ``[report]`` table of a scene that ``fcalc design`` sizes: what its calculation sheet adds."""

    design: list[str] = Field(
        default_factory=list, max_length=5,
        description="- [-]: ranges KEY=LO:HI [m] of fcalc design --vary (block.length, block.width, block.height,"
        " piles.length, piles.diameter); the sheet of a scene that fails prints the cheapest design over them"
        " that passes every check (its values and worst margin), or says that none does",
        examples=[["block.length=4:8", "block.width=3:7"]],
    )
    design_step: float | None = Field(
        None, gt=0, description="s [m]: grid step of every range of design (fcalc design --step; default 0.1 m)",
        examples=[0.25],
    )


def office_file(scene_path: str | Path) -> Path | None:
    """The ``fcalc.toml`` nearest to the scene: in its folder or the first parent that has one."""
    folder = Path(scene_path).resolve().parent
    for candidate in (folder, *folder.parents):
        path = candidate / OFFICE_FILE
        if path.is_file():
            return path
    return None


def with_office_defaults(document: dict[str, Any], scene_path: str | Path) -> dict[str, Any]:
    """The scene ``document`` with the ``[project]`` of the nearest ``fcalc.toml`` under its own
    (a scene's key wins); unchanged when there is no such file.

    Raises
    ------
    SceneError
        naming ``fcalc.toml`` when it cannot be read, has a table other than ``[project]`` and
        ``[require]``, or an unknown or invalid key in it (the message names the key and suggests
        the nearest one).

    The office's ``[require]`` rules join the scene's own: a rule either sets is in force.
    """
    path = office_file(scene_path)
    if path is None:
        return document
    from foundation_calc.scenes.files import read_toml
    from foundation_calc.scenes.validation import validate

    office = read_toml(path)
    unknown = sorted(set(office) - {"project", "require"})
    if unknown:
        raise SceneError(str(path), [(key, f"{OFFICE_FILE} holds only a [project] table (office defaults) and a [require] table (office rules)") for key in unknown])
    merged = dict(document)
    for table, model, what in (("project", Project, "title-block fields"), ("require", Requirements, "office rules")):
        given = office.get(table, {})
        if not isinstance(given, dict):
            raise SceneError(str(path), [(table, f"must be a table of {what}")])
        validate(model, given, str(path), prefix=f"{table}.")
        own = document.get(table, {})
        if not isinstance(own, dict):  # the scene's own validation says what is wrong
            continue
        if table == "project":  # a scene's value wins
            merged[table] = {**given, **own}
        elif given:  # a rule either file sets is in force
            merged[table] = {**own, **{key: True for key, value in given.items() if value}}
    return merged


class SceneHeader(SceneModel):
    """The keys every scene kind opens with: its kind (each kind's model narrows it to its own
    name), the format's version, its name, its ``[project]`` and its ``[require]``."""

    kind: str = quantity("-", "-", "scene kind")
    schema_version: Literal[1] = quantity("-", "-", "version of the scene format", SCENE_SCHEMA_VERSION)
    name: str = quantity("-", "-", "free text shown in reports", "", max_length=200)
    project: Project | None = quantity(
        "-", "-", "title block of the calculation sheet (job, calculation number, revision, sign-off);"
        " fcalc.toml in the scene's folder or a parent gives the office defaults", None
    )
    require: Requirements | None = quantity(
        "-", "-", "rules of the office the scene must meet (soil_bracketing); fcalc.toml [require] sets them"
        " for every scene under it", None
    )
