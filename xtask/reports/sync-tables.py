#!/usr/bin/env python3
"""Refreshes the marked tables of README.md and of the pages in docs/ from the generated reports
they quote.

A table after a line `<!-- from docs/NAME.md -->` is replaced by the table of that report whose
header row is the same (the README may quote a table whole). tests/docs.rs checks that every row of
a marked table is a row of its report; this script keeps them so after the reports are
regenerated. Marked tables whose header no longer appears in the report are reported, not changed.
"""
import pathlib
import sys

root = pathlib.Path(__file__).resolve().parent.parent.parent


def tables(text):
    """Every table of a report: a list of its lines."""
    found, current = [], []
    for line in text.split("\n"):
        if line.startswith("|"):
            current.append(line.rstrip())
        elif current:
            found.append(current)
            current = []
    if current:
        found.append(current)
    return found


stale = []


def sync(path):
    """Refreshes the marked tables of one page; notes the ones whose header is gone."""
    lines = path.read_text().split("\n")
    out, index = [], 0
    while index < len(lines):
        line = lines[index]
        out.append(line)
        index += 1
        marker = line.strip()
        if not (marker.startswith("<!-- from ") and marker.endswith(" -->")):
            continue
        source = marker[len("<!-- from "):-len(" -->")]
        if index < len(lines) and lines[index].startswith("```"):
            continue  # a quoted code block: kept as written, checked by tests/docs.rs
        start = index
        while index < len(lines) and lines[index].startswith("|"):
            index += 1
        table = lines[start:index]
        report = (root / source).read_text()
        match = [t for t in tables(report) if table and t[0] == table[0].rstrip()]
        if match:
            out.extend(match[0])
        else:
            out.extend(table)
            stale.append(f"{source}: {table[0] if table else '(empty)'}")
    path.write_text("\n".join(out))


pages = [root / "README.md"] + sorted((root / "docs").glob("*.md"))
for page in pages:
    text = page.read_text()
    if "<!-- from " in text:
        sync(page)

for entry in stale:
    print(f"no table with this header in {entry}", file=sys.stderr)
sys.exit(1 if stale else 0)
