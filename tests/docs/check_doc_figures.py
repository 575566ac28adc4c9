#!/usr/bin/env python3
"""Checks that the figures README.md, docs/*.md and srs/README.md state are true or are pointers.

    check_doc_figures.py REPO [TAMIAS2D]
    check_doc_figures.py --self-test REPO [TAMIAS2D]

A figure in the docs is one of three things:

  * a fact of the repository (a count of SRS items, a constant of the code, a limit of a
    test, the example scenes): FACTS below names the file, the sentence (a pattern) and how to
    compute the figure from the repository, and the check fails when the two differ or the
    sentence is gone (then the table is out of date);
  * a pointer to a figure the report generates (reports/index.html, reports/data/<program>.json
    by check, table or series name), or to a dated record under verification/bench/results/
    (<machine>/<file>.json#<run>, or `#<run>` after the text names the file): every record must
    be well-formed (verification/bench/results/README.md) and every cited file and run exist;
  * nothing else. A measured figure (a time, a ratio, a share, a size of a run) anywhere else in
    README.md or docs/*.md (docs/srs-errata.md is generated and not read) fails the check. The
    detector looks for numbers followed by a unit of measurement: ms, µs, ns, a speed-up (2.5x),
    %, kB to GB and J, always; seconds, minutes and hours after words that time a run ("took",
    "about", "in all"...). Inline code (`...`) is not read: it holds names and commands. A line
    that states a limit or a design constant in such a unit, and no measurement, is exempt by
    ALLOWED (each entry says why); a line with a measured figure still to be moved is listed in
    KNOWN (each says where it is). An entry that no longer matches a flagged figure fails, so
    both lists only shrink.

TAMIAS2D, the build's `tamias2d` command, counts the example scenes' bodies
(`tamias2d validate`); without it that check fails.

--self-test damages copies of the docs and records in each way the checks must catch (a repository
fact changed, a measured figure added, a record without its commit, a citation of a run that does
not exist, an allowed line removed, the example scenes' table missing a scene) and fails unless
each is reported. Exit status: 0 when every check passes, 1 when one fails, 2 for a bad command
line.
"""
from __future__ import annotations

import glob
import json
import math
import os
import re
import subprocess
import sys

import yaml

RESULTS = "verification/bench/results"


# ------------------------------------------------------------------------------- the repository
class Repo:
    """The repository's files, read once; `docs` may be replaced by damaged copies."""

    def __init__(self, root, tamias=None):
        self.root = root
        self.tamias = tamias
        self._cache = {}
        self.computed = {}
        self.bodies = {}
        self.docs = {}
        for path in ["README.md", "srs/README.md"] + sorted(
                os.path.relpath(p, root) for p in glob.glob(os.path.join(root, "docs", "*.md"))):
            self.docs[path] = self.read(path)
        self.records = {}
        for path in sorted(glob.glob(os.path.join(root, RESULTS, "*", "*.json"))):
            self.records[os.path.relpath(path, root)] = self.read(os.path.relpath(path, root))

    def read(self, path):
        if path not in self._cache:
            with open(os.path.join(self.root, path), encoding="utf-8") as f:
                self._cache[path] = f.read()
        return self._cache[path]

    def find(self, path, pattern, group=1, cast=float):
        """The first match of `pattern` in a source file, its group cast."""
        m = re.search(pattern, self.read(path), re.S | re.M)
        if not m:
            raise LookupError(f"{path}: no match for {pattern!r}")
        return cast(m.group(group))


# -------------------------------------------------------------- (i) facts of the repository
def srs_items(repo):
    if "srs" not in repo.computed:
        items = []
        for path in sorted(glob.glob(os.path.join(repo.root, "srs", "*.yaml"))):
            if os.path.basename(path) in ("errata.yaml", "meta.yaml"):
                continue
            items += yaml.load(open(path, encoding="utf-8"), Loader=getattr(yaml, "CSafeLoader", yaml.SafeLoader)) or []
        repo.computed["srs"] = items
    return repo.computed["srs"]


def srs_counts(repo):
    items = srs_items(repo)
    count = lambda kind: sum(1 for i in items if i["kind"] == kind)  # noqa: E731
    dc = [i["label"] for i in items if i["kind"] == "DC"]
    return (count("GS"), count("A"), count("TM"), count("GD"), count("DD"), count("IM"), len(dc),
            sum(1 for d in dc if d.startswith("DCI_")), sum(1 for d in dc if d.startswith("DCO_")),
            sum(1 for d in dc if d.startswith("DCX_")), count("R"), count("NFR"), count("LC"),
            count("UC"), len(items))


def errata_last(repo):
    ids = [e["id"] for e in yaml.load(open(os.path.join(repo.root, "srs", "errata.yaml")),
                                     Loader=getattr(yaml, "CSafeLoader", yaml.SafeLoader))]
    assert ids == [f"E{k:02d}" for k in range(1, len(ids) + 1)], "errata ids with gaps"
    return (len(ids),)


def expand_labels(text):
    """'GD3, DD17-DD31, IM5-IM7, DCX_damping and DCX_range' as a set of labels."""
    out = set()
    for part in re.split(r",\s*|\s+and\s+", text.strip()):
        m = re.fullmatch(r"([A-Z]+)(\d+)-\1(\d+)", part)
        if m:
            out |= {f"{m.group(1)}{k}" for k in range(int(m.group(2)), int(m.group(3)) + 1)}
        elif part:
            out.add(part)
    return out


def project_items(repo):
    return {i["label"] for i in srs_items(repo) if str(i["source"].get("seed")) == "project"}


def clock_sums(steps_a, rate_a, steps_b, rate_b):
    """World::time() after n steps of 1/rate: t += dt, as the engine accumulates it."""
    def after(n, rate):
        t = 0.0
        for _ in range(n):
            t += 1.0 / rate
        return t
    return after(steps_a, rate_a), after(steps_b, rate_b)


def late_jumps():
    """How many of the GSL scenarios' six step sizes see a load jumping at 0.5 s one step late."""
    late = 0
    for rate in (30, 60, 120, 240, 480, 960):
        t = 0.0
        for _ in range(rate // 2):
            t += 1.0 / rate
        late += t < 0.5
    return late, 6


def output_every_range(repo):
    values = [json.load(open(p)).get("output_every", 0)
              for p in glob.glob(os.path.join(repo.root, "examples", "scenes", "*.json"))]
    values = [v for v in values if v]
    return min(values), max(values)


def player_speeds(repo):
    speeds = [float(v) for v in re.findall(r'<option value="([\d.]+)"',
                                           repo.read("apps/cli/player/player.html"))]
    return min(speeds), max(speeds)


def marked_shares(repo):
    text = repo.read("tests/collision/test_dynamic_tree.cpp")
    body = text[text.index("marked_pairs_equal_brute_force"):]
    shares = [float(x) for x in re.search(r"for \(const double share : \{([^}]*)\}", body).group(1).split(",")]
    return tuple(100 * s for s in shares if 0 < s < 1)


PEER_BENCH = "verification/bench/peer_bench.cpp"
WORK_PRECISION = "verification/bench/work_precision.cpp"
WORLD_DEF = "include/tamias2d/world_def.hpp"


def const(path, name, scale=1.0):
    """A `name = value` (or `name{value}`) constant of a source file, times `scale`."""
    return lambda repo: (repo.find(path, rf"\b{name}\s*=\s*([\d.e+-]+)") * scale,)


def constants(*fns):
    return lambda repo: tuple(v for fn in fns for v in fn(repo))


# Each fact: (file, pattern whose groups are the figures, how the repository gives them, why).
# A pattern may match several sentences; each must agree. A compute returns the figures in group
# order (numbers compare as numbers), or a callable that judges the groups itself.
FACTS = [
    ("srs/README.md",
     r"Counts: GS (\d+), A (\d+), TM (\d+), GD (\d+), DD (\d+), IM (\d+), DC (\d+) \((\d+) input, "
     r"(\d+) output, (\d+) project\), R (\d+),\s+NFR (\d+), LC (\d+), UC (\d+) — (\d+) items",
     srs_counts, "the items of srs/*.yaml by kind"),
    ("srs/README.md", r"errata E01-E(\d+)", errata_last, "srs/errata.yaml, numbered without gaps"),
    ("srs/README.md", r"(\d+) items, of which ((?:[\w-]+,\s+)+[\w-]+\s+and\s+[\w-]+) are the project's",
     lambda repo: (lambda g: (int(g[0]) == len(srs_items(repo)) and expand_labels(g[1]) == project_items(repo),
                              f"{len(srs_items(repo))} items; the project's: {sorted(project_items(repo))}")),
     "the items whose source is the project"),
    ("README.md", r"find_package\(tamias2d (\d+\.\d+) CONFIG",
     lambda repo: (".".join(repo.find("CMakeLists.txt", r"project\(tamias2d VERSION ([\d.]+)", cast=str).split(".")[:2]),),
     "the project's version"),
    ("README.md", r"libtamias2d\.so\.(\d+\.\d+)",
     lambda repo: (".".join(repo.find("CMakeLists.txt", r"project\(tamias2d VERSION ([\d.]+)", cast=str).split(".")[:2]),),
     "the shared library's SONAME follows the version"),
    ("docs/performance.md", r"at most ([\d.]+) times Chipmunk 7's", const(PEER_BENCH, "comparable_limit"),
     "NFR1's check (E56)"),
    ("docs/performance.md", r"Chipmunk 7's ms/step at least (\d+) times", const(PEER_BENCH, "floor_vs_chipmunk"),
     "the floor against Chipmunk 7"),
    ("docs/performance.md", r"Box2D 2\.4's ms/step at least (\d+) times", const(PEER_BENCH, "floor_vs_box2d"),
     "the floor against Box2D 2.4"),
    ("docs/performance.md", r"16 times the bodies cost at most (\d+) times the time",
     const(PEER_BENCH, "scaling_limit"), "the scaling target"),
    ("docs/performance.md", r"\((\d+) s for the scaling series, (\d+) s elsewhere, a quarter with",
     lambda repo: (repo.find(PEER_BENCH, r"make_wide_rain\(name, 1000 \* k\); \}, false, 0, \d+, \d+,\s*([\d.]+), true"),
                   repo.find(PEER_BENCH, r"double budget_s = ([\d.]+);")),
     "the peers' CPU budgets"),
    ("docs/performance.md", r"Tamias2D's,? (\d+) s, guards", const(PEER_BENCH, "tamias_budget_s"),
     "Tamias2D's CPU budget"),
    ("docs/performance.md", r"working sets from ([\d.]+) to (\d+) MiB",
     lambda repo: (lambda v: (v[0], v[-1]))([float(x) for x in repo.find(
         PEER_BENCH, r"sizes_mib\[\] = \{([^}]*)\}", cast=str).split(",")]),
     "the memory probe's working sets"),
    ("docs/performance.md", r"(\d+)\s+ABBA pairs", const(PEER_BENCH, "const int pairs"),
     "the unit-typing check's pairs"),
    ("docs/performance.md", r"at most (\d+) % more instructions",
     const("tests/bench/check_typing_instructions.py", "TOLERANCE", 100), "typing_kernel_same_instructions' limit"),
    ("docs/performance.md", r"from (\d+) MiB on, are mapped\s+directly on (\d+) MiB boundaries",
     lambda repo: (repo.find("src/tamias2d/memory/large_array.cpp", r"large_from = std::size_t\((\d+)\) << 20"),
                   repo.find("src/tamias2d/memory/large_array.cpp", r"huge_page = std::size_t\((\d+)\) << 20")),
     "LargeArray's threshold and alignment"),
    ("docs/user-guide.md", r"arrays of (\d+) MiB and more are mapped from the kernel on (\d+) MiB boundaries",
     lambda repo: (repo.find("src/tamias2d/memory/large_array.cpp", r"large_from = std::size_t\((\d+)\) << 20"),
                   repo.find("src/tamias2d/memory/large_array.cpp", r"huge_page = std::size_t\((\d+)\) << 20")),
     "LargeArray's threshold and alignment"),
    ("docs/performance.md", r"up to\s+(\d+) MiB in all",
     lambda repo: (repo.find("src/tamias2d/memory/retained_blocks.hpp", r"limit = std::size_t\((\d+)\) << 20"),),
     "the retained blocks' limit"),
    ("docs/user-guide.md", r"up to (\d+) MiB in all",
     lambda repo: (repo.find("src/tamias2d/memory/retained_blocks.hpp", r"limit = std::size_t\((\d+)\) << 20"),),
     "the retained blocks' limit"),
    ("docs/performance.md", r"more than 1 in (\d+)\s+\(`regroup_share`\)",
     const("src/tamias2d/dynamics/constraint_graph.hpp", "regroup_share"), "ConstraintGraph's rule"),
    ("docs/design.md", r"more than 1\s+in (\d+) changed group",
     const("src/tamias2d/dynamics/constraint_graph.hpp", "regroup_share"), "ConstraintGraph's rule"),
    ("docs/performance.md", r"Tamias2D up\s+to (\d+) mm", const(WORLD_DEF, "manifold_reuse_distance", 1000),
     "WorldDef's default reuse distance"),
    ("docs/collision.md", r"`manifold_reuse_distance` \(default (\d+) mm\)", const(WORLD_DEF, "manifold_reuse_distance", 1000),
     "WorldDef's default reuse distance"),
    ("docs/performance.md", r"`linear_slop` (\d+) by default", const(WORLD_DEF, "linear_slop"), "WorldDef's default"),
    ("docs/peer-differences.md", r"`linear_slop`, default (\d+)", const(WORLD_DEF, "linear_slop"), "WorldDef's default"),
    ("docs/peer-differences.md", r"\(`contact_hertz` (\d+) Hz", const(WORLD_DEF, "contact_hertz"), "WorldDef's default"),
    ("docs/performance.md", r"`WorldDef` defaults: (\d+) substeps", const(WORLD_DEF, "substeps"), "WorldDef's default"),
    ("docs/performance.md", r"`joint_hertz` (\d+), `joint_damping_ratio`\s+(\d+)",
     constants(const(WORLD_DEF, "joint_hertz"), const(WORLD_DEF, "joint_damping_ratio")), "WorldDef's defaults"),
    ("docs/collision.md", r"read only when in use \((\d+) bytes\)",
     lambda repo: (repo.find("src/tamias2d/dynamics/contacts/contact.hpp", r"sizeof\(Contact\) == (\d+)"),),
     "contact.hpp's static_assert"),
    ("docs/collision.md", r"scan for none, (\d+) %, (\d+) %, (\d+) % and all leaves marked", marked_shares,
     "the shares dynamic_tree/marked_pairs_equal_brute_force marks"),
    ("docs/collision.md", r"taken up to ([\d.]+) marked nodes per moved proxy",
     const("src/tamias2d/collision/broad_phase.hpp", "marks_per_moved_for_descent"), "BroadPhase's threshold"),
    ("docs/viewer.md", r"`output_every` \((\d+) to (\d+) steps\)", output_every_range,
     "the example scenes' non-zero output_every"),
    ("docs/viewer.md", r"from ([\d.]+)x to (\d+)x of simulated time", player_speeds, "the player's speed menu"),
    ("docs/viewer.md", r"a code per (\d+) KiB block",
     lambda repo: (2 ** repo.find("apps/cli/view_deflate.cpp", r"block_size = std::size_t\{1\} << (\d+)") / 1024,),
     "view_deflate.cpp's block"),
    ("docs/viewer.md", r"over (\d+) % of its canvas is drawn",
     lambda repo: (100 * repo.find("tests/viewer/check_player.py", r"if drawn <= ([\d.]+):"),),
     "check_player.py's threshold"),
    ("docs/user-guide.md", r"c = ([\d.]+) halves the speed in\s+about ([\d.]+) s",
     lambda repo: (lambda g: (abs(math.log(2) / float(g[0]) - float(g[1])) < 0.05,
                              f"ln 2 / {g[0]} = {math.log(2) / float(g[0]):.3f} s")),
     "e^(-c t) = 1/2"),
    ("docs/verification.md",
     r"after (\d+) steps of 1/(\d+) s it reads\s+([\d.]+), after (\d+) steps of 1/(\d+) s ([\d.]+)\.",
     lambda repo: (lambda g: (lambda a, b: ((float(g[2]), float(g[5])) == (a, b), f"{a!r} and {b!r}"))(
         *clock_sums(int(g[0]), int(g[1]), int(g[3]), int(g[4])))),
     "IEEE double sums, as World::time() accumulates"),
    ("docs/verification.md", r"\((\d+) of the (\d+) step sizes\s+above would see the 0\.5 s jump one step late\)",
     lambda repo: late_jumps(), "the same sums at 0.5 s"),
    ("docs/verification.md", r"`t \+ (\d+) ns`",
     lambda repo: (1e9 * repo.find("verification/gsl_reference/gsl_reference.hpp", r"clock_guard = ([\d.e-]+);"),),
     "gsl_reference.hpp's clock guard"),
    ("docs/verification.md", r"(?:at most|within) (\d+) % \+ (\d+) MiB",
     lambda repo: (100 / repo.find("tests/fuzz/soak.cpp", r"start \+ start / (\d+) \+"),
                   repo.find("tests/fuzz/soak.cpp", r"\(std::size_t\{(\d+)\} << 20\)")),
     "the soak's memory bound (soak.cpp, soak_busy.cpp alike)"),
    ("docs/verification.md", r"(\d+) s per target",
     lambda repo: (repo.find("scripts/fuzz.sh", r"^seconds=(\d+);"),), "scripts/fuzz.sh's default"),
    ("docs/verification.md", r"a unit slower than (\d+) s",
     lambda repo: (repo.find("scripts/fuzz.sh", r"-timeout=(\d+)"),), "scripts/fuzz.sh's timeout"),
    ("docs/verification.md", r"out-of-memory \(over (\d+) GB\)",
     lambda repo: (repo.find("scripts/fuzz.sh", r"-rss_limit_mb=(\d+)") / 1024,), "scripts/fuzz.sh's memory limit"),
    ("docs/scene-format.md", r"\| scene text \| (\d+) MiB \(`io::max_scene_bytes`",
     lambda repo: (repo.find("include/tamias2d/io/scene.hpp", r"max_scene_bytes = std::size_t\{(\d+)\} << 20"),),
     "io::max_scene_bytes"),
    ("docs/scene-format.md", r"\| bodies in all \| ([\d ]+), written",
     const("include/tamias2d/io/scene.hpp", "max_scene_bodies"), "io::max_scene_bodies"),
    ("docs/scene-format.md", r"\| chain points \| ([\d ]+) in all",
     const("include/tamias2d/io/scene.hpp", "max_chain_points"), "io::max_chain_points"),
    ("docs/traceability.md", r"checks the sum against (\d+) % of the lines",
     const("verification/change_cost/likely_change_cost.py", "LIMIT", 100), "NFR5's limit (E71)"),
    ("docs/traceability.md", r"touched more than (\d+) % of the existing lines",
     const("verification/change_cost/likely_change_cost.py", "LIMIT", 100), "NFR5's limit (E71)"),
    ("docs/traceability.md", r"a target: under (\d+) % of the existing lines",
     const("verification/change_cost/likely_change_cost.py", "EXTRA_LIMIT", 100),
     "issue 44's target for one more joint kind"),
    ("docs/peer-differences.md", r"both kinetic energies below (\d+) % of the\s+initial energy",
     lambda repo: (100 * repo.find("verification/peer_chipmunk/verify_chipmunk.cpp", r"t\.kinetic < ([\d.]+) \* e0"),),
     "verify_chipmunk's pile check"),
]


def as_number(text):
    t = text.replace(" ", "").replace("\u202f", "")
    try:
        return float(t)
    except ValueError:
        return t


def known_spans(path, text):
    """The stretches of a doc that KNOWN lists, with their entries' indices."""
    return [(m.start(), m.end(), k) for k, (p, snippet, _why) in enumerate(KNOWN) if p == path
            for m in re.finditer(re.escape(snippet), text)]


def check_facts(repo):
    """Every FACTS sentence agrees with the repository; a sentence inside a KNOWN line is left
    to that entry (it is to be moved) and spans of checked figures are returned, which the
    detector of measured figures then leaves alone."""
    problems, spans, deferred = [], {}, set()
    for path, pattern, compute, why in FACTS:
        text = repo.docs.get(path)
        if text is None:
            problems.append(f"{path}: no such file (FACTS: {why})")
            continue
        matches = []
        for m in re.finditer(pattern, text):
            inside = [k for s, e, k in known_spans(path, text) if s <= m.start() and m.end() <= e]
            deferred.update(("KNOWN", k) for k in inside)
            if not inside:
                matches.append(m)
        if not matches and any(re.finditer(pattern, text)):
            continue
        if not matches:
            problems.append(f"{path}: the sentence with {why} is gone or reworded; FACTS' pattern "
                            f"{pattern!r} matches nothing (update the table)")
            continue
        try:
            # The sources do not change within a run (the self-test damages docs and records
            # only), so each figure is computed once.
            key = (path, pattern)
            if key not in repo.computed:
                repo.computed[key] = compute(repo)
            expected = repo.computed[key]
        except (LookupError, OSError, subprocess.CalledProcessError) as e:
            problems.append(f"{path}: cannot compute {why}: {e}")
            continue
        for m in matches:
            line = text.count("\n", 0, m.start()) + 1
            spans.setdefault(path, []).append((m.start(), m.end()))
            if callable(expected):
                ok, said = expected(m.groups())
                if not ok:
                    problems.append(f"{path}:{line}: \"{m.group(0)}\" disagrees with {why}: {said}")
                continue
            got = tuple(as_number(g) for g in m.groups())
            want = tuple(as_number(str(v)) if not isinstance(v, (int, float)) else float(v) for v in expected)
            if got != want:
                problems.append(f"{path}:{line}: \"{m.group(0)}\" says {got}; {why} gives {want}")
    return problems, spans, deferred


def check_example_scenes(repo):
    """scene-format.md's table of example scenes: one row per examples/scenes/*.json, in any
    order, each with the bodies `tamias2d validate` counts."""
    text = repo.docs["docs/scene-format.md"]
    section = text[text.index("## The example scenes"):]
    section = section[:section.index("\n## ", 4)]
    rows = dict(re.findall(r"^\| `([\w.]+\.json)` \|.*\| (\d+) \|$", section, re.M))
    files = sorted(os.path.basename(p) for p in glob.glob(os.path.join(repo.root, "examples", "scenes", "*.json")))
    problems = [f"docs/scene-format.md: example scene {f} has no row in \"The example scenes\"" for f in files if f not in rows]
    problems += [f"docs/scene-format.md: \"The example scenes\" lists {f}, which examples/scenes/ lacks" for f in rows if f not in files]
    if not repo.tamias or not os.access(repo.tamias, os.X_OK):
        return problems + [f"the tamias2d command ({repo.tamias}) is needed to count the example scenes' bodies"]
    for f in files:
        if f not in rows:
            continue
        if f not in repo.bodies:
            out = subprocess.run([repo.tamias, "validate", os.path.join(repo.root, "examples", "scenes", f)],
                                 capture_output=True, text=True)
            m = re.search(r"OK: (\d+) bodies", out.stdout)
            repo.bodies[f] = int(m.group(1)) if m else None
        if repo.bodies[f] is None:
            problems.append(f"tamias2d validate {f} printed no body count")
        elif int(rows[f]) != repo.bodies[f]:
            problems.append(f"docs/scene-format.md: {f} has {rows[f]} bodies in the table; tamias2d "
                            f"validate counts {repo.bodies[f]}")
    return problems


# ------------------------------------------------- (ii) measured figures outside the allowed forms
UNIT_ALWAYS = r"(?:ms|µs|us|ns|%|per\s?cent|kB|KB|KiB|MB|MiB|GB|GiB|J|kJ|mJ)"
UNIT_TIMED = r"(?:s|sec|seconds?|min|minutes?|hours?)"
NUMBER = r"(?<![\w/.^=-])\d[\d ,.]*\d(?:-\d[\d.]*)?|(?<![\w/.^=-])\d(?:-\d[\d.]*)?"
ALWAYS = re.compile(rf"({NUMBER})\s?{UNIT_ALWAYS}(?![\w/^])")
SPEEDUP = re.compile(r"(?<![\w.])\d+(?:\.\d+)?x(?![\w])")
TIMED = re.compile(rf"\b(?:took|takes|take|taking|lasts|lasted|ran|spent|about|~|in all|of CPU|wall)"
                   rf"[^.;:()`|]{{0,20}}?(?<![=/])\s({NUMBER})\s?{UNIT_TIMED}(?![\w/^])"
                   rf"|({NUMBER})\s?{UNIT_TIMED}\s(?:per (?:built|run|step|mutant|target run)|each|of CPU|of wall)\b")

# Lines that state a limit or a design constant in a unit the detector reads, not a measurement.
ALLOWED = [
    ("docs/traceability.md", "by more than the noise band, 10 % relative by default (`--noise`)",
     "diff_reports.py's default noise band: a setting of the tool, not a measurement"),
    ("docs/peer-differences.md", "10 % of the overlap beyond the slop per 1/60 s",
     "Chipmunk's collisionBias default: a constant of the peer, from its source"),
    ("docs/verification.md", "after the last is at most 1 MiB above its value after the first 1000 (one leaked allocation per world, 32 bytes or more, would add 3 MiB)",
     "the churn test's bound, and what one leak per world would add to it (arithmetic)"),
    ("docs/verification.md", "check \"at least 90 % of the non-equivalent mutants killed\" applies the floor",
     "the mutation check's stated target, not a score"),
    ("docs/verification.md", "under 1 MiB, must validate and step once within 10 s of CPU time and 2 GiB of the library's",
     "the resource oracle's bounds (tests/fuzz/test_fuzz_scenes.cpp): limits of a test, not measurements"),
]

# Lines that still carry a measured figure outside the allowed forms; each is to be moved to a
# record or a report pointer, and leaves this list when it is.
KNOWN = []


def strip_code(line):
    """The line without inline code spans (names and commands), same length."""
    return re.sub(r"`[^`]*`", lambda m: " " * len(m.group(0)), line)


def measured_figures(path, text):
    """(line number, line, start, end) of every figure the detector reads in a doc."""
    hits, offset = [], 0
    for n, line in enumerate(text.split("\n"), 1):
        plain = strip_code(line)
        for rx in (ALWAYS, SPEEDUP, TIMED):
            for m in rx.finditer(plain):
                group = next((g for g in range(1, (m.lastindex or 0) + 1) if m.group(g)), 0) if rx is TIMED else 0
                hits.append((n, line, offset + m.start(group), offset + (m.end(group) if group == 0 else m.end())))
        offset += len(line) + 1
    return hits


def check_measured(repo, fact_spans, deferred=()):
    problems, used = [], {key: True for key in deferred}
    for path, text in repo.docs.items():
        if path == "docs/srs-errata.md" or path == "srs/README.md":
            continue
        exempt = [(s, e, None) for s, e in fact_spans.get(path, [])]
        for kind, entries in (("ALLOWED", ALLOWED), ("KNOWN", KNOWN)):
            for k, (p, snippet, _why) in enumerate(entries):
                if p != path:
                    continue
                for m in re.finditer(re.escape(snippet), text):
                    exempt.append((m.start(), m.end(), (kind, k)))
        for n, line, start, end in measured_figures(path, text):
            cover = [key for s, e, key in exempt if s <= start and end <= e]
            if not cover:
                problems.append(f"{path}:{n}: a measured figure, \"{text[start:end].strip()}\": state it as "
                                f"a pointer to the report's figure or to a dated record under {RESULTS}/ "
                                f"(or, for a limit or a design constant, add it to FACTS or ALLOWED): {line.strip()}")
            for key in cover:
                if key:
                    used[key] = True
    for kind, entries in (("ALLOWED", ALLOWED), ("KNOWN", KNOWN)):
        for k, (p, snippet, why) in enumerate(entries):
            if not used.get((kind, k)):
                problems.append(f"{kind} entry no longer exempts a figure in {p} (\"{snippet}\": {why}): "
                                f"remove it")
    return problems


# ----------------------------------------------------------------------- records and citations
HEX40 = re.compile(r"[0-9a-f]{40}")


def check_records(repo):
    problems, ids = [], {}
    for path, text in repo.records.items():
        where = f"{path}"
        try:
            doc = json.loads(text)
        except ValueError as e:
            problems.append(f"{where}: not JSON: {e}")
            continue
        machine_dir = path.split("/")[-2]
        m = doc.get("machine", {})
        if doc.get("format") != "tamias2d-record-1":
            problems.append(f"{where}: format is not tamias2d-record-1")
        if not doc.get("title"):
            problems.append(f"{where}: no title")
        if m.get("name") != machine_dir:
            problems.append(f"{where}: machine.name {m.get('name')!r} is not its directory {machine_dir!r}")
        if not m.get("cpu") or not isinstance(m.get("cores"), int) or m.get("cores", 0) < 1:
            problems.append(f"{where}: the machine names no CPU model or no number of cores")
        runs = doc.get("runs") or []
        if not runs:
            problems.append(f"{where}: no runs")
        seen = set()
        for r in runs:
            rid = r.get("id", "?")
            at = f"{where}#{rid}"
            if rid in seen:
                problems.append(f"{at}: run id repeated")
            seen.add(rid)
            for key in ("what", "date", "command", "stated_from"):
                if not r.get(key):
                    problems.append(f"{at}: no {key}")
            if r.get("commit") is None:
                if not r.get("commit_note"):
                    problems.append(f"{at}: no commit, and no commit_note saying why")
            elif not HEX40.fullmatch(str(r["commit"])):
                problems.append(f"{at}: commit {r['commit']!r} is not a 40-digit hash")
            if r.get("stated_from") and not HEX40.fullmatch(str(r["stated_from"])):
                problems.append(f"{at}: stated_from is not a 40-digit hash")
            if r.get("date") and not re.fullmatch(r"\d{4}-\d\d-\d\d", str(r["date"])):
                problems.append(f"{at}: date {r['date']!r} is not YYYY-MM-DD")
            if not r.get("tables") and not r.get("figures"):
                problems.append(f"{at}: neither tables nor figures")
            for t in r.get("tables", []):
                if not t.get("name") or not t.get("columns"):
                    problems.append(f"{at}: a table without name or columns")
                for row in t.get("rows", []):
                    if len(row) != len(t.get("columns", [])):
                        problems.append(f"{at}: table \"{t.get('name')}\" has a row of {len(row)} cells "
                                        f"for {len(t.get('columns', []))} columns")
            for f in r.get("figures", []):
                if "what" not in f or "value" not in f:
                    problems.append(f"{at}: a figure without what or value")
        ids[path] = seen
    return problems, ids


CITATION = re.compile(r"(?:verification/bench/)?results/([\w.-]+)/([\w.-]+\.json)(?:#([\w.-]+))?")
BARE = re.compile(r"`#([a-z0-9]+(?:-[a-z0-9]+)+)`")


def check_citations(repo, ids):
    problems = []
    every_id = set().union(*ids.values()) if ids else set()
    for path, text in repo.docs.items():
        for m in CITATION.finditer(text):
            line = text.count("\n", 0, m.start()) + 1
            record = f"{RESULTS}/{m.group(1)}/{m.group(2)}"
            if record not in ids:
                problems.append(f"{path}:{line}: cites {record}, which is no record")
            elif m.group(3) and m.group(3) not in ids[record]:
                problems.append(f"{path}:{line}: cites run {m.group(3)} of {record}, which has none")
        for m in BARE.finditer(text):
            if m.group(1) not in every_id:
                line = text.count("\n", 0, m.start()) + 1
                problems.append(f"{path}:{line}: cites run #{m.group(1)}, which no record has")
    # The benchmark's figures are cited by name: every name "Reading the figures" quotes is one
    # the benchmark writes.
    perf = repo.docs.get("docs/performance.md", "")
    if "## Reading the figures" in perf:
        section = perf[perf.index("## Reading the figures"):]
        section = section[:section.index("\n## ", 4)]
        flat = re.sub(r"\"\s*\n\s*\"", "", repo.read(PEER_BENCH))  # adjacent literals joined
        for name in re.findall(r"\"([^\"]+)\"", section):
            name = re.sub(r"\s+", " ", name)
            if name not in flat:
                problems.append(f"docs/performance.md: \"Reading the figures\" names \"{name}\", which "
                                f"{PEER_BENCH} does not write")
    # So are the work-precision diagrams' tables, where that section says where its figures are
    # ("<scene>" stands for each scene's name).
    where = "**Where the figures are**"
    if "## Work-precision diagrams" in perf and where in perf:
        section = perf[perf.index(where):]
        section = section[:section.index("\n\n")]
        flat = re.sub(r"\"\s*\n\s*\"", "", repo.read(WORK_PRECISION))
        for name in re.findall(r"\"([^\"]+)\"", section):
            name = re.sub(r"\s+", " ", name)
            if name.split("<")[0] not in flat:
                problems.append(f"docs/performance.md: \"{where}\" names \"{name}\", which "
                                f"{WORK_PRECISION} does not write")
    return problems


# ---------------------------------------------------------------------------------- the checks
def check(repo):
    problems, spans, deferred = check_facts(repo)
    problems += check_example_scenes(repo)
    problems += check_measured(repo, spans, deferred)
    record_problems, ids = check_records(repo)
    problems += record_problems
    problems += check_citations(repo, ids)
    return problems


def self_test(repo):
    """Each damage must be reported; the repository as it is must pass."""
    failures = []
    if check(repo):
        failures.append("the repository as it is fails the checks")
    first_record = next(iter(repo.records))
    record = json.loads(repo.records[first_record])
    no_commit = json.loads(json.dumps(record))
    no_commit["runs"][0]["commit"] = None
    no_commit["runs"][0].pop("commit_note", None)
    damages = {
        "an SRS count changed": ("docs", "srs/README.md", lambda t: re.sub(r"DD (\d+), IM", lambda m: f"DD {int(m.group(1)) + 1}, IM", t, 1)),
        "a code constant changed": ("docs", "docs/performance.md", lambda t: t.replace("up to\n  64 MiB in all", "up to\n  32 MiB in all", 1).replace("up to 64 MiB in all", "up to 32 MiB in all", 1)),
        "a repository-fact sentence reworded": ("docs", "docs/viewer.md", lambda t: t.replace("a code per 256 KiB block", "a code per block", 1)),
        "a time added": ("docs", "docs/design.md", lambda t: t.replace("## Layers\n", "## Layers\n\nA pyramid of 820 boxes steps in 0.43 ms.\n", 1)),
        "a speed-up added": ("docs", "README.md", lambda t: t.replace("## Layout\n", "## Layout\n\nTamias2D runs 2.7x faster than Chipmunk.\n", 1)),
        "a share added": ("docs", "docs/collision.md", lambda t: t.replace("## Conventions\n", "## Conventions\n\nThe narrow phase is 17 % of the step.\n", 1)),
        "a run's duration added": ("docs", "docs/viewer.md", lambda t: t.replace("## Limits\n", "## Limits\n\nThe stage took about 20 s.\n", 1)),
        "an allowed line removed": ("docs", "docs/peer-differences.md", lambda t: t.replace("10 % of the overlap beyond the slop per 1/60 s", "a tenth of the overlap beyond the slop per 1/60 s", 1)),
        "a record without its commit": ("records", first_record, lambda t: json.dumps(no_commit)),
        "a record's machine without cores": ("records", first_record, lambda t: t.replace('"cores": 2', '"cores": "two"', 1)),
        "a citation of a run no record has": ("docs", "docs/performance.md", lambda t: t.replace("#wide-packs", "#narrow-packs", 1)),
        "a citation of a record that does not exist": ("docs", "docs/performance.md", lambda t: t.replace("joint-scenes.json", "joint-scene.json", 1)),
        "an example scene missing from the table": ("docs", "docs/scene-format.md", lambda t: re.sub(r"^\| `free_fall\.json` \|.*\n", "", t, count=1, flags=re.M)),
        "an example scene's bodies miscounted": ("docs", "docs/scene-format.md", lambda t: re.sub(r"^(\| `pyramid20\.json` \|.*\| )211 \|$", r"\g<1>212 |", t, count=1, flags=re.M)),
    }
    for what, (where, path, damage) in damages.items():
        store = repo.docs if where == "docs" else repo.records
        original = store[path]
        damaged = damage(original)
        if damaged == original:
            failures.append(f"{what}: the damage did not apply")
            continue
        store[path] = damaged
        try:
            reported = check(repo)
        finally:
            store[path] = original
        if not reported:
            failures.append(f"{what}: not reported")
        else:
            print(f"self-test: {what}: reported ({reported[0][:110]})")
    return failures


def main(argv):
    args = argv[1:]
    test = args[:1] == ["--self-test"]
    if test:
        args = args[1:]
    if not 1 <= len(args) <= 2:
        print(__doc__, file=sys.stderr)
        return 2
    repo = Repo(args[0], args[1] if len(args) > 1 else None)
    problems = self_test(repo) if test else check(repo)
    for p in problems:
        print(f"check_doc_figures: {p}")
    if problems:
        return 1
    print(f"check_doc_figures: {'self-test passed' if test else 'OK'}: {len(FACTS)} facts, "
          f"{len(repo.docs)} docs, {len(repo.records)} records, {len(ALLOWED)} allowed and "
          f"{len(KNOWN)} known lines")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
