"""The module reach tool's own test (no build): how perturbations apply, what the tree check
finds wrong in a made-up tree, which CTest entries count as the engine's, and how results are
judged against srs/. Oracle: made-up trees, catalogues and results, with the verdicts stated."""
import os
import sys
import tempfile
import unittest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import module_reach as mr  # noqa: E402
from perturbations import P  # noqa: E402

MODULE = """#pragma once
namespace tamias2d::model::dd17 {
/// \\srs{DD17} a_d = -c v
inline double acceleration(double c, double v) {
    return -(c * v);
}
}
"""


def make_tree(root, modules, items):
    """A tree with model modules {name: text} and srs items [(label, kind)]."""
    os.makedirs(os.path.join(root, mr.MODEL_DIR))
    for name, text in modules.items():
        with open(os.path.join(root, mr.MODEL_DIR, name), "w", encoding="utf-8") as fh:
            fh.write(text)
    os.makedirs(os.path.join(root, "srs"))
    by_file = {f: [] for f in mr.SRS_FILES}
    kinds = {"TM": "theoretical_models.yaml", "GD": "general_definitions.yaml",
             "DD": "data_definitions.yaml", "IM": "instance_models.yaml",
             "DC": "data_constraints.yaml"}
    for label, kind, extra in items:
        by_file[kinds[kind]].append(dict({"label": label, "kind": kind}, **extra))
    import yaml
    for f, its in by_file.items():
        with open(os.path.join(root, "srs", f), "w", encoding="utf-8") as fh:
            yaml.safe_dump(its, fh)


FLIP = P("dd17_linear_damping.hpp", "acceleration", "return -(c * v);", "return c * v;",
         "a_d = +c v")


class Apply(unittest.TestCase):
    def test_applies_once(self):
        self.assertIn("return c * v;", mr.apply(MODULE, FLIP))
        self.assertNotIn("return -(c * v);", mr.apply(MODULE, FLIP))

    def test_absent_repeated_or_empty_perturbations_are_errors(self):
        with self.assertRaisesRegex(ValueError, "occurs 0 times"):
            mr.apply(MODULE, P(FLIP.module, "x", "return c;", "return -c;", ""))
        with self.assertRaisesRegex(ValueError, "occurs 2 times"):
            mr.apply(MODULE + MODULE, FLIP)
        with self.assertRaisesRegex(ValueError, "changes nothing"):
            mr.apply(MODULE, P(FLIP.module, "x", FLIP.old, FLIP.old, ""))


class TreeCheck(unittest.TestCase):
    def check(self, modules, items, perturbations):
        with tempfile.TemporaryDirectory() as root:
            make_tree(root, modules, items)
            return mr.check_tree(root, perturbations, {"damping": ["DD17"]})

    def test_a_consistent_tree_passes(self):
        self.assertEqual(self.check({"dd17_linear_damping.hpp": MODULE},
                                    [("DD17", "DD", {})], [FLIP]), [])

    def test_each_fault_is_named(self):
        got = self.check({"dd17_linear_damping.hpp": MODULE,
                          "dd18_angular_damping.hpp": MODULE.replace("DD17", "DD18"),
                          "dd99_x.hpp": "no tag here"},
                         [("DD17", "DD", {}), ("DD18", "DD", {}), ("GD7", "GD", {})],
                         [FLIP, FLIP, P("gone.hpp", "f", "a", "b", ""),
                          P(FLIP.module, "g", FLIP.old, FLIP.new, "", judged_by=("IM99",))])
        text = "\n".join(got)
        self.assertIn("dd99_x.hpp: its \\srs tags name no item", text)
        self.assertIn("no model module gone.hpp", text)
        self.assertIn("dd18_angular_damping.hpp: no perturbation", text)
        self.assertIn("two perturbations named acceleration", text)
        self.assertIn("GD7: no model module", text)
        self.assertIn("judged by IM99, not an SRS item", text)

    def test_a_module_of_an_unknown_item_is_named(self):
        got = self.check({"dd17_linear_damping.hpp": MODULE}, [], [FLIP])
        self.assertTrue(any("DD17 is not an SRS item" in g for g in got), got)
        self.assertIn("subset damping: DD17 has no module",
                      self.check({}, [], []))

    def test_the_repository_fits_its_perturbations(self):
        self.assertEqual(mr.check_tree(mr.ROOT), [])


class Judging(unittest.TestCase):
    def test_engine_entries_leave_out_the_model_tests_and_compile_checks(self):
        catalogue = [{"name": n} for n in (
            "model_tests@DD17", "model_tests.unlabelled", "compile_fail.dd02_x",
            "system_tests@DD17", "system_tests.unlabelled", "determinism_tests@determinism",
            "formula_lint")]
        self.assertEqual(mr.engine_entries(catalogue),
                         {"system_tests@DD17": "system_tests",
                          "system_tests.unlabelled": "system_tests",
                          "determinism_tests@determinism": "determinism_tests"})

    def test_an_instrumented_scratch_stays_instrumented(self):
        with tempfile.TemporaryDirectory() as scratch:
            self.assertFalse(mr.instrumented(scratch))  # no build yet: the plain build
            os.makedirs(os.path.join(scratch, "build"))
            cache = os.path.join(scratch, "build", "CMakeCache.txt")
            with open(cache, "w", encoding="utf-8") as fh:
                fh.write("TAMIAS_COVERAGE:BOOL=OFF\n")
            self.assertFalse(mr.instrumented(scratch))
            with open(cache, "w", encoding="utf-8") as fh:
                fh.write("TAMIAS_COVERAGE:BOOL=ON\n")
            self.assertTrue(mr.instrumented(scratch))

    def test_a_run_cut_short_says_so(self):
        import argparse
        import json
        rows = [{"label": "DD17", "module": "dd17_linear_damping.hpp", "function": "acceleration",
                 "why": "a_d = +c v", "judged_by": ["DD17"], "result": "verified",
                 "expected": "verified", "failed": "system_tests@DD17", "seconds": 1.0}]
        run = {"commit": "c", "dirty": False, "tree": "t", "build": {"name": "b"}, "chosen": 2,
               "started": "s", "prep_secs": 1.0, "judging_secs": 1.0}
        with tempfile.TemporaryDirectory() as out:
            a = argparse.Namespace(out_dir=out, subset="damping", only=None)
            mr.write(a, rows, {"DD17": {}}, {}, run, quiet=True)
            with open(os.path.join(out, "module_reach.json"), encoding="utf-8") as fh:
                doc = json.load(fh)
            checks = {c["name"]: c["passed"] for c in doc["checks"]}
            self.assertFalse(checks["every perturbation chosen was judged"])
            self.assertIn("cut short: 1 of 2 judged", doc["summary"])
            run["chosen"] = 1
            mr.write(a, rows, {"DD17": {}}, {}, run, quiet=True)
            with open(os.path.join(out, "module_reach.json"), encoding="utf-8") as fh:
                doc = json.load(fh)
            self.assertTrue(all(c["passed"] for c in doc["checks"]))
            self.assertEqual(doc["provenance"]["tree"], "t")

    def test_a_stopped_run_resumes_on_its_own_tree_only(self):
        # Oracle: the rows written by the stopped run (write, as above), found again by
        # (module, function) for the chosen perturbations, and none for another tree.
        import argparse
        row = {"label": "DD17", "module": FLIP.module, "function": FLIP.name,
               "why": FLIP.why, "judged_by": ["DD17"], "result": "verified",
               "expected": "verified", "failed": "system_tests@DD17", "seconds": 1.0}
        other = P("dd18_angular_damping.hpp", "acceleration", "x", "y", "w")
        run = {"commit": "c", "dirty": False, "tree": "t", "build": {"name": "b"}, "chosen": 2,
               "started": "s", "prep_secs": 1.0, "judging_secs": 1.0}
        with tempfile.TemporaryDirectory() as out:
            self.assertEqual(mr.resumed(out, "t", [FLIP, other]), {})  # nothing written yet
            a = argparse.Namespace(out_dir=out, subset=None, only=None)
            mr.write(a, [row], {"DD17": {}}, {}, run, quiet=True)
            self.assertEqual(mr.resumed(out, "t", [FLIP, other]),
                             {(FLIP.module, FLIP.name): row})
            self.assertEqual(mr.resumed(out, "t", [other]), {})  # not chosen this time
            self.assertEqual(mr.resumed(out, "another tree", [FLIP, other]), {})

    def test_expectations_follow_srs(self):
        items = {"T3": {"engine": "model-only", "engine_reason": "not in the engine"},
                 "GD3": {"engine": "property", "engine_reason": "a law the results obey"},
                 "DD17": {}}
        self.assertEqual(mr.expected("T3", items), "not reached")
        self.assertEqual(mr.expected("GD3", items), "not reached")
        self.assertEqual(mr.expected("DD17", items), "verified")

    def test_summary_per_item(self):
        items = {"T3": {"engine": "model-only"}, "DD17": {}, "DD8": {}}
        rows = [{"label": "DD17", "module": "a", "result": "verified"},
                {"label": "DD8", "module": "b", "result": "verified"},
                {"label": "DD8", "module": "b", "result": "reached"},
                {"label": "T3", "module": "c", "result": "not reached"}]
        got = {s["label"]: s for s in mr.summarise(rows, items, {})}
        self.assertTrue(got["DD17"]["as_expected"])
        self.assertFalse(got["DD8"]["as_expected"])
        self.assertEqual(got["DD8"]["results"], ["reached", "verified"])
        self.assertTrue(got["T3"]["as_expected"])
        self.assertEqual([s["label"] for s in mr.summarise(rows, items, {})],
                         ["DD8", "DD17", "T3"])

    def test_a_failing_entry_is_checked_unperturbed_after_the_restore(self):
        # judge() leaves the question "does it fail anyway?" pending; judge_reach asks it once
        # judge() has restored the build, and judges again without an entry that fails anyway.
        calls = []

        def fake_judge(p, label, src, build, engine, objects, baseline, timeout, unmutated=None):
            calls.append(("judge", dict(baseline)))
            failed = "e@DD17" if baseline.get("e@DD17", True) else "f@DD17"
            return {"result": "verified", "failed": failed, "pending": failed}

        def fake_passes(name, build, engine, baseline, timeout):
            calls.append(("baseline", name))
            baseline[name] = name != "e@DD17"  # e fails unperturbed too; f passes
            return baseline[name]

        saved = mr.judge, mr.passes_unperturbed
        mr.judge, mr.passes_unperturbed = fake_judge, fake_passes
        try:
            row = mr.judge_reach(FLIP, "DD17", "src", "build", {}, {}, {}, 60)
        finally:
            mr.judge, mr.passes_unperturbed = saved
        self.assertEqual(row["failed"], "f@DD17")
        self.assertNotIn("pending", row)
        self.assertEqual([c[0] for c in calls], ["judge", "baseline", "judge", "baseline"])
        self.assertEqual(calls[2][1], {"e@DD17": False})

    def test_a_scratch_in_use_by_a_mutation_run_is_refused(self):
        # mutate.py and this script share the scratch: one lock for both, or they would build
        # each other's mutants.
        with tempfile.TemporaryDirectory() as d:
            root, scratch = os.path.join(d, "tree"), os.path.join(d, "scratch")
            os.makedirs(root)
            held = mr.mutate.lock_scratch(scratch)
            with self.assertRaises(SystemExit):
                mr.hold_scratch(root, scratch)
            held.close()
            mr.hold_scratch(root, scratch).close()

    def test_breadth_first_reaches_every_module_first(self):
        ps = [P(m + ".hpp", f, "", "", "") for m, f in
              [("a", "f"), ("a", "g"), ("b", "h"), ("c", "i"), ("c", "j"), ("c", "k")]]
        got = [p.name for p in mr.breadth_first(ps)]
        self.assertEqual(got, ["f", "h", "i", "g", "j", "k"])


if __name__ == "__main__":
    unittest.main()
