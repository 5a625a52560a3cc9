"""The layers of docs/architecture.md hold: imports go down, never up, and no module imports itself round a cycle.

Every ``import hydroservo.x`` in the package is read from the source (module
level and inside functions; ``if TYPE_CHECKING:`` blocks are not imports). A
module may import its own layer and the layers below. Imports inside a
function that go up are allowed only where the architecture says why
(:data:`DELEGATIONS`): convenience methods of result objects that hand over
to the io and plotting layers when called.
"""

from __future__ import annotations

import ast
from pathlib import Path

import pytest

PACKAGE = Path(__file__).resolve().parents[2] / "src" / "hydroservo"

#: Layer of each top-level module or package, bottom (0) to top.
LAYERS = {
    "errors": 0,
    "units": 0,
    "backend": 0,
    "references": 0,
    "data": 0,
    "version": 0,
    "laws": 1,
    "fluids": 2,
    "components": 3,
    "system": 4,
    "analysis": 5,
    "identification": 6,
    "io": 7,
    "plotting": 7,
    "codegen": 7,
    "validation": 8,
    "workflows": 9,
    "cli": 10,
    "__init__": 11,
    "__main__": 11,
}

#: Upward imports allowed inside functions: (importing module, imported top-level package).
DELEGATIONS = {
    ("hydroservo.system.result", "io"),  # Result.to_csv / to_mat, a notebook's display of a result (io.notebook)
    ("hydroservo.system.system", "plotting"),  # System.diagram
    ("hydroservo.system.system", "io"),  # a notebook's display of a system (io.notebook)
    ("hydroservo.system.result", "plotting"),  # Result.plot, BatchResult.plot
    ("hydroservo.system.result", "analysis"),  # BatchResult.table
    ("hydroservo.analysis.frequency", "plotting"),  # FrequencyResponse.plot
    ("hydroservo.analysis.sensitivity", "plotting"),  # OneAtATime.plot, GlobalStudy.plot
    ("hydroservo.analysis.sensitivity", "io"),  # a notebook's display of a study (io.notebook)
    ("hydroservo.system.system", "identification"),  # System.calibrate, System.plan_experiment
    ("hydroservo.identification.calibration", "plotting"),  # Calibration.plot
    ("hydroservo.identification.calibration", "io"),  # Calibration.lines: its tables laid out by io.text
}


def _modules() -> dict[str, Path]:
    out = {}
    for path in PACKAGE.rglob("*.py"):
        rel = path.relative_to(PACKAGE.parent).with_suffix("")
        parts = list(rel.parts)
        if parts[-1] == "__init__" and len(parts) > 2:
            parts = parts[:-1]
        out[".".join(parts)] = path
    return out


def _imports(path: Path) -> list[tuple[str, bool]]:
    """(imported hydroservo module, inside a function) for every import of the file."""
    tree = ast.parse(path.read_text(encoding="utf-8"))
    found: list[tuple[str, bool]] = []

    def visit(node: ast.AST, in_function: bool) -> None:
        if isinstance(node, ast.If) and "TYPE_CHECKING" in ast.unparse(node.test):
            return
        if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)):
            in_function = True
        if isinstance(node, ast.Import):
            found.extend((a.name, in_function) for a in node.names if a.name.startswith("hydroservo"))
        elif isinstance(node, ast.ImportFrom) and node.module and node.module.startswith("hydroservo"):
            if node.module == "hydroservo":  # from hydroservo import x: x is a module of the package
                found.extend((f"hydroservo.{a.name}", in_function) for a in node.names)
            else:
                found.append((node.module, in_function))
        for child in ast.iter_child_nodes(node):
            visit(child, in_function)

    visit(tree, False)
    return found


def _top(module: str) -> str:
    parts = module.split(".")
    if len(parts) == 1 or (len(parts) == 2 and parts[1] not in LAYERS):  # the package itself, or a name it defines
        return "__init__"
    return parts[1]


MODULES = _modules()


@pytest.mark.parametrize("module", sorted(MODULES))
def test_imports_go_down(module: str) -> None:
    own = _top(module) if module != "hydroservo" else "__init__"
    if module == "hydroservo.__main__":
        own = "__main__"
    assert own in LAYERS, f"{module}: no layer in LAYERS (docs/architecture.md)"
    for target, in_function in _imports(MODULES[module]):
        top = _top(target)
        if LAYERS[top] <= LAYERS[own] or own in ("__init__", "__main__"):
            continue
        allowed = in_function and (module, top) in DELEGATIONS
        assert allowed, f"{module} (layer {own}) imports {target} (layer {top}), which is above it"


def _assert_no_cycle(graph: dict[str, set[str]]) -> None:
    """Fail naming the first cycle of imports found in ``graph`` (module -> modules it imports)."""
    state: dict[str, int] = {}
    stack: list[str] = []

    def visit(m: str) -> None:
        state[m] = 1
        stack.append(m)
        for t in sorted(graph[m]):
            if state.get(t) == 1:
                raise AssertionError("import cycle: " + " -> ".join([*stack[stack.index(t) :], t]))
            if t not in state:
                visit(t)
        stack.pop()
        state[m] = 2

    for m in sorted(graph):
        if m not in state:
            visit(m)


def test_no_import_cycles() -> None:
    graph = {
        m: {t for t, in_function in _imports(p) if not in_function and t in MODULES and t != m}
        for m, p in MODULES.items()
    }
    # a package's own __init__ re-exporting its modules is not a cycle of theirs
    for m in graph:
        graph[m] = {t for t in graph[m] if not m.startswith(t + ".")}
    _assert_no_cycle(graph)


#: What the command line may import: it parses options into a workflow, runs it, writes and prints.
CLI_MAY_IMPORT = ("workflows", "cli", "errors", "units", "version")


@pytest.mark.parametrize("module", sorted(m for m in MODULES if _top(m) == "cli"))
def test_the_command_line_imports_only_workflows(module: str) -> None:
    for target, _ in _imports(MODULES[module]):
        top = _top(target)
        assert top in CLI_MAY_IMPORT, (
            f"{module} imports {target}: a command parses, runs a workflow (hydroservo.workflows), writes and prints; "
            f"it may import only {', '.join(CLI_MAY_IMPORT)}"
        )


def test_the_rule_for_the_command_line_catches_an_import_below_the_workflows(tmp_path: Path) -> None:
    path = tmp_path / "cmd.py"
    path.write_text("def cmd(args):\n    from hydroservo.analysis.linear import linearize\n")
    tops = {_top(t) for t, _ in _imports(path)}
    assert tops == {"analysis"} and not tops <= set(CLI_MAY_IMPORT)


def test_no_import_cycles_even_inside_functions() -> None:
    """Imports inside functions too (the lazy ones), leaving out the delegations the architecture allows: no two
    modules need each other (units and data did, through two functions)."""
    graph: dict[str, set[str]] = {}
    for m, p in MODULES.items():
        targets = {t for t, in_function in _imports(p) if t in MODULES and t != m and not m.startswith(t + ".")}
        graph[m] = {t for t in targets if (m, _top(t)) not in DELEGATIONS}
    _assert_no_cycle(graph)
