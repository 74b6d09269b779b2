# The type stubs (stochtex/_stochtex.pyi) name what the extension has, with
# the same keyword names: an editor's completion cannot drift from the module.
import ast
import os
import re

import stochtex
from stochtex import _stochtex

STUB = os.path.join(os.path.dirname(stochtex.__file__), "_stochtex.pyi")


def stub_tree():
    with open(STUB) as f:
        return ast.parse(f.read())


def stub_parameters(fn):
    a = fn.args
    return [x.arg for x in a.posonlyargs + a.args + a.kwonlyargs if x.arg not in ("self",)]


def bound_parameters(obj):
    # pybind11's docstring starts with the signature: "name(self: X, a: int, *, b: List[int] = [2, 4]) -> R".
    first = (obj.__doc__ or "").strip().splitlines()[0]
    inside = first[first.index("(") + 1 : first.rindex(") ->")]
    parts, depth, current = [], 0, ""
    for ch in inside:  # split at the commas outside brackets
        depth += ch in "[(" and 1 or ch in "])" and -1 or 0
        if ch == "," and depth == 0:
            parts.append(current)
            current = ""
        else:
            current += ch
    parts.append(current)
    names = [re.split(r"[:=]", p.strip())[0].strip() for p in parts if p.strip()]
    return [n for n in names if n not in ("self", "*") and not n.startswith("**")]


def test_every_public_name_has_a_stub_and_the_reverse():
    tree = stub_tree()
    stubbed = {n.name for n in tree.body if isinstance(n, (ast.FunctionDef, ast.ClassDef))}
    public = {n for n in dir(_stochtex) if not n.startswith("_")}
    assert stubbed == public


def test_functions_and_methods_have_the_bound_keywords():
    checked = 0
    for node in stub_tree().body:
        if isinstance(node, ast.FunctionDef):
            assert stub_parameters(node) == bound_parameters(getattr(_stochtex, node.name)), node.name
            checked += 1
        if isinstance(node, ast.ClassDef) and not issubclass(getattr(_stochtex, node.name), Exception):
            cls = getattr(_stochtex, node.name)
            for item in node.body:
                if not isinstance(item, ast.FunctionDef):
                    continue
                bound = getattr(cls, item.name)
                assert bound is not None, f"{node.name}.{item.name}"
                if isinstance(bound, property):
                    continue
                assert stub_parameters(item) == bound_parameters(bound), f"{node.name}.{item.name}"
                checked += 1
    assert checked >= 10
