"""The mutation tool's own test, without building the project: which mutants a fragment of C++
yields, how they are judged, scored, sharded and merged (builds and tests mocked), the test
runner on made-up executables and the restoring of a made-up CMake project's build. Each class
names its oracle; the first: the mutants of each hand-written line, listed by hand."""
import contextlib
import io
import json
import os
import re
import shutil
import sys
import tempfile
import unittest
from unittest import mock

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import mutate  # noqa: E402


def ops(code):
    return [(m["line"], m["op"], m["after"].strip()) for m in mutate.mutants_of("f.hpp", code)]


class Mutants(unittest.TestCase):
    def test_operators(self):
        self.assertEqual(ops("    return a + b * c;"),
                         [(1, "arith + to -", "return a - b * c;"),
                          (1, "arith * to /", "return a + b / c;")])
        self.assertEqual(ops("    if (x <= y)"), [(1, "compare <= to <", "if (x < y)")])

    def test_constants_and_removed_statements(self):
        got = ops("    v.x = 0.5 * w;")
        self.assertIn((1, "constant 0.5 to 1.0", "v.x = 1.0 * w;"), got)
        self.assertIn((1, "statement removed", ""), got)
        self.assertIn((1, "constant 0.0 to 1.0", "z = 1.0;"), ops("    z = 0.0;"))
        # A declaration is not removed (the mutant would not compile).
        self.assertNotIn("statement removed", [o for _, o, _ in ops("    const double k = a;")])

    def test_what_is_left_alone(self):
        for code in ("// a + b", "    x++;", "#include <a>", "template <class V> V f();",
                     '    s = "a + b";', "/* a\n   + b */", "    p->q;"):
            with self.subTest(code=code):
                self.assertEqual([o for o in ops(code) if not o[1].startswith("statement")], [])

    def test_labels_and_listing(self):
        with tempfile.TemporaryDirectory() as root:
            d = os.path.join(root, "src/tamias2d/model")
            os.makedirs(d)
            os.makedirs(os.path.join(root, "src/tamias2d/dynamics"))
            with open(os.path.join(d, "x.hpp"), "w") as fh:
                fh.write("/// \\\\srs{DD8, IM3} j\ninline double j(double a) { return -a * 2.0; }\n")
            self.assertEqual(mutate.labels_of(root, "src/tamias2d/model/x.hpp"), ["DD8", "IM3"])
            # A file without tags takes those of the headers it includes.
            with open(os.path.join(root, "src/tamias2d/dynamics/y.cpp"), "w") as fh:
                fh.write('#include "tamias2d/model/x.hpp"\nint y;\n')
            self.assertEqual(mutate.labels_of(root, "src/tamias2d/dynamics/y.cpp"), ["DD8", "IM3"])
            muts = mutate.all_mutants(root)
            self.assertEqual([m["op"] for m in muts], ["arith * to /", "constant 2.0 to 4.0"])
            self.assertEqual([m["id"] for m in muts], [0, 1])  # y.cpp has nothing to mutate

    def test_untagged_file_takes_its_users_labels(self):
        with tempfile.TemporaryDirectory() as root:
            d = os.path.join(root, "src/tamias2d/dynamics")
            os.makedirs(d)
            os.makedirs(os.path.join(root, "src/tamias2d/model"))
            with open(os.path.join(d, "store.hpp"), "w") as fh:
                fh.write("struct Store { int n = 0; };\n")
            with open(os.path.join(d, "store.cpp"), "w") as fh:
                fh.write('#include "tamias2d/dynamics/store.hpp"\nint f() { return 1 + 2; }\n')
            with open(os.path.join(d, "solver.cpp"), "w") as fh:
                fh.write('/// \\srs{IM7} soft\n#include "tamias2d/dynamics/store.hpp"\n')
            # Neither reaches a tag; solver.cpp includes the header: its labels are theirs.
            self.assertEqual(mutate.labels_of(root, "src/tamias2d/dynamics/store.hpp"), ["IM7"])
            self.assertEqual(mutate.labels_of(root, "src/tamias2d/dynamics/store.cpp"), ["IM7"])
            self.assertEqual(mutate.labels_of(root, "src/tamias2d/dynamics/solver.cpp"), ["IM7"])


class Scratch(unittest.TestCase):
    """Oracle: sync_tree's promise, checked file by file on a made-up tree."""

    def test_sync_keeps_matching_files_and_rewrites_the_rest(self):
        with tempfile.TemporaryDirectory() as root, tempfile.TemporaryDirectory() as dest:
            os.makedirs(os.path.join(root, "src"))
            os.makedirs(os.path.join(root, "build"))
            for rel, text in (("src/a.hpp", "a"), ("src/b.cpp", "b"), ("build/x.o", "x"),
                              ("src/build_info.hpp", "i")):
                with open(os.path.join(root, rel), "w") as fh:
                    fh.write(text)
            mutate.sync_tree(root, dest)
            self.assertFalse(os.path.exists(os.path.join(dest, "build")))  # ignored
            # A source named build_* below the top is a source, not a build.
            self.assertTrue(os.path.isfile(os.path.join(dest, "src/build_info.hpp")))
            # a.hpp restored after a mutant (same bytes, a later time); b.cpp left mutated;
            # a file root no longer has.
            os.utime(os.path.join(dest, "src/a.hpp"), ns=(4 * 10**18, 4 * 10**18))
            with open(os.path.join(dest, "src/b.cpp"), "w") as fh:
                fh.write("mutant")
            os.utime(os.path.join(dest, "src/b.cpp"), ns=(10**18, 10**18))
            with open(os.path.join(dest, "src/gone.cpp"), "w") as fh:
                fh.write("g")
            mutate.sync_tree(root, dest)
            self.assertEqual(os.stat(os.path.join(dest, "src/a.hpp")).st_mtime_ns, 4 * 10**18)
            with open(os.path.join(dest, "src/b.cpp")) as fh:
                self.assertEqual(fh.read(), "b")
            self.assertGreater(os.stat(os.path.join(dest, "src/b.cpp")).st_mtime_ns, 10**18)
            self.assertFalse(os.path.exists(os.path.join(dest, "src/gone.cpp")))


class Sampling(unittest.TestCase):
    """Oracle: the sampling rule's promise, checked on made-up files: an edit to one line
    changes the sample only by that line's mutants."""

    def test_an_edit_elsewhere_leaves_the_sample(self):
        lines = [f"    x{k} = a{k} + b{k} * c{k};" for k in range(40)]
        before = mutate.mutants_of("f.cpp", "\n".join(lines))
        lines[7] = "    y = p - q;"
        after = mutate.mutants_of("f.cpp", "\n".join(["    // a new first line"] + lines))
        for muts in (before, after):
            for i, m in enumerate(muts):
                m["id"] = i
        key = lambda m: (m["before"].strip(), m["op"])
        edited = {key(m) for m in before if "x7 " in m["before"]}
        edited |= {key(m) for m in after if "y = " in m["before"]}
        for n in (5, 20, 60):
            a = {key(m) for m in mutate.sample_of(before, n, 3)} - edited
            b = {key(m) for m in mutate.sample_of(after, n, 3)} - edited
            with self.subTest(n=n):
                # The unedited lines' mutants rank as before: one sample holds the other's
                # up to the places the edited line's mutants take or free.
                self.assertLessEqual(len(a ^ b), 2 * 3)
        self.assertNotEqual({key(m) for m in mutate.sample_of(before, 20, 3)},
                            {key(m) for m in mutate.sample_of(before, 20, 4)})
        self.assertEqual(mutate.sample_of(before, 20, 3), mutate.sample_of(before, 20, 3))


class Scoring(unittest.TestCase):
    """Oracle: the scoring rule counted by hand on a made-up run."""

    def judgements(self, entries):
        with tempfile.TemporaryDirectory() as d:
            path = os.path.join(d, "survivors.json")
            with open(path, "w") as fh:
                json.dump({"survivors": entries}, fh)
            return mutate.load_judgements(path)

    def test_score_counts_only_survivors_not_judged_equivalent(self):
        def mut(line, verdict):
            return {"file": "f.cpp", "before": f"  x = {line};", "op": "statement removed",
                    "occurrence": 1, "verdict": verdict}
        results = [mut(1, "killed"), mut(2, "killed"), mut(3, "killed"), mut(4, "survived"),
                   mut(5, "survived"), mut(6, "survived"), mut(7, "stillborn"),
                   mut(8, "no tests")]
        j = self.judgements([
            {"file": "f.cpp", "line": "x = 4;", "op": "statement removed", "occurrence": 1,
             "verdict": "equivalent", "reason": "x is never read"},
            {"file": "f.cpp", "line": "x = 5;", "op": "statement removed", "occurrence": 1,
             "verdict": "gap", "reason": "no test reads x"}])
        # 3 killed; survivors 4 (equivalent, out), 5 (gap, in), 6 (not judged, in): 3 / 5.
        self.assertEqual(mutate.score_of(results, j), (3 / 5, 3, 1, 5))
        self.assertEqual(mutate.score_of(results, {}), (3 / 6, 3, 0, 6))
        # Keyed by the line's text, not its number or id: the judgement follows the line.
        self.assertIn(mutate.survivor_key(mut(4, "survived")), j)

    def test_one_judgement_stands_for_one_mutant(self):
        # The same loop twice in a file, and a line with the operator twice: four mutants of
        # one line text and operator pair or another, told apart by their occurrence.
        code = ("    for (int l = 0; l < n; ++l) {\n    }\n    y = a + b + c;\n"
                "    for (int l = 0; l < n; ++l) {\n    }\n")
        muts = [m for m in mutate.mutants_of("f.cpp", code) if m["op"].startswith(("compare <",
                                                                                  "arith +"))]
        self.assertEqual([(m["line"], m["op"], m["occurrence"]) for m in muts],
                         [(1, "compare < to <=", 1), (3, "arith + to -", 1),
                          (3, "arith + to -", 2), (4, "compare < to <=", 2)])
        self.assertEqual([m["after"].strip() for m in muts[1:3]],
                         ["y = a - b + c;", "y = a + b - c;"])
        j = self.judgements([{"file": "f.cpp", "line": "for (int l = 0; l < n; ++l) {",
                              "op": "compare < to <=", "occurrence": 2, "verdict": "equivalent",
                              "reason": "the second loop's stray pass reads nothing"}])
        results = [dict(m, verdict="survived") for m in muts if m["op"] == "compare < to <="]
        # The judgement covers the second loop only: the first survivor still counts.
        self.assertEqual(mutate.score_of(results, j), (0.0, 0, 1, 1))
        # An occurrence past the last such mutant of the file is stale.
        stale = self.judgements([{"file": "f.cpp", "line": "y = a + b + c;",
                                  "op": "arith + to -", "occurrence": 3, "verdict": "gap",
                                  "reason": "r"}])
        self.assertEqual(mutate.stale_judgements(stale, muts),
                         [("f.cpp", "y = a + b + c;", "arith + to -", 3)])
        self.assertEqual(mutate.stale_judgements(j, muts), [])
        # A survivor of the reference analysis is judged for the reference's tree: its record
        # is not stale where its line changed since, but a key the reference killed is.
        gone = ("f.cpp", "y = a * b;", "arith * to /", 1)
        changed = self.judgements([{"file": gone[0], "line": gone[1], "op": gone[2],
                                    "occurrence": 1, "verdict": "gap", "reason": "r"}])
        self.assertEqual(mutate.stale_judgements(changed, muts), [gone])
        self.assertEqual(mutate.stale_judgements(changed, muts, {gone}), [])
        self.assertEqual(mutate.stale_judgements(stale, muts, {gone}),
                         [("f.cpp", "y = a + b + c;", "arith + to -", 3)])

    def test_malformed_judgement_is_an_error(self):
        good = {"file": "f", "line": "x", "op": "o", "occurrence": 1, "verdict": "gap",
                "reason": "r"}
        for bad in (dict(good, verdict="maybe"), dict(good, reason=" "),
                    {k: v for k, v in good.items() if k != "reason"},
                    {k: v for k, v in good.items() if k != "occurrence"},  # keyed by line only
                    dict(good, occurrence=0), dict(good, occurrence="1"),
                    dict(good, occurrence=True), dict(good, ocurrence=2)):
            with self.subTest(bad=bad), self.assertRaises(SystemExit):
                self.judgements([bad])
        with self.assertRaises(SystemExit):  # the same key twice
            self.judgements([good, good])
        self.assertEqual(len(self.judgements([good, dict(good, occurrence=2)])), 2)

    def test_a_gap_names_the_tests_that_close_it_by_their_report_ids(self):
        good = {"file": "f", "line": "x", "op": "o", "occurrence": 1, "verdict": "gap",
                "reason": "r", "closed_by": ["engine_tests:suite/case", "x-tests:a/b/c"]}
        self.assertEqual(self.judgements([good])[("f", "x", "o", 1)]["closed_by"],
                         good["closed_by"])
        for bad in (dict(good, verdict="equivalent"),  # nothing to close
                    dict(good, closed_by=[]), dict(good, closed_by="engine_tests:suite/case"),
                    dict(good, closed_by=["suite/case"]),  # no executable
                    dict(good, closed_by=["engine_tests:case"]),  # no suite
                    dict(good, closed_by=["engine_tests:suite/case "])):
            with self.subTest(bad=bad), self.assertRaises(SystemExit):
                self.judgements([bad])

    def test_the_reference_survivors_are_read_from_its_file(self):
        # Only the survivors: a killed or stillborn mutant of the reference needs no record.
        row = {"file": "f.cpp", "before": "  y = a * b;", "op": "arith * to /", "occurrence": 1}
        with tempfile.TemporaryDirectory() as root:
            self.assertEqual(mutate.reference_survivors(root), set())
            path = os.path.join(root, mutate.REFERENCE)
            os.makedirs(os.path.dirname(path))
            with open(path, "w", encoding="utf-8") as fh:
                json.dump({"mutants": [dict(row, verdict="survived"),
                                       dict(row, occurrence=2, verdict="killed"),
                                       dict(row, occurrence=3, verdict="stillborn")]}, fh)
            self.assertEqual(mutate.reference_survivors(root),
                             {("f.cpp", "y = a * b;", "arith * to /", 1)})

    def test_the_repository_record_is_well_formed(self):
        # Every judged survivor names a mutant of this tree: its line text in its file with a
        # mutant of that operator, and at least as many of them as its occurrence. A record
        # that no mutant reaches any more is stale.
        muts = mutate.all_mutants(mutate.ROOT)
        reference = mutate.reference_survivors(mutate.ROOT)
        self.assertEqual(mutate.stale_judgements(mutate.load_judgements(), muts, reference), [])
        mutate.check_record(mutate.SURVIVORS, muts, reference)

    def test_failed_entries_from_a_ctest_log(self):
        log = ("50% tests passed, 1 tests failed out of 2\n\nThe following tests FAILED:\n"
               "\t  7 - engine_tests@IM3 (Failed)\n\t  9 - model_tests@DD8 (Timeout)\n"
               "Errors while running CTest\n")
        self.assertEqual(mutate.failed_entries(log), ["engine_tests@IM3", "model_tests@DD8"])
        self.assertEqual(mutate.failed_entries("100% tests passed"), [])


class Interval(unittest.TestCase):
    """Oracle: the Wilson score intervals (no continuity correction) tabulated by Newcombe,
    Statistics in Medicine 17 (1998) 857-872, Table II, method 3."""

    def test_wilson_interval_against_the_table(self):
        for k, n, lo, hi in ((81, 263, 0.2553, 0.3662), (15, 148, 0.0624, 0.1605),
                             (0, 20, 0.0, 0.1611), (1, 29, 0.0061, 0.1718),
                             (29, 29, 0.8830, 1.0)):
            with self.subTest(k=k, n=n):
                got = mutate.wilson(k, n)
                self.assertAlmostEqual(got[0], lo, places=4)
                self.assertAlmostEqual(got[1], hi, places=4)
        self.assertEqual(mutate.wilson(0, 0), (0.0, 1.0))

    def doc(self, killed, survived, complete):
        results = ([{"id": i, "file": "f.cpp", "line": i, "before": f"x = {i};",
                     "after": "", "op": "statement removed", "occurrence": 1,
                     "verdict": "killed", "labels": ["IM1"], "tests": ["t@IM1"],
                     "seconds": 1.0, "build_seconds": 0.5, "test_seconds": 0.5}
                    for i in range(killed)]
                   + [{"id": 100 + i, "file": "f.cpp", "line": 100 + i,
                       "before": f"y = {i};", "after": "", "op": "statement removed",
                       "occurrence": 1, "verdict": "survived", "labels": ["IM1"],
                       "tests": ["t@IM1"], "seconds": 1.0, "build_seconds": 0.5,
                       "test_seconds": 0.5} for i in range(survived)])
        return mutate.make_doc(results, {}, population=1604, chosen=len(results),
                               selection={"mode": "all"} if complete else
                               {"mode": "sample", "seed": 1, "sample": 1000, "minutes": 4},
                               complete=complete, provenance={}, prep_secs=0.0,
                               sanitizer=None, broken=[])

    def test_the_floor_applies_to_the_lower_bound_of_a_sample(self):
        # 16 of 17 (94 %, interval 73-99 %): a sample misses the floor, every mutant meets it.
        sample, full = self.doc(16, 1, False), self.doc(16, 1, True)
        self.assertEqual(sample["floor_applies_to"], "lower bound")
        self.assertFalse(sample["checks"][0]["passed"])
        self.assertEqual(full["floor_applies_to"], "point estimate")
        self.assertTrue(full["checks"][0]["passed"])
        self.assertAlmostEqual(sample["interval"][0], 0.7302, places=4)
        self.assertEqual((sample["sample_size"], sample["counted"], sample["population"]),
                         (17, 17, 1604))
        self.assertIn("lower bound", sample["checks"][0]["details"])
        self.assertIn("73.0-99.0 %", sample["checks"][0]["figure"])
        # 16 of 18 is below the floor either way; 100 of 101 (lower bound 94.6 %) above it.
        self.assertFalse(self.doc(16, 2, True)["checks"][0]["passed"])
        self.assertTrue(self.doc(100, 1, False)["checks"][0]["passed"])
        sys.path.insert(0, mutate.ROOT)
        from traceability.vvdata import validate
        self.assertEqual(validate(sample), [])


class Judges(unittest.TestCase):
    """Oracle: which tests judge a mutant, and the second judge's rule, on a made-up catalogue
    and made-up test runs (no build)."""

    CATALOGUE = [{"name": n, "properties": [{"name": "LABELS", "value": [n.split("@")[1]]}]}
                 for n in ("model_tests@DD8", "engine_tests@IM3", "engine_tests@R7",
                           "determinism_tests@determinism", "reliability_tests@determinism",
                           "snapshot_tests@determinism", "snapshot_tests@reliability",
                           "events_tests@DD11", "events_tests@reliability",
                           "recording_tests@determinism")]
    GOLDEN = {"determinism_tests@determinism": "determinism_tests",
              "snapshot_tests@determinism": "snapshot_tests",
              "snapshot_tests@reliability": "snapshot_tests",
              "events_tests@DD11": "events_tests", "events_tests@reliability": "events_tests",
              "recording_tests@determinism": "recording_tests"}

    def test_golden_hashes_judge_every_mutant_of_the_model_and_the_dynamics(self):
        for rel in ("src/tamias2d/dynamics/joints/joint_store.cpp", "src/tamias2d/model/x.hpp"):
            with self.subTest(rel=rel):
                self.assertEqual(mutate.entries_of(self.CATALOGUE, ["IM3"], rel),
                                 {"engine_tests@IM3": "engine_tests", **self.GOLDEN})
        # A file with no label is judged by the golden hashes, the snapshot suite and the API
        # suites (every entry of each, its SRS labels' too) alone; a test of another target
        # carrying the same category label (run-to-run repeatability) is not one of them.
        self.assertEqual(mutate.entries_of(self.CATALOGUE, [], "src/tamias2d/dynamics/y.cpp"),
                         self.GOLDEN)
        # A file outside the model and the dynamics: its labels' entries only.
        self.assertEqual(mutate.entries_of(self.CATALOGUE, ["IM3"], "src/tamias2d/io/z.cpp"),
                         {"engine_tests@IM3": "engine_tests"})

    def sanitizer_run(self, asan_log, unmutated_fails=False):
        """SanitizerScratch.judge of a mutant whose tests fail in the sanitizer build with
        asan_log (None: they pass), every build and command mocked."""
        calls = []

        def fake_run(cmd, cwd=None, timeout=None, env=None):
            calls.append((cmd, env))
            return 0, '{"tests": []}'  # configure, build, and ctest's empty listing

        def fake_run_tests(entries, commands, test_timeout, env=None, jobs=2):
            # The unmutated sources, asked when a test kills.
            calls.append(("unmutated", sorted(entries), env))
            return (sorted(entries), "failed") if unmutated_fails else ([], "")

        def fake_judge(m, src, build, entries, test_timeout, objects=None, env=None,
                       **_):
            calls.append(("judge", build, env))
            return ("killed", asan_log, 1.0, 2.0, sorted(entries)) if asan_log and entries \
                else ("survived", "", 1.0, 2.0, [])

        with mock.patch.object(mutate, "run", fake_run), \
                mock.patch.object(mutate, "run_tests", fake_run_tests), \
                mock.patch.object(mutate, "judge", fake_judge):
            s = mutate.SanitizerScratch("/scratch", "/scratch/src")
            out = s.judge({"id": 7}, {"engine_tests@IM3": "engine_tests"}, 60)
        return out, calls, s

    def test_a_sanitizer_report_kills_a_survivor(self):
        log = ("1/1 Test #3: engine_tests@IM3 ...***Failed\n==1==ERROR: AddressSanitizer: "
               "heap-buffer-overflow on address 0x6\nThe following tests FAILED:\n"
               "\t  3 - engine_tests@IM3 (Failed)\n")
        (killed, summary, _, _, failed), calls, s = self.sanitizer_run(log)
        self.assertTrue(killed)
        self.assertEqual(failed, ["engine_tests@IM3"])
        self.assertIn("AddressSanitizer: heap-buffer-overflow", summary)
        judged = [c for c in calls if c[0] == "judge"]
        self.assertEqual(judged[0][1:], ("/scratch/build-asan", mutate.SANITIZER_ENV))
        # Configured lazily, once, with the sanitizers on, and built before the mutant.
        configure = [c[0] for c in calls if c[0][0] == "cmake" and "-S" in c[0]]
        self.assertEqual(len(configure), 1)
        self.assertIn("-DTAMIAS_SANITIZE=ON", configure[0])
        self.assertEqual(s.built, {"engine_tests"})
        # The kill is confirmed on the unmutated sources, in the sanitizer build's setting.
        self.assertIn(("unmutated", ["engine_tests@IM3"], mutate.SANITIZER_ENV), calls)

    def test_no_kill_by_a_test_that_fails_unmutated_or_without_failing(self):
        log = "==1==ERROR: AddressSanitizer: x\nThe following tests FAILED:\n" \
              "\t  3 - engine_tests@IM3 (Failed)\n"
        (killed, _, _, _, _), _, s = self.sanitizer_run(log, unmutated_fails=True)
        self.assertFalse(killed)
        self.assertEqual(s.baseline, {"engine_tests@IM3": False})
        (killed, _, _, _, _), calls, s = self.sanitizer_run(None)
        self.assertFalse(killed)


class Shards(unittest.TestCase):
    """Oracle: a sharded run and its merge give what one run of the same mutants gives (every
    mutant once, the same verdicts and score), on made-up files with the builds and tests
    mocked: a mutant's verdict is a function of its key, as a real build's would be."""

    FILES = {"src/tamias2d/model/a.hpp": "".join(f"    x{k} = a{k} + b{k} * 2.0;\n"
                                                   for k in range(6)),
             "src/tamias2d/dynamics/b.cpp": "    for (int l = 0; l < n; ++l) {\n    }\n" * 3
             + "    y = p - q;\n"}

    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.root = os.path.join(self.tmp.name, "root")
        for rel, text in self.FILES.items():
            os.makedirs(os.path.dirname(os.path.join(self.root, rel)), exist_ok=True)
            with open(os.path.join(self.root, rel), "w") as fh:
                fh.write(text)
        self.record = os.path.join(self.tmp.name, "survivors.json")
        with open(self.record, "w") as fh:
            json.dump({"survivors": [{"file": "src/tamias2d/dynamics/b.cpp",
                                      "line": "for (int l = 0; l < n; ++l) {",
                                      "op": "compare < to <=", "occurrence": 2,
                                      "verdict": "equivalent", "reason": "made up"}]}, fh)
        self.tree = "tree-1"
        self.judged = []
        self.stop_after = None

    def tearDown(self):
        self.tmp.cleanup()

    @staticmethod
    def verdict(m, build):
        h = int(mutate.hashlib.sha256(repr(mutate.survivor_key(m)).encode()).hexdigest(), 16)
        if h % 5 == 0 and build.endswith("build-asan"):
            return "killed"  # a stray read the sanitizer build reports
        return "survived" if h % 5 in (0, 1) else "killed"

    def run_main(self, *args):
        def fake_judge(m, src, build, entries, test_timeout, objects=None, env=None,
                       **_):
            if len(self.judged) == self.stop_after:
                raise KeyboardInterrupt  # the run is stopped here
            self.judged.append((m["id"], build))
            v = self.verdict(m, build)
            return v, ("==1==ERROR: AddressSanitizer: stray read" if v == "killed" and
                       build.endswith("build-asan") else ""), 1.0, 1.0, \
                sorted(entries) if v == "killed" else []

        catalogue = [{"name": "determinism_tests@determinism",
                      "properties": [{"name": "LABELS", "value": ["determinism"]}]}]
        out = os.path.join(self.tmp.name, "out")
        with mock.patch.object(mutate, "prepare_scratch",
                               lambda root, scratch, coverage=False:
                               (scratch + "/src", scratch + "/build", catalogue, {})), \
                mock.patch.object(mutate, "judge", fake_judge), \
                mock.patch.object(mutate, "run", lambda *a, **k: (0, '{"tests": []}')), \
                mock.patch.object(mutate, "run_tests", lambda *a, **k: ([], "")), \
                mock.patch.object(mutate, "commit_of", lambda root: ("c0ffee", False)), \
                mock.patch.object(mutate, "tree_of", lambda root: self.tree), \
                mock.patch.object(mutate, "scratch_build", lambda s, c: {"name": "scratch"}), \
                contextlib.redirect_stdout(io.StringIO()):
            self.assertEqual(mutate.main([out, "--root", self.root, "--survivors", self.record,
                                          "--scratch", os.path.join(self.tmp.name, "s"),
                                          *args]), 0)
        return out

    def load(self, path):
        with open(path) as fh:
            return json.load(fh)

    def test_shards_merge_into_the_whole_run(self):
        muts = mutate.all_mutants(self.root)
        whole = self.load(os.path.join(self.run_main("--all"), "mutation.json"))
        self.assertTrue(whole["complete"])
        self.assertEqual(whole["population"], len(muts))
        self.assertGreater(whole["killed_by_sanitizer"], 0)
        files, seen = [], []
        for i in range(3):
            out = self.run_main("--all", "--shard", f"{i}/3")
            files.append(os.path.join(out, mutate.shard_file(i, 3)))
            doc = self.load(files[-1])
            self.assertFalse(doc["complete"])
            self.assertEqual(doc["floor_applies_to"], "lower bound")
            seen += [r["id"] for r in doc["mutants"]]
        self.assertEqual(sorted(seen), [m["id"] for m in muts])  # disjoint, together all
        merged_dir = os.path.join(self.tmp.name, "merged")
        with contextlib.redirect_stdout(io.StringIO()):
            mutate.main(["--merge", merged_dir, *files, "--survivors", self.record])
        merged = self.load(os.path.join(merged_dir, "mutation.json"))
        for key in ("score", "killed", "counted", "interval", "population", "complete",
                    "floor_applies_to", "killed_by_sanitizer"):
            self.assertEqual(merged[key], whole[key], key)
        self.assertEqual(sorted((r["id"], r["verdict"]) for r in merged["mutants"]),
                         sorted((r["id"], r["verdict"]) for r in whole["mutants"]))
        self.assertEqual(merged["shards"]["missing"], [])
        sys.path.insert(0, mutate.ROOT)
        from traceability.vvdata import validate
        self.assertEqual(validate(merged), [])

        # A missing shard: reported, and the rest is a sample (the floor on the lower bound).
        with contextlib.redirect_stdout(io.StringIO()):
            mutate.main(["--merge", merged_dir, files[0], files[2], "--survivors", self.record])
        part = self.load(os.path.join(merged_dir, "mutation.json"))
        self.assertEqual(part["shards"]["missing"], [1])
        self.assertFalse(part["complete"])
        self.assertEqual(part["floor_applies_to"], "lower bound")
        self.assertIn("shards missing: 1 of 3", part["checks"][0]["details"])

        # Refused: a shard twice, and shards of another tree.
        for bad in ([files[0], files[0]], [files[0], self.other_tree_shard()]):
            with self.subTest(bad=bad), self.assertRaises(SystemExit):
                mutate.main(["--merge", merged_dir, *bad, "--survivors", self.record])

    def other_tree_shard(self):
        self.tree = "tree-2"
        return os.path.join(self.run_main("--all", "--shard", "1/3"), mutate.shard_file(1, 3))

    def test_a_stopped_run_resumes_where_it_stopped(self):
        # Oracle: the run stopped and resumed gives the uninterrupted run's verdicts, and
        # judges each mutant once in all.
        whole = self.load(os.path.join(self.run_main("--all", "--shard", "0/2"),
                                       mutate.shard_file(0, 2)))
        self.judged, self.stop_after = [], 3
        with self.assertRaises(KeyboardInterrupt):
            self.run_main("--all", "--shard", "0/2")
        first = [i for i, b in self.judged if not b.endswith("build-asan")]
        journal = os.path.join(self.tmp.name, "out", "mutation-shard-0-of-2.journal")
        with open(journal) as fh:
            kept = [json.loads(line)["id"] for line in fh.read().splitlines()[1:]]
        # Each mutant whose verdict was reached is kept; the one cut short is not.
        self.assertEqual(kept, first[:len(kept)])
        self.assertGreaterEqual(len(kept), len(first) - 1)
        self.judged, self.stop_after = [], None
        out = self.run_main("--all", "--shard", "0/2", "--resume")
        again = [i for i, b in self.judged if not b.endswith("build-asan")]
        self.assertEqual(sorted(kept + again), sorted(r["id"] for r in whole["mutants"]))
        resumed = self.load(os.path.join(out, mutate.shard_file(0, 2)))
        self.assertEqual([(r["id"], r["verdict"]) for r in resumed["mutants"]],
                         [(r["id"], r["verdict"]) for r in whole["mutants"]])
        self.assertEqual(resumed["score"], whole["score"])
        # Without --resume, or with a journal of another tree, every mutant is judged again.
        for tree, args in (("tree-1", ()), ("tree-2", ("--resume",))):
            self.judged, self.tree = [], tree
            self.run_main("--all", "--shard", "0/2", *args)
            self.assertEqual(sorted(i for i, b in self.judged if not b.endswith("build-asan")),
                             sorted(r["id"] for r in whole["mutants"]))

    def test_a_partial_reference_goes_on_elsewhere_from_its_merged_results(self):
        # Oracle: the uninterrupted shards' verdicts. Two shards stopped early are merged (the
        # repository's partial reference); on a machine without their journals each shard goes
        # on from that merge, judging only the mutants it lacks, and ends as if never stopped.
        whole = {i: self.load(os.path.join(self.run_main("--all", "--shard", f"{i}/2"),
                                           mutate.shard_file(i, 2))) for i in range(2)}
        parts = []
        for i in range(2):
            self.judged, self.stop_after = [], 3
            with self.assertRaises(KeyboardInterrupt):
                self.run_main("--all", "--shard", f"{i}/2")
            part = os.path.join(self.tmp.name, f"part-{i}.json")
            shutil.copy(os.path.join(self.tmp.name, "out", mutate.shard_file(i, 2)), part)
            parts.append(part)
        reference = os.path.join(self.tmp.name, "reference")
        with contextlib.redirect_stdout(io.StringIO()):
            mutate.main(["--merge", reference, *parts, "--survivors", self.record])
        reference = os.path.join(reference, "mutation.json")
        before = {r["id"] for r in self.load(reference)["mutants"]}
        self.assertTrue(before)
        for i in range(2):
            shutil.rmtree(os.path.join(self.tmp.name, "out"))  # another machine: no journal
            self.judged, self.stop_after = [], None
            out = self.run_main("--all", "--shard", f"{i}/2", "--resume-from", reference)
            again = {j for j, b in self.judged if not b.endswith("build-asan")}
            ids = {r["id"] for r in whole[i]["mutants"]}
            self.assertEqual(again, ids - before)
            done = self.load(os.path.join(out, mutate.shard_file(i, 2)))
            self.assertEqual([(r["id"], r["verdict"]) for r in done["mutants"]],
                             [(r["id"], r["verdict"]) for r in whole[i]["mutants"]])
            self.assertTrue(done["shard"]["complete"])
        # Results of another tree are refused by name, not silently judged again.
        self.tree = "tree-2"
        with self.assertRaises(SystemExit) as refused:
            self.run_main("--all", "--shard", "0/2", "--resume-from", reference)
        self.assertIn("tree", str(refused.exception))

    def test_a_run_of_every_mutant_stopped_early_leaves_a_seeded_sample(self):
        # Oracle: sample_of, the main job's sample: a whole run judges in its rank order, so the
        # mutants judged when it stops at a window's end are the sample of that size, and the
        # result written so far says so (not complete: the floor on the interval's lower bound).
        muts = mutate.all_mutants(self.root)
        self.stop_after = mutate.WINDOW
        with self.assertRaises(KeyboardInterrupt):
            self.run_main("--all", "--no-sanitizer", "--seed", "7")
        self.assertEqual({i for i, _ in self.judged},
                         {m["id"] for m in mutate.sample_of(muts, mutate.WINDOW, 7)})
        doc = self.load(os.path.join(self.tmp.name, "out", "mutation.json"))
        self.assertEqual(sorted(r["id"] for r in doc["mutants"]),
                         sorted(i for i, _ in self.judged))
        self.assertFalse(doc["complete"])
        self.assertEqual(doc["floor_applies_to"], "lower bound")
        self.assertIn("rank order of seed 7", doc["description"])

    def test_the_split_is_stable_under_edits_elsewhere(self):
        before = {mutate.survivor_key(m): mutate.shard_of(m, 4)
                  for m in mutate.all_mutants(self.root)}
        with open(os.path.join(self.root, "src/tamias2d/model/a.hpp"), "a") as fh:
            fh.write("    z = u / v;\n")
        after = {mutate.survivor_key(m): mutate.shard_of(m, 4)
                 for m in mutate.all_mutants(self.root)}
        self.assertEqual({k: v for k, v in after.items() if k in before}, before)
        self.assertEqual(len(set(before.values())), 4)  # every shard gets some

    def test_one_run_per_scratch(self):
        scratch = os.path.join(self.tmp.name, "s")
        os.makedirs(scratch)
        with open(os.path.join(scratch, ".lock"), "w") as held:
            mutate.fcntl.flock(held, mutate.fcntl.LOCK_EX)
            with self.assertRaises(SystemExit):
                self.run_main("--all")
        self.run_main("--all")  # released

    def test_a_survivor_goes_to_the_sanitizer_build_only(self):
        doc = self.load(os.path.join(self.run_main("--all"), "mutation.json"))
        asan = {i for i, b in self.judged if b.endswith("build-asan")}
        self.assertEqual(asan, {r["id"] for r in doc["mutants"]
                                if r["verdict"] == "survived" or
                                r.get("killed_by") == "sanitizer"})


def script(path, body):
    with open(path, "w") as fh:
        fh.write("#!/bin/sh\n" + body + "\n")
    os.chmod(path, 0o755)
    return path


class Tests(unittest.TestCase):
    """Oracle: what made-up test executables (shell scripts that log their arguments) were
    asked to do, and when run_tests returned."""

    def test_each_executable_runs_once_with_its_entries_labels(self):
        with tempfile.TemporaryDirectory() as d:
            log = os.path.join(d, "log")
            exe = script(os.path.join(d, "engine_tests"), f'echo "$@" >> {log}')
            other = script(os.path.join(d, "model_tests"), f'echo "model $@" >> {log}')
            commands = {"engine_tests@IM3": (exe, d), "engine_tests@R7": (exe, d),
                        "model_tests@DD8": (other, d)}
            entries = {n: n.split("@")[0] for n in commands}
            self.assertEqual(mutate.run_tests(entries, commands, 30), ([], ""))
            with open(log) as fh:
                self.assertEqual(sorted(fh.read().split("\n")),
                                 ["", "--run_test=@IM3:@R7 --color_output=no",
                                  "model --run_test=@DD8 --color_output=no"])

    def test_an_unlabelled_entry_runs_on_its_own_with_its_own_filter(self):
        with tempfile.TemporaryDirectory() as d:
            log = os.path.join(d, "log")
            exe = script(os.path.join(d, "engine_tests"), f'echo "$@" >> {log}')
            commands = {"engine_tests@IM3": (exe, d, None),
                        "engine_tests.unlabelled": (exe, d, {"args": ["--run_test=!@IM3:!@R7",
                                                                      "--color_output=no"],
                                                             "skip": []})}
            entries = {n: "engine_tests" for n in commands}
            self.assertEqual(mutate.run_tests(entries, commands, 30), ([], ""))
            with open(log) as fh:
                self.assertEqual(sorted(fh.read().split("\n")),
                                 ["", "--run_test=!@IM3:!@R7 --color_output=no",
                                  "--run_test=@IM3 --color_output=no"])
            bad = script(os.path.join(d, "bad"), "echo 'check failed'; exit 201")
            commands["engine_tests.unlabelled"] = (bad, d, {"args": ["--run_test=!@IM3"],
                                                            "skip": ["no test cases matching"]})
            failed, _ = mutate.run_tests(entries, commands, 30)
            self.assertEqual(failed, ["engine_tests.unlabelled"])
            # Boost.Test's answer when every case has a label: skipped, as CTest reads it.
            none = script(os.path.join(d, "none"),
                          "echo 'Test setup error: no test cases matching filter'; exit 200")
            commands["engine_tests.unlabelled"] = (none, d, {"args": ["--run_test=!@IM3"],
                                                             "skip": ["no test cases matching"]})
            self.assertEqual(mutate.run_tests(entries, commands, 30)[0], [])

    def test_the_entries_of_a_label_bring_their_executables_unlabelled_cases(self):
        def entry(name, labels, args=()):
            return {"name": name, "command": ["/b/" + name.split("@")[0].split(".")[0], *args],
                    "properties": [{"name": "LABELS", "value": labels}]}
        catalogue = [entry("engine_tests@IM3", ["IM3"]), entry("engine_tests@R7", ["R7"]),
                     entry("engine_tests.unlabelled", ["unlabelled"], ["--run_test=!@IM3"]),
                     entry("model_tests@DD8", ["DD8"]),
                     entry("model_tests.unlabelled", ["unlabelled"], ["--run_test=!@DD8"])]
        self.assertEqual(mutate.ctest_entries(catalogue, ["IM3"]),
                         {"engine_tests@IM3": "engine_tests",
                          "engine_tests.unlabelled": "engine_tests"})
        catalogue[2]["properties"].append({"name": "SKIP_REGULAR_EXPRESSION",
                                           "value": ["no test cases matching filter"]})
        commands = mutate.commands_of(catalogue)
        self.assertEqual(commands["engine_tests.unlabelled"][2],
                         {"args": ["--run_test=!@IM3"], "skip": ["no test cases matching filter"]})
        self.assertIsNone(commands["engine_tests@IM3"][2])

    def test_the_entries_of_a_label_bring_their_executables_category_cases(self):
        # A case tagged with a category (internals: the packs against their plain form) of a
        # chosen executable judges too; one of an executable not chosen does not, nor does an
        # entry that carries an SRS label of another item.
        def entry(name, labels):
            return {"name": name, "command": ["/b/" + name.split("@")[0]],
                    "properties": [{"name": "LABELS", "value": labels}]}
        catalogue = [entry("engine_tests@IM3", ["IM3"]), entry("engine_tests@R7", ["R7"]),
                     entry("engine_tests@internals", ["internals"]),
                     entry("reliability_tests@internals", ["internals"])]
        self.assertEqual(mutate.ctest_entries(catalogue, ["IM3"], categories=("internals",)),
                         {"engine_tests@IM3": "engine_tests",
                          "engine_tests@internals": "engine_tests"})
        self.assertEqual(mutate.ctest_entries(catalogue, ["IM3"]),
                         {"engine_tests@IM3": "engine_tests"})
        root = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
        self.assertIn("internals", mutate.category_labels(root))

    def test_the_first_failure_stops_the_others_and_a_time_out_fails(self):
        with tempfile.TemporaryDirectory() as d:
            slow = script(os.path.join(d, "slow"), "sleep 30")
            bad = script(os.path.join(d, "bad"), "echo 'check failed'; exit 201")
            commands = {"slow@A": (slow, d), "bad@B": (bad, d), "bad@C": (bad, d)}
            t0 = mutate.time.monotonic()
            failed, log = mutate.run_tests({n: n.split("@")[0] for n in commands}, commands, 60)
            self.assertLess(mutate.time.monotonic() - t0, 20)
            self.assertEqual(failed, ["bad@B", "bad@C"])
            self.assertIn("check failed", log)
            failed, log = mutate.run_tests({"slow@A": "slow"}, commands, 1)
            self.assertEqual(failed, ["slow@A"])
            self.assertIn("time-out after 1 s", log)

    def test_an_executable_is_stopped_at_its_first_failed_check(self):
        # Boost.Test's own line for a failed check; the executable would go on for 30 s and
        # then exit 0 here, so only the stop can make it fail within the bound.
        with tempfile.TemporaryDirectory() as d:
            exe = script(os.path.join(d, "engine_tests"),
                         'echo \'test.cpp(12): error: in "suite/case": check a == b has '
                         'failed [1 != 2]\'; sleep 30')
            t0 = mutate.time.monotonic()
            failed, log = mutate.run_tests({"engine_tests@IM3": "engine_tests"},
                                           {"engine_tests@IM3": (exe, d)}, 60)
            self.assertLess(mutate.time.monotonic() - t0, 20)
            self.assertEqual(failed, ["engine_tests@IM3"])
            self.assertIn("stopped at its first failed check", log)
            self.assertIn("check a == b has failed", log)

    def test_the_executable_that_killed_a_files_mutants_runs_first_on_that_file(self):
        with tempfile.TemporaryDirectory() as d:
            order = os.path.join(d, "order")
            a = script(os.path.join(d, "a"), f'echo a >> {order}')
            b = script(os.path.join(d, "b"), f'echo b >> {order}; exit 1')
            commands = {"a@X": (a, d), "b@X": (b, d)}
            entries = {n: n.split("@")[0] for n in commands}
            saved = dict(mutate._KILLS), dict(mutate._COSTS)
            try:
                mutate._KILLS.clear()
                mutate._COSTS.clear()
                # The two take as long (set before each run, so that the host's load leaves
                # only the kill rates to order them; equal ones: by name).
                for _ in range(3):  # b kills each time; a, never run after the first
                    mutate._COSTS.update(a=1.0, b=1.0)
                    mutate.run_tests(entries, commands, 30, jobs=1, key="f.cpp")
                with open(order) as fh:
                    self.assertEqual(fh.read().split(), ["a", "b", "b", "b"])
                os.remove(order)
                # Another file's mutants have no record yet: the first order again.
                mutate._COSTS.update(a=1.0, b=1.0)
                mutate.run_tests(entries, commands, 30, jobs=1, key="g.cpp")
                with open(order) as fh:
                    self.assertEqual(fh.read().split(), ["a", "b"])
            finally:
                mutate._KILLS.clear()
                mutate._KILLS.update(saved[0])
                mutate._COSTS.clear()
                mutate._COSTS.update(saved[1])


@unittest.skipUnless(all(shutil.which(t) for t in ("cmake", "ninja", "c++")),
                     "needs cmake, ninja and a C++ compiler")
class Restore(unittest.TestCase):
    """Oracle: ninja's own dry run and the bytes of the outputs, on a made-up CMake project
    built as the scratch is (a shared library, executables not relinked when only it changes):
    after a mutant and its restoring, the build is as the unmutated sources leave it."""

    def test_a_mutant_leaves_the_build_unmutated_and_the_next_builds_only_itself(self):
        with tempfile.TemporaryDirectory() as d:
            src, build = os.path.join(d, "src"), os.path.join(d, "build")
            os.makedirs(src)
            files = {"CMakeLists.txt": "cmake_minimum_required(VERSION 3.16)\nproject(t CXX)\n"
                                       "add_library(lib SHARED a.cpp b.cpp)\n"
                                       "add_executable(app main.cpp)\n"
                                       "target_link_libraries(app lib)\n",
                     "h.hpp": "inline int g() { return 2 * 3; }\n",
                     "a.cpp": '#include "h.hpp"\nint f() {\n    return 1 + g();\n}\n',
                     "b.cpp": "int k() {\n    return 4 - 1;\n}\n",
                     "main.cpp": '#include "h.hpp"\nint f();\nint k();\n'
                                 "int main() { return f() == 7 && k() == 3 && g() == 6 ? 0 : 1; }\n"}
            for name, text in files.items():
                with open(os.path.join(src, name), "w") as fh:
                    fh.write(text)
            rc, out = mutate.run(["cmake", "-S", src, "-B", build, "-G", "Ninja",
                                  "-DCMAKE_BUILD_TYPE=Release", "-DBUILD_SHARED_LIBS=ON",
                                  "-DCMAKE_LINK_DEPENDS_NO_SHARED=ON"])
            self.assertEqual(rc, 0, out)
            self.assertEqual(mutate.run(["cmake", "--build", build])[0], 0)
            unmutated, objects = mutate.Unmutated(build), mutate.object_digests(build)
            app = os.path.join(build, "app")
            entries, commands = {"app@X": "app"}, {"app@X": (app, build)}

            def mutant(name, no, before, after):
                return {"file": name, "line": no, "before": before, "after": after, "id": 0}

            def dry_run():
                return mutate.run(["ninja", "-C", build, "-n"])[1]

            for m in (mutant("a.cpp", 3, "    return 1 + g();", "    return 1 - g();"),
                      mutant("h.hpp", 1, files["h.hpp"][:-1],
                             "inline int g() { return 2 / 3; }")):
                with self.subTest(file=m["file"]):
                    path = os.path.join(src, m["file"])
                    before = os.stat(path).st_mtime_ns
                    verdict = mutate.judge(m, src, build, entries, 60, objects,
                                           commands=commands, unmutated=unmutated)
                    self.assertEqual(verdict[0], "killed")  # the program checks f() and g()
                    self.assertEqual(os.stat(path).st_mtime_ns, before)
                    self.assertIn("no work to do", dry_run())
                    for out_path, data in unmutated.files.items():
                        with open(out_path, "rb") as fh:
                            self.assertEqual(fh.read(), data, out_path)
            # The next mutant's build compiles its own file and links, nothing else.
            m = mutant("b.cpp", 2, "    return 4 - 1;", "    return 4 + 1;")
            with mock.patch.object(mutate, "run_tests", lambda *a, **k: (["app@X"], "")):
                real_run = mutate.run
                logs = []

                def logging_run(cmd, **kw):
                    rc, out = real_run(cmd, **kw)
                    logs.append(out)
                    return rc, out
                with mock.patch.object(mutate, "run", logging_run):
                    mutate.judge(m, src, build, entries, 60, objects, commands=commands,
                                 unmutated=unmutated)
            compiled = re.findall(r"Building CXX object (\S+)", logs[0])
            self.assertEqual(compiled, ["CMakeFiles/lib.dir/b.cpp.o"])
            self.assertIn("no work to do", dry_run())
            self.assertEqual(mutate.judge(dict(m, after=m["before"]), src, build, entries, 60,
                                          objects, commands=commands, unmutated=unmutated)[0],
                             "not built")
            # The control: restored without its outputs, the source is rebuilt.
            mutate.judge(m, src, build, entries, 60, objects, commands=commands)
            self.assertIn("b.cpp.o", dry_run())


if __name__ == "__main__":
    unittest.main()
