"""Shared fixtures: the shipped configs, a CLI runner, scene documents to break."""

from __future__ import annotations

import copy
from pathlib import Path

import pytest
from typer.testing import CliRunner

from foundation_calc.scenes import read_toml

ROOT = Path(__file__).resolve().parents[1]
CONFIGS = ROOT / "configs"


def configs_of_kind(kind: str) -> list[Path]:
    """Every file in configs/ whose ``kind`` is ``kind``."""
    return sorted(p for p in CONFIGS.glob("*.toml") if read_toml(p).get("kind") == kind)


def mechanism_configs() -> list[Path]:
    """The crank_foundation files in configs/ with a [mechanism] (not a machine given by its loads only)."""
    return [p for p in configs_of_kind("crank_foundation") if "mechanism" in read_toml(p)]


@pytest.fixture
def runner() -> CliRunner:
    return CliRunner()


@pytest.fixture
def frame_saw() -> dict:
    """A fresh copy of configs/frame_saw_extra_resonance.toml as a dict, to modify in a test."""
    return copy.deepcopy(read_toml(CONFIGS / "frame_saw_extra_resonance.toml"))
