"""`fcalc check` over many scenes: table, JSON, JUnit XML, exit codes, one bad file never hides others."""

from __future__ import annotations

import json
import shutil
import xml.etree.ElementTree as ET

import pytest
import tomli_w

from foundation_calc.checks import registry
from foundation_calc.cli.app import app
from foundation_calc.output.console import stdout
from foundation_calc.scenes import parse_scene, read_toml
from tests.conftest import CONFIGS, configs_of_kind, only_input_warnings

GOOD = sorted(CONFIGS.glob("*.toml"))


def _invoke(runner, *args):
    return runner.invoke(app, ["check", *map(str, args)])


@pytest.fixture
def quick_checks(monkeypatch):
    """Crank scenes run only the resonance check (the amplitude check takes ~1 s a scene), for
    tests of the report itself rather than of the checks."""
    monkeypatch.setitem(registry.CHECKS, "crank_foundation", {"resonance": registry.resonance})


@pytest.fixture
def mixed_folder(tmp_path, frame_saw):
    """Every shipped config, plus broken scenes in a subfolder (bad TOML, bad value, not UTF-8)."""
    folder = tmp_path / "scenes"
    (folder / "broken").mkdir(parents=True)
    for config in GOOD:
        shutil.copy(config, folder / config.name)
    (folder / "broken" / "not_toml.toml").write_text("kind = \n", encoding="utf-8")
    frame_saw["foundation"]["mass"] = -5.0
    (folder / "broken" / "negative_mass.toml").write_text(tomli_w.dumps(frame_saw), encoding="utf-8")
    (folder / "broken" / "latin1.toml").write_bytes("name = 'Säge'\n".encode("latin-1"))
    (folder / "notes.txt").write_text("not a scene", encoding="utf-8")
    return folder


@pytest.mark.parametrize("config", configs_of_kind("crank_foundation"), ids=lambda p: p.name)
def test_each_crank_config_agrees_with_resonance_and_amplitudes(runner, config):
    """`check` on one crank scene gives the verdicts of `resonance`, `amplitudes` and, for a scene
    with a transient limit, `runup`, and the worst exit code."""
    names = ("resonance", "amplitudes", *(("runup",) if "transient_amplitude" in config.read_text() else ()))
    warned = ("inputs",) * bool(parse_scene(read_toml(config)).plausibility_warnings())  # a row of its own
    singles = {name: runner.invoke(app, [name, str(config), "--json"]) for name in names}
    result = _invoke(runner, config, "--json")
    assert result.exit_code == max(single.exit_code for single in singles.values()), result.stdout
    assert only_input_warnings(result.stderr, config)
    doc = json.loads(result.stdout)
    assert doc["schema_version"] == 1 and doc["command"] == "check"
    (scene,) = doc["scenes"]
    checks = {c["check"]: c for c in scene["checks"]}
    assert list(checks) == [*warned, *names]
    for name, single in singles.items():
        assert checks[name]["verdict"] == json.loads(single.stdout)["verdict"], name
    assert checks["resonance"]["result"]["resonances"] == json.loads(singles["resonance"].stdout)["resonances"]
    assert checks["resonance"]["values"]["speed"]["unit"] == "rad/s"


@pytest.mark.parametrize("config", configs_of_kind("platform"), ids=lambda p: p.name)
def test_each_platform_config_agrees_with_fcalc_platform(runner, config):
    single = runner.invoke(app, ["platform", str(config), "--json"])
    result = _invoke(runner, config, "--json")
    assert result.exit_code == single.exit_code, result.stdout
    assert result.stderr == ""
    (scene,) = json.loads(result.stdout)["scenes"]
    design, *runup = scene["checks"]
    assert design["check"] == "design" and design["verdict"] == json.loads(single.stdout)["verdict"]
    if "transient_amplitude" in config.read_text():  # its start-up is judged as `fcalc runup` judges it
        (runup,) = runup
        assert runup["verdict"] == json.loads(runner.invoke(app, ["runup", str(config), "--json"]).stdout)["verdict"]
    else:
        assert runup == []
    assert design["result"]["checks"] == json.loads(single.stdout)["checks"]
    assert len(design["details"]) == len(design["result"]["checks"])


def test_folder_with_good_and_broken_scenes(runner, mixed_folder, tmp_path):
    report = tmp_path / "reports" / "junit.xml"
    report.parent.mkdir()
    result = _invoke(runner, mixed_folder, "--json", "--junit", report)
    assert result.exit_code == 3  # the worst: invalid scenes (no internal errors)
    doc = json.loads(result.stdout)
    sources = [s["source"] for s in doc["scenes"]]
    assert len(sources) == len(GOOD) + 3  # notes.txt is not a scene
    by_name = {s["source"].rsplit("/", 1)[-1]: s for s in doc["scenes"]}
    assert by_name["negative_mass.toml"]["checks"][0]["verdict"] == "invalid"
    problems = by_name["negative_mass.toml"]["checks"][0]["problems"]
    assert problems[0]["field"] == "foundation.mass" and "[kg]" in problems[0]["message"]
    assert "not UTF-8" in by_name["latin1.toml"]["checks"][0]["reason"]
    assert "not valid TOML" in by_name["not_toml.toml"]["checks"][0]["reason"]
    for config in GOOD:
        assert by_name[config.name]["checks"][0]["verdict"] in {"pass", "warn", "fail"}

    root = ET.parse(report).getroot()
    suites = root.findall("testsuite")
    assert sorted(s.get("name") for s in suites) == sorted(sources)
    cases = root.iter("testcase")
    assert all(len(list(s.iter("testcase"))) >= 1 for s in suites)
    assert int(root.get("tests")) == len(list(cases)) == sum(len(s["checks"]) for s in doc["scenes"])
    assert int(root.get("errors")) == 3
    assert int(root.get("failures")) == doc["counts"]["fail"] >= 1
    error = root.find(".//testcase[@classname]/error")
    assert error is not None and error.get("message")
    assert not list(report.parent.glob(".*tmp"))  # no temporary file left behind


def test_table_lists_every_scene(runner, quick_checks, mixed_folder, monkeypatch):
    monkeypatch.setattr(stdout(), "width", 250)  # one line per row: names are not folded
    result = _invoke(runner, mixed_folder)
    assert result.exit_code == 3
    text = result.stdout.replace("\n", "")
    for name in ("frame_saw", "negative_mass", "latin1", "not_toml", "INVALID", "exit code 3"):
        assert name in text


def test_strict_makes_warnings_fail_like_the_single_commands(runner, quick_checks, tmp_path):
    platform = CONFIGS / "platform_explicit_vertical.toml"  # warns (exciter height), fails nothing
    assert _invoke(runner, platform).exit_code == 0
    assert _invoke(runner, platform, "--strict").exit_code == 1
    assert runner.invoke(app, ["platform", str(platform), "--strict"]).exit_code == 1
    scene = read_toml(CONFIGS / "compressor_vendor_loads.toml")
    scene["loads"] = [load for load in scene["loads"] if load["order"] == 2]
    scene["operation"]["speed_rpm"] = 900  # ω 10 % below p2, no load of order 1: a warning only
    crank = tmp_path / "loads_900rpm.toml"
    crank.write_text(tomli_w.dumps(scene))
    assert runner.invoke(app, ["resonance", str(crank)]).exit_code == 0
    assert runner.invoke(app, ["resonance", str(crank), "--strict"]).exit_code == 1
    doc = json.loads(_invoke(runner, crank, "--strict", "--json").stdout)
    assert doc["strict"] and doc["scenes"][0]["checks"][0]["verdict"] == "fail"
    doc = json.loads(_invoke(runner, crank, "--json").stdout)
    assert doc["scenes"][0]["checks"][0]["verdict"] == "warn"


def test_crash_in_one_check_is_internal_and_others_still_run(runner, monkeypatch, tmp_path):
    def broken(scene):
        raise ZeroDivisionError("float division by zero")

    monkeypatch.delenv("FCALC_DEBUG", raising=False)
    checks = {**registry.CHECKS["crank_foundation"], "boom": broken}
    monkeypatch.setitem(registry.CHECKS, "crank_foundation", checks)
    report = tmp_path / "junit.xml"
    result = _invoke(runner, CONFIGS / "frame_saw_extra_resonance.toml", CONFIGS / "crank_press.toml", "--junit", report)
    assert result.exit_code == 4
    assert "Traceback" not in result.output
    root = ET.parse(report).getroot()
    assert root.get("tests") == "6" and root.get("errors") == "2"  # 2 scenes x (resonance, amplitudes, boom)
    assert [e.get("type") for e in root.iter("error")] == ["internal", "internal"]


def test_missing_file_is_reported_and_the_rest_run(runner, quick_checks, tmp_path):
    result = _invoke(runner, tmp_path / "nope.toml", CONFIGS / "crank_press.toml", "--json")
    assert result.exit_code == 3
    doc = json.loads(result.stdout)
    assert [s["exit_code"] for s in doc["scenes"]] == [3, 0]
    assert "cannot be read" in doc["scenes"][0]["checks"][0]["reason"]


def test_no_scene_files_is_a_usage_error(runner, tmp_path):
    result = _invoke(runner, tmp_path)
    assert result.exit_code == 2
    assert "no scene files" in result.output


def test_units_in_table_and_json_stays_si(runner, quick_checks, monkeypatch):
    monkeypatch.setattr(stdout(), "width", 250)
    scene = CONFIGS / "frame_saw_extra_resonance.toml"  # 300 rpm = 31.416 rad/s = 5 Hz
    assert "300 rpm" in _invoke(runner, scene, "--units", "rpm").stdout
    assert "5 Hz" in _invoke(runner, scene, "--units", "mm,Hz").stdout
    assert "31.416 rad/s" in _invoke(runner, scene).stdout
    doc = json.loads(_invoke(runner, scene, "--units", "rpm", "--json").stdout)
    assert doc["scenes"][0]["checks"][0]["values"]["speed"]["value"] == pytest.approx(10 * 3.141592653589793)
    bad = _invoke(runner, scene, "--units", "furlong")
    assert bad.exit_code == 2 and "furlong" in bad.output


def test_junit_replaces_an_old_report_and_escapes_odd_names(runner, quick_checks, tmp_path):
    odd = tmp_path / "odd\x01name.toml"
    odd.write_text("kind = 'crank_foundation'\n", encoding="utf-8")
    report = tmp_path / "junit.xml"
    report.write_text("old", encoding="utf-8")
    result = _invoke(runner, odd, "--junit", report)
    assert result.exit_code == 3
    root = ET.parse(report).getroot()  # parses: the control character was replaced
    assert root.find("testsuite").get("name") == str(odd).replace("\x01", "\ufffd")


def test_unwritable_junit_path_is_not_a_crash(runner, quick_checks, tmp_path):
    result = _invoke(runner, CONFIGS / "crank_press.toml", "--junit", tmp_path / "no" / "such" / "dir.xml")
    assert result.exit_code == 2
    assert "Traceback" not in result.output


def test_resonance_tables_follow_units(runner, monkeypatch):
    """`fcalc resonance --units`: critical speeds in the chosen unit; JSON unchanged (SI)."""
    monkeypatch.setattr(stdout(), "width", 250)
    scene = str(CONFIGS / "frame_saw_extra_resonance.toml")
    si = runner.invoke(app, ["resonance", scene])
    hz = runner.invoke(app, ["resonance", scene, "--units", "Hz"])
    assert "rad/s, avg. inertia" in si.stdout and "Hz, avg. inertia" in hz.stdout
    # k0 = 108.732 rad/s = 17.305 Hz (natural-frequency table); ω = k0 row in Hz:
    row = next(line for line in hz.stdout.splitlines() if line.startswith("│ ω = k0 "))
    assert row.count("17.305") == 2 and "1038.3" not in row
    plain = runner.invoke(app, ["resonance", scene, "--json"]).stdout
    assert runner.invoke(app, ["resonance", scene, "--json", "--units", "Hz"]).stdout == plain


def test_jobs_give_the_serial_result_in_the_same_order(runner, tmp_path):
    """Scenes spread over worker processes: the same document as the serial run, a broken scene
    still reported in its place."""
    for name in ("frame_saw.toml", "crank_press.toml", "compressor_near_resonance.toml", "vertical_compressor.toml"):
        shutil.copy(CONFIGS / name, tmp_path / name)
    (tmp_path / "broken.toml").write_text('kind = "crank_foundation"\n[foundation\n', encoding="utf-8")
    serial = runner.invoke(app, ["check", str(tmp_path), "--json", "--jobs", "1"])
    parallel = runner.invoke(app, ["check", str(tmp_path), "--json", "--jobs", "2"])
    assert serial.exit_code == parallel.exit_code == 3
    assert json.loads(serial.stdout) == json.loads(parallel.stdout)
    assert [s["source"].rsplit("/", 1)[-1] for s in json.loads(parallel.stdout)["scenes"]][0] == "broken.toml"


def test_streamed_document_is_the_whole_documents_text(quick_checks, mixed_folder):
    """fcalc check --json writes the document scene by scene, keeping only light runs; the text is
    exactly the dump of the document built from the full runs (skipped files included)."""
    from foundation_calc.checks.batch import run_scenes
    from foundation_calc.output import check_report

    scenes = run_scenes([mixed_folder])
    whole = json.dumps(check_report.check_document(scenes, True), indent=2, ensure_ascii=False) + "\n"
    parts = []
    light = check_report.stream_check_json((check_report.json_entry(s, True) for s in scenes), True, parts.append)
    assert "".join(parts) == whole
    assert all(s.scene is None and all(r.report is None for r in s.runs) for s in light)
    assert [s.source for s in light] == [s.source for s in scenes]


def test_absolute_and_relative_paths_together(runner, monkeypatch, tmp_path):
    """`fcalc check /abs/a.toml rel/b.toml`: both checked, names printed as given."""
    (tmp_path / "rel").mkdir()
    shutil.copy(CONFIGS / "crank_press.toml", tmp_path / "rel" / "b.toml")
    monkeypatch.chdir(tmp_path)
    result = runner.invoke(app, ["check", str(CONFIGS / "frame_saw.toml"), "rel/b.toml"])
    assert result.exit_code == 0, result.output
    assert "frame_saw.toml" in result.stdout and "b.toml" in result.stdout


def test_junit_carries_each_checks_own_time(runner, monkeypatch, tmp_path):
    """A check that takes at least 50 ms is reported with at least that time; a suite's time is
    the sum of its test cases', the run's the sum of its suites' (JUnit's ``time``, seconds)."""
    import time

    def slow_resonance(scene):
        time.sleep(0.05)
        return registry.resonance(scene)

    monkeypatch.setitem(registry.CHECKS, "crank_foundation", {"resonance": slow_resonance})
    report = tmp_path / "junit.xml"
    _invoke(runner, CONFIGS / "crank_press.toml", CONFIGS / "frame_saw.toml", "--junit", report)
    root = ET.parse(report).getroot()
    suites = root.findall("testsuite")
    assert len(suites) == 2
    for suite in suites:
        times = [float(case.get("time")) for case in suite.iter("testcase")]
        assert times and min(times) >= 0.05
        assert float(suite.get("time")) == pytest.approx(sum(times), abs=1e-5)
    assert float(root.get("time")) == pytest.approx(sum(float(s.get("time")) for s in suites), abs=1e-5)
