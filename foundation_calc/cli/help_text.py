"""Help pages in an engineer's words: ``fcalc resonance [OPTIONS] SCENE``, ``--jobs N`` and
``[at least 1]``, where typer would print ``{SCENE}``, ``<int range>`` and ``[x>=1]``."""

from __future__ import annotations

import re

from typer.core import TyperCommand

#: What a value of each of typer's type names is called in a help page.
VALUE_NAMES = {"int": "N", "int range": "N", "float": "NUMBER", "float range": "NUMBER", "path": "FILE", "str": "TEXT"}

_TYPE = re.compile(r"\s*<([^<>]*)>")
_CHOICES = re.compile(r"list\[(.*)\]")
_RANGES = ((re.compile(r"\bx>=(\S+?)(?=[\];])"), r"at least \1"), (re.compile(r"\bx<=(\S+?)(?=[\];])"), r"at most \1"),
           (re.compile(r"\b(\S+?)<=x<=(\S+?)(?=[\];])"), r"\1 to \2"))


def _value_name(match: re.Match) -> str:
    """`` <int range>`` -> `` N``, `` <list[a|b]>`` -> `` a|b`` (a repeatable choice)."""
    name = match.group(1)
    choices = _CHOICES.fullmatch(name)
    if choices:
        return " " + choices.group(1)
    return " " + VALUE_NAMES.get(name, name.upper())


def _argument_name(param) -> str:
    name = param.metavar or param.name.upper()
    return name + ("..." if param.nargs != 1 else "")


class PlainCommand(TyperCommand):
    """A typer command whose usage line and help rows name values as an engineer would."""

    def collect_usage_pieces(self, ctx) -> list[str]:
        pieces = [self.options_metavar] if self.options_metavar else []
        for param in self.get_params(ctx):
            if param.param_type_name == "argument" and not param.hidden:
                name = _argument_name(param)
                pieces.append(name if param.required else f"[{name}]")
        return pieces

    def format_options(self, ctx, formatter) -> None:
        arguments, options = [], []
        for param in self.get_params(ctx):
            record = param.get_help_record(ctx)
            if record is None:
                continue
            name, text = record
            for pattern, words in _RANGES:
                text = pattern.sub(words, text)
            if param.param_type_name == "argument":
                arguments.append((_argument_name(param), text))
            else:
                options.append((_TYPE.sub(_value_name, name), text))
        for title, rows in (("Arguments", arguments), ("Options", options)):
            if rows:
                with formatter.section(title):
                    formatter.write_dl(rows)
