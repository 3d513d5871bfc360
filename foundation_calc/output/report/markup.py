"""The marks of fcalc's plain sheet text that the PDF and HTML typeset: exponents and subscripts.

The sheet's text is plain (Markdown prints it as it is). An exponent is written ``e^{i nωt}`` (or
``^½``, ``^¼`` for a root); a
subscript is a symbol of one letter (a bar over it welcome: ``M̄_xθ``), ``_`` and its index of
letters and digits, commas joining indices: ``Z_n``, ``K_z``, ``a_0``, ``u_P,n``, ``v_rms``, ``M_Σ``. A scene key is not a symbol
and keeps its ``_``: a word before it (``speed_rpm``, ``xi_z``), a dotted path (``soil.c_phi``), a
Greek letter spelled out (``c_phi``), a second ``_`` (``balance_grade_mm_s``), and a table's
column of keys (:attr:`~foundation_calc.output.report.model.Table.literal`).

>>> pieces("Re(Z_n e^{i nωt}), u_P,n and speed_rpm, soil.c_phi")
[('text', 'Re(Z'), ('sub', 'n'), ('text', ' e'), ('super', 'i nωt'), ('text', '), u'), ('sub', 'P,n'), ('text', ' and speed_rpm, soil.c_phi')]
"""

from __future__ import annotations

import re

#: Letters a symbol and its index are made of (Latin and Greek).
_LETTER = "A-Za-zα-ωΑ-Ω"

_MARK = re.compile(
    r"\^(?:\{(?P<super>[^{}]*)\}|(?P<fraction>[½¼¾]))"
    rf"|(?<![{_LETTER}0-9_.\\])(?P<symbol>[{_LETTER}]\u0304?)_(?P<sub>[{_LETTER}0-9]+(?:,[{_LETTER}0-9]+)*)(?![_{_LETTER}0-9])"
)

#: Greek letters spelled out: ``c_phi`` is a scene key, ``c_φ`` the symbol.
SPELLED_GREEK = frozenset(
    "alpha beta gamma delta epsilon zeta eta theta iota kappa lambda mu nu xi omicron pi rho sigma tau upsilon"
    " phi chi psi omega".split()
)


def pieces(plain: str, subscripts: bool = True) -> list[tuple[str, str]]:
    """``plain`` cut into ``("text" | "super" | "sub", text)`` pieces (module docstring); without
    ``subscripts`` only the exponents are cut out (a column of scene keys)."""
    out: list[tuple[str, str]] = []
    at = 0

    def add(kind: str, text: str) -> None:
        if kind == "text" and out and out[-1][0] == "text":
            out[-1] = ("text", out[-1][1] + text)
        elif text or kind != "text":
            out.append((kind, text))

    for match in _MARK.finditer(plain):
        if match.group("super") is not None or match.group("fraction") is not None:
            add("text", plain[at:match.start()])
            add("super", match.group("super") or match.group("fraction"))
        elif subscripts and match.group("sub").lower() not in SPELLED_GREEK:
            add("text", plain[at:match.start()] + match.group("symbol"))
            add("sub", match.group("sub"))
        else:
            continue
        at = match.end()
    add("text", plain[at:])
    return out
