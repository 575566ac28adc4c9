"""Self-test of srs/check_srs.py: run with /usr/bin/python3 -m unittest discover -s srs.

A tiny SRS is written to a temporary directory; the valid version must pass and each broken
variant (duplicate label, dangling reference, non-bijective alias, ...) must be rejected.
The committed SRS itself must be valid and its errata document up to date.
"""
import copy
import io
import os
import sys
import tempfile
import unittest
from contextlib import redirect_stderr, redirect_stdout

import yaml

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import check_srs  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(HERE)


def _item(label, kind, **kw):
    it = {"label": label, "kind": kind, "alias": None, "title": f"title of {label}",
          "equation": None, "symbols": [], "uses": [], "source": {"seed": "000", "section": "1"},
          "description": f"description of {label}"}
    it.update(kw)
    return it


def tiny_srs():
    """A minimal valid SRS: one item of most kinds, one alias, one erratum."""
    sym = [{"symbol": "x", "unit": "m", "description": "a length"}]
    return {
        "goals.yaml": [_item("GS1", "GS", uses=["IM1"])],
        "assumptions.yaml": [_item("A1", "A")],
        "theoretical_models.yaml": [_item("T1", "TM", equation="x = x", symbols=sym,
                                          seed_ref_by=["DD1"])],
        "general_definitions.yaml": [],
        "data_definitions.yaml": [_item("DD1", "DD", alias="DD:thing", equation="x = 1",
                                        symbols=sym, uses=["T1", "A1"], seed_ref_by=["IM1"],
                                        alias_ref_by=["IM1"], errata=["E01"])],
        "instance_models.yaml": [_item("IM1", "IM", equation="x = 2", symbols=sym,
                                       uses=["DD1"], seed_ref_by=["GS1", "R1"])],
        "requirements.yaml": [_item("R1", "R", uses=["IM1", "DCI_x"], obligation="shall",
                                    description="The software shall do x.")],
        "nonfunctional.yaml": [_item("NFR1", "NFR", obligation="should",
                                     description="Its x should stay small.")],
        "changes.yaml": [_item("LC1", "LC", uses=["A1"]), _item("UC1", "UC")],
        "data_constraints.yaml": [_item("DCI_x", "DC", variable="x", constraint="x >= 0",
                                        typical="1 m", equation="x \\ge 0", symbols=sym)],
        "errata.yaml": [{"id": "E01", "items": ["DD1"], "kind": "units", "seed_text": "x (s)",
                         "problem": "x is a length", "correct_reading": "x in m",
                         "compile_fail": True}],
        "meta.yaml": {"drasil_names": {"DD:thing": "DD1"}},
    }


def write(files, d):
    for name, data in files.items():
        with open(os.path.join(d, name), "w", encoding="utf-8") as fh:
            yaml.safe_dump(data, fh, sort_keys=False)


class TinySrs(unittest.TestCase):
    def run_check(self, files):
        with tempfile.TemporaryDirectory() as d:
            write(files, d)
            return check_srs.check(d, use_seeds=False)

    def assertRejected(self, files, fragment):
        res = self.run_check(files)
        self.assertFalse(res.valid, "broken SRS was accepted")
        self.assertTrue(any(fragment in e for e in res.errors),
                        f"no error mentions {fragment!r}: {res.errors}")

    def test_valid_tiny_srs_passes(self):
        res = self.run_check(tiny_srs())
        self.assertTrue(res.valid, res.errors)
        self.assertEqual(res.ref_by["DD1"], ["IM1"])
        self.assertEqual(res.ref_by["IM1"], ["GS1", "R1"])
        self.assertEqual(res.disagreements, [])

    def test_refby_disagreement_is_a_finding_not_an_error(self):
        files = tiny_srs()
        files["theoretical_models.yaml"][0]["seed_ref_by"] = ["IM1"]  # seed is wrong
        res = self.run_check(files)
        self.assertTrue(res.valid, res.errors)
        self.assertEqual(len(res.disagreements), 1)
        d = res.disagreements[0]
        self.assertEqual((d["label"], d["missing_in_seed"], d["extra_in_seed"]),
                         ("T1", ["DD1"], ["IM1"]))

    def test_duplicate_label_rejected(self):
        files = tiny_srs()
        files["assumptions.yaml"].append(_item("A1", "A"))
        self.assertRejected(files, "duplicate label A1")

    def test_dangling_use_rejected(self):
        files = tiny_srs()
        files["instance_models.yaml"][0]["uses"].append("DD99")
        self.assertRejected(files, "'DD99' is not an SRS label")

    def test_dangling_seed_ref_by_rejected(self):
        files = tiny_srs()
        files["theoretical_models.yaml"][0]["seed_ref_by"] = ["T??"]
        self.assertRejected(files, "'T??' is not an SRS label")

    def test_unresolved_seed_reference_recorded_separately_passes(self):
        files = tiny_srs()
        files["theoretical_models.yaml"][0]["seed_ref_by_unresolved"] = ["T??"]
        res = self.run_check(files)
        self.assertTrue(res.valid, res.errors)
        self.assertIn("T??", [u["text"] for u in res.unresolved])

    def test_alias_given_twice_rejected(self):
        files = tiny_srs()
        files["instance_models.yaml"][0]["alias"] = "DD:thing"
        self.assertRejected(files, "aliases are one-to-one")

    def test_unmapped_drasil_name_rejected(self):
        files = tiny_srs()
        files["meta.yaml"]["drasil_names"]["DD:other"] = "IM1"
        self.assertRejected(files, "DD:other")

    def test_alias_not_in_drasil_names_rejected(self):
        files = tiny_srs()
        files["assumptions.yaml"][0]["alias"] = "A:made"
        self.assertRejected(files, "not a Drasil name")

    def test_bad_label_characters_rejected(self):
        files = tiny_srs()
        files["nonfunctional.yaml"][0]["label"] = "NFR-1"
        self.assertRejected(files, "must match [A-Za-z0-9_]+")

    def test_bad_kind_rejected(self):
        files = tiny_srs()
        files["nonfunctional.yaml"][0]["kind"] = "XX"
        self.assertRejected(files, "is not one of")

    def test_missing_unit_rejected(self):
        files = tiny_srs()
        files["data_definitions.yaml"][0]["symbols"] = [{"symbol": "x", "description": "d"}]
        self.assertRejected(files, "missing or empty 'unit'")

    def test_unparsable_unit_rejected(self):
        files = tiny_srs()
        files["data_definitions.yaml"][0]["symbols"][0]["unit"] = "furlong"
        self.assertRejected(files, "does not parse")

    def test_tamias_unit_must_match_up_to_radians(self):
        files = tiny_srs()
        files["data_definitions.yaml"][0]["symbols"] = [
            {"symbol": "tau", "unit": "N m", "tamias_unit": "N rad^-1", "description": "d"}]
        self.assertRejected(files, "radian exponent")

    def test_model_item_without_equation_rejected(self):
        files = tiny_srs()
        files["instance_models.yaml"][0]["equation"] = None
        self.assertRejected(files, "needs an equation")

    def test_unknown_key_rejected(self):
        files = tiny_srs()
        files["goals.yaml"][0]["usess"] = []
        self.assertRejected(files, "unknown keys")

    def test_erratum_must_be_listed_both_ways(self):
        files = tiny_srs()
        files["data_definitions.yaml"][0]["errata"] = []
        self.assertRejected(files, "does not list E01")

    def test_erratum_with_dangling_item_rejected(self):
        files = tiny_srs()
        files["errata.yaml"][0]["items"].append("GD7")
        self.assertRejected(files, "'GD7' is not an SRS label")

    def test_requirement_without_obligation_rejected(self):
        files = tiny_srs()
        del files["requirements.yaml"][0]["obligation"]
        self.assertRejected(files, "R1: a R needs obligation")

    def test_obligation_must_match_the_verb(self):
        files = tiny_srs()
        files["nonfunctional.yaml"][0]["obligation"] = "shall"
        self.assertRejected(files, "NFR1: obligation shall but the statement says 'should'")

    def test_mixed_verbs_need_an_obligation_erratum(self):
        files = tiny_srs()
        files["requirements.yaml"][0]["description"] = "It shall do x; x should take 1 s."
        self.assertRejected(files, "R1: the statement has shall, should")
        files["requirements.yaml"][0]["errata"] = ["E02"]
        files["errata.yaml"].append({"id": "E02", "items": ["R1"], "kind": "obligation",
                                     "seed_text": "shall ... should", "problem": "mixed",
                                     "correct_reading": "shall governs", "compile_fail": False})
        res = self.run_check(files)
        self.assertTrue(res.valid, res.errors)

    def test_obligation_only_on_requirements(self):
        files = tiny_srs()
        files["goals.yaml"][0]["obligation"] = "shall"
        self.assertRejected(files, "only requirements")

    def test_model_only_item_passes_with_its_reason(self):
        files = tiny_srs()
        files["theoretical_models.yaml"][0].update(engine="model-only",
                                                   engine_reason="the engine never forms x")
        res = self.run_check(files)
        self.assertTrue(res.valid, res.errors)
        self.assertEqual(res.items["T1"]["engine"], "model-only")

    def test_model_only_needs_a_reason(self):
        files = tiny_srs()
        files["theoretical_models.yaml"][0]["engine"] = "model-only"
        self.assertRejected(files, "needs engine_reason")
        files["theoretical_models.yaml"][0]["engine_reason"] = " "
        self.assertRejected(files, "needs engine_reason")

    def test_property_item_passes_with_its_reason(self):
        files = tiny_srs()
        files["theoretical_models.yaml"][0].update(engine="property",
                                                   engine_reason="a law the results obey")
        res = self.run_check(files)
        self.assertTrue(res.valid, res.errors)

    def test_engine_value_is_model_only(self):
        files = tiny_srs()
        files["data_definitions.yaml"][0].update(engine="runs", engine_reason="it does")
        self.assertRejected(files, "engine must be one of model-only")
        files = tiny_srs()
        files["data_definitions.yaml"][0]["engine_reason"] = "a reason alone"
        self.assertRejected(files, "engine must be one of model-only")

    def test_engine_only_on_model_items(self):
        files = tiny_srs()
        files["requirements.yaml"][0].update(engine="model-only", engine_reason="no formula")
        self.assertRejected(files, "carry engine")

    def test_cycle_in_uses_rejected(self):
        files = tiny_srs()
        files["theoretical_models.yaml"][0]["uses"] = ["IM1"]
        self.assertRejected(files, "cycle")


class CommittedSrs(unittest.TestCase):
    def test_committed_srs_is_valid(self):
        res = check_srs.check(HERE)
        self.assertTrue(res.valid, "\n".join(res.errors))

    def test_committed_errata_doc_is_current(self):
        doc = os.path.join(REPO, "docs", "srs-errata.md")
        with redirect_stdout(io.StringIO()), redirect_stderr(io.StringIO()):
            rc = check_srs.main(["--quiet", "--check-errata-md", doc])
        self.assertEqual(rc, 0, "docs/srs-errata.md is stale: regenerate it")

    def test_stale_errata_doc_detected(self):
        with tempfile.TemporaryDirectory() as d:
            stale = os.path.join(d, "stale.md")
            with open(stale, "w", encoding="utf-8") as fh:
                fh.write("# outdated\n")
            with redirect_stdout(io.StringIO()), redirect_stderr(io.StringIO()):
                rc = check_srs.main(["--quiet", "--check-errata-md", stale])
        self.assertEqual(rc, 1)

    def test_json_graph(self):
        import json
        with tempfile.TemporaryDirectory() as d:
            out = os.path.join(d, "g.json")
            with redirect_stdout(io.StringIO()):
                rc = check_srs.main(["--quiet", "--json", out])
            self.assertEqual(rc, 0)
            with open(out, encoding="utf-8") as fh:
                g = json.load(fh)
        for key in ("items", "uses", "ref_by", "seed_ref_by", "disagreements", "errata"):
            self.assertIn(key, g)
        # Ref. By is computed from `uses`: IM3, the distance, line and wheel constraints DD20,
        # DD23 and DD25, the distance joint's motor DD35, a surface's tangent speed DD47, the soft
        # contacts IM7 and their energy bound GD3 use DD8.
        self.assertEqual(g["ref_by"]["DD8"],
                         ["GD3", "DD20", "DD23", "DD25", "DD35", "DD47", "IM3", "IM7"])


if __name__ == "__main__":
    unittest.main()
