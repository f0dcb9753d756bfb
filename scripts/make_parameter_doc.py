#!/usr/bin/env python3
"""Generate doc/parameters.md from the parameter declarations of lithostress.

Usage:
    python3 scripts/make_parameter_doc.py <path-to-lithostress-binary> > doc/parameters.md
    python3 scripts/make_parameter_doc.py --json saved.json > doc/parameters.md

Runs `<binary> --print-parameters=json` (deal.II ParameterHandler JSON) and
writes one Markdown section per subsection path, with a table
Entry | Default | Allowed values | Description.

deal.II 9.4 writes demangled names (with spaces) in its JSON output. Older and
other writers mangle every character that is not a letter or a digit into
`_xx` (two lower-case hex digits, e.g. `Output_20directory`). Both forms are
accepted: the file is treated as mangled only if no key contains a character
that mangling cannot produce, and some key contains a `_xx` escape.

Python 3 standard library only.
"""
import json
import os
import re
import subprocess
import sys

# Subsections whose names the user chooses. The program declares them with
# one example name (ParameterFile::names_from); path -> the entry that lists
# the names.
USER_NAMED = {
    ("Materials", "rock"): "Materials/Names",
    ("Boundary conditions", "base"): "Boundary conditions/Prescribed displacement parts",
    ("Loads", "Tractions", "top"): "Loads/Tractions/Boundary parts",
}

ENTRY_KEYS = {"value", "default_value", "documentation", "pattern",
              "pattern_description", "actions"}

MANGLED_ESCAPE = re.compile(r"_([0-9a-fA-F]{2})")
MANGLED_ONLY = re.compile(r"^[A-Za-z0-9_]*$")

INT_MIN, INT_MAX = "-2147483648", "2147483647"
UINT_MAX = "4294967295"


# ---------------------------------------------------------------- reading
def run_binary(binary):
    env = dict(os.environ)
    env["OMPI_ALLOW_RUN_AS_ROOT"] = "1"
    env["OMPI_ALLOW_RUN_AS_ROOT_CONFIRM"] = "1"
    try:
        result = subprocess.run([binary, "--print-parameters=json"],
                                capture_output=True, text=True, env=env,
                                timeout=300)
    except OSError as error:
        sys.exit("make_parameter_doc: cannot run <%s>: %s" % (binary, error))
    if result.returncode != 0:
        sys.exit("make_parameter_doc: <%s --print-parameters=json> exited with "
                 "status %d:\n%s" % (binary, result.returncode, result.stderr))
    return result.stdout


def parse_json(text):
    # Anything printed before the JSON object (e.g. MPI notices) is skipped.
    start = text.find("{")
    if start < 0:
        sys.exit("make_parameter_doc: no JSON object in the program's output")
    try:
        return json.loads(text[start:])
    except ValueError as error:
        sys.exit("make_parameter_doc: cannot parse the JSON: %s" % error)


def is_entry(node):
    return (isinstance(node, dict) and "value" in node
            and not isinstance(node["value"], dict)
            and set(node) <= ENTRY_KEYS)


def all_keys(node):
    for key, child in node.items():
        yield key
        if isinstance(child, dict) and not is_entry(child):
            yield from all_keys(child)


def names_are_mangled(tree):
    keys = list(all_keys(tree))
    if any(not MANGLED_ONLY.match(k) for k in keys):
        return False
    return any(MANGLED_ESCAPE.search(k) for k in keys)


def demangle(name):
    return MANGLED_ESCAPE.sub(lambda m: chr(int(m.group(1), 16)), name)


def collect(tree, mangled):
    """[(path tuple, [(entry name, entry dict)])] depth first, entries of a
    subsection before its subsections, in the order of the JSON file."""
    name = demangle if mangled else (lambda s: s)
    sections = []

    def walk(node, path):
        entries, subsections = [], []
        for key, child in node.items():
            if is_entry(child):
                entries.append((name(key), child))
            elif isinstance(child, dict):
                subsections.append((name(key), child))
        sections.append((path, entries))
        for key, child in subsections:
            walk(child, path + (key,))

    walk(tree, ())
    return sections


# ---------------------------------------------------------------- formatting
def number(text):
    return {"-MAX_DOUBLE": "−∞", "MAX_DOUBLE": "∞", INT_MIN: "−∞",
            INT_MAX: "∞", UINT_MAX: "∞"}.get(text, text)


def range_text(kind, low, high):
    low_open = low in ("-MAX_DOUBLE", INT_MIN)
    high_open = high in ("MAX_DOUBLE", INT_MAX)
    if low_open and high_open:
        return "any " + kind
    if high_open:
        return "%s ≥ %s" % (kind, low)
    if low_open:
        return "%s ≤ %s" % (kind, high)
    return "%s in [%s, %s]" % (kind, low, high)


def describe_pattern(text):
    """A readable form of deal.II's pattern description; the raw description
    if it is not recognized."""
    text = text.strip()
    m = re.fullmatch(r"\[Anything\]", text)
    if m:
        return "any text"
    if text == "[Bool]":
        return "`true` | `false`"
    if text == "[FileName]" or text.startswith("[FileName"):
        return "file name"
    if text.startswith("[DirectoryName"):
        return "directory name"
    m = re.fullmatch(r"\[Double (\S+)\.\.\.(\S+) \(inclusive\)\]", text)
    if m:
        return range_text("real", m.group(1), m.group(2))
    m = re.fullmatch(r"\[Integer range (\S+)\.\.\.(\S+) \(inclusive\)\]", text)
    if m:
        return range_text("integer", m.group(1), m.group(2))
    m = re.fullmatch(r"\[Selection (.*)\]", text, re.S)
    if m:
        options = [o.strip() for o in m.group(1).split("|")]
        return " | ".join("`%s`" % o for o in options)
    m = re.fullmatch(r"\[MultipleSelection (.*)\]", text, re.S)
    if m:
        options = [o.strip() for o in m.group(1).split("|")]
        return "comma-separated subset of " + ", ".join("`%s`" % o for o in options)
    m = re.fullmatch(r"\[List of <(.*)> of length (\S+)\.\.\.(\S+) \(inclusive\)"
                     r"(?: separated by <(.*)>)?\]", text, re.S)
    if m:
        inner = describe_pattern(m.group(1))
        low, high = m.group(2), m.group(3)
        separator = m.group(4) if m.group(4) is not None else ","
        if low == high:
            length = "%s items" % low
        elif high == UINT_MAX:
            length = "any number of items" if low == "0" else "at least %s items" % low
        else:
            length = "%s to %s items" % (low, high)
        return "`%s`-separated list of %s: %s" % (separator, length, inner)
    return "`%s`" % text


def escape_cell(text):
    """Markdown table cell: one line, `|` escaped; `<`, `>`, `&` escaped
    outside code spans."""
    text = " ".join(str(text).split())
    parts = text.split("`")
    for i in range(0, len(parts), 2):
        parts[i] = (parts[i].replace("&", "&amp;").replace("<", "&lt;")
                    .replace(">", "&gt;"))
    text = "`".join(parts)
    return text.replace("|", "\\|")


def default_cell(value):
    if value == "":
        return "*(empty)*"
    return "`%s`" % value


def anchor(title):
    """GitHub's heading anchor."""
    slug = title.strip().lower()
    slug = re.sub(r"[^\w\- ]", "", slug)
    return slug.replace(" ", "-")


def title_of(path):
    return "Top level" if not path else " / ".join(path)


def write_markdown(sections, out):
    present = {path for path, _ in sections}
    for path in USER_NAMED:
        if path not in present:
            sys.stderr.write("make_parameter_doc: warning: expected the example "
                             "subsection <%s> in the declarations\n" % "/".join(path))
    shown = [(p, e) for p, e in sections if e]

    out.write("# lithostress — input parameters\n\n")
    out.write("<!-- Generated by scripts/make_parameter_doc.py from "
              "`lithostress --print-parameters=json`. Do not edit by hand: "
              "change the declarations in the source and regenerate. -->\n\n")
    out.write("This file is generated by `scripts/make_parameter_doc.py` from "
              "`lithostress --print-parameters=json` (the program's "
              "`ParameterHandler` declarations) and must not be edited by "
              "hand. To regenerate it:\n\n"
              "```\npython3 scripts/make_parameter_doc.py build/lithostress "
              "> doc/parameters.md\n```\n\n")
    out.write("A `.prm` file sets entries with `set Entry = value` inside "
              "`subsection Name` … `end`. `lithostress model.prm --set "
              "'Section/Entry=value'` overrides a value from the command line. "
              "Lengths are in `Geometry/Length unit` (m or km) where it says "
              "[length unit]. Functions of position receive x and y in metres. "
              "All other quantities are SI.\n\n")
    named = [(p, lst) for p, lst in USER_NAMED.items() if p in present]
    if named:
        out.write("**User-named subsections.** Some subsections are named by "
                  "the user, one per name in a list entry. They appear below "
                  "under the example names that the program declares "
                  "for documentation:\n\n")
        for path, lst in named:
            out.write("- `%s`: one subsection per name in `%s`\n"
                      % ("/".join(path), lst))
        out.write("\n")

    out.write("## Sections\n\n")
    for path, _ in shown:
        title = title_of(path)
        out.write("- [%s](#%s)\n" % (title, anchor(title)))
    out.write("\n")

    for path, entries in shown:
        out.write("## %s\n\n" % title_of(path))
        if path in USER_NAMED:
            out.write("*`%s` is an example name: there is one such subsection per "
                      "name in `%s`.*\n\n" % (path[-1], USER_NAMED[path]))
        out.write("| Entry | Default | Allowed values | Description |\n")
        out.write("| --- | --- | --- | --- |\n")
        for name, entry in entries:
            out.write("| %s | %s | %s | %s |\n" % (
                escape_cell("`%s`" % name),
                escape_cell(default_cell(entry.get("default_value",
                                                   entry.get("value", "")))),
                escape_cell(describe_pattern(entry.get("pattern_description", ""))),
                escape_cell(entry.get("documentation", ""))))
        out.write("\n")


def renamed_entries(binary):
    """The rows (old, new, since) of `<binary> --print-renamed-entries`."""
    result = subprocess.run([binary, "--print-renamed-entries"],
                            capture_output=True, text=True)
    if result.returncode != 0:
        sys.exit("make_parameter_doc: <%s --print-renamed-entries> exited with "
                 "status %d" % (binary, result.returncode))
    rows = [line.split("\t") for line in result.stdout.splitlines() if "\t" in line]
    if not rows or any(len(r) != 3 for r in rows):
        sys.exit("make_parameter_doc: <%s --print-renamed-entries> printed no "
                 "table of three columns" % binary)
    return rows


def write_renamed(rows, out):
    out.write("## Renamed entries\n\n")
    out.write("An input file that sets one of these is answered with one line "
              "naming the new entry or value. `<name>` stands for any "
              "user-named subsection.\n\n")
    out.write("| Old | New | Since |\n| --- | --- | --- |\n")
    for old, new, since in rows:
        out.write("| %s | %s | %s |\n" % (escape_cell("`%s`" % old),
                                           escape_cell("`%s`" % new),
                                           escape_cell(since)))
    out.write("\n")


def main(argv):
    renamed = None
    if len(argv) == 3 and argv[1] == "--json":
        with open(argv[2], encoding="utf-8") as f:
            text = f.read()
    elif len(argv) == 2 and not argv[1].startswith("-"):
        text = run_binary(argv[1])
        renamed = renamed_entries(argv[1])
    else:
        sys.stderr.write(__doc__)
        return 2
    tree = parse_json(text)
    sections = collect(tree, names_are_mangled(tree))
    write_markdown(sections, sys.stdout)
    if renamed:
        write_renamed(renamed, sys.stdout)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
