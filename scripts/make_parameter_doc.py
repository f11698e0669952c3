#!/usr/bin/env python3
"""Write doc/parameters.md from `fosls-contact --print-parameters`.

    scripts/make_parameter_doc.py [--binary build/fosls-contact]
                                  [--output doc/parameters.md] [--check]

The program prints its ParameterHandler declarations as JSON (nested
subsections; each entry has "value", "default_value", "documentation",
"pattern" and "pattern_description"). This script writes one table per
subsection with every parameter, its default, its valid values (from the
pattern description) and its documentation.

Sections and parameters are listed in the order in which the sources
declare them: AllParameters::declare_parameters (source/parameters/parameters.cc)
calls the subsections' declare_parameters, each in its own
source/parameters/<subsection>.cc (anything not found there follows in
alphabetical order). With --check, nothing is written and the exit code is 1
if the file is out of date.
"""

import argparse
import json
import re
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent


def declaration_sources(aggregate):
    """The sources that declare the parameters, in the order in which
    AllParameters::declare_parameters in @p aggregate calls them: the
    struct Geometry in parameters/geometry.cc, and so on."""
    if not aggregate.is_file():
        return []
    calls = re.findall(r'\b(\w+)::declare_parameters\(prm\)', aggregate.read_text())
    snake = [re.sub(r'(?<!^)([A-Z])', r'_\1', name).lower() for name in calls]
    return [aggregate.parent / f"{name}.cc" for name in snake]


def declaration_order(sources):
    """Map section path (tuple) -> list of entry names, and the section
    order, as declared in the C++ sources. Empty if they are missing."""
    sections, entries = [], {}
    text = "".join(s.read_text() for s in sources if s.is_file())
    stack = []
    token = re.compile(r'enter_subsection\(\s*"([^"]*)"\s*\)'
                       r'|(leave_subsection)\(\s*\)'
                       r'|declare_entry\(\s*"([^"]*)"')
    for m in token.finditer(text):
        if m.group(1) is not None:
            stack.append(m.group(1))
            if tuple(stack) not in entries:
                sections.append(tuple(stack))
                entries[tuple(stack)] = []
        elif m.group(2) is not None:
            if stack:
                stack.pop()
        else:
            names = entries.setdefault(tuple(stack), [])
            if m.group(3) not in names:
                names.append(m.group(3))
    return sections, entries


def ordered(names, preferred):
    rank = {n: i for i, n in enumerate(preferred)}
    return sorted(names, key=lambda n: (rank.get(n, len(rank)), n))


def human_pattern(desc):
    """A readable form of a deal.II pattern description."""
    d = desc.strip()
    if d.startswith("[") and d.endswith("]"):
        d = d[1:-1].strip()

    def bound(x):
        return {"MAX_DOUBLE": "inf", "-MAX_DOUBLE": "-inf",
                "2147483647": "inf", "4294967295": "inf"}.get(x, x)

    def rng(lo, hi):
        lo, hi = bound(lo), bound(hi)
        if lo == "-inf" and hi == "inf":
            return ""
        if hi == "inf":
            return f" >= {lo}"
        if lo == "-inf":
            return f" <= {hi}"
        return f" in [{lo}, {hi}]"

    if d == "Anything":
        return "any text"
    if d.startswith("FileName"):
        return "a file name"
    if d == "Bool":
        return "`true` or `false`"
    m = re.fullmatch(r"Selection (.*)", d)
    if m:
        return ", ".join(f"`{o.strip()}`" for o in m.group(1).split("|"))
    m = re.fullmatch(r"Integer range (\S+)\.\.\.(\S+) \(inclusive\)", d)
    if m:
        return "integer" + rng(*m.groups())
    m = re.fullmatch(r"Integer", d)
    if m:
        return "integer"
    m = re.fullmatch(r"Double (\S+)\.\.\.(\S+) \(inclusive\)", d)
    if m:
        return "number" + rng(*m.groups())
    m = re.fullmatch(r"List of <(.*)> of length (\S+)\.\.\.(\S+) \(inclusive\)"
                     r"(?: separated by <(.*)>)?", d)
    if m:
        inner, lo, hi, sep = m.groups()
        lo, hi = bound(lo), bound(hi)
        sep = "," if sep is None else sep
        item = human_pattern(inner)
        item = re.sub(r"^integer", "integers", item)
        item = re.sub(r"^number", "numbers", item)
        if hi == "inf":
            length = "any length" if lo == "0" else f"at least {lo} entries"
        elif lo == hi:
            length = f"{lo} entries"
        else:
            length = f"{lo} to {hi} entries"
        return f"list of {item}, separated by `{sep}`, {length}"
    return desc.strip()


def cell(text):
    """Escape a string for a Markdown table cell."""
    return text.replace("|", "\\|").replace("\n", " ")


def prose(text):
    """Escape documentation text: no HTML tags, no emphasis."""
    return text.strip().replace("<", "&lt;").replace("*", "\\*")


def code(text):
    return f"`{text}`" if text.strip() else "*(empty)*"


def collect(tree, path=()):
    """Yield (section path, {name: entry}) for every subsection."""
    entries = {k: v for k, v in tree.items()
               if isinstance(v, dict) and "default_value" in v}
    if entries:
        yield path, entries
    subsections = {k: v for k, v in tree.items()
                   if isinstance(v, dict) and "default_value" not in v}
    for name, sub in subsections.items():
        yield from collect(sub, path + (name,))


def render(tree, sources):
    section_order, entry_order = declaration_order(sources)
    sections = dict(collect(tree))
    rank = {s: i for i, s in enumerate(section_order)}
    paths = sorted(sections, key=lambda p: (rank.get(p, len(rank)), p))

    out = [
        "# Parameters",
        "",
        "<!-- generated by scripts/make_parameter_doc.py from "
        "`fosls-contact --print-parameters`: do not edit -->",
        "",
        "Every parameter of `fosls-contact`, by subsection of the scene file. "
        "A scene file sets parameters as",
        "",
        "```",
        "subsection Solver",
        "  set Type = active set",
        "end",
        "```",
        "",
        "and the command line overrides them with "
        "`--set \"Solver/Type=active set\"`. Parameters that a scene does not "
        "set keep the default listed here. Every run writes the complete set "
        "of values it used to `used_parameters.prm` in the output directory.",
        "",
        "Expressions (displacements, tractions, gap, ...) are "
        "muparser expressions in `x`, `y` (and `z`), with vector components "
        "separated by `;`.",
        "",
        "Sections: " + ", ".join(
            f"[{'/'.join(p)}](#{anchor('/'.join(p))})" for p in paths),
        "",
    ]
    for p in paths:
        entries = sections[p]
        out += [f"## {'/'.join(p)}", "",
                "| Parameter | Default | Valid values | Description |",
                "|---|---|---|---|"]
        for name in ordered(entries, entry_order.get(p, [])):
            e = entries[name]
            out.append("| " + " | ".join([
                cell(f"`{name}`"),
                cell(code(e.get("default_value", ""))),
                cell(human_pattern(e.get("pattern_description", ""))),
                cell(prose(e.get("documentation", ""))),
            ]) + " |")
        out.append("")
    return "\n".join(out)


def anchor(title):
    """GitHub's heading anchor."""
    a = title.strip().lower()
    a = re.sub(r"[^\w\- ]", "", a)
    return a.replace(" ", "-")


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--binary", default=str(ROOT / "build" / "fosls-contact"),
                    help="the fosls-contact executable (default: %(default)s)")
    ap.add_argument("--output", default=str(ROOT / "doc" / "parameters.md"),
                    help="the file to write (default: %(default)s)")
    ap.add_argument("--check", action="store_true",
                    help="do not write; exit 1 if the file is out of date")
    args = ap.parse_args()

    binary = Path(args.binary)
    if not binary.is_file():
        sys.exit(f"make_parameter_doc.py: {binary} not found; "
                 "build first with scripts/setup.sh")
    result = subprocess.run([str(binary), "--print-parameters"],
                            capture_output=True, text=True)
    if result.returncode != 0:
        sys.exit(f"make_parameter_doc.py: {binary} --print-parameters "
                 f"failed:\n{result.stderr}")
    try:
        tree = json.loads(result.stdout)
    except json.JSONDecodeError as e:
        sys.exit(f"make_parameter_doc.py: output of --print-parameters is "
                 f"not JSON ({e})")

    text = render(tree, declaration_sources(ROOT / "source" / "parameters" / "parameters.cc"))
    output = Path(args.output)
    if args.check:
        current = output.read_text() if output.is_file() else None
        if current != text:
            print(f"{output} is out of date; run scripts/make_parameter_doc.py",
                  file=sys.stderr)
            return 1
        return 0
    output.parent.mkdir(parents=True, exist_ok=True)
    output.write_text(text)
    print(f"wrote {output}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
