"""The API reference of docs/python.md, rendered from the package's docstrings (one source: the code).

    PYTHONPATH=build/release/python /usr/bin/python3 python/tools/api_reference.py --write docs/python.md

rewrites the block between the api-reference markers; without --write it prints the block. The test
python.docs fails when docs/python.md is not up to date."""
import argparse
import inspect
import sys

BEGIN, END = "<!-- api-reference: begin (python/tools/api_reference.py) -->", "<!-- api-reference: end -->"


def _signature(obj):
    try:
        return str(inspect.signature(obj))
    except (TypeError, ValueError):
        return "(...)"


def _doc(obj):
    doc = inspect.getdoc(obj) or ""
    return "\n".join("    " + line if line else "" for line in doc.splitlines())


def render():
    import rbcstab
    out = [BEGIN, ""]
    for name in sorted(rbcstab.__all__, key=lambda n: (not n[0].islower(), n.lower())):
        if name.startswith("__"):
            continue
        obj = getattr(rbcstab, name)
        if inspect.isclass(obj):
            if issubclass(obj, Warning) or issubclass(obj, Exception):
                out += [f"### `rbcstab.{name}` (exception)", "", _doc(obj), ""]
                continue
            out += [f"### `rbcstab.{name}`", "", _doc(obj), ""]
            members = []
            for mname, member in sorted(vars(obj).items()):
                if mname.startswith("_") and mname not in ("__init__", "__getitem__", "__len__"):
                    continue
                if isinstance(member, property) or type(member).__name__ in ("property", "instancemethod"):
                    doc = (inspect.getdoc(member) or "").split("\n\n")[0].replace("\n", " ")
                    members.append(f"- `{mname}`" + (f": {doc}" if doc else ""))
                elif callable(member) or isinstance(member, (staticmethod, classmethod)):
                    fn = member.__func__ if isinstance(member, (staticmethod, classmethod)) else member
                    doc = (inspect.getdoc(fn) or "").split("\n\n")[0].replace("\n", " ")
                    members.append(f"- `{mname}{_signature(fn)}`" + (f": {doc}" if doc else ""))
            out += members + [""]
        elif callable(obj):
            out += [f"### `rbcstab.{name}{_signature(obj)}`", "", _doc(obj), ""]
    out.append(END)
    return "\n".join(out) + "\n"


def updated(text):
    start, end = text.index(BEGIN), text.index(END) + len(END) + 1
    return text[:start] + render() + text[end:]


def main():
    ap = argparse.ArgumentParser(description="docs/python.md's API reference from the docstrings")
    ap.add_argument("--write", metavar="FILE", help="rewrite the marked block of FILE")
    args = ap.parse_args()
    if args.write:
        with open(args.write) as f:
            text = f.read()
        with open(args.write, "w") as f:
            f.write(updated(text))
    else:
        sys.stdout.write(render())


if __name__ == "__main__":
    main()
