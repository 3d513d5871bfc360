"""Numbers as a calculation sheet prints them, read back for comparison with the JSON documents."""

from __future__ import annotations

import re

NUMBER = re.compile(r"-?\d+(?:\.\d+)?(?:e[-+]?\d+|·10[⁻⁰¹²³⁴⁵⁶⁷⁸⁹]+)?")
_SUPERSCRIPTS = str.maketrans("⁻⁰¹²³⁴⁵⁶⁷⁸⁹", "-0123456789")


def numbers(text: str) -> list[float]:
    """Every number in ``text``, ``a.bc·10ⁿ`` included."""
    return [float(m.replace("·10", "e").translate(_SUPERSCRIPTS)) for m in NUMBER.findall(text.replace("−", "-"))]
