#!/usr/bin/python3
"""Checks docs/scene.schema.json, the JSON Schema of the scene format (docs/scene-format.md).

Usage: python3 tests/io/check_scene_schema.py <repo_root>

(a) the schema is a valid JSON Schema of its draft, and every property it defines has a
    "description";
(b) it accepts every example scene (examples/scenes/*.json) and the complete example embedded
    in docs/scene-format.md (its first ```json block, extracted as apps/cli/doc_example.cmake
    does for cli.validate.doc_example);
(c) it rejects the malformed scenes of tests/io/data/malformed/ whose defect a schema can
    express, each at the JSON pointer where the loader reports it, and a few inline variants
    (an unknown key at each level of nesting).

The loader (src/tamias2d/io/, its reader scene_reader.cpp) remains the authority: the malformed scenes in
LOADER_ONLY are rejected by it but not by the schema, for the reason given. A malformed scene in
neither list fails the check until it is classified here.

Prints one line per check and ends with "N passed, M failed"; exits non-zero on any failure.
Needs only the standard library and jsonschema (Debian: python3-jsonschema).
"""

import importlib.metadata
import json
import pathlib
import sys

import jsonschema
from jsonschema.validators import validator_for

# Malformed scenes the schema must reject: file -> (JSON pointer, keyword) of the expected
# schema error. The pointers are the ones the loader reports (tests/io/test_scene_errors.cpp).
SCHEMA_REJECTS = {
    "unknown_key.json": ("/bodies/0/shapes/0", "additionalProperties"),
    "missing_radius.json": ("/bodies/0/shapes/0", "required"),
    "missing_steps.json": ("", "required"),
    "wrong_type.json": ("/bodies/0/position/1", "type"),
    "negative_radius.json": ("/bodies/1/shapes/0/radius", "exclusiveMinimum"),
    "zero_width.json": ("/bodies/0/shapes/0/width", "exclusiveMinimum"),
    "restitution_above_one.json": ("/materials/bouncy/restitution", "maximum"),
    "zero_density.json": ("/bodies/0/shapes/0/material/density", "exclusiveMinimum"),
    "negative_friction.json": ("/materials/default/friction", "minimum"),
    "negative_damping.json": ("/bodies/0/linear_damping", "minimum"),
    "zero_dt.json": ("/dt", "exclusiveMinimum"),
    "unknown_load_kind.json": ("/bodies/0/loads/torque/kind", "enum"),
    "gravity_three_components.json": ("/world/gravity", "maxItems"),
    "zero_substeps.json": ("/world/substeps", "minimum"),
    "pyramid_base_zero.json": ("/bodies/0/base", "minimum"),
    "not_an_object.json": ("", "type"),
    "negative_inertia.json": ("/bodies/0/inertia", "exclusiveMinimum"),
    "zero_mass.json": ("/bodies/0/mass", "exclusiveMinimum"),
    "rain_negative_width.json": ("/bodies/0/container/width", "exclusiveMinimum"),
    "control_char_key.json": ("", "additionalProperties"),
    "rain_seed_2_63.json": ("/bodies/0/seed", "maximum"),
    "chain_one_point.json": ("/bodies/0/shapes/0/points", "minItems"),
    "capsule_negative_radius.json": ("/bodies/0/shapes/0/radius", "exclusiveMinimum"),
    "segment_only_dynamic.json": ("/bodies/0/shapes", "contains"),
}

# Malformed scenes left to the loader, and why a JSON Schema cannot detect them.
LOADER_ONLY = {
    "joint_zero_axis.json": "a prismatic joint's axis of zero length: a schema can bound each "
    "component, not the vector's length",
    "joint_unknown_body.json": "a joint names a body that does not exist: a schema cannot "
    "relate a value to the names elsewhere in the document",
    "trailing_comma.json": "not JSON (syntax error): no schema runs; an editor's JSON parser "
    "flags it",
    "truncated.json": "not JSON (unexpected end): no schema runs; an editor's JSON parser "
    "flags it",
    "duplicate_key.json": "a key given twice: a schema sees the parsed object, which keeps only "
    "one of them",
    "overflow.json": "1e400 is a valid JSON number that overflows a double (DCX_finite); JSON "
    "Schema has no finiteness keyword",
    "duplicate_name.json": "names unique across bodies: uniqueItems compares whole elements, not "
    "one key of them",
    "unknown_material.json": "a material name must be declared in /materials: a cross-reference "
    "standard JSON Schema cannot express",
    "collinear_polygon.json": "the convex hull's area and vertex count are geometry (DCX_shape), "
    "computed by the loader",
    "bow_tie_polygon.json": "whether a polygon's outline crosses itself is geometry (DCX_shape): "
    "a schema sees each point, not the segments between them",
    "sliver_box.json": "the sliver rule (DCX_shape) relates a box's sides to each other, which a "
    "schema's per-value bounds cannot",
    "box_too_wide.json": "the supported range (DCX_range, docs/design.md) is the library's check; "
    "the schema bounds signs, not magnitudes",
    "box_too_thin.json": "the supported range (DCX_range) is the library's check",
    "velocity_too_large.json": "the supported range (DCX_range) is the library's check",
    "force_too_large.json": "the supported range (DCX_range) is the library's check",
    "dt_too_large.json": "the supported range (DCX_range) is the library's check",
    "deep_nesting.json": "nesting deeper than 128 levels: JSON Schema has no depth keyword (it "
    "rejects the array at /bodies/0 by its type, not where the loader stops)",
    "nul_after_scene.json": "not JSON (a NUL byte after the document): no schema runs",
    "zero_length_segment.json": "whether a segment's two ends coincide is geometry (DCX_shape): "
    "a schema sees each point, not the distance between them",
}

# Inline variants: name -> (scene, expected (pointer, keyword) or None for "accepted").
_SHAPE = {"type": "circle", "radius": 1}
INLINE = {
    "unknown key at the top": (
        {"dt": 0.1, "steps": 1, "bodies": [], "stpes": 1}, ("", "additionalProperties")),
    "\"$schema\" key (the loader rejects it too)": (
        {"$schema": "./scene.schema.json", "dt": 0.1, "steps": 1, "bodies": []},
        ("", "additionalProperties")),
    "unknown key in world": (
        {"dt": 0.1, "steps": 1, "world": {"gravty": [0, -10]}, "bodies": []},
        ("/world", "additionalProperties")),
    "unknown key in a material": (
        {"dt": 0.1, "steps": 1, "materials": {"m": {"densty": 1}}, "bodies": []},
        ("/materials/m", "additionalProperties")),
    "unknown key in a body": (
        {"dt": 0.1, "steps": 1, "bodies": [{"postion": [0, 0], "shapes": [_SHAPE]}]},
        ("/bodies/0", "additionalProperties")),
    "unknown key in a load": (
        {"dt": 0.1, "steps": 1,
         "bodies": [{"shapes": [_SHAPE], "loads": {"torque": {"kind": "constant", "valu": 1}}}]},
        ("/bodies/0/loads/torque", "additionalProperties")),
    "unknown key in a generator": (
        {"dt": 0.1, "steps": 1, "bodies": [{"generator": "pyramid", "bsae": 3}]},
        ("/bodies/0", "additionalProperties")),
    "unknown key in a rain container": (
        {"dt": 0.1, "steps": 1,
         "bodies": [{"generator": "rain", "count": 1, "container": {"widht": 4}}]},
        ("/bodies/0/container", "additionalProperties")),
    "dynamic body without shape or mass": (
        {"dt": 0.1, "steps": 1, "bodies": [{"name": "a"}]}, ("/bodies/0", "required")),
    "a loop of two points": (
        {"dt": 0.1, "steps": 1, "bodies": [{"type": "static", "shapes": [
            {"type": "chain", "points": [[0, 0], [1, 0]], "loop": True}]}]},
        ("/bodies/0/shapes/0/points", "minItems")),
    "unknown key in a chain": (
        {"dt": 0.1, "steps": 1, "bodies": [{"type": "static", "shapes": [
            {"type": "chain", "points": [[0, 0], [1, 0]], "closed": True}]}]},
        ("/bodies/0/shapes/0", "additionalProperties")),
    "bullet not a boolean": (
        {"dt": 0.1, "steps": 1, "bodies": [{"bullet": 1, "shapes": [_SHAPE]}]},
        ("/bodies/0/bullet", "type")),
    "accepted: every shape kind, a bullet, a dynamic body of a segment with a mass": (
        {"dt": 0.1, "steps": 1,
         "bodies": [{"type": "static", "shapes": [
             {"type": "chain", "points": [[4, 0], [0, 0], [-4, 1]]},
             {"type": "chain", "points": [[0, 0], [1, 0], [0, 1]], "loop": True,
              "material": {"friction": 0.5}, "filter": {"mask_bits": 3}},
             {"type": "chain_segment", "ghost1": [-1, 0], "point1": [0, 0], "point2": [1, 0],
              "ghost2": [2, 0]},
             {"type": "segment", "point1": [0, 2], "point2": [3, 2], "sensor": True}]},
                    {"bullet": True, "shapes": [
                        {"type": "capsule", "center1": [0, 0], "center2": [1, 0], "radius": 0.2},
                        {"type": "segment", "point1": [0, 0], "point2": [1, 1]}]},
                    {"mass": 1, "shapes": [{"type": "segment", "point1": [0, 0], "point2": [1, 0]}]}]},
        None),
    "dt fraction string with a typo": (
        {"dt": "1:60", "steps": 1, "bodies": []}, ("/dt", "pattern")),
    "accepted: static body without shapes, dt \"-1/-60\", steps 10.0, constant load number": (
        {"dt": "-1/-60", "steps": 10.0,
         "bodies": [{"type": "static"},
                    {"mass": 2, "loads": {"force_x": 3, "torque": {"kind": "ramp", "t1": 1,
                                                                   "to": 2}}}]},
        None),
}


def pointer(path):
    """RFC 6901 pointer of a jsonschema error path."""
    return "".join("/" + str(p).replace("~", "~0").replace("/", "~1") for p in path)


def all_errors(validator, instance):
    """Every error, including those nested in the context of anyOf/oneOf errors."""
    stack = list(validator.iter_errors(instance))
    out = []
    while stack:
        e = stack.pop()
        out.append(e)
        stack.extend(e.context or [])
    return out


def undescribed_properties(schema, where="#"):
    """Places of property definitions without a "description" (conditions under if/not are
    tests, not definitions, and are skipped)."""
    missing = []
    if isinstance(schema, dict):
        for key, sub in schema.items():
            if key in ("if", "not"):
                continue
            if key == "properties" and isinstance(sub, dict):
                for name, prop in sub.items():
                    if not (isinstance(prop, dict) and "description" in prop):
                        missing.append(f"{where}/properties/{name}")
            missing += undescribed_properties(sub, f"{where}/{key}")
    elif isinstance(schema, list):
        for i, sub in enumerate(schema):
            missing += undescribed_properties(sub, f"{where}/{i}")
    return missing


def doc_example(markdown):
    """The first ```json block, extracted as apps/cli/doc_example.cmake does."""
    start = markdown.find("```json\n")
    if start == -1:
        raise ValueError("no ```json block")
    rest = markdown[start + 8:]
    end = rest.find("```")
    return rest[:end] if end != -1 else rest


def main(argv):
    if len(argv) != 2:
        print(__doc__.strip().splitlines()[2], file=sys.stderr)
        return 2
    root = pathlib.Path(argv[1])
    passed = failed = 0

    def report(ok, what, detail=""):
        nonlocal passed, failed
        if ok:
            passed += 1
        else:
            failed += 1
        print(f"{'PASS' if ok else 'FAIL'} {what}" + (f": {detail}" if detail else ""))

    schema_path = root / "docs" / "scene.schema.json"
    try:
        schema = json.loads(schema_path.read_text(encoding="utf-8"))
        cls = validator_for(schema)
        cls.check_schema(schema)
        report(True, "docs/scene.schema.json is a valid schema",
               f"{schema.get('$schema')}, jsonschema {importlib.metadata.version('jsonschema')}")
    except (OSError, ValueError, jsonschema.exceptions.SchemaError) as e:
        report(False, "docs/scene.schema.json is a valid schema", str(e).splitlines()[0])
        print(f"{passed} passed, {failed} failed")
        return 1
    missing = undescribed_properties(schema)
    report(not missing, "every property has a description", ", ".join(missing))
    validator = cls(schema)

    def accepts(what, instance):
        errors = sorted(validator.iter_errors(instance), key=lambda e: list(e.path))
        report(not errors, what,
               "; ".join(f"{pointer(e.path) or '(root)'}: {e.message}" for e in errors[:3]))

    def rejects(what, instance, expected):
        want_ptr, want_kw = expected
        errors = all_errors(validator, instance)
        hit = any(pointer(e.path) == want_ptr and e.validator == want_kw for e in errors)
        got = "; ".join(f"{pointer(e.path) or '(root)'} [{e.validator}]" for e in errors[:4])
        report(hit, what,
               f"rejected at {want_ptr or '(root)'} [{want_kw}]" if hit else
               f"expected an error at {want_ptr or '(root)'} [{want_kw}], got: {got or 'none'}")

    # (b) the example scenes and the documentation's complete example
    scenes = sorted((root / "examples" / "scenes").glob("*.json"))
    if not scenes:
        report(False, "examples/scenes/*.json", "no example scenes found")
    for path in scenes:
        name = f"examples/scenes/{path.name}"
        try:
            instance = json.loads(path.read_text(encoding="utf-8"))
        except ValueError as e:
            report(False, name, f"not JSON: {e}")
            continue
        accepts(name, instance)
    try:
        text = (root / "docs" / "scene-format.md").read_text(encoding="utf-8")
        accepts("docs/scene-format.md (complete example)", json.loads(doc_example(text)))
    except (OSError, ValueError) as e:
        report(False, "docs/scene-format.md (complete example)", str(e))

    # (c) the malformed scenes
    malformed_dir = root / "tests" / "io" / "data" / "malformed"
    present = {p.name for p in malformed_dir.glob("*.json")}
    for name in sorted(present | set(SCHEMA_REJECTS)):
        what = f"tests/io/data/malformed/{name}"
        if name in LOADER_ONLY:
            print(f"SKIP {what}: left to the loader: {LOADER_ONLY[name]}")
            continue
        if name not in SCHEMA_REJECTS:
            report(False, what, "not classified: add it to SCHEMA_REJECTS or LOADER_ONLY in "
                   "tests/io/check_scene_schema.py")
            continue
        if name not in present:
            report(False, what, "missing")
            continue
        try:
            instance = json.loads((malformed_dir / name).read_text(encoding="utf-8"))
        except ValueError as e:
            report(False, what, f"not JSON ({e}): move it to LOADER_ONLY")
            continue
        rejects(what, instance, SCHEMA_REJECTS[name])
    for name, (instance, expected) in INLINE.items():
        if expected is None:
            accepts(f"inline: {name}", instance)
        else:
            rejects(f"inline: {name}", instance, expected)

    print(f"{passed} passed, {failed} failed")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
