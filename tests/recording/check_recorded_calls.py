#!/usr/bin/env python3
"""Checks that a recording holds every call that changes a World.

    check_recorded_calls.py ROOT
    check_recorded_calls.py --self-test ROOT

  * Every non-const member function of `class World` (include/tamias2d/world.hpp; constructors,
    operators and static functions aside) is either declared by `class Recorder`
    (include/tamias2d/recorder.hpp) with the same parameters and result, or named in the
    "Not recorded" list of src/tamias2d/recording/recorded_calls.hpp.
  * A `try_` form of such a call (World::try_create_body) is declared by Recorder too, with
    the same parameters and result, and is covered by its throwing form's entry in the list.
  * Every Recorder call is in the call list TAMIAS2D_RECORDED_CALLS of recorded_calls.hpp
    (create_joint and set_user_data by their overloads' entries), and the list names nothing
    World lacks.

--self-test removes a call from World's copy of each list in turn and fails unless each removal
is reported.
Exit status: 0 when every check passes, 1 when one fails, 2 for a bad command line.
"""
from __future__ import annotations

import re
import sys
from pathlib import Path

# The overloaded World calls' entries in the list, by their first parameter's type.
OVERLOADS = {
    ("create_joint", "RevoluteJointDef"): "create_revolute_joint",
    ("create_joint", "DistanceJointDef"): "create_distance_joint",
    ("create_joint", "TargetJointDef"): "create_target_joint",
    ("create_joint", "PrismaticJointDef"): "create_prismatic_joint",
    ("create_joint", "WeldJointDef"): "create_weld_joint",
    ("create_joint", "WheelJointDef"): "create_wheel_joint",
    ("create_joint", "MotorJointDef"): "create_motor_joint",
    ("create_joint", "FilterJointDef"): "create_filter_joint",
    ("set_user_data", "UserData"): "set_world_user_data",
    ("set_user_data", "BodyId"): "set_body_user_data",
    ("set_user_data", "ShapeId"): "set_shape_user_data",
    ("set_user_data", "JointId"): "set_joint_user_data",
}


def members(text, cls):
    """(result, name, parameter types) of the class's non-const, non-static member functions."""
    start = text.index(f"class TAMIAS2D_EXPORT {cls} {{")
    body = text[start:text.index("\n};", start)]
    body = re.sub(r"//[^\n]*", "", body)
    out = []
    for d in re.split(r";|\{[^{}]*\}", body):
        d = " ".join(d.split())
        d = re.sub(r"^(public:|private:)\s*", "", d)
        m = re.match(r"^(static\s+|explicit\s+|friend\s+)?(.*?)\b(\w+)\s*\((.*)\)\s*(const)?\s*"
                     r"(noexcept)?\s*(=\s*\w+)?$", d)
        if not m or m.group(1) or m.group(5):
            continue
        result, name, params = m.group(2).strip(), m.group(3), m.group(4)
        if not result or name.startswith("operator") or name == cls:
            continue
        types = []
        for p in filter(None, (p.strip() for p in split_params(params))):
            p = p.split("=")[0].strip()
            types.append(" ".join(p.split()[:-1]) if " " in p else p)
        out.append((result, name, tuple(types)))
    return out


def split_params(params):
    """Splits at the commas outside <> and ()."""
    depth, cur, out = 0, "", []
    for c in params:
        if c in "<(":
            depth += 1
        elif c in ">)":
            depth -= 1
        if c == "," and depth == 0:
            out.append(cur)
            cur = ""
        else:
            cur += c
    out.append(cur)
    return out


def entry(name, types):
    key = (name, (types[0].replace("const ", "").rstrip("&") if types else ""))
    return OVERLOADS.get(key, name)


def check(world_hpp, recorder_hpp, calls_hpp):
    problems = []
    world = members(world_hpp, "World")
    recorder = {(n, t): r for r, n, t in members(recorder_hpp, "Recorder")}
    listed = re.findall(r"^\s*X\((\w+),", calls_hpp, re.M)
    not_recorded = re.search(r"Not recorded.*?:(.*?)\n#", calls_hpp, re.S)
    skipped = set(re.findall(r"\b(set_\w+)\b", not_recorded.group(1))) if not_recorded else set()
    entries = set()
    for result, name, types in world:
        # A `try_` form is recorded by Recorder's `try_` form of the same call, under the
        # throwing form's entry: it checks as that form does, and adds no entry of its own.
        twin = name.startswith("try_") and name[4:] in {n for _, n, _ in world}
        if name in skipped or (twin and name[4:] in skipped):
            continue
        if (name, types) not in recorder:
            problems.append(f"World::{name}({', '.join(types)}) changes the world but Recorder "
                            "does not declare it (recorder.hpp), nor does recorded_calls.hpp "
                            "list it as not recorded")
        elif recorder[(name, types)] != result:
            problems.append(f"Recorder::{name} returns {recorder[(name, types)]}, World's "
                            f"{result}")
        e = entry(name[4:] if twin else name, types)
        entries.add(e)
        if e not in listed:
            problems.append(f"World::{name}({', '.join(types)}) has no entry {e} in "
                            "TAMIAS2D_RECORDED_CALLS (recorded_calls.hpp)")
    for e in listed:
        if e not in entries:
            problems.append(f"TAMIAS2D_RECORDED_CALLS lists {e}, which is no mutating World call")
    if len(listed) != len(set(listed)):
        problems.append("TAMIAS2D_RECORDED_CALLS lists a call twice")
    return problems


def main(argv):
    self_test = "--self-test" in argv
    args = [a for a in argv if a != "--self-test"]
    if len(args) != 1:
        print(__doc__, file=sys.stderr)
        return 2
    root = Path(args[0])
    world = (root / "include/tamias2d/world.hpp").read_text()
    recorder = (root / "include/tamias2d/recorder.hpp").read_text()
    calls = (root / "src/tamias2d/recording/recorded_calls.hpp").read_text()
    problems = check(world, recorder, calls)
    if not self_test:
        for p in problems:
            print(f"check_recorded_calls: {p}")
        print(f"check_recorded_calls: {len(members(world, 'World'))} mutating World calls, "
              f"{'OK' if not problems else f'{len(problems)} problems'}")
        return 1 if problems else 0
    if problems:
        print("check_recorded_calls: self-test needs a passing tree first")
        return 1
    damaged = {
        "a Recorder call removed": (world, recorder.replace(
            "    void apply_impulse(BodyId body, Vec2d impulse, Vec2d world_point);\n", ""), calls),
        "a list entry removed": (world, recorder, re.sub(r"\n\s*X\(set_gravity_scale,[^\n]*", "",
                                                         calls)),
        "a Recorder try_ form removed": (world, recorder.replace(
            "    Result<void> try_apply_impulse(BodyId body, Vec2d impulse, Vec2d world_point) "
            "noexcept;\n", ""), calls),
        "a World call added": (world.replace(
            "    void set_gravity(Vec2d g);", "    void set_gravity(Vec2d g);\n    void set_wind("
            "Vec2d w);"), recorder, calls),
        "a list entry World lacks": (world, recorder, calls.replace(
            "X(set_workers, &World::set_workers)", "X(set_workers, &World::set_workers) \\\n"
            "    X(set_wind, &World::set_wind)")),
    }
    failed = 0
    for what, files in damaged.items():
        if files == (world, recorder, calls) or not check(*files):
            print(f"check_recorded_calls: self-test: {what}: not reported")
            failed += 1
    print(f"check_recorded_calls: self-test: {len(damaged) - failed} of {len(damaged)} damages "
          "reported")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
