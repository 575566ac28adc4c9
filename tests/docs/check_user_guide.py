#!/usr/bin/env python3
"""Checks that docs/user-guide.md agrees with itself and with the code it describes.

    check_user_guide.py GUIDE WORLD_DEF_HPP EXAMPLE_CPP WORLD_HPP
    check_user_guide.py --self-test GUIDE WORLD_DEF_HPP EXAMPLE_CPP WORLD_HPP

  * Its "Contents:" paragraph links every `##` section (outside code blocks), in the order of
    the sections, each by the anchor GitHub gives the heading and with the heading's words, and
    names nothing else.
  * Its table of WorldDef fields ("The world") has a row for every field of
    `struct WorldDef` in WORLD_DEF_HPP and no row for a field that does not exist; a field
    initialised there with a plain number or boolean has that default in its row.
  * Its first program ("A first program") is EXAMPLE_CPP, which CTest builds and runs
    (example.two_bodies), and has as many lines of code as it says.
  * Its "API at a glance" tables have a row naming every public call of `class World` in
    WORLD_HPP (constructors and operators included) and name no call World lacks.

--self-test damages a copy of the guide in each way the checks must catch (a section left out
of the contents, one named that does not exist, two swapped, a table row removed, a default
changed, a line of the listing changed, a World call's row removed, a row naming a call World
lacks) and fails unless each is reported.
Exit status: 0 when every check passes, 1 when one fails, 2 for a bad command line.
"""
from __future__ import annotations

import re
import sys


def slug(heading):
    """The anchor GitHub gives a heading: lower case, punctuation dropped, spaces to hyphens."""
    return re.sub(r"[^\w\- ]", "", heading.lower()).replace(" ", "-")


def sections(guide):
    """The `##` headings outside fenced code blocks, in order."""
    heads, fence = [], None
    for line in guide.splitlines():
        m = re.match(r"^(`{3,})", line)
        if m:
            if fence is None:
                fence = m.group(1)
            elif line.strip() == fence:
                fence = None
            continue
        if fence is None and line.startswith("## "):
            heads.append(line[3:].strip())
    return heads


def section_text(guide, heading):
    start = guide.index(f"\n## {heading}\n")
    end = guide.find("\n## ", start + 1)
    return guide[start:end if end >= 0 else len(guide)]


def check_contents(guide):
    problems = []
    m = re.search(r"^Contents:(.*?)\n\n", guide, re.S | re.M)
    if not m:
        return ["no \"Contents:\" paragraph"]
    links = re.findall(r"\[([^\]]+)\]\(#([^)]+)\)", m.group(1))
    heads = sections(guide)
    anchors = [a for _, a in links]
    wanted = [slug(h) for h in heads]
    for h in heads:
        if slug(h) not in anchors:
            problems.append(f"section \"{h}\" is missing from the contents")
    for text, anchor in links:
        if anchor not in wanted:
            problems.append(f"the contents name \"{text}\" (#{anchor}), which is no section")
    for h in heads:
        for text, anchor in links:
            if anchor == slug(h) and text.lower() != h.lower():
                problems.append(f"the contents call section \"{h}\" \"{text}\"")
    common = [a for a in anchors if a in wanted]
    if not problems and common != wanted:
        problems.append("the contents list the sections in another order than the guide: "
                        + ", ".join(common))
    return problems


def world_def_fields(header):
    """{field: initialiser text or None} of `struct WorldDef`, in declaration order."""
    body = re.search(r"struct WorldDef \{(.*?)\n\};", header, re.S)
    if not body:
        raise SystemExit("check_user_guide: no struct WorldDef in the header")
    fields = {}
    for line in body.group(1).splitlines():
        line = line.strip()
        if not line or line.startswith("//"):
            continue
        m = re.match(r"^[\w:<>]+\s+(\w+)\s*(?:\{([^;]*)\}|=\s*([^;]+))?;", line)
        if m:
            fields[m.group(1)] = (m.group(2) if m.group(2) is not None else m.group(3) or "").strip()
    return fields


NUMBER = r"-?\d+(?:\.\d+)?(?:e-?\d+)?"


def literal_default(init):
    """The initialiser's values when they are plain numbers or booleans, else None."""
    parts = [p.strip() for p in init.split(",")] if init else []
    if not parts:
        return None
    values = []
    for p in parts:
        if p in ("true", "false"):
            values.append(p)
        elif re.fullmatch(NUMBER, p):
            values.append(float(p))
        else:
            return None
    return values


def check_world_table(guide, header):
    problems = []
    fields = world_def_fields(header)
    rows = {}
    for line in section_text(guide, "The world").splitlines():
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        if len(cells) < 3 or not cells[0].startswith("`") or cells[1] == "default":
            continue  # not a row, or the table's head
        for name in re.findall(r"`(\w+)`", cells[0]):
            rows[name] = (cells[0], cells[1])
    if not rows:
        return ["no table of WorldDef fields in \"The world\""]
    for name in fields:
        if name not in rows:
            problems.append(f"WorldDef::{name} has no row in the table of \"The world\"")
    for name in rows:
        if name not in fields:
            problems.append(f"the table of \"The world\" has a row for {name}, which WorldDef lacks")
    checked = set()
    for name, (first, default) in rows.items():
        names = re.findall(r"`(\w+)`", first)
        if first in checked or any(n not in fields for n in names):
            continue
        checked.add(first)
        expected = []
        for n in names:
            v = literal_default(fields[n])
            if v is None:
                break
            expected += v
        else:
            got = [float(x) if re.fullmatch(NUMBER, x) else x
                   for x in re.findall(NUMBER + r"|\btrue\b|\bfalse\b", default)]
            if got != expected:
                problems.append(f"the table's default of {', '.join(names)} is \"{default}\"; "
                                f"world_def.hpp initialises it to {fields[names[0]] if len(names) == 1 else [fields[n] for n in names]}")
    return problems


def check_first_program(guide, example):
    problems = []
    text = section_text(guide, "A first program")
    m = re.search(r"```cpp\n(.*?)```", text, re.S)
    if not m:
        return ["no C++ listing in \"A first program\""]
    lines = example.splitlines(keepends=True)
    if m.group(1) != example:
        problems.append("the listing of \"A first program\" is not apps/examples/two_bodies.cpp")
    code = sum(1 for line in lines if line.strip() and not line.strip().startswith("//"))
    claim = re.search(r"(\d+) lines of code", text)
    if claim and int(claim.group(1)) != code:
        problems.append(f"\"A first program\" says {claim.group(1)} lines of code; the example has {code}")
    return problems


def world_calls(world_hpp):
    """The names of class World's public member functions ("World" for its constructors; the
    destructor is no call)."""
    body = re.search(r"class TAMIAS2D_EXPORT World \{\n  public:\n(.*?)\n  private:", world_hpp, re.S)
    if not body:
        raise SystemExit("check_user_guide: no class World with a public part in the header")
    names = []
    for line in body.group(1).split("\\cond INTERNAL")[0].splitlines():
        code = line.split("//")[0]
        m = re.search(r"(operator=|~?\w+)\s*\(", code)
        if (m and not m.group(1).startswith("~") and not code.lstrip().startswith(("struct", "#"))
                and m.group(1) not in names):
            names.append(m.group(1))
    return names


def check_api_table(guide, world_hpp):
    """Every World call has a row in "API at a glance", and every row names World calls only."""
    if "## API at a glance" not in guide:
        return ["no section \"API at a glance\""]
    named = set()
    for line in section_text(guide, "API at a glance").splitlines():
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        if not line.startswith("|") or len(cells) < 4 or not cells[0].startswith("`"):
            continue  # not a row, or a table's head
        for code in re.findall(r"`([^`]+)`", cells[0]):
            called = re.findall(r"(operator=|\w+)\s*\(", code)
            named.update(called if called else re.findall(r"^\w+$", code))
    calls = world_calls(world_hpp)
    # A `try_` form (try_create: the constructor's) is covered by its throwing form's row.
    calls = [c for c in calls if not (c.startswith("try_") and
                                      (c[4:] in calls or (c == "try_create" and "World" in calls)))]
    problems = [f"World::{c} has no row in \"API at a glance\"" for c in calls if c not in named]
    problems += [f"\"API at a glance\" names {n}, which is no call of World" for n in sorted(named)
                 if n not in calls]
    return problems


def check(guide, header, example, world_hpp):
    return (check_contents(guide) + check_world_table(guide, header) +
            check_first_program(guide, example) + check_api_table(guide, world_hpp))


def self_test(guide, header, example, world_hpp):
    """Each damage must be reported; the undamaged guide must pass."""
    contents = re.search(r"^Contents:.*?\n\n", guide, re.S | re.M).group(0)
    heads = sections(guide)
    first, second = heads[1], heads[2]
    link = lambda h: f"[{h[0].lower() + h[1:]}](#{slug(h)})"  # noqa: E731
    assert link(first) in contents and link(second) in contents, "contents as written by the guide"
    swapped = contents.replace(link(first), "\0").replace(link(second), link(first)).replace("\0", link(second))
    damages = {
        "a section missing from the contents":
            guide.replace(contents, contents.replace(link(heads[-1]), "")),
        "a contents entry without a section":
            guide.replace(contents, contents.replace("Contents:", "Contents: [gears](#gears) ·")),
        "two contents entries swapped": guide.replace(contents, swapped),
        "a WorldDef row removed":
            re.sub(r"^\| `workers` \|.*\n", "", guide, flags=re.M),
        "a WorldDef default changed":
            re.sub(r"^(\| `substeps` \| )4 ", r"\g<1>8 ", guide, flags=re.M),
        "the first program's listing changed":
            guide.replace("world.step(1.0 / 60.0);\n        if (step % 20", "world.step(1.0 / 30.0);\n        if (step % 20", 1),
        "a World call's row removed":
            re.sub(r"^\| `query_point\(.*\n", "", guide, flags=re.M),
        "a row naming a call World lacks":
            guide.replace("| `time()` |", "| `clock()` |", 1),
    }
    failures = []
    if check(guide, header, example, world_hpp):
        failures.append("the guide as it is fails the checks")
    for what, damaged in damages.items():
        if damaged == guide:
            failures.append(f"{what}: the damage did not apply")
        elif not check(damaged, header, example, world_hpp):
            failures.append(f"{what}: not reported")
        else:
            print(f"self-test: {what}: reported")
    return failures


def main(argv):
    args = argv[1:]
    test = args[:1] == ["--self-test"]
    if test:
        args = args[1:]
    if len(args) != 4:
        print(__doc__, file=sys.stderr)
        return 2
    guide, header, example, world_hpp = (open(p, encoding="utf-8").read() for p in args)
    problems = (self_test(guide, header, example, world_hpp) if test
                else check(guide, header, example, world_hpp))
    for p in problems:
        print(f"check_user_guide: {p}")
    if problems:
        return 1
    print(f"check_user_guide: {'self-test passed' if test else 'OK'}: {len(sections(guide))} sections, "
          f"{len(world_def_fields(header))} WorldDef fields, {len(world_calls(world_hpp))} World calls")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
