"""A formula over a scene's result keys, as a preset writes the book's own calculation of a
printed value (``"points.D.a / 0.91"``): numbers, + − × ÷ and powers, abs() and sqrt(), and
keys such as ``members.4.epsilon``. Parsed by Python's ``ast`` and evaluated by walking the
tree, so nothing else can run."""

from __future__ import annotations

import ast
import math
import operator
import re
from collections.abc import Mapping

from .messages import Text

KEY = re.compile(r"\b[a-z_]+\.[A-Za-z0-9_-]+\.[a-z_]+\b")
OPERATORS = {ast.Add: operator.add, ast.Sub: operator.sub, ast.Mult: operator.mul,
             ast.Div: operator.truediv, ast.Pow: operator.pow, ast.USub: operator.neg}
FUNCTIONS = {"abs": abs, "sqrt": math.sqrt}


def _tree(formula: str) -> tuple[ast.Expression, dict[str, str]]:
    names = {}
    def name(match: re.Match) -> str:
        names[f"k{len(names)}"] = match.group(0)
        return f"k{len(names) - 1}"
    try:
        return ast.parse(KEY.sub(name, formula), mode="eval"), names
    except SyntaxError:
        raise ValueError(Text("formula.syntax", formula=formula)) from None


def formula_keys(formula: str) -> list[str]:
    """The result keys the formula uses; ValueError names what it may not contain."""
    tree, names = _tree(formula)
    for node in ast.walk(tree):
        allowed = (ast.Expression, ast.BinOp, ast.UnaryOp, ast.Constant, ast.Name, ast.Call,
                   ast.Load, *OPERATORS)
        if not isinstance(node, allowed) or (isinstance(node, ast.Constant)
                                              and not isinstance(node.value, (int, float))):
            raise ValueError(Text("formula.allowed", functions=", ".join(FUNCTIONS),
                                  formula=formula))
        if isinstance(node, ast.Call) and not (isinstance(node.func, ast.Name)
                                               and node.func.id in FUNCTIONS and len(node.args) == 1):
            raise ValueError(Text("formula.calls", functions=", ".join(FUNCTIONS),
                                  formula=formula))
        if isinstance(node, ast.Name) and node.id not in names and node.id not in FUNCTIONS:
            raise ValueError(Text("formula.name", name=node.id, formula=formula))
    return list(names.values())


def evaluate(formula: str, values: Mapping[str, float]) -> float | None:
    """The formula's value, or None when a key it uses is not among ``values``."""
    formula_keys(formula)
    tree, names = _tree(formula)
    if any(key not in values for key in names.values()):
        return None

    def walk(node) -> float:
        if isinstance(node, ast.Expression):
            return walk(node.body)
        if isinstance(node, ast.Constant):
            return float(node.value)
        if isinstance(node, ast.Name):
            return float(values[names[node.id]])
        if isinstance(node, ast.UnaryOp):
            return OPERATORS[type(node.op)](walk(node.operand))
        if isinstance(node, ast.Call):
            return FUNCTIONS[node.func.id](walk(node.args[0]))
        return OPERATORS[type(node.op)](walk(node.left), walk(node.right))
    try:
        return walk(tree)
    except (OverflowError, ZeroDivisionError, ValueError):  # 9**9**9, x/0, sqrt(−1)
        return math.nan
