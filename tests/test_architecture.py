"""The layers of docs/architecture.md, read from every module's imports with ``ast``: each
package imports only its own layer and the ones below; no import circle between files; the
numerical core, the book's methods, the reports, the exams and the scenes neither draw nor
talk to a browser; no definition runs over about 120 lines."""

from __future__ import annotations

import ast
from pathlib import Path

import re

import pytest

ROOT = Path(__file__).resolve().parents[1]

# Top to bottom; a module may import its own layer and every layer below it.
LAYERS = [
    ("cli",),  # the command line, on top of everything that computes
    ("app", "asgi", "pages"),  # app.py's pages; asgi.py serves them with the LTI routes
    ("ui",),
    ("lti",),  # the app as an LTI 1.3 tool: platforms, launches, grades back (Starlette routes)
    ("classes",),
    ("exams",),
    ("figures",),
    ("reports",),
    ("methods",),
    ("solvers",),
    ("mechanisms",),
]
# ``python -m solvers`` as documented: the one module nothing imports, handing over to cli.
ENTRY_POINTS = {"solvers/__main__.py"}
NO_BROWSER = {"mechanisms", "solvers", "methods", "reports", "exams", "classes", "lti", "cli"}  # no Streamlit
NO_DRAWING = NO_BROWSER - {"cli"}  # no Plotly either
LONGEST = 120  # lines of one function or class


def _level(package: str) -> int:
    return next(i for i, names in enumerate(LAYERS) if package in names)


def _modules() -> dict[str, Path]:
    """Module name → file, for every module of the layered packages."""
    out = {"app": ROOT / "app.py", "asgi": ROOT / "asgi.py"}
    for names in LAYERS:
        for package in names:
            folder = ROOT / package
            for path in sorted(folder.rglob("*.py")) if folder.is_dir() else []:
                parts = path.relative_to(ROOT).with_suffix("").parts
                name = ".".join(parts[:-1] if parts[-1] == "__init__" else parts)
                out[name] = path
    return out


MODULES = _modules()


def _imports(name: str, path: Path) -> list[tuple[str, int]]:
    """(imported module, line) for every import of the module, relative ones resolved;
    ``from package import module`` names the module when there is one."""
    tree = ast.parse(path.read_text(), str(path))
    is_package = path.name == "__init__.py"
    out = []
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            out += [(alias.name, node.lineno) for alias in node.names]
        elif isinstance(node, ast.ImportFrom):
            base = node.module or ""
            if node.level:
                here = name.split(".") if is_package else name.split(".")[:-1]
                here = here[:len(here) - node.level + 1]
                base = ".".join(here + ([node.module] if node.module else []))
            for alias in node.names:
                full = f"{base}.{alias.name}"
                out.append((full if full in MODULES else base, node.lineno))
    return out


def _own(module: str) -> str | None:
    """The project module an import names (or its package), None for a library."""
    while module and module not in MODULES:
        module = module.rpartition(".")[0]
    return module or None


def _package(module: str) -> str:
    return module.split(".")[0]


def test_every_layered_package_is_found():
    found = {_package(m) for m in MODULES}
    assert found == {p for names in LAYERS for p in names}


def _against_layers(name: str, path: Path) -> list[str]:
    """The module's imports of a layer above its own."""
    wrong = []
    for target, line in _imports(name, path):
        own = _own(target)
        if own and _level(_package(own)) < _level(_package(name)):
            wrong.append(f"{path.name}:{line} imports {own} (a layer above)")
    return wrong


def test_imports_run_down_the_layers():
    wrong = [w for name, path in MODULES.items()
             if str(path.relative_to(ROOT)) not in ENTRY_POINTS
             for w in _against_layers(name, path)]
    assert not wrong, "\n".join(wrong)


def test_the_entry_point_only_hands_over_to_the_command_line():
    for entry in ENTRY_POINTS:
        path = ROOT / entry
        targets = {_own(t) for t, _ in _imports(path.stem, path)} - {None}
        assert targets == {"cli"}


def test_no_import_circle_between_files():
    graph = {name: {o for t, _ in _imports(name, path) if (o := _own(t)) and o != name}
             for name, path in MODULES.items()}
    done: set[str] = set()

    def visit(node: str, trail: list[str]) -> list[str] | None:
        if node in trail:
            return trail[trail.index(node):] + [node]
        if node in done:
            return None
        for nxt in sorted(graph[node]):
            if circle := visit(nxt, trail + [node]):
                return circle
        done.add(node)
        return None

    for name in sorted(graph):
        circle = visit(name, [])
        assert circle is None, " → ".join(circle)


@pytest.mark.parametrize("library, packages", [("streamlit", NO_BROWSER), ("plotly", NO_DRAWING)])
def test_what_computes_does_not_draw(library, packages):
    wrong = [f"{path.relative_to(ROOT)}:{line}" for name, path in MODULES.items()
             if _package(name) in packages
             for target, line in _imports(name, path) if _package(target) == library]
    assert not wrong


def test_the_numerical_core_writes_no_latex():
    """LaTeX is for people: methods/ writes it (the Willis formula moved there), solvers/
    only computes."""
    for path in sorted((ROOT / "solvers").glob("*.py")):
        text = path.read_text(encoding="utf-8")
        assert not re.search(r"\\\\(frac|omega|text|quad)\b", text), path.name


def test_no_definition_runs_over_about_120_lines():
    long = []
    for path in MODULES.values():
        for node in ast.walk(ast.parse(path.read_text())):
            if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef)):
                lines = node.end_lineno - node.lineno + 1
                if lines > LONGEST:
                    long.append(f"{path.relative_to(ROOT)}:{node.lineno} {node.name}: {lines}")
    assert not long, "\n".join(long)


def test_the_check_sees_an_import_against_the_layers(tmp_path):
    """A module of the core that imports a method, relatively or by name, is refused; an
    import from below and a library are not."""
    fake = tmp_path / "kinematics.py"
    fake.write_text("from ..methods import compass\nfrom methods.plans import build\n"
                    "from .loops import cross\nfrom mechanisms.schema import Scene\nimport numpy\n")
    assert _against_layers("solvers.kinematics", fake) == [
        "kinematics.py:1 imports methods.compass (a layer above)",
        "kinematics.py:2 imports methods.plans (a layer above)"]
