"""Page 1 of a calculation sheet: the title block with the ``[project]`` fields, sign boxes and
the revision history, and the header every page carries ("job · calc no. · rev · page n of N").

What the scene does not give stays blank (a sign box is signed by hand); the file's SHA-256, the
office file ``fcalc.toml`` that gave defaults or rules and its SHA-256, the fcalc version (a release
or a development build) and the command make the sheet traceable to its inputs and build.
"""

from __future__ import annotations

import hashlib
from dataclasses import dataclass
from datetime import datetime, timezone
from pathlib import Path

from foundation_calc.output.report.model import Section, table
from foundation_calc.version import build_kind


@dataclass(frozen=True)
class TitleBlock:
    """Where a sheet comes from: scene, file and its SHA-256, fcalc version, date, command, the
    scene's ``[project]`` (None when it has none) and the office file with its SHA-256 ("" without one)."""

    name: str
    file: str
    sha256: str
    version: str
    date: str
    command: str
    project: object = None
    office_file: str = ""
    office_sha256: str = ""


def title_block(path: Path, scene, command: str) -> TitleBlock:
    """The title block of a sheet for the ``scene`` read from ``path``."""
    from foundation_calc import __version__
    from foundation_calc.scenes.project import office_file

    digest = hashlib.sha256(path.read_bytes()).hexdigest()
    date = datetime.now(timezone.utc).strftime("%Y-%m-%d %H:%M:%S")
    office = office_file(path)
    office_digest = "" if office is None else hashlib.sha256(office.read_bytes()).hexdigest()
    return TitleBlock(scene.name or path.name, str(path), digest, __version__, date, command, scene.project,
                      "" if office is None else str(office), office_digest)


def _text(value) -> str:
    return "" if value is None else str(value)


def page_header(title: TitleBlock) -> str:
    """The running header's text before "page n of N": job · calc no. · rev · purpose of issue
    (blank fields left out)."""
    p = title.project
    parts = [] if p is None else [
        f"job {p.job}" if p.job else "", f"calc. {p.calculation}" if p.calculation else "",
        f"rev. {p.revision}" if p.revision else "", p.purpose or "",
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
        ("purpose of issue", get("purpose")),
        ("client", get("client")), ("office", get("office")),
        ("scene", title.name), ("file", title.file), ("SHA-256 of the file", title.sha256),
        ("office file", title.office_file or "none (no fcalc.toml in the scene's folder or a parent)"),
        *((("SHA-256 of the office file", title.office_sha256),) if title.office_file else ()),
        ("fcalc version", f"{title.version} ({build_kind(title.version)})"), ("made (UTC)", title.date), ("command", title.command),
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
