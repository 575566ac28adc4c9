"""The ReqIF export and import (traceability/reqif.py) on the fixture repository: the export
holds every item, test and code site with typed relations, is the same from the report's JSON,
validates against the ReqIF 1.2 schema and reads back without loss; the two samples of real
tools import without a crash and with what cannot be mapped listed.

The schema lives outside the repository: $TAMIAS_REQIF_SCHEMA, else
../shared/standards/reqif/reqif.xsd beside the checkout; the samples are in its examples/.
Without them those tests are skipped. Run:
/usr/bin/python3 -m unittest discover -s traceability/tests -t .
"""
import json
import os
import re
import shutil
import subprocess
import tempfile
import unittest
import xml.etree.ElementTree as ET

from traceability import analysis, reqif, srsdata
from traceability.tests.test_harness import REPO, run_harness

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
SCRIPT = os.path.join(ROOT, "traceability", "reqif.py")
SCHEMA = os.environ.get("TAMIAS_REQIF_SCHEMA") or os.path.normpath(
    os.path.join(ROOT, "..", "shared", "standards", "reqif", "reqif.xsd"))
EXAMPLES = os.path.join(os.path.dirname(SCHEMA), "examples")
NS = {"r": reqif.REQIF_NS, "x": reqif.XHTML_NS}
NCNAME = re.compile(r"^[A-Za-z_][A-Za-z0-9._-]*$")

try:
    import xmlschema
except ImportError:  # python3-xmlschema (scripts/debian-packages.txt)
    xmlschema = None


_SCHEMA = []


def validation_errors(path):
    if not _SCHEMA:  # parsed once: the XHTML modules make it the slow part
        _SCHEMA.append(xmlschema.XMLSchema(SCHEMA))
    return [f"{e.reason} at {e.path}" for e in _SCHEMA[0].iter_errors(path)]


class FixtureExport(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.mkdtemp(prefix="trace-reqif-")
        cls.out = os.path.join(cls.tmp, "reports")
        run_harness(REPO, cls.out)
        cls.path = os.path.join(cls.out, reqif.FILE_NAME)
        with open(os.path.join(cls.out, "traceability.json"), encoding="utf-8") as fh:
            cls.report = json.load(fh)
        cls.root = ET.parse(cls.path).getroot()
        cls.objects = {o.get("IDENTIFIER"): o for o in cls.root.iter(f"{{{reqif.REQIF_NS}}}SPEC-OBJECT")}
        cls.relations = [r for r in cls.root.iter(f"{{{reqif.REQIF_NS}}}SPEC-RELATION")]

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.tmp, ignore_errors=True)

    def test_every_item_test_and_code_site_is_an_object(self):
        ids = set(self.objects)
        for it in self.report["items"]:
            self.assertIn(reqif.ident("SRS", it["label"]), ids)
        for t in self.report["tests"]:
            self.assertIn(reqif.ident("TEST", t["id"]), ids)
        self.assertEqual(len(ids), len(self.report["items"]) + len(self.report["tests"]) +
                         len(self.report["code_sites"]))
        self.assertEqual(self.report["reqif"]["spec_objects"],
                         {"items": 13, "tests": len(self.report["tests"]), "code_sites": 6})

    def test_identifiers_are_derived_from_names(self):
        # Oracle: the escaping rule of reqif.ident, applied by hand.
        self.assertEqual(reqif.ident("TEST", "model_tests:model/im1_free_fall"),
                         "TEST-model_tests.3amodel.2fim1_free_fall")
        self.assertEqual(reqif.ident("REL", "uses", "SRS-IM1", "SRS-DD1"), "REL-uses-SRS.2dIM1-SRS.2dDD1")
        names = ["a-b", "a.2db", "a b", "a_b", "a/b", "a:b", "ä", "a--b", "a", "a-", "-a"]
        made = [reqif.ident("T", n) for n in names]
        self.assertEqual(len(set(made)), len(names))  # one name, one identifier
        for x in made + [e.get("IDENTIFIER") for e in self.root.iter() if e.get("IDENTIFIER")]:
            self.assertRegex(x, NCNAME)

    def test_relations_are_typed(self):
        kinds = {}
        for r in self.relations:
            kinds.setdefault(r.get("LONG-NAME"), set()).add(
                (r.findtext("r:SOURCE/r:SPEC-OBJECT-REF", namespaces=NS),
                 r.findtext("r:TARGET/r:SPEC-OBJECT-REF", namespaces=NS)))
        self.assertIn((reqif.ident("TEST", "model_tests:model/im2_spin"), "SRS-IM2"), kinds["verifies"])
        self.assertIn(("SRS-IM2", "SRS-T1"), kinds["refines"])   # an IM uses a TM
        self.assertIn(("SRS-IM1", "SRS-DD1"), kinds["uses"])
        self.assertIn(("SRS-DD1", "SRS-T1"), kinds["uses"])      # a DD is no refinement
        self.assertEqual(len(kinds["verifies"]), len(self.report["links"]))
        self.assertEqual(len(kinds["implements"]),
                         sum(s["label"] in {i["label"] for i in self.report["items"]}
                             for s in self.report["code_sites"]))
        # The link's grade and review state are attributes of the verifies relation.
        rel = next(r for r in self.relations if r.get("IDENTIFIER") == reqif.ident(
            "REL", "verifies", reqif.ident("TEST", "peer_compare:step_time_within_2x_of_peer"), "SRS-NFR1"))
        refs = [e.text for e in rel.iter(f"{{{reqif.REQIF_NS}}}ENUM-VALUE-REF")]
        self.assertEqual(refs, ["EV-Grade-weak", "EV-Review-unreviewed"])

    def test_one_specification_per_section_in_the_srs_order(self):
        specs = [s.get("LONG-NAME") for s in self.root.iter(f"{{{reqif.REQIF_NS}}}SPECIFICATION")]
        self.assertEqual(specs, ["5.1.3 Goal statements", "5.2.1 Assumptions", "5.2.2 Theoretical models",
                                 "5.2.4 Data definitions", "5.2.5 Instance models", "5.2.6 Data constraints",
                                 "6.1 Functional requirements", "6.2 Non-functional requirements",
                                 "7 Likely changes", "Tests and verification checks", "Code sites (\\srs tags)"])
        dd = next(s for s in self.root.iter(f"{{{reqif.REQIF_NS}}}SPECIFICATION") if s.get("IDENTIFIER") == "SPEC-DD")
        self.assertEqual([x.text for x in dd.iter(f"{{{reqif.REQIF_NS}}}SPEC-OBJECT-REF")], ["SRS-DD1", "SRS-DD2"])

    def test_the_command_exports_the_same_bytes_from_the_json(self):
        other = os.path.join(self.tmp, "again.reqif")
        proc = subprocess.run(["/usr/bin/python3", SCRIPT, "export", "--report",
                               os.path.join(self.out, "traceability.json"), "--out", other],
                              capture_output=True, text=True, timeout=120)
        self.assertEqual(proc.returncode, 0, proc.stderr)
        with open(self.path, "rb") as a, open(other, "rb") as b:
            self.assertEqual(a.read(), b.read())

    def test_the_only_time_is_the_creation_time(self):
        with open(self.path, encoding="utf-8") as fh:
            text = fh.read()
        stamps = set(re.findall(r"\d{4}-\d\d-\d\dT\d\d:\d\d:\d\dZ", text))
        created = self.root.findtext("r:THE-HEADER/r:REQ-IF-HEADER/r:CREATION-TIME", namespaces=NS)
        self.assertEqual(created, "2000-01-01T00:00:00Z")  # the report's generated (--date)
        last = {e.get("LAST-CHANGE") for e in self.root.iter() if e.get("LAST-CHANGE")}
        self.assertEqual(len(last), 1)  # the reported commit's date, on every element
        self.assertEqual(last, {self.report["reqif"]["last_change"]})
        self.assertEqual(stamps, last | {created})

    def test_item_attributes(self):
        got = reqif.read(self.path)
        ev = got["evidence"]["IM2"]
        self.assertEqual(ev["status"], "failing")
        self.assertEqual(len(ev["fingerprint"]), 16)
        nfr2 = next(i for i in got["items"] if i["label"] == "NFR2")
        self.assertEqual(nfr2["obligation"], "should")
        dd1 = next(i for i in got["items"] if i["label"] == "DD1")
        self.assertEqual(dd1["symbols"], [{"symbol": "p_CM", "unit": "m", "description": "centre of mass"}])
        self.assertEqual((dd1["errata"], dd1["source"]), (["E1"], {"seed": "000", "section": "5.2.4"}))
        spin = next(t for t in got["tests"] if t["id"] == "model_tests:model/im2_spin")
        self.assertEqual((spin["status"], spin["oracle"]), ("failed", "angular momentum is conserved without torque"))
        self.assertEqual(spin["source"], "tests/model/test_model.cpp:16")

    def test_round_trip_loses_nothing(self):
        got = reqif.read(self.path)
        self.assertEqual(got["unmapped"], [])
        self.assertEqual(reqif.compare_items(srsdata.load_srs(os.path.join(REPO, "srs")).items, got["items"]), [])
        self.assertEqual({(ln["item"], ln["test"], ln["grade"], ln["review"]) for ln in got["links"]},
                         {(ln["item"], ln["test"], ln["grade"], ln["review"]["status"])
                          for ln in self.report["links"]})
        self.assertEqual({t["id"] for t in got["tests"]}, {t["id"] for t in self.report["tests"]})
        # Written back as srs/ files, the items load as they were.
        out = os.path.join(self.tmp, "srs-again")
        subprocess.run(["/usr/bin/python3", SCRIPT, "import", self.path, "--out", out], check=True,
                       capture_output=True, timeout=120)
        again = srsdata.load_srs(out)
        self.assertEqual(reqif.compare_items(srsdata.load_srs(os.path.join(REPO, "srs")).items,
                                             [dict(v) for v in again.items.values()]), [])

    @unittest.skipUnless(os.path.exists(SCHEMA), f"ReqIF schema absent ({SCHEMA}; set TAMIAS_REQIF_SCHEMA)")
    @unittest.skipUnless(xmlschema, "python3-xmlschema is not installed")
    def test_validates_against_the_reqif_schema(self):
        self.assertEqual(validation_errors(self.path), [])


class ProjectSrs(unittest.TestCase):
    """Every item of the project's own srs/ (LaTeX, symbol tables, DC rows, IM inputs) goes
    through the export and back unchanged."""

    def test_round_trip_of_the_projects_srs(self):
        srs = srsdata.load_srs(os.path.join(ROOT, "srs"))
        res = analysis.analyse(srs, [], [], {"category_labels": []})
        reqif.srs_extra(srs, res["items"])
        report = json.loads(json.dumps({"items": res["items"], "errata": srs.errata, "source": {},
                                        "generated": "2000-01-01 00:00 UTC"}))
        with tempfile.TemporaryDirectory() as tmp:
            path = os.path.join(tmp, "srs.reqif")
            with open(path, "w", encoding="utf-8") as fh:
                fh.write(reqif.export_text(report)[0])
            got = reqif.read(path)
            if os.path.exists(SCHEMA) and xmlschema:
                self.assertEqual(validation_errors(path), [])
        self.assertEqual(len(got["items"]), len(srs.items))
        self.assertEqual(reqif.compare_items(srs.items, got["items"]), [])
        self.assertEqual(got["unmapped"], [])

    def test_text_survives_paragraphs_and_line_breaks(self):
        # Oracle: the texts themselves; each must come back character for character.
        for text in ["a", "", "two\n\nparagraphs", "line\nbreak", "a\n\n\nb", "\nlead", "trail\n",
                     "  spaced  <&>\"' ", "x\n\n"]:
            root = ET.fromstring(f'<v xmlns:xhtml="{reqif.XHTML_NS}">' +
                                 "".join(reqif.serialize(reqif.text_xhtml(text))) + "</v>")
            self.assertEqual(reqif.xhtml_text(root[0]), text)


@unittest.skipUnless(os.path.isdir(EXAMPLES), f"ReqIF samples absent ({EXAMPLES})")
class ForeignSamples(unittest.TestCase):
    """Files written by Eclipse RMF/ProR and by IBM DOORS (via StrictDoc's tests), read in
    place: nothing of theirs is an SRS item, and the import says what it could not map."""

    def test_samples_import_and_report_what_they_cannot_map(self):
        names = sorted(n for n in os.listdir(EXAMPLES) if n.endswith(".reqif"))
        self.assertEqual(len(names), 2)
        for name in names:
            path = os.path.join(EXAMPLES, name)
            got = reqif.read(path)
            self.assertGreater(len(got["unmapped"]), 0)
            self.assertTrue(any(u.startswith("object ") for u in got["unmapped"]), got["unmapped"])
            proc = subprocess.run(["/usr/bin/python3", SCRIPT, "import", path], capture_output=True,
                                  text=True, timeout=120)
            self.assertEqual(proc.returncode, 0, proc.stderr)
            self.assertIn(f"not mapped ({len(got['unmapped'])}):", proc.stdout)


if __name__ == "__main__":
    unittest.main()
