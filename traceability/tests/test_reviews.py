"""Suspect links: fingerprints of both ends of each trace link, review records, and the links
whose ends changed since their review (traceability/fingerprints.py, traceability/review.py).

On a scratch copy of the fixture: every link reviewed, then one SRS item's statement changed
makes exactly its links suspect (and `review.py mark` refuses until the report is rebuilt);
reviewing them again clears them; a changed test body makes its links suspect. Run:
/usr/bin/python3 -m unittest discover -s traceability/tests -t .
"""
import json
import os
import shutil
import subprocess
import tempfile
import unittest

from traceability import fingerprints
from traceability.tests.test_harness import REPO, run_harness

HERE = os.path.dirname(os.path.abspath(__file__))
REVIEW = os.path.join(os.path.dirname(HERE), "review.py")


class SuspectLinks(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.mkdtemp(prefix="trace-review-")
        self.addCleanup(shutil.rmtree, self.tmp, True)
        self.repo = os.path.join(self.tmp, "repo")
        shutil.copytree(REPO, self.repo)
        self.out = os.path.join(self.tmp, "reports")

    def report(self, *extra):
        code = run_harness(self.repo, self.out, extra)
        with open(os.path.join(self.out, "traceability.json"), encoding="utf-8") as fh:
            return code, json.load(fh)

    def review(self, *args):
        return subprocess.run(["/usr/bin/python3", REVIEW, "--source", self.repo, "--report",
                               os.path.join(self.out, "traceability.json"), *args],
                              capture_output=True, text=True, timeout=120)

    def edit(self, rel, old, new):
        path = os.path.join(self.repo, rel)
        with open(path, encoding="utf-8") as fh:
            text = fh.read()
        self.assertIn(old, text)
        with open(path, "w", encoding="utf-8") as fh:
            fh.write(text.replace(old, new, 1))

    @staticmethod
    def states(rep):
        return {(ln["item"], ln["test"]): ln["review"]["status"] for ln in rep["links"]}

    def review_all(self):
        proc = self.review("mark-all", "--reviewer", "Fixture Reviewer", "--date", "2000-01-02")
        self.assertEqual(proc.returncode, 0, proc.stderr)

    def test_a_changed_statement_makes_exactly_its_links_suspect(self):
        _, rep = self.report()
        self.assertEqual(set(self.states(rep).values()), {"unreviewed"})
        self.review_all()
        with open(os.path.join(self.repo, "traceability", "reviews.yaml"), encoding="utf-8") as fh:
            self.assertIn("reviewer: Fixture Reviewer", fh.read())
        _, rep = self.report()
        self.assertEqual(set(self.states(rep).values()), {"reviewed"})
        self.assertEqual(rep["reviews"]["reviewed"], len(rep["links"]))

        self.edit("srs/data_definitions.yaml", "description: Fixture data definition.\n",
                  "description: Fixture data definition, reworded.\n")
        # The review is of what the report shows: with the sources newer, mark refuses.
        dd1_tests = [t for (i, t) in self.states(rep) if i == "DD1"]
        proc = self.review("mark", "DD1", dd1_tests[0], "--reviewer", "Fixture Reviewer")
        self.assertEqual(proc.returncode, 1)
        self.assertIn("build the report again", proc.stderr)

        code, rep = self.report()
        suspect = {k for k, v in self.states(rep).items() if v == "suspect"}
        self.assertEqual(suspect, {("DD1", t) for t in dd1_tests})
        self.assertEqual(len(suspect), 2)  # model/im1_free_fall, compile_fail.dd01_mass
        self.assertTrue(all(s["changed"] == ["item"] for s in rep["gate"]["suspect_links"]))
        self.assertEqual(rep["reviews"]["suspect"], 2)
        self.assertFalse(any("suspect" in r for r in rep["gate"]["reasons"]))  # not gating
        items = {i["label"]: i for i in rep["items"]}
        self.assertEqual({v["review"] for v in items["DD1"]["links"].values()}, {"suspect"})
        with open(os.path.join(self.out, "index.html"), encoding="utf-8") as fh:
            page = fh.read()
        self.assertIn('id="suspect-links"', page)
        self.assertIn("Suspect trace links (2)", page)
        with open(os.path.join(self.out, "traceability.md"), encoding="utf-8") as fh:
            self.assertIn("Suspect trace links", fh.read())

        code_gating, rep_gating = self.report("--suspect-gates")
        self.assertEqual(code_gating, 1)
        self.assertTrue(any("2 suspect trace link(s)" in r for r in rep_gating["gate"]["reasons"]))

        # A person looks again and records it: the links are reviewed, nothing is suspect.
        proc = self.review("mark-all", "--reviewer", "Second Reviewer", "--only", "suspect")
        self.assertEqual(proc.returncode, 0, proc.stderr)
        self.assertEqual(proc.stdout.count("reviewed: DD1 <- "), 2)
        _, rep = self.report()
        self.assertEqual(set(self.states(rep).values()), {"reviewed"})
        self.assertEqual(rep["gate"]["suspect_links"], [])

    def test_a_changed_test_body_makes_its_links_suspect(self):
        self.report()
        self.review_all()
        self.edit("tests/model/test_model.cpp", '"DD1")) { BOOST_TEST(true); }',
                  '"DD1")) { BOOST_TEST(1 + 1 == 2); }')
        _, rep = self.report()
        suspect = {k for k, v in self.states(rep).items() if v == "suspect"}
        self.assertEqual(suspect, {("IM1", "model_tests:model/im1_free_fall"),
                                   ("DD1", "model_tests:model/im1_free_fall")})
        self.assertTrue(all(s["changed"] == ["test"] for s in rep["gate"]["suspect_links"]))
        # A new title or note is not normative: no link becomes suspect.
        self.edit("srs/instance_models.yaml", "title: Translational motion", "title: Translation")
        _, rep2 = self.report()
        self.assertEqual({k for k, v in self.states(rep2).items() if v == "suspect"}, suspect)

    def test_a_record_of_a_vanished_link_is_listed(self):
        self.report()
        self.review_all()
        path = os.path.join(self.repo, "traceability", "reviews.yaml")
        with open(path, encoding="utf-8") as fh:
            text = fh.read()
        with open(path, "w", encoding="utf-8") as fh:
            fh.write(text + "- item: IM1\n  test: model_tests:model/gone\n  reviewer: R\n  date: '2000-01-01'\n"
                     "  item_fingerprint: x\n  test_fingerprint: y\n")
        _, rep = self.report()
        self.assertEqual([(o["item"], o["test"]) for o in rep["reviews"]["orphan_records"]],
                         [("IM1", "model_tests:model/gone")])
        proc = self.review("prune")
        self.assertIn("pruned 1 record", proc.stdout)


class Fingerprints(unittest.TestCase):
    def test_item_fingerprint_reads_only_the_normative_fields(self):
        # Oracle: the rule of fingerprints.py: statement, equation, symbols, uses (a set) and
        # obligation, whitespace runs as one space.
        base = {"label": "R1", "title": "T", "description": "The software shall  do x.",
                "equation": None, "symbols": [], "uses": ["IM1", "DC1"], "obligation": "shall",
                "notes": "n", "errata": ["E1"]}
        fp = fingerprints.item_fingerprint(base)
        for same in ({"title": "U"}, {"notes": "m"}, {"errata": []}, {"uses": ["DC1", "IM1"]},
                     {"description": "The software shall do\nx."}):
            self.assertEqual(fingerprints.item_fingerprint(dict(base, **same)), fp, same)
        for other in ({"description": "The software shall do y."}, {"uses": ["IM1"]},
                      {"obligation": "should"}, {"equation": "x = 1"},
                      {"symbols": [{"symbol": "x", "unit": "m"}]}):
            self.assertNotEqual(fingerprints.item_fingerprint(dict(base, **other)), fp, other)

    def test_test_case_text_spans_its_oracle_to_the_next_case(self):
        lines = ["// header", "", "// first case", "// Oracle: a", "BOOST_AUTO_TEST_CASE(a) {",
                 "  BOOST_TEST(1);", "}", "", "// Oracle: b", "BOOST_TEST_DECORATOR(*utf::label(\"X\"))",
                 "BOOST_DATA_TEST_CASE(b, data) {}", "BOOST_AUTO_TEST_SUITE_END()"]
        self.assertEqual(fingerprints.boost_case_text(lines, 5),
                         "// first case\n// Oracle: a\nBOOST_AUTO_TEST_CASE(a) {\n  BOOST_TEST(1);\n}")
        self.assertEqual(fingerprints.boost_case_text(lines, 11),
                         "// Oracle: b\nBOOST_TEST_DECORATOR(*utf::label(\"X\"))\n"
                         "BOOST_DATA_TEST_CASE(b, data) {}\nBOOST_AUTO_TEST_SUITE_END()")
        self.assertIsNone(fingerprints.boost_case_text(lines, 6))  # not a declaration

    def test_cmake_entry_text_is_the_comment_and_the_call(self):
        lines = ["add_test(NAME other COMMAND x)", "# Oracle: the seed's form must not compile",
                 "tamias_add_compile_fail(dd01 SOURCE a.cpp", "  LABELS DD1 \"(x)\")", "set(A 1)"]
        self.assertEqual(fingerprints.cmake_entry_text(lines, 3),
                         "# Oracle: the seed's form must not compile\ntamias_add_compile_fail(dd01 SOURCE a.cpp\n"
                         "  LABELS DD1 \"(x)\")")


if __name__ == "__main__":
    unittest.main()
