"""One table of what a class can practise (classes.methods.METHODS), read by every surface:
the store, the command line, the lecturer's form, a student's link and seat, LTI's picker.
Each method's page holds its panel, its scenes are the kind its steps take, and no module
keeps a list of the methods of its own (five did)."""

from __future__ import annotations

import ast
from pathlib import Path

import pytest

from classes import store
from classes.methods import METHODS
from classes.steps import practice_link, steps_of
from mechanisms import load_preset, preset_ids
from methods import practice_steps

ROOT = Path(__file__).resolve().parents[1]
KIND_OF = {"linkage": "Scene", "gears": "GearTrain", "rotor": "Rotor"}


@pytest.mark.parametrize("method", list(METHODS))
def test_each_method_is_practised_on_its_page_with_its_panel(method, tmp_path):
    m = METHODS[method]
    source = (ROOT / "pages" / f"{m.page}.py").read_text(encoding="utf-8")
    assert f'"{m.panel}"' in source  # the page draws the method's practice panel
    assert practice_steps.KINDS[method].__name__ == KIND_OF[m.scenes]  # the scenes it offers
    task = next(p for p in preset_ids(m.scenes) if practice_steps.steps_for(load_preset(p), method))
    url = f"sqlite:///{tmp_path / 'classes.db'}"
    code, _ = store.create(task, method, url=url)  # the store takes it …
    found = store.find(code, url=url)
    token = store.join(code, "ana", url=url)
    page, params = practice_link(found, token, "en", url=url)  # … the link opens its page …
    assert page == m.page and all(params[k] == v for k, v in m.link.items())
    assert steps_of(found)  # … on steps the class can check


def test_the_command_line_and_lti_offer_exactly_these_methods():
    from lti.routes import method_name

    from .test_cli import run

    said = run("class", "create", "zbirka-3.1", "--method", "nope")
    offered = ", ".join(f"'{m}'" for m in METHODS)
    assert said.returncode == 2 and f"(choose from {offered})" in said.stderr
    for method in METHODS:  # LTI's picker names each in both languages
        assert method_name(method, False) and method_name(method, True)


def test_no_module_keeps_its_own_list_of_the_class_methods():
    """A literal naming four or more of the methods is a second copy of the table. The one
    allowed below classes/: methods.practice_steps.KINDS, the steps' own scene kinds (a
    lower layer; it also holds the three-position method, which is not a class's)."""
    allowed = {("classes/methods.py", "METHODS"), ("methods/practice_steps.py", "KINDS")}
    names = set(METHODS)
    copies = []
    for path in sorted(ROOT.glob("*/*.py")) + sorted(ROOT.glob("*.py")):
        if path.parts[-2] in ("tests", ".venv", "node_modules", "bench"):
            continue
        relative = path.relative_to(ROOT).as_posix()
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if isinstance(node, ast.Assign) and isinstance(node.value, (ast.Dict, ast.Tuple, ast.List, ast.Set)):
                elements = node.value.keys if isinstance(node.value, ast.Dict) else node.value.elts
                named = {e.value for e in elements if isinstance(e, ast.Constant)} & names
                target = getattr(node.targets[0], "id", "?")
                if len(named) >= 4 and (relative, target) not in allowed:
                    copies.append(f"{relative}: {target}")
    assert copies == []
