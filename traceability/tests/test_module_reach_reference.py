"""The reference module reach as the report reads it (traceability/module_reach_reference.py).

Oracle: a reference written here by module_reach.py's own writer from rows made up here, whose
counts and items not as srs/ states follow from the rows written.
"""
from __future__ import annotations

import argparse
import os
import sys
import tempfile
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, ROOT)
sys.path.insert(0, os.path.join(ROOT, "verification", "model_reach"))

import module_reach  # noqa: E402
from traceability import module_reach_reference as mrr  # noqa: E402


def row(label, module, result, expected="verified"):
    return {"label": label, "module": module, "function": "f", "why": "w", "judged_by": [label],
            "result": result, "expected": expected, "failed": None, "seconds": 1.0}


class Reference(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.root = self.tmp.name

    def tearDown(self):
        self.tmp.cleanup()

    def write(self, rows, chosen):
        run = {"commit": "c0ffee", "dirty": False, "tree": "t", "build": {"name": "b"},
               "chosen": chosen, "started": "s", "prep_secs": 1.0, "judging_secs": 1.0}
        items = {"DD17": {}, "DD18": {}, "T3": {"engine": "model-only"}}
        out = os.path.join(self.root, os.path.dirname(mrr.REFERENCE))
        module_reach.write(argparse.Namespace(out_dir=out, subset=None, only=None), rows, items,
                           {}, run, quiet=True)

    def test_absent_reference_is_none(self):
        self.assertIsNone(mrr.collect(self.root, []))

    def test_counts_and_items_off_their_srs_expectation(self):
        self.write([row("DD17", "dd17.hpp", "verified"), row("DD18", "dd18.hpp", "reached"),
                    row("T3", "t3.hpp", "not reached", "not reached")], chosen=4)
        ref = mrr.collect(self.root, [])
        self.assertEqual(ref["results"], {"verified": 1, "reached": 1, "not reached": 1})
        self.assertEqual(ref["not_as_expected"], ["DD18"])
        self.assertFalse(ref["complete"])  # 3 of 4 chosen
        self.assertEqual(ref["judged_of_chosen"], "3 of 4")
        text = mrr.summary(ref)
        self.assertIn("3 of 4 perturbations judged (the run had not finished)", text)
        self.assertIn("not as srs/ states: DD18", text)

    def test_a_finished_run_as_srs_states(self):
        self.write([row("DD17", "dd17.hpp", "verified")], chosen=1)
        ref = mrr.collect(self.root, [])
        self.assertTrue(ref["complete"])
        self.assertIn("every item as srs/ states", mrr.summary(ref))


if __name__ == "__main__":
    unittest.main()
