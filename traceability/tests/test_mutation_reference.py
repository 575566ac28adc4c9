"""The reference mutation analysis as the report reads it (traceability/mutation_reference.py).

Oracle: a reference and a survivors record written here by hand, whose counts, score and floor
verdict follow from the rows written (score = killed / (killed + survivors not judged
equivalent); the Wilson interval of a 3-of-4 sample from its closed form), and a git repository
made here, whose changed files are known.
"""
from __future__ import annotations

import json
import math
import os
import subprocess
import sys
import tempfile
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, ROOT)

from traceability import mutation_reference  # noqa: E402


def row(i, verdict, before="x = a + b;", occurrence=1, **extra):
    return dict({"id": i, "file": "src/tamias2d/model/a.hpp", "line": 10 + i,
                 "op": "arith + to -", "before": "    " + before, "after": "    x = a - b;",
                 "occurrence": occurrence, "verdict": verdict}, **extra)


class Reference(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.root = self.tmp.name
        os.makedirs(os.path.join(self.root, "verification", "mutation", "reference"))
        # The scoring rules are mutate.py's, read from the checkout: this one's.
        os.symlink(os.path.join(ROOT, "verification", "mutation", "mutate.py"),
                   os.path.join(self.root, "verification", "mutation", "mutate.py"))
        os.makedirs(os.path.join(self.root, "src", "tamias2d", "model"))

    def tearDown(self):
        self.tmp.cleanup()

    def write(self, rows, complete, commit="c0ffee", survivors=()):
        doc = {"mutants": rows, "population": 10, "complete": complete,
               "selection": {"mode": "all", "seed": 1},
               "provenance": {"commit": commit, "dirty": False, "generated": "2026-11-30T10:00:00Z"}}
        with open(os.path.join(self.root, mutation_reference.REFERENCE), "w") as fh:
            json.dump(doc, fh)
        with open(os.path.join(self.root, "verification", "mutation", "survivors.json"), "w") as fh:
            json.dump({"survivors": list(survivors)}, fh)

    def test_absent_reference_is_none(self):
        self.assertIsNone(mutation_reference.collect(self.root, []))

    def test_a_sample_is_scored_with_the_checkouts_record(self):
        rows = [row(0, "killed"), row(1, "killed"), row(2, "killed", killed_by="sanitizer"),
                row(3, "survived", before="y = c + d;"), row(4, "survived", before="z = e + f;"),
                row(5, "stillborn")]
        judged = {"file": "src/tamias2d/model/a.hpp", "line": "y = c + d;", "op": "arith + to -",
                  "occurrence": 1, "verdict": "equivalent", "reason": "made up"}
        self.write(rows, complete=False, survivors=[judged])
        ref = mutation_reference.collect(self.root, [])
        # 3 killed, 1 survivor equivalent, 1 not judged: 3 of 4 counted.
        self.assertEqual((ref["killed"], ref["equivalent"], ref["counted"]), (3, 1, 4))
        self.assertAlmostEqual(ref["score"], 0.75)
        z = 1.959963984540054
        n, p = 4, 0.75
        centre = (p + z * z / (2 * n)) / (1 + z * z / n)
        half = z * math.sqrt(p * (1 - p) / n + z * z / (4 * n * n)) / (1 + z * z / n)
        self.assertAlmostEqual(ref["interval"][0], centre - half, places=12)
        self.assertAlmostEqual(ref["interval"][1], centre + half, places=12)
        self.assertEqual(ref["floor_applies_to"], "lower bound")
        self.assertFalse(ref["floor_met"])
        self.assertEqual(ref["killed_by_sanitizer"], 1)
        self.assertEqual([s["judgement"] for s in ref["survivors"]], ["equivalent", "not judged"])
        self.assertEqual(ref["not_judged"], 1)
        self.assertEqual((ref["judged"], ref["population"]), (6, 10))
        text = mutation_reference.summary(ref)
        self.assertIn("6 of 10 mutants, a seeded random sample", text)
        self.assertIn("not met", text)
        self.assertIn("git cannot compare", text)  # no repository here

    def test_a_complete_run_applies_the_floor_to_the_score(self):
        rows = [row(i, "killed") for i in range(9)] + [row(9, "survived", before="q = r + s;")]
        gap = {"file": "src/tamias2d/model/a.hpp", "line": "q = r + s;", "op": "arith + to -",
               "occurrence": 1, "verdict": "gap", "reason": "made up"}
        self.write(rows, complete=True, survivors=[gap])
        ref = mutation_reference.collect(self.root, [])
        self.assertAlmostEqual(ref["score"], 0.9)
        self.assertEqual(ref["floor_applies_to"], "point estimate")
        self.assertTrue(ref["floor_met"])  # 0.9 >= 0.9; its lower bound is far below
        self.assertLess(ref["interval"][0], 0.9)
        self.assertEqual(ref["gaps"], 1)

    def test_files_changed_since_its_commit_are_named(self):
        def git(*args):
            subprocess.run(["git", "-C", self.root, "-c", "user.name=t", "-c", "user.email=t@t",
                            *args], check=True, capture_output=True)
        a = os.path.join(self.root, "src", "tamias2d", "model", "a.hpp")
        with open(a, "w") as fh:
            fh.write("x = a + b;\n")
        git("init", "-q")
        git("add", "-A")
        git("commit", "-qm", "one")
        commit = subprocess.run(["git", "-C", self.root, "rev-parse", "HEAD"], capture_output=True,
                                text=True, check=True).stdout.strip()
        self.write([row(0, "killed")], complete=True, commit=commit)
        self.assertEqual(mutation_reference.collect(self.root, [])["changed_since"], [])
        self.assertIn("unchanged", mutation_reference.summary(mutation_reference.collect(self.root, [])))
        with open(a, "a") as fh:
            fh.write("y = 1.0;\n")
        ref = mutation_reference.collect(self.root, [])
        self.assertEqual(ref["changed_since"], ["src/tamias2d/model/a.hpp"])
        self.assertIn("1 of the mutated files changed", mutation_reference.summary(ref))

    def test_a_gap_is_closed_only_by_named_tests_that_passed_in_this_run(self):
        rows = [row(0, "killed"), row(1, "survived", before="q = r + s;"),
                row(2, "survived", before="t = u + v;")]
        closed = {"file": "src/tamias2d/model/a.hpp", "line": "q = r + s;", "op": "arith + to -",
                  "occurrence": 1, "verdict": "gap", "reason": "made up",
                  "closed_by": ["x_tests:suite/case"]}
        still_open = {"file": "src/tamias2d/model/a.hpp", "line": "t = u + v;",
                      "op": "arith + to -", "occurrence": 1, "verdict": "gap",
                      "reason": "made up"}
        self.write(rows, complete=False, survivors=[closed, still_open])
        for status, count in (("passed", 1), ("failed", 0)):
            warnings = []
            tests = [{"id": "x_tests:suite/case", "status": status, "binary": "x_tests"}]
            ref = mutation_reference.collect(self.root, warnings, tests)
            self.assertEqual((ref["gaps"], ref["gaps_closed"]), (2, count), status)
            self.assertIn(f"({count} closed at the checkout by tests that passed in this run, "
                          f"{2 - count} open)", mutation_reference.summary(ref))
            self.assertEqual(mutation_reference.judgement_text(ref["survivors"][0]),
                             f"gap, {'closed' if count else 'not closed'} at the checkout by "
                             f"x_tests:suite/case ({status})")
            self.assertEqual(mutation_reference.judgement_text(ref["survivors"][1]), "gap")
            self.assertEqual(warnings, [])
        # Without a run of its executable the test is "not run", and the gap open.
        ref = mutation_reference.collect(self.root, [], [])
        self.assertEqual(ref["gaps_closed"], 0)
        self.assertEqual(ref["survivors"][0]["closed_by"],
                         [{"test": "x_tests:suite/case", "status": "not run"}])
        # Its executable ran without it: the record names a test that is gone, a warning.
        warnings = []
        mutation_reference.collect(self.root, warnings,
                                   [{"id": "x_tests:suite/other", "status": "passed",
                                     "binary": "x_tests"}])
        self.assertEqual(len(warnings), 1)
        self.assertIn("x_tests:suite/case", warnings[0])

    def test_declared_tests_are_named_by_executable_and_suite_path(self):
        d = os.path.join(self.root, "tests", "x", "sub")
        os.makedirs(d)
        with open(os.path.join(self.root, "tests", "x", "CMakeLists.txt"), "w") as fh:
            fh.write("tamias_add_boost_test(x_tests SOURCES a.cpp)\n")
        with open(os.path.join(d, "test_a.cpp"), "w") as fh:
            fh.write("BOOST_AUTO_TEST_SUITE(outer)\nBOOST_AUTO_TEST_CASE(one) {}\n"
                     "BOOST_AUTO_TEST_SUITE(inner)\n"
                     "BOOST_AUTO_TEST_CASE(two, *utf::label(\"A\")) {}\n"
                     "BOOST_AUTO_TEST_SUITE_END()\nBOOST_AUTO_TEST_CASE(three) {}\n"
                     "BOOST_AUTO_TEST_SUITE_END()\n")
        self.assertEqual(mutation_reference.declared_tests(self.root),
                         {"x_tests:outer/one", "x_tests:outer/inner/two", "x_tests:outer/three"})

    def test_the_checkouts_closing_tests_are_declared(self):
        # The repository's own record: every test it names as closing a gap exists.
        self.assertEqual(mutation_reference.undeclared_closing_tests(ROOT), [])

    def test_an_unreadable_reference_is_a_warning(self):
        with open(os.path.join(self.root, mutation_reference.REFERENCE), "w") as fh:
            fh.write("{not json")
        warnings = []
        self.assertIsNone(mutation_reference.collect(self.root, warnings))
        self.assertEqual(len(warnings), 1)


if __name__ == "__main__":
    unittest.main()
