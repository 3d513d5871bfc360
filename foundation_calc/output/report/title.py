"""Page 1 of a calculation sheet: the title block with the ``[project]`` fields, sign boxes and
the revision history, and the header every page carries ("job · calc no. · rev · page n of N").

What the scene does not give stays blank (a sign box is signed by hand); the file's SHA-256, the
fcalc version and the command make the sheet traceable to its inputs and build.
"""

from __future__ import annotations

import hashlib
from dataclasses import dataclass
from datetime import datetime, timezone
from pathlib import Path

from foundation_calc.output.report.model import Section, table


@dataclass(frozen=True)
class TitleBlock:
    """Where a sheet comes from: scene, file and its SHA-256, fcalc version, date, command, and
    the scene's ``[project]`` (None when it has none)."""

    name: str
    file: str
    sha256: str
    version: str
    date: str
    command: str
    project: object = None


def title_block(path: Path, scene, command: str) -> TitleBlock:
    """The title block of a sheet for the ``scene`` read from ``path``."""
    from foundation_calc import __version__

    digest = hashlib.sha256(path.read_bytes()).hexdigest()
    date = datetime.now(timezone.utc).strftime("%Y-%m-%d %H:%M:%S")
    return TitleBlock(scene.name or path.name, str(path), digest, __version__, date, command, scene.project)


def _text(value) -> str:
    return "" if value is None else str(value)


def page_header(title: TitleBlock) -> str:
    """The running header's text before "page n of N": job · calc no. · rev (blank fields left out)."""
    p = title.project
    parts = [] if p is None else [
        f"job {p.job}" if p.job else "", f"calc. {p.calculation}" if p.calculation else "",
        f"rev. {p.revision}" if p.revision else "",
    ]
    return " · ".join(x for x in parts if x) or title.name


def sheet_title(title: TitleBlock) -> str:
    """The sheet's heading: the project's title, else the scene's name."""
    p = title.project
    return f"Calculation sheet: {p.title if p is not None and p.title else title.name}"


def title_section(title: TitleBlock, note: str | None = None) -> Section:
    """Project fields, the traceability rows, the sign boxes and the revision history; first, the
    scene file's own ``note`` that its data are not real, when it says so."""
    p = title.project
    get = (lambda key: _text(getattr(p, key))) if p is not None else (lambda key: "")
    rows = (
        ("job", get("job")), ("calculation no.", get("calculation")), ("revision", get("revision")),
        ("client", get("client")), ("office", get("office")),
        ("scene", title.name), ("file", title.file), ("SHA-256 of the file", title.sha256),
        ("fcalc version", title.version), ("made (UTC)", title.date), ("command", title.command),
    )
    signs = table(
        "Sign-off",
        ("", "name", "date", "signature"),
        ((role, get(f"{key}_by"), get(f"{key}_date"), "") for role, key in
         (("prepared", "prepared"), ("checked", "checked"), ("approved", "approved"))),
        (False, False, False, False),
        wide=3,
    )
    blocks = [table("NOTE: the data are not real", ("the scene file's own comment",), ((note,),), (False,))] if note else []
    blocks += [table("", ("item", "value"), rows, (False, False)), signs]
    if p is not None and p.revisions:
        blocks.append(table(
            "Revision history", ("rev.", "date", "description", "by"),
            ((r.revision, _text(r.date), r.description, _text(r.by)) for r in p.revisions),
            (False, False, False, False),
        ))
    return Section("Title block", tuple(blocks))
