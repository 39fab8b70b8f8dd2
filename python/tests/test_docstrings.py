"""The docstring audit (issue 30, point 8): every public function, class, method and property of the rbcstab
package has a docstring, every numeric parameter is named in it with its range and unit (or "dimensionless"), and
every numeric property states its own; every scene key's help gives its range. The audit is checked against
deliberately bad docstrings, so it can fail."""
import ast
import inspect
import numbers
import os
import re
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, os.path.join(ROOT, "python", "tools"))

import stubs  # noqa: E402  (the pybind11 signature reader the stub generator uses)

# A range: an interval "[a, b]" / "(a, b]", a comparison "> 0", ">= 1", "a..b", "finite", "0 or more".
RANGE = re.compile(r"[\[(][^\[\]()]*,[^\[\]()]*[\])]|[<>]=?\s*[-+]?\d|\d\s*\.\.\s*\d|\bfinite\b")
# A unit: a time, an SI unit, a count (an integer), or the word dimensionless.
UNIT = re.compile(r"dimensionless|1/shear rate|\bPa s\b|1/s\b|\bseconds\b|\[(s|m|m\^2|m\^3|J|K|N/m)\]|N/m|"
                  r"\bintegers?\b|\bradians?\b")
# Where a parameter's clause ends: a sentence, a semicolon, a blank line, or the next row of a keyword table.
_CLAUSE_END = re.compile(r"\.\s|;|\n\s*\n|\n {0,4}\w[\w, ]*\s{2,}")


def clause(doc, name):
    """The clauses of doc that start where `name` is mentioned as a word (each up to its end, at most 300
    characters)."""
    out = []
    for m in re.finditer(rf"(?<![\w.-]){re.escape(name)}(?![\w(-])", doc):
        rest = doc[m.end():m.end() + 300]
        end = _CLAUSE_END.search(rest)
        out.append(name + (rest[:end.start()] if end else rest))
    return out


def numeric_names():
    """Keywords that take numbers whatever their default (None: the library's), from the package's own tables:
    the numeric scene keys, the continuation's numeric options, and times."""
    import rbcstab
    c = sys.modules["rbcstab.continuation"]  # the module (rbcstab.continuation is the function)
    keys = {k["keyword"] for k in rbcstab.scene_keys() if re.search(r"\b(float|int)\b", k["type"])}
    options = {k for k, kind in c._KINDS.items() if kind in (c._number, c._integer)}
    return keys | options | {"t", "t_eval"}


def is_numeric(name, default, annotation, names):
    if isinstance(default, numbers.Real) and not isinstance(default, bool):
        return True
    if annotation and re.search(r"\b(float|int)\b", annotation) and not re.search(r"\bstr\b", annotation):
        return True
    return name in names


def problems_of(qualname, obj, doc, params, names):
    """What the docstring `doc` of `obj` lacks: itself, or for a numeric parameter its mention, range or unit.
    params: (name, default, annotation) of its parameters."""
    if not doc.strip():
        return [f"{qualname}: no docstring"]
    out = []
    for name, default, annotation in params:
        if name in ("self", "cls") or not is_numeric(name, default, annotation, names):
            continue
        found = clause(doc, name)
        if not found:
            out.append(f"{qualname}: numeric parameter {name!r} is not named in the docstring")
        elif not any(RANGE.search(c) for c in found):
            out.append(f"{qualname}: numeric parameter {name!r} has no range where it is named: {found[0]!r}")
        elif not any(UNIT.search(c) for c in found):
            out.append(f"{qualname}: numeric parameter {name!r} has no unit (or 'dimensionless'): {found[0]!r}")
    return out


def _params(obj):
    """(name, default, annotation text) of a Python function's or a pybind11 function's parameters."""
    try:
        sig = inspect.signature(obj)
    except (TypeError, ValueError):
        sig = None
    if sig is not None:
        return [(p.name, p.default, "" if p.annotation is p.empty else str(p.annotation))
                for p in sig.parameters.values() if p.kind not in (p.VAR_POSITIONAL, p.VAR_KEYWORD)]
    parsed = stubs._pybind_signature(obj, "")
    out = []
    for text in (parsed[0] if parsed else []):
        m = re.match(r"(\w+)(?:\s*:\s*([^=]+?))?(?:\s*=\s*(.+))?$", text)
        if m and not m.group(1).startswith("*"):
            default = m.group(3)
            try:
                default = ast.literal_eval(default) if default is not None else None
            except (ValueError, SyntaxError):
                pass
            out.append((m.group(1), default, m.group(2) or ""))
    return out


def _stub_property_types():
    """{(class, property): annotation} from the compiled module's stub."""
    with open(os.path.join(ROOT, "python", "rbcstab", "_rbcstab.pyi")) as f:
        tree = ast.parse(f.read())
    out = {}
    for cls in (n for n in tree.body if isinstance(n, ast.ClassDef)):
        for fn in (n for n in cls.body if isinstance(n, ast.FunctionDef)):
            if any(isinstance(d, ast.Name) and d.id == "property" for d in fn.decorator_list) and fn.returns:
                out[(cls.name, fn.name)] = ast.unparse(fn.returns)
    return out


def _own_doc(obj):
    """The docstring without pybind11's signature line (its first line, "name(...) -> type")."""
    doc = inspect.getdoc(obj) or ""
    lines = doc.splitlines()
    if lines and re.match(r"^\w*\(.*\) -> .+$", lines[0]):
        doc = "\n".join(lines[1:])
    return doc


def public_api():
    """(qualified name, object, docstring, parameters, property annotation) of every public function, class,
    method and property of rbcstab: the names of __all__, and of a class every public member it defines or
    inherits from the package (not from Python's builtins or pybind11's base)."""
    import rbcstab
    out = []
    for name in sorted(n for n in rbcstab.__all__ if not n.startswith("__")):
        obj = getattr(rbcstab, name)
        if not callable(obj):
            continue
        if not inspect.isclass(obj):
            out.append((f"rbcstab.{name}", obj, _own_doc(obj), _params(obj), None))
            continue
        out.append((f"rbcstab.{name}", obj, _own_doc(obj), [], None))
        if issubclass(obj, BaseException):
            continue
        seen = set()
        for klass in obj.__mro__:
            if not (klass.__module__ or "").startswith("rbcstab"):
                continue
            for mname, member in vars(klass).items():
                if mname in seen or (mname.startswith("_") and mname != "__init__"):
                    continue
                seen.add(mname)
                qual = f"rbcstab.{name}.{mname}"
                if isinstance(member, property):
                    out.append((qual, member, _own_doc(member), [], (klass.__name__, mname)))
                elif mname == "__init__":
                    # Documented by the class: its numeric parameters must be named in the class docstring.
                    params = [p for p in _params(member) if p[0] != "self"]
                    if obj is rbcstab.Scene:  # every keyword is a property of its own (checked there)
                        continue
                    out.append((qual, member, _own_doc(obj), params, None))
                elif isinstance(member, (staticmethod, classmethod)) or callable(member):
                    fn = member.__func__ if isinstance(member, (staticmethod, classmethod)) else member
                    out.append((qual, fn, _own_doc(fn), _params(fn), None))
    return out


def audit():
    names = numeric_names()
    types = _stub_property_types()
    found = []
    for qual, obj, doc, params, prop in public_api():
        found += problems_of(qual, obj, doc, params, names)
        annotation = types.get(prop, "") if prop else ""
        if prop and doc.strip() and is_numeric(prop[1], None, annotation, set()):
            if not RANGE.search(doc):
                found.append(f"{qual}: numeric property ({annotation}) gives no range: {doc!r}")
            elif not UNIT.search(doc):
                found.append(f"{qual}: numeric property ({annotation}) gives no unit (or 'dimensionless'): {doc!r}")
    return found


def test_every_public_docstring_gives_units_and_ranges():
    found = audit()
    assert not found, "\n".join(found)


def test_the_audit_walks_the_whole_api():
    """The walk reaches functions, classes, inherited pybind11 methods and properties (a walk that found nothing
    would pass everything)."""
    quals = {q for q, *_ in public_api()}
    for q in ("rbcstab.simulate", "rbcstab.Scene", "rbcstab.Scene.h_init", "rbcstab.Scene.from_toml",
              "rbcstab.Model.rhs", "rbcstab.Model.n", "rbcstab.Branch.restart", "rbcstab.Diagram.plot"):
        assert q in quals, q
    params = {q: p for q, _, _, p, _ in public_api()}
    assert {"t", "y"} <= {n for n, *_ in params["rbcstab.Model.rhs"]}
    names = numeric_names()
    assert {"rtol", "h_init", "T", "L", "min", "max_points", "step", "t_eval"} <= names


def test_the_audit_flags_bad_docstrings():
    names = numeric_names()

    def undocumented(rtol=1e-8):
        pass

    def unnamed(rtol=None):
        """Runs it."""

    def no_range(rtol=None):
        """rtol: the relative tolerance, dimensionless."""

    def no_unit(rtol=None):
        """rtol: the relative tolerance, in [1e-15, 0.1]."""

    def good(rtol=None, label=None):
        """rtol: the relative tolerance (dimensionless), in [1e-15, 0.1]; label: a name."""

    def check(f):
        return problems_of(f.__name__, f, inspect.getdoc(f) or "", _params(f), names)

    assert check(undocumented) == ["undocumented: no docstring"]
    assert "is not named" in check(unnamed)[0]
    assert "has no range" in check(no_range)[0]
    assert "has no unit" in check(no_unit)[0]
    assert check(good) == []
    # A numeric keyword known only by its default, and one known only from the tables (default None).
    assert check(lambda x=2.5: None) == ["<lambda>: no docstring"]

    def by_default(horizon=0.0):
        """Integrates."""
    assert "'horizon' is not named" in check(by_default)[0]


def test_the_clause_of_a_keyword_ends_at_its_sentence():
    doc = "min, max: its bounds, in [0, 1]. step: the first step; T: the horizon"
    assert clause(doc, "max") == ["max: its bounds, in [0, 1]"]
    assert clause(doc, "step")[0] == "step: the first step"
    assert clause("x_max: 1 < 2; finite-horizon: 0 < 1", "max") == []  # a word, not a part of one
    assert clause("finite-horizon: 0 < 1", "horizon") == []


def test_every_scene_key_help_gives_a_range():
    """rbcstab.scene_keys() (the scene-file key table, io/scene_file.cpp): a numeric key's help gives its range
    and unit, a name-valued key lists its names."""
    import rbcstab

    def key_problems(k):
        if k["names"]:
            return []
        if re.search(r"\b(float|int)\b", k["type"]):
            if not RANGE.search(k["help"]):
                return [f"{k['path']}: no range in {k['help']!r}"]
            if not UNIT.search(k["help"]):
                return [f"{k['path']}: no unit in {k['help']!r}"]
        return []

    found = [p for k in rbcstab.scene_keys() for p in key_problems(k)]
    assert not found, "\n".join(found)
    assert {k["key"] for k in rbcstab.scene_keys()} >= {"h_init", "h_min", "max_steps", "max_seconds"}
    # The help h_init had before this audit fails it.
    assert key_problems({"path": "integrator.h_init", "names": [], "type": "float", "help": "first trial step"})
