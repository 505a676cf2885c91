"""methods() and patterns() are the registries `aabench list` prints; scenes read and write as
the CLI's export does."""

import json
import re

import aabench
from conftest import run_cli


def list_sections():
    """`aabench list` parsed: section title word -> {id: [(param, default, range), ...]}."""
    sections, rows, current = {}, None, None
    for line in run_cli("list").stdout.splitlines():
        if not line.strip():
            continue
        if not line.startswith(" "):
            rows = sections.setdefault(line.split()[0], {})
        elif re.match(r"^  \S", line):
            current = rows.setdefault(line.split()[0], [])
        elif m := re.match(r"^      (\S+)\s+default (\S*)\s+range (\S+)", line):
            current.append(m.groups())
    return sections


def test_methods_and_patterns_are_the_registries_list_prints():
    sections = list_sections()
    for rows, listed in [(aabench.methods(), sections["methods"]),
                         (aabench.patterns(), sections["patterns"])]:
        assert [r["id"] for r in rows] == list(listed)
        for row in rows:
            assert row["summary"] and isinstance(row["traits"], dict)
            assert [(p["name"], p["default_text"], p["range"]) for p in row["parameters"]] == \
                listed[row["id"]], row["id"]


def test_registry_rows_carry_defaults_ranges_and_traits():
    methods = {m["id"]: m for m in aabench.methods()}
    n = {p["name"]: p for p in methods["box-multiscan"]["parameters"]}["n"]
    assert n["kind"] == "int" and n["default"] == 3 and n["min"] >= 1 and n["max"] > n["min"]
    assert methods["box-multiscan"]["spec"] == "box-multiscan:n=3"
    assert methods["gauss-multiscan"]["traits"]["filter"].startswith("gaussian")
    assert methods["taa"]["traits"]["temporal"] and methods["fxaa"]["traits"]["post_process"]
    assert methods["exact"]["traits"]["reference_renderer"]
    patterns = {p["id"]: p for p in aabench.patterns()}
    assert patterns["curves"]["traits"]["bezier"]
    assert not patterns["mirror"]["traits"]["in_default_run"]
    spokes = {p["name"]: p for p in patterns["star"]["parameters"]}["spokes"]
    assert spokes["kind"] == "int" and isinstance(spokes["default"], int)


def test_scenes_read_and_write_as_the_cli_exports(tmp_path):
    path = tmp_path / "curves.json"
    run_cli("export", "--pattern", "curves", "--size", "40x30", "--out", path)
    scene = aabench.Scene.pattern("curves", size=(40, 30))
    assert scene.to_json() == path.read_text()
    assert aabench.Scene.from_file(path).to_json() == path.read_text()
    assert aabench.Scene.from_file(str(path)).to_json() == path.read_text()
    assert aabench.Scene.from_json(path.read_text()).to_json() == path.read_text()
    assert aabench.Scene.from_json(json.loads(path.read_text())).to_json() == path.read_text()
    assert repr(scene).startswith("<aabench.Scene 40x30 (2-D, ")
    assert "pattern 'curves'" in repr(scene)
    room = aabench.Scene.pattern("room", size=(40, 30))
    assert room.is_3d and not scene.is_3d and "3-D" in repr(room)
